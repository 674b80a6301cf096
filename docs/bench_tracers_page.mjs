// The page's Whitted trace and radiosity solve in headless Chromium, to set beside `luz render`
// on the same machine in the same minutes. A measurement, never part of the build or the tests:
//
//   python3 src/app/web/serve.py build-web 8000 &
//   NODE_PATH=build-web/npm/node_modules node docs/bench_tracers_page.mjs http://127.0.0.1:8000/luz.html [ROUNDS] [whitted]
//
// `whitted` times Whitted's trace alone. The one-thread page: serve build-web/ without the
// isolation headers (serve.py --no-isolation) and run the script with
// LUZ_PAGE_NO_SERVICE_WORKERS=1 (tests/web/browser.mjs), a browser without service workers.
//
// Each round opens the page twice: Whitted's scene in Whitted's model at 1024x1024 (depth 5, the
// default), timing `trace` through luz.run from the request to its last tile drawn (the tracer's
// own seconds are in the status line: what the page's user waits for is the figure here); and
// the Cornell box in radiosity at the viewer's defaults, timing `wait-shots 1000000` (the solver
// run to its stopping rule, 0.5% unshot). Prints every round, the best and the median, with the
// load average before and after.
import { readFileSync } from 'node:fs';
import { openLuz, openPage } from '../tests/web/browser.mjs';

const [base, roundsText = '3', only] = process.argv.slice(2);
if (!base) {
  console.error('usage: bench_tracers_page.mjs BASE_URL [ROUNDS]');
  process.exit(2);
}
const load = () => readFileSync('/proc/loadavg', 'utf8').split(' ')[0];
const loadBefore = load();

async function timed(query, lines, timed_line) {
  const { browser, page } = await openPage(() => {});
  try {
    const outcome = await openLuz(page, `${base}?${query}`);
    if (!outcome.ok) throw new Error(outcome.message);
    for (const line of lines) await page.evaluate((l) => window.luz.run(l), line);
    // Started in the page and polled: a solve may outlast one call's protocol timeout.
    await page.evaluate((l) => {
      const start = performance.now();
      window.benchSeconds = null;
      window.luz.run(l).then(() => { window.benchSeconds = (performance.now() - start) / 1000; },
                             (error) => { window.benchSeconds = 'failed: ' + error.message; });
    }, timed_line);
    for (;;) {
      const seconds = await page.evaluate(() => window.benchSeconds);
      if (typeof seconds === 'number') return seconds;
      if (seconds !== null) throw new Error(seconds);
      await new Promise((resolve) => setTimeout(resolve, 500));
    }
  } finally {
    await browser.close();
  }
}

const figures = { whitted: [], radiosity: [] };
for (let round = 0; round < Number(roundsText); ++round) {
  const w = await timed('scene=whitted&model=whitted&size=1024x1024&panel=0', ['wait 2'], 'trace');
  figures.whitted.push(w);
  if (only === 'whitted') {
    console.log(`round ${round + 1}: Whitted 1024x1024 ${w.toFixed(2)} s`);
    continue;
  }
  const r = await timed('scene=cornell_box&model=radiosity&panel=0', ['wait 2'], 'wait-shots 1000000');
  figures.radiosity.push(r);
  console.log(`round ${round + 1}: Whitted 1024x1024 ${w.toFixed(2)} s, radiosity to its stopping rule ${r.toFixed(2)} s`);
}
const summary = (list) => {
  const sorted = [...list].sort((a, b) => a - b);
  return `best ${sorted[0].toFixed(2)} s, median ${sorted[Math.floor(sorted.length / 2)].toFixed(2)} s`;
};
console.log(`Whitted: ${summary(figures.whitted)}` + (only === 'whitted' ? '' : `; radiosity: ${summary(figures.radiosity)}`));
console.log(`load average ${loadBefore} before, ${load()} after; ${navigatorCores()} cores`);
function navigatorCores() { return readFileSync('/proc/cpuinfo', 'utf8').split('\n').filter((l) => l.startsWith('processor')).length; }
