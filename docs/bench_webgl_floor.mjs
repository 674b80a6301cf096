// The floor under the page's frame: what a bare WebGL 2 page (docs/webgl_floor.html, no Luz)
// takes a frame in the same headless Chromium on SwiftShader, for each of its modes, to set beside
// docs/bench_page.mjs's figure for Luz's Phong frame. A measurement, never part of the build or
// the tests:
//
//   NODE_PATH=build-web/npm/node_modules node docs/bench_webgl_floor.mjs [ROUNDS]
//
// Each round opens the page once per mode, lets 2 s of frames pass, then counts the frames of the
// next 3 s. Prints every round, and the best and median of each mode, with the load average.
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { openPage } from '../tests/web/browser.mjs';

const modes = ['clear', 'fill', 'float-fill', 'shade', 'float-shade'];
const rounds = Number(process.argv[2] || '3');
const url = pathToFileURL(join(dirname(fileURLToPath(import.meta.url)), 'webgl_floor.html')).href;
const load = () => readFileSync('/proc/loadavg', 'utf8').split(' ')[0];
const loadBefore = load();
const figures = Object.fromEntries(modes.map((m) => [m, []]));
for (let round = 0; round < rounds; ++round) {
  const line = [];
  for (const mode of modes) {
    const { browser, page } = await openPage(() => {});
    try {
      await page.setViewport({ width: 1280, height: 720 });
      await page.goto(`${url}?mode=${mode}`);
      await new Promise((resolve) => setTimeout(resolve, 2000));
      const ms = await page.evaluate(async () => {
        const frames = window.frames, start = performance.now();
        await new Promise((resolve) => setTimeout(resolve, 3000));
        return (performance.now() - start) / (window.frames - frames);
      });
      figures[mode].push(ms);
      line.push(`${mode} ${ms.toFixed(1)}`);
    } finally {
      await browser.close();
    }
  }
  console.log(`round ${round + 1}: ${line.join(', ')} ms a frame; load ${load()}`);
}
for (const mode of modes) {
  const sorted = [...figures[mode]].sort((a, b) => a - b);
  console.log(`${mode}: best ${sorted[0].toFixed(1)} ms, median ${sorted[Math.floor(sorted.length / 2)].toFixed(1)} ms`);
}
console.log(`load average ${loadBefore} before, ${load()} after`);
