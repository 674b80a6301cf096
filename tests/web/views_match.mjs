// The page's windows and counters, as its script dumps them, against what the `luz` commands
// compute for the same settings (tests/web/page_views_match_cli.sh runs them; the tolerances
// are said there). One check a call:
//
//   ray-tree-panel WINDOWS.json WIDGETS.json WIDGETS_CLEARED.json
//       the panel shows the clicked pixel's tree as a table of five columns (ray, depth, hit,
//       local, share), each as wide as its text, and its "clear [X]" button in view; once that
//       button is clicked, the button is gone with the tree
//   brute BVH_TRACE.json BRUTE_TRACE.json
//       brute force traced the same rays as the BVH (every kind, the same count) and counted its
//       ray-triangle tests; the BVH counts none
//   rays TRACE.json LUZ_RENDER_OUTPUT.txt
//       the page's trace (dump-trace) traced the rays `luz render` printed, kind for kind
//   radiosity DUMP.json LUZ_RENDER_OUTPUT.txt MESHING UNSHOT_LIMIT
//       the page's solution (dump-radiosity) has the mesh `luz render` printed (its patches and
//       its elements, adaptive subdivision's included), after the same shots, its unshot power
//       within UNSHOT_LIMIT relative; MESHING adaptive: elements were cut, uniform: none
//   item-buffer DUMP.json PANEL.png
//       the item-buffer window is shown for the last shooter, and its rectangle of the page's
//       canvas holds the hemicube's false colours (more than 100, one a patch seen)
//   solvers DUMP.json LUZ_SOLVERS.csv LUZ_SOLVERS_OUTPUT.txt LIMIT
//       slide 36's window (dump-solvers) has `luz solvers`'s patches, and every sample of each
//       method's curve up to the CSV's last row count is the CSV's sample at the same rows,
//       residual and error within LIMIT relative
//   solver-plots DUMP.json EARLY.png LATER.png ROWS
//       its plots (their rectangle dumped with LATER) changed between two pictures of the canvas,
//       more than 1% of their pixels by more than 8 codes: the curves drawn on; and the window
//       paused at exactly the ROWS that `wait-solver-rows ROWS` asked for
//   difference DUMP.json LUZ_COMPARE_OUTPUT.txt PAGE_HEATMAP.png LUZ_HEATMAP.png
//       the difference view's figures (dump-difference) are `luz compare`'s of the same model
//       and reference renders, within the noise of the reference's paths (below); its picture is
//       `luz compare --heatmap`'s map (above its legend)
//   panes BEFORE.json AFTER.json
//       every pane was drawn with one camera, before and after a drag, and the drag moved it
import { readFileSync } from 'node:fs';
import { readPng } from './png.mjs';

const [kind, ...args] = process.argv.slice(2);
const json = (file) => JSON.parse(readFileSync(file, 'utf8'));
let failed = false;
const check = (ok, what) => {
  console.log(`${ok ? 'ok' : 'FAILED'}: ${what}`);
  if (!ok) failed = true;
};
const relative = (a, b) => Math.abs(a - b) / Math.max(Math.abs(b), 1e-30);

function rayTreePanel([windowsFile, widgetsFile, clearedFile]) {
  const tables = json(windowsFile).tables.filter((t) => t.window === 'Luz');
  check(tables.length === 1 && tables[0].columns.length === 5, `the panel has one table of 5 columns (${tables.map((t) => t.columns.length)})`);
  for (const t of tables)
    check(t.columns.every((c) => c.text <= c.room + 0.5) && !t.scrolls_sideways, 'each column as wide as its text');
  const clear = (file) => json(file).widgets.find((w) => w.label === 'clear [X]');
  check(clear(widgetsFile)?.visible === true, 'the tree\'s "clear [X]" button is in view');
  check(clear(clearedFile) === undefined, 'clicked, the button is gone with the tree');
}

function brute([bvhFile, bruteFile]) {
  const bvh = json(bvhFile), bruteForce = json(bruteFile);
  check(bvh.phase === 'done' && bruteForce.phase === 'done', `both traces done (${bvh.phase}, ${bruteForce.phase})`);
  check(JSON.stringify(bvh.rays) === JSON.stringify(bruteForce.rays),
        `brute force traced the BVH's rays: ${JSON.stringify(bruteForce.rays)} against ${JSON.stringify(bvh.rays)}`);
  const rays = Object.values(bruteForce.rays).reduce((a, b) => a + b, 0);
  check(bvh.intersection_tests === 0 && bruteForce.intersection_tests > rays,
        `brute force counted ${bruteForce.intersection_tests} ray-triangle tests for ${rays} rays; the BVH ${bvh.intersection_tests}`);
}

function rays([traceFile, outputFile]) {
  const trace = json(traceFile), printed = readFileSync(outputFile, 'utf8');
  const m = printed.match(/rays: (\d+) primary, (\d+) shadow, (\d+) reflected, (\d+) transmitted/);
  check(m !== null, `luz render printed its rays: ${printed.split('\n')[1] ?? printed}`);
  if (!m) return;
  ['primary', 'shadow', 'reflected', 'transmitted'].forEach((kind, k) =>
    check(trace.rays[kind] === Number(m[k + 1]), `${kind} rays: the page ${trace.rays[kind]}, luz render ${m[k + 1]}`));
}

function radiosity([dumpFile, outputFile, meshing, limitText]) {
  const d = json(dumpFile), printed = readFileSync(outputFile, 'utf8');
  const m = printed.match(/(\d+) patches .* of (\d+) elements, hemicube \d+, (\d+) shots, unshot ([0-9.]+)%/);
  check(m !== null, `luz render printed its mesh and shots: ${printed.split('\n')[0]}`);
  if (!m) return;
  const [patches, elements, shots, unshot] = [Number(m[1]), Number(m[2]), Number(m[3]), Number(m[4]) / 100];
  check(d.shots === shots, `the page shot ${d.shots} times, luz render ${shots}`);
  check(d.patches === patches && d.elements === elements,
        `the page's mesh: ${d.patches} patches of ${d.elements} elements; luz render's ${patches} of ${elements}`);
  check(meshing === 'adaptive' ? d.refined_elements > 0 && d.refinement_passes >= 1 : d.refined_elements === 0,
        `${meshing} meshing: ${d.refined_elements} elements cut in ${d.refinement_passes} passes`);
  const limit = Number(limitText);
  check(relative(d.unshot_fraction, unshot) <= limit,
        `unshot ${(100 * d.unshot_fraction).toFixed(3)}% of the emitted power against luz render's ${(100 * unshot).toFixed(3)}% ` +
        `(${(100 * relative(d.unshot_fraction, unshot)).toFixed(3)}% apart, limit ${100 * limit}%)`);
}

function itemBuffer([dumpFile, panelFile]) {
  const d = json(dumpFile), panel = readPng(panelFile);
  check(d.item_view_shown === true, 'the item-buffer window is shown');
  check(d.item_view_shooter === d.shooter && /^patch \d+/.test(d.shooter),
        `it is the last shooter's hemicube: "${d.item_view_shooter}", the shooter "${d.shooter}"`);
  const [x0, y0, x1, y1] = d.item_view_rect.map(Math.round);
  check(x1 - x0 > 50 && x1 <= panel.width && y1 <= panel.height, `its rectangle ${d.item_view_rect} inside the canvas`);
  const colours = new Set();
  for (let y = Math.max(y0, 0); y < Math.min(y1, panel.height); ++y)
    for (let x = Math.max(x0, 0); x < Math.min(x1, panel.width); ++x) colours.add(panel.rgb(x, y).join(','));
  check(colours.size > 100, `${colours.size} colours in it (more than 100: one a patch the hemicube sees)`);
}

function solvers([dumpFile, csvFile, outputFile, limitText]) {
  const d = json(dumpFile), limit = Number(limitText);
  const m = readFileSync(outputFile, 'utf8').match(/solvers: (\d+) patches/);
  check(m !== null && d.patches === Number(m[1]), `the window's ${d.patches} patches are luz solvers's ${m?.[1]}`);
  const headless = new Map();
  let lastRows = 0;
  for (const line of readFileSync(csvFile, 'utf8').trim().split('\n').slice(1)) {
    const [method, , rows, , residual, error] = line.split(',');
    headless.set(`${method} ${rows}`, [Number(residual), Number(error)]);
    lastRows = Math.max(lastRows, Number(rows));
  }
  for (const method of ['jacobi', 'gauss-seidel', 'southwell', 'shooting']) {
    const curve = d.curves[method] ?? [];
    let compared = 0, worst = 0, missing = null;
    for (const sample of curve) {
      if (sample.rows > lastRows) continue;
      const found = headless.get(`${method} ${sample.rows}`);
      if (!found) { missing ??= sample.rows; continue; }
      ++compared;
      worst = Math.max(worst, relative(sample.residual, found[0]), relative(sample.error, found[1]));
    }
    check(compared >= 3 && missing === null && worst <= limit,
          `${method}: ${compared} samples of the window's curve at luz solvers's rows` +
          `${missing !== null ? `, none there at ${missing} rows` : ''}, residual and error at most ` +
          `${(100 * worst).toFixed(2)}% apart (limit ${100 * limit}%)`);
  }
}

function solverPlots([dumpFile, earlyFile, laterFile, rowsText]) {
  const d = json(dumpFile), early = readPng(earlyFile), later = readPng(laterFile);
  check(d.rows === Number(rowsText) && !d.running, `the window paused at ${d.rows} rows (asked for ${rowsText}), running: ${d.running}`);
  const [x0, y0, x1, y1] = d.plot.map(Math.round);
  check(x1 - x0 > 40 && y1 - y0 > 100 && x1 <= later.width && y1 <= later.height, `the plots' rectangle ${d.plot} inside the canvas`);
  let moved = 0, total = 0;
  for (let y = y0; y < Math.min(y1, later.height); ++y)
    for (let x = x0; x < Math.min(x1, later.width); ++x, ++total) {
      const a = early.rgb(x, y), b = later.rgb(x, y);
      if (a.some((v, k) => Math.abs(v - b[k]) > 8)) ++moved;
    }
  check(moved > 0.01 * total, `the plots drew the curves: ${moved} of their ${total} pixels changed (more than 1%)`);
}

// The figures `luz compare` prints: mean error per channel, rel-RMSE, the mean relative error and
// its lit pixels.
function printedFigures(text) {
  const number = '([-+]?[0-9.]+)';
  const mean = text.match(new RegExp(`mean error \\(A - B\\): +R ${number} +G ${number} +B ${number}`));
  const rmse = text.match(new RegExp(`rel-RMSE: +${number}`));
  const lit = text.match(new RegExp(`over lit pixels: ${number} .*, ([0-9]+) of`));
  if (!mean || !rmse || !lit) return null;
  return { mean_error: mean.slice(1, 4).map(Number), rel_rmse: Number(rmse[1]), mean_relative_error: Number(lit[1]), lit_pixels: Number(lit[2]) };
}

function difference([dumpFile, outputFile, pageMapFile, luzMapFile]) {
  const d = json(dumpFile), p = printedFigures(readFileSync(outputFile, 'utf8'));
  check(d.valid === true && d.model === 'Whitted' && d.reference_spp === 4,
        `the difference view compares ${d.model} with the path tracer's ${d.reference_spp} samples (valid: ${d.valid})`);
  check(p !== null, 'luz compare printed its figures');
  if (!p || !d.valid) return;
  const near = (a, b, limit) => Math.abs(a - b) <= limit;
  check(d.mean_error.every((v, c) => near(v, p.mean_error[c], 0.002)),
        `mean error ${d.mean_error.map((v) => v.toFixed(5))} against luz compare's ${p.mean_error} (limit 0.002)`);
  check(near(d.rel_rmse, p.rel_rmse, 0.01), `rel-RMSE ${d.rel_rmse.toFixed(5)} against ${p.rel_rmse} (limit 0.01)`);
  check(near(d.mean_relative_error, p.mean_relative_error, 0.01),
        `mean relative error over lit pixels ${d.mean_relative_error.toFixed(4)} against ${p.mean_relative_error} (limit 0.01)`);
  check(near(d.lit_pixels, p.lit_pixels, 0.001 * p.lit_pixels), `${d.lit_pixels} lit pixels against ${p.lit_pixels}`);
  // The heat map: its colours (blue darker, red brighter) where luz compare's map is clearly
  // one or the other, and how far its codes are on average.
  const page = readPng(pageMapFile), luz = readPng(luzMapFile);
  check(page.width === luz.width && luz.height > page.height, `the page's map ${page.width}x${page.height} above luz compare's legend`);
  let sum = 0, same = 0, clear = 0;
  for (let y = 0; y < page.height; ++y)
    for (let x = 0; x < page.width; ++x) {
      const a = page.rgb(x, y), b = luz.rgb(x, y);
      sum += Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]);
      if (Math.abs(b[0] - b[2]) > 40) {
        ++clear;
        if (Math.sign(a[0] - a[2]) === Math.sign(b[0] - b[2])) ++same;
      }
    }
  const mean = sum / (3 * page.width * page.height);
  check(clear > 0.1 * page.width * page.height && same >= 0.95 * clear,
        `${same} of the ${clear} pixels luz compare's map shows clearly red or blue have its colour in the page's (at least 95%)`);
  check(mean <= 10, `the maps ${mean.toFixed(2)} codes apart on average (at most 10)`);
}

function panes([beforeFile, afterFile]) {
  const before = json(beforeFile), after = json(afterFile);
  const cameras = (d) => d.panes.map((p) => JSON.stringify(p.camera));
  for (const [name, d] of [['before', before], ['after', after]])
    check(d.panes.length >= 2 && new Set(cameras(d)).size === 1, `${name} the drag: ${d.panes.length} panes, one camera`);
  check(cameras(before)[0] !== cameras(after)[0], 'the drag moved the camera');
}

const checks = { 'ray-tree-panel': rayTreePanel, brute, rays, radiosity, 'item-buffer': itemBuffer, solvers, 'solver-plots': solverPlots, difference, panes };
if (!checks[kind]) {
  console.error(`usage: views_match.mjs (${Object.keys(checks).join('|')}) ARGS...`);
  process.exit(2);
}
checks[kind](args);
process.exit(failed ? 1 : 0);
