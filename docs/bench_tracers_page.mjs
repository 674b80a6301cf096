// The page's Whitted trace and radiosity solve in headless Chromium, set beside `luz render` on
// the same machine in the same minutes. A measurement, never part of the build or the tests:
//
//   python3 src/app/web/serve.py build-web 8000 &
//   NODE_PATH=build-web/npm/node_modules node docs/bench_tracers_page.mjs http://127.0.0.1:8000/luz.html \
//       [ROUNDS] [--whitted-only | --radiosity-only] [--luz build/luz]
//
// The one-thread page: serve build-web/ without the isolation headers (serve.py
// --no-isolation) and run the script with LUZ_PAGE_NO_SERVICE_WORKERS=1 (tests/web/browser.mjs),
// a browser without service workers.
//
// Each round opens the page twice: Whitted's scene in Whitted's model at 1024x1024 (depth 5, the
// default), timing `trace` through luz.run from the request to its last tile drawn (the tracer's
// own seconds, which the status line shows, are printed beside it: what the page's user waits
// for is the first figure), then `trace` again in the same page (the first trace also runs the
// tracer's WebAssembly as the browser first compiles it, before it optimises what runs most);
// and the Cornell box in radiosity at the viewer's defaults, timing
// `wait-shots 1000000` (the solver run to its stopping rule, 0.5% unshot). --whitted-only leaves
// the radiosity out, --radiosity-only the trace. With --luz (run from the repository's root),
// each round also runs that `luz render` of the same scene, model and size right after the
// page's trace, and prints the tracer's seconds and the model's picture with its set-up as it
// reports them, and the page's figure over the latter; and `luz render scenes/cornell_box.gltf
// --model radiosity` right after the page's solve, its "s solving" (the same 1845 shots) and
// the page's figure over it. Prints every round, the best and the median, with the load average
// before and after.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { openLuz, openPage } from '../tests/web/browser.mjs';

const args = process.argv.slice(2);
const whittedOnly = args.includes('--whitted-only');
const radiosityOnly = args.includes('--radiosity-only');
const luzAt = args.indexOf('--luz');
const luz = luzAt >= 0 ? args[luzAt + 1] : null;
const [base, roundsText = '3'] = args.filter((a, i) => !a.startsWith('--') && (luzAt < 0 || i !== luzAt + 1));
if (!base || (luzAt >= 0 && !luz)) {
  console.error('usage: bench_tracers_page.mjs BASE_URL [ROUNDS] [--whitted-only | --radiosity-only] [--luz PATH_TO_LUZ]');
  process.exit(2);
}
const load = () => readFileSync('/proc/loadavg', 'utf8').split(' ')[0];
const loadBefore = load();

// The seconds of the timed line, and what `dump-trace` says after it (the tracer's own seconds),
// for each of `times` runs of it in the same page.
async function timed(query, lines, timed_line, times = 1) {
  const { browser, page } = await openPage(() => {});
  try {
    const outcome = await openLuz(page, `${base}?${query}`);
    if (!outcome.ok) throw new Error(outcome.message);
    for (const line of lines) await page.evaluate((l) => window.luz.run(l), line);
    const runs = [];
    while (runs.length < times) {
      // Started in the page and polled: a solve may outlast one call's protocol timeout.
      await page.evaluate((l) => {
        const start = performance.now();
        window.benchSeconds = null;
        window.luz.run(l).then(() => { window.benchSeconds = (performance.now() - start) / 1000; },
                               (error) => { window.benchSeconds = 'failed: ' + error.message; });
      }, timed_line);
      for (;;) {
        const seconds = await page.evaluate(() => window.benchSeconds);
        if (typeof seconds === 'number') {
          const tracer = await page.evaluate(async () => {
            await window.luz.run('dump-trace /tmp/bench-trace.json');
            return JSON.parse(new TextDecoder().decode(window.FS.readFile('/tmp/bench-trace.json'))).seconds;
          });
          runs.push({ seconds, tracer });
          break;
        }
        if (seconds !== null) throw new Error(seconds);
        await new Promise((resolve) => setTimeout(resolve, 500));
      }
    }
    return runs;
  } finally {
    await browser.close();
  }
}

// `luz render`'s own figures for the same trace: "time: S s" (the tracer) and "the model's
// picture (its set-up included) S s".
const scratch = mkdtempSync(join(tmpdir(), 'luz-bench-'));
function native() {
  const text = execFileSync(luz, ['render', 'scenes/whitted.gltf', '--model', 'whitted', '--size', '1024x1024',
                                  '--out', join(scratch, 'whitted.png')], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const number = (pattern) => Number(text.match(pattern)[1]);
  return { tracer: number(/time: ([0-9.]+) s/), picture: number(/its set-up included\) ([0-9.]+) s/) };
}

// `luz render`'s solve of the Cornell box at the defaults: "..., N shots, ..., S s solving".
function nativeRadiosity() {
  const text = execFileSync(luz, ['render', 'scenes/cornell_box.gltf', '--model', 'radiosity',
                                  '--out', join(scratch, 'radiosity.png')], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  return { shots: Number(text.match(/([0-9]+) shots/)[1]), solving: Number(text.match(/([0-9.]+) s solving/)[1]) };
}

const figures = { whitted: [], tracer: [], again: [], radiosity: [], luz: [], luzTracer: [], ratio: [], againRatio: [],
                  luzRadiosity: [], radiosityRatio: [] };
for (let round = 0; round < Number(roundsText); ++round) {
  let line = `round ${round + 1}: `;
  if (!radiosityOnly) {
    const [w, again] = await timed('scene=whitted&model=whitted&size=1024x1024&panel=0', ['wait 2'], 'trace', 2);
    figures.whitted.push(w.seconds);
    figures.tracer.push(w.tracer);
    figures.again.push(again.seconds);
    line += `Whitted 1024x1024 ${w.seconds.toFixed(2)} s (its tracer ${w.tracer.toFixed(2)} s), ` +
            `again ${again.seconds.toFixed(2)} s (${again.tracer.toFixed(2)} s)`;
    if (luz) {
      const n = native();
      figures.luz.push(n.picture);
      figures.luzTracer.push(n.tracer);
      figures.ratio.push(w.seconds / n.picture);
      figures.againRatio.push(again.seconds / n.picture);
      line += `, luz render ${n.picture.toFixed(3)} s (its tracer ${n.tracer.toFixed(3)} s): ` +
              `${(w.seconds / n.picture).toFixed(1)}x, again ${(again.seconds / n.picture).toFixed(1)}x`;
    }
    if (!whittedOnly) line += ', ';
  }
  if (!whittedOnly) {
    const [r] = await timed('scene=cornell_box&model=radiosity&panel=0', ['wait 2'], 'wait-shots 1000000');
    figures.radiosity.push(r.seconds);
    line += `radiosity to its stopping rule ${r.seconds.toFixed(2)} s`;
    if (luz) {
      const n = nativeRadiosity();
      figures.luzRadiosity.push(n.solving);
      figures.radiosityRatio.push(r.seconds / n.solving);
      line += `, luz render ${n.solving.toFixed(2)} s solving (${n.shots} shots): ${(r.seconds / n.solving).toFixed(1)}x`;
    }
  }
  console.log(`${line}; load ${load()}`);
}
rmSync(scratch, { recursive: true, force: true });
const summary = (list, digits = 2, unit = ' s') => {
  const sorted = [...list].sort((a, b) => a - b);
  return `best ${sorted[0].toFixed(digits)}${unit}, median ${sorted[Math.floor(sorted.length / 2)].toFixed(digits)}${unit}`;
};
let text = radiosityOnly ? '' : `Whitted: ${summary(figures.whitted)} (its tracer ${summary(figures.tracer)}), again ${summary(figures.again)}`;
if (luz && !radiosityOnly) {
  text += `; luz render: ${summary(figures.luz, 3)} (its tracer ${summary(figures.luzTracer, 3)}); ` +
          `page / luz render, round by round: ${summary(figures.ratio, 1, 'x')}, again ${summary(figures.againRatio, 1, 'x')}`;
}
if (!whittedOnly) {
  text += `${radiosityOnly ? '' : '; '}radiosity: ${summary(figures.radiosity)}`;
  if (luz) {
    text += `; luz render's solving: ${summary(figures.luzRadiosity)}; page / luz render, round by round: ` +
            summary(figures.radiosityRatio, 1, 'x');
  }
}
console.log(text);
console.log(`load average ${loadBefore} before, ${load()} after; ${navigatorCores()} cores`);
function navigatorCores() { return readFileSync('/proc/cpuinfo', 'utf8').split('\n').filter((l) => l.startsWith('processor')).length; }
