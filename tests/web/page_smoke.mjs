// Opens the page in Debian's chromium, headless on SwiftShader, and checks that it draws:
// the status line reports a frame time (not an error) and the canvas shows more than one colour.
// Usage: node tests/web/page_smoke.mjs URL SCREENSHOT.png [CANVAS.png]
//        (NODE_PATH=build-web/npm/node_modules): the page's screenshot, and the canvas's pixels.
import { writeFileSync } from 'node:fs';
import { openPage } from './browser.mjs';

const [url, screenshot, canvasFile] = process.argv.slice(2);
if (!url || !screenshot) {
  console.error('usage: page_smoke.mjs URL SCREENSHOT.png');
  process.exit(2);
}

let failed = false;
const { browser, page } = await openPage(() => { failed = true; });
try {
  await page.goto(url);
  const started = Date.now();
  await page.waitForFunction(
    () => / ms$/.test(document.getElementById('status').textContent) ||
          !/Loading/.test(document.getElementById('status').textContent),
    { timeout: 60000 });
  const status = await page.$eval('#status', (s) => s.textContent);
  console.log(`status after ${Date.now() - started} ms: ${status}`);
  if (!/ ms$/.test(status)) failed = true;
  const colours = await page.evaluate(() => {
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    const data = context.getImageData(0, 0, copy.width, copy.height).data;
    const seen = new Set();
    for (let i = 0; i < data.length; i += 4 * 97) seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    return seen.size;
  });
  console.log(`distinct colours sampled: ${colours}`);
  if (colours < 10) failed = true;
  await page.screenshot({ path: screenshot });
  if (canvasFile) {
    const dataUrl = await page.$eval('#canvas', (canvas) => canvas.toDataURL('image/png'));
    writeFileSync(canvasFile, Buffer.from(dataUrl.split(',')[1], 'base64'));
  }
} finally {
  await browser.close();
}
console.log(failed ? 'page: FAILED' : 'page: drawn');
process.exit(failed ? 1 : 0);
