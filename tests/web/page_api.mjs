// Drives the page's script entry point in Debian's chromium, headless on SwiftShader:
// opens BASE/luz.html?QUERY, waits for window.luz.ready and writes window.luz.picture() to a PNG
// (for `luz compare` against `luz render`), or, with --expect-error, checks that ready rejects and
// the page shows that error in words (not a blank canvas).
// Usage: node tests/web/page_api.mjs URL PICTURE.png [SCREENSHOT.png]
//        node tests/web/page_api.mjs --expect-error URL SCREENSHOT.png
//        (NODE_PATH=build-web/npm/node_modules)
import { writeFileSync } from 'node:fs';
import { openLuz, openPage } from './browser.mjs';

const args = process.argv.slice(2);
const expectError = args[0] === '--expect-error';
if (expectError) args.shift();
const [url, output, screenshot] = args;
if (!url || !output) {
  console.error('usage: page_api.mjs [--expect-error] URL OUTPUT.png [SCREENSHOT.png]');
  process.exit(2);
}

let failed = false;
const { browser, page } = await openPage(() => { failed = true; });
try {
  const outcome = await openLuz(page, url);
  const status = await page.$eval('#status', (s) => s.textContent);
  console.log(`ready after ${outcome.ms} ms: ${outcome.ok ? 'picture' : 'error'}; status: ${status}`);
  if (expectError) {
    // The rejection's text is what the page shows, and it is a sentence, not "Loading".
    if (outcome.ok || status !== outcome.message || status.length < 20) failed = true;
    await page.screenshot({ path: output });
  } else {
    if (!outcome.ok) failed = true;
    else {
      const dataUrl = await page.evaluate(() => window.luz.picture());
      if (!dataUrl.startsWith('data:image/png;base64,')) failed = true;
      writeFileSync(output, Buffer.from(dataUrl.split(',')[1], 'base64'));
    }
    if (screenshot) await page.screenshot({ path: screenshot });
  }
} finally {
  await browser.close();
}
console.log(failed ? 'page: FAILED' : 'page: as expected');
process.exit(failed ? 1 : 0);
