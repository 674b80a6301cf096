// Drives the page through window.luz in Debian's chromium, headless on SwiftShader: opens URL,
// waits for luz.ready, then takes the steps in order:
//   picture FILE.png        writes luz.picture() (the picture as `luz render` writes it)
//   run LINE                luz.run(LINE), which must resolve
//   reject LINE TEXT        luz.run(LINE), which must reject with an error containing TEXT
//   shot FILE.png           a screenshot of the page
//   width W                 the canvas must be W pixels wide (panel=0: the picture's width)
// Usage: node tests/web/page_script.mjs URL STEP ARGS [STEP ARGS ...]
//        (NODE_PATH=build-web/npm/node_modules)
import { writeFileSync } from 'node:fs';
import { openLuz, openPage } from './browser.mjs';

const [url, ...steps] = process.argv.slice(2);
if (!url || steps.length === 0) {
  console.error('usage: page_script.mjs URL (picture FILE | run LINE | reject LINE TEXT | shot FILE | width W)...');
  process.exit(2);
}

let failed = false;
const check = (ok, what) => {
  console.log(`${ok ? 'ok' : 'FAILED'}: ${what}`);
  if (!ok) failed = true;
};
const { browser, page } = await openPage(() => { failed = true; });
try {
  const outcome = await openLuz(page, url);
  check(outcome.ok, `ready after ${outcome.ms} ms${outcome.ok ? '' : ': ' + outcome.message}`);
  for (let i = 0; outcome.ok && i < steps.length; ++i) {
    const step = steps[i];
    if (step === 'picture') {
      const dataUrl = await page.evaluate(() => window.luz.picture());
      check(dataUrl.startsWith('data:image/png;base64,'), `picture ${steps[i + 1]}`);
      writeFileSync(steps[++i], Buffer.from(dataUrl.split(',')[1], 'base64'));
    } else if (step === 'run') {
      const line = steps[++i];
      const result = await page.evaluate((l) => window.luz.run(l).then(() => 'done', (e) => 'rejected: ' + e.message), line);
      check(result === 'done', `run("${line}"): ${result}`);
    } else if (step === 'reject') {
      const line = steps[++i], text = steps[++i];
      const result = await page.evaluate((l) => window.luz.run(l).then(() => 'done', (e) => 'rejected: ' + e.message), line);
      check(result.startsWith('rejected: ') && result.includes(text), `run("${line}") rejects with "${text}": ${result}`);
    } else if (step === 'shot') {
      await page.screenshot({ path: steps[++i] });
    } else if (step === 'width') {
      const width = await page.$eval('#canvas', (c) => String(c.width));
      check(width === steps[++i], `canvas ${width} pixels wide, expected ${steps[i]}`);
    } else {
      check(false, `unknown step "${step}"`);
      break;
    }
  }
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
