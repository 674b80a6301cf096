// The page's frame time in headless Chromium on SwiftShader, to set beside the window's
// (docs/bench_viewer.py) on the same machine in the same minutes. A measurement, never part of
// the build or the tests:
//
//   python3 src/app/web/serve.py build-web 8000 &
//   NODE_PATH=build-web/npm/node_modules node docs/bench_page.mjs \
//       'http://127.0.0.1:8000/luz.html?scene=cornell_box&model=phong&size=1280x720' [ROUNDS]
//
// Each round opens the page, waits for luz.ready and 60 frames, then times `wait 120` (the script
// language's wait, which draws a frame each time) through luz.run: its wall time over 120 is the
// round's milliseconds a frame, as the page's user sees them. Prints every round, the best and
// the median, with the load average before and after.
import { readFileSync } from 'node:fs';
import { openPage } from '../tests/web/browser.mjs';

const [url, roundsText = '5'] = process.argv.slice(2);
if (!url) {
  console.error('usage: bench_page.mjs URL [ROUNDS]');
  process.exit(2);
}
const FRAMES = 120;
const load = () => readFileSync('/proc/loadavg', 'utf8').split(' ')[0];
const loadBefore = load();
const figures = [];
for (let round = 0; round < Number(roundsText); ++round) {
  const { browser, page } = await openPage(() => {});
  try {
    await page.goto(url);
    await page.evaluate(() => window.luz.ready);
    await page.evaluate(() => window.luz.run('wait 60'));
    const ms = await page.evaluate(async (frames) => {
      const start = performance.now();
      await window.luz.run(`wait ${frames}`);
      return (performance.now() - start) / frames;
    }, FRAMES);
    figures.push(ms);
    console.log(`round ${round + 1}: ${ms.toFixed(1)} ms a frame`);
  } finally {
    await browser.close();
  }
}
figures.sort((a, b) => a - b);
const median = figures[Math.floor(figures.length / 2)];
console.log(`best ${figures[0].toFixed(1)} ms, median ${median.toFixed(1)} ms over ${figures.length} rounds;` +
            ` load average ${loadBefore} before, ${load()} after`);
