// The student's own files in the page, in Debian's chromium, headless on SwiftShader: opens URL,
// waits for luz.ready, then takes the steps in order:
//   open FILE[,FILE...] PICTURE.png   the files given through the page's file input load (luz.opening
//                                     resolves, the page says "loaded"); writes luz.picture()
//   refuse FILE[,FILE...] TEXT[,TEXT...]
//                                     they do not load: luz.opening rejects with the page's error,
//                                     which holds each TEXT (the file named), and the picture is
//                                     the one before (the scene shown stays)
//   drop FILE[,FILE...] TEXT          the files dropped on the canvas load, the page's words holding
//                                     TEXT (the file's name)
//   download BUTTON W H               a click on the page's button #BUTTON downloads one PNG of
//                                     W x H pixels (`canvas canvas`: the canvas's size); with W H
//                                     `picture picture`, the same bytes as luz.picture()
// Usage: node tests/web/page_files.mjs URL DOWNLOAD_DIR STEP ARGS [STEP ARGS ...]
//        (NODE_PATH=build-web/npm/node_modules)
import { mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { openLuz, openPage } from './browser.mjs';

const [url, downloads, ...steps] = process.argv.slice(2);
if (!url || !downloads || steps.length === 0) {
  console.error('usage: page_files.mjs URL DOWNLOAD_DIR (open FILES PICTURE | refuse FILES TEXTS | download BUTTON W H)...');
  process.exit(2);
}

let failed = false;
const check = (ok, what) => {
  console.log(`${ok ? 'ok' : 'FAILED'}: ${what}`);
  if (!ok) failed = true;
};

// The files through the input, as a student's choice: the page's answer and what it shows.
async function give(page, files) {
  await page.evaluate(() => { window.luz.opening = null; });
  const input = await page.$('#files');
  await input.uploadFile(...files.split(','));
  await page.waitForFunction(() => window.luz.opening !== null, { timeout: 10000 });
  const outcome = await page.evaluate(() =>
    window.luz.opening.then((text) => ({ ok: true, text }), (error) => ({ ok: false, text: error.message })));
  const shown = await page.$eval('#messages', (m) => ({ text: m.textContent, error: m.className === 'error' }));
  return { ...outcome, shown };
}

const picture = (page) => page.evaluate(() => window.luz.picture());

// The one file the browser has finished downloading into `folder` (Chromium writes NAME.crdownload
// until it is done), waited for up to 15 s.
async function downloaded(folder) {
  for (let tries = 0; tries < 150; ++tries) {
    const names = readdirSync(folder);
    if (names.length === 1 && !names[0].endsWith('.crdownload')) return names[0];
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
  return null;
}

// A PNG's width and height from its IHDR chunk, or null when the bytes are not a PNG.
function pngSize(bytes) {
  const signature = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  if (bytes.length < 24 || !bytes.subarray(0, 8).equals(signature) || bytes.toString('latin1', 12, 16) !== 'IHDR') return null;
  return { width: bytes.readUInt32BE(16), height: bytes.readUInt32BE(20) };
}

const { browser, page } = await openPage(() => { failed = true; });
try {
  const outcome = await openLuz(page, url);
  check(outcome.ok, `ready after ${outcome.ms} ms${outcome.ok ? '' : ': ' + outcome.message}`);
  const session = await page.target().createCDPSession();
  for (let i = 0; outcome.ok && i < steps.length; ++i) {
    const step = steps[i];
    if (step === 'open') {
      const files = steps[++i], output = steps[++i];
      const result = await give(page, files);
      check(result.ok && !result.shown.error && result.shown.text === result.text,
            `open ${files}: ${result.ok ? 'loaded' : 'refused'}; the page says: ${result.shown.text}`);
      const dataUrl = await picture(page);
      writeFileSync(output, Buffer.from(dataUrl.split(',')[1], 'base64'));
    } else if (step === 'refuse') {
      const files = steps[++i], texts = steps[++i].split(',');
      const before = await picture(page);
      const result = await give(page, files);
      check(!result.ok && result.shown.error && result.shown.text === result.text,
            `refuse ${files}: ${result.ok ? 'loaded' : 'refused'}; the page says, as an error: ${result.shown.text}`);
      for (const text of texts) check(result.text.includes(text), `the message names "${text}"`);
      check((await picture(page)) === before, 'the scene shown stays (the same picture as before)');
    } else if (step === 'drop') {
      const files = steps[++i].split(','), text = steps[++i];
      const given = files.map((file) => ({ name: file.slice(file.lastIndexOf('/') + 1), bytes: readFileSync(file).toString('base64') }));
      await page.evaluate((list) => {
        window.luz.opening = null;
        const transfer = new DataTransfer();
        for (const file of list)
          transfer.items.add(new File([Uint8Array.from(atob(file.bytes), (c) => c.charCodeAt(0))], file.name));
        document.getElementById('canvas').dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }, given);
      await page.waitForFunction(() => window.luz.opening !== null, { timeout: 10000 });
      const result = await page.evaluate(() =>
        window.luz.opening.then((t) => ({ ok: true, text: t }), (error) => ({ ok: false, text: error.message })));
      check(result.ok && result.text.includes(text), `drop ${files}: ${result.ok ? 'loaded' : 'refused'}: ${result.text}`);
    } else if (step === 'download') {
      const button = steps[++i], w = steps[++i], h = steps[++i];
      const folder = join(downloads, `${button}-${i}`);
      rmSync(folder, { recursive: true, force: true });
      mkdirSync(folder, { recursive: true });
      await session.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: folder });
      await page.click(`#${button}`);
      const name = await downloaded(folder);
      const bytes = name ? readFileSync(join(folder, name)) : Buffer.alloc(0);
      const size = pngSize(bytes);
      let expected;
      if (w === 'canvas') expected = await page.$eval('#canvas', (c) => ({ width: c.width, height: c.height }));
      else if (w === 'picture') {
        const dataUrl = await picture(page);
        const shot = Buffer.from(dataUrl.split(',')[1], 'base64');
        expected = pngSize(shot);
        check(bytes.equals(shot), `#${button}'s download holds the same bytes as luz.picture()`);
      } else expected = { width: Number(w), height: Number(h) };
      check(name !== null && name.startsWith('luz-') && name.endsWith('.png'), `#${button}'s download is named ${name}`);
      check(size !== null && size.width === expected.width && size.height === expected.height,
            `#${button} downloaded ${name}: ${size ? `a ${size.width}x${size.height} PNG` : 'no PNG'}, ` +
            `expected ${expected.width}x${expected.height}`);
    } else {
      check(false, `unknown step "${step}"`);
      break;
    }
  }
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
