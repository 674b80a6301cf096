// Opens the page in Debian's chromium, headless on SwiftShader, and checks that it draws:
// luz.ready resolves (no error in words) and the canvas, as the page shows it, has more than a
// few colours (the viewer's panel, picture and status line).
// Usage: node tests/web/page_smoke.mjs URL SCREENSHOT.png [CANVAS.png]
//        (NODE_PATH=build-web/npm/node_modules): the page's screenshot, and the canvas's.
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
  const outcome = await page.evaluate(() =>
    window.luz.ready.then(() => 'ready', (error) => 'error: ' + error.message));
  const status = await page.$eval('#status', (s) => s.textContent);
  console.log(`${outcome} after ${Date.now() - started} ms; status: "${status}"`);
  if (outcome !== 'ready') failed = true;
  // The canvas as shown (WebGL's drawing buffer is not kept after it is shown: a screenshot).
  const canvas = await page.$('#canvas');
  const shown = await canvas.screenshot({ encoding: 'base64' });
  const colours = await page.evaluate(async (png) => {
    const image = new Image();
    image.src = 'data:image/png;base64,' + png;
    await image.decode();
    const copy = document.createElement('canvas');
    copy.width = image.width;
    copy.height = image.height;
    const context = copy.getContext('2d');
    context.drawImage(image, 0, 0);
    const data = context.getImageData(0, 0, copy.width, copy.height).data;
    const seen = new Set();
    for (let i = 0; i < data.length; i += 4 * 97) seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    return seen.size;
  }, shown);
  console.log(`distinct colours sampled: ${colours}`);
  if (colours < 10) failed = true;
  await page.screenshot({ path: screenshot });
  if (canvasFile) writeFileSync(canvasFile, Buffer.from(shown, 'base64'));
} finally {
  await browser.close();
}
console.log(failed ? 'page: FAILED' : 'page: drawn');
process.exit(failed ? 1 : 0);
