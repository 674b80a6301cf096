// Drives the page through window.luz in Debian's chromium, headless on SwiftShader: opens URL,
// waits for luz.ready, then takes the steps in order:
//   picture FILE.png        writes luz.picture() (the picture as `luz render` writes it)
//   run LINE                luz.run(LINE), which must resolve
//   reject LINE TEXT        luz.run(LINE), which must reject with an error containing TEXT
//   shot FILE.png           a screenshot of the page
//   width W                 the canvas must be W pixels wide (panel=0: the picture's width)
//   viewport WxH            the browser's window resized to W x H (then waits for the canvas)
//   fills                   the canvas takes the window's whole width and, with what the page shows
//                           under it, its height (the page ending within 20 pixels of the window's
//                           bottom), and the page does not scroll
//   picture-width W         luz.picture()'s PNG is W pixels wide
//   note-has TEXT           the viewer's status-line note (dump-state's "note") contains TEXT
//   note-lacks TEXT         ... does not contain TEXT
//   trace-state STATE       the first pane's trace (dump-state's): raster, tracing or done
//   live LINE SECONDS MS    luz.run(LINE), not waited for, and for SECONDS from just before it
//                           the browser's frames keep coming: none more than MS milliseconds
//                           after the one before (a page whose main thread works through a
//                           whole trace in one frame fails)
//   file PAGE_PATH FILE     copies a file the page wrote into its own files (a `dump-...` line's
//                           JSON, a `screenshot` verb's PNG) to FILE
// A run step that takes more than a minute fails (a page whose program ended never settles), and
// says whether the page still answers at all; the steps after it are not taken.
// Usage: node tests/web/page_script.mjs URL STEP ARGS [STEP ARGS ...]
//        (NODE_PATH=build-web/npm/node_modules)
import { writeFileSync } from 'node:fs';
import { openLuz, openPage } from './browser.mjs';

const [url, ...steps] = process.argv.slice(2);
const within = (promise, ms, what) =>
  Promise.race([promise, new Promise((resolve) => setTimeout(() => resolve(`no answer in ${ms / 1000} s (${what})`), ms))]);
// The viewer's status-line note, through dump-state into the page's files.
const note = (page) => page.evaluate(() => window.luz.run('dump-state /tmp/luz-test-state.json').then(() =>
  JSON.parse(Module.FS.readFile('/tmp/luz-test-state.json', { encoding: 'utf8' })).note));
// A PNG's width: its IHDR chunk, bytes 16-19, big-endian.
const pngWidth = (bytes) => bytes.readUInt32BE(16);

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
      const result = await within(page.evaluate((l) => window.luz.run(l).then(() => 'done', (e) => 'rejected: ' + e.message), line), 60000, line);
      if (result.startsWith('no answer')) {
        // Two different failures: a page whose main thread is stuck answers nothing, while one
        // whose line never settles (a wait never met, a program that ended) answers at once.
        // The steps after it would wait behind it (lines run in order): they are not taken.
        const alive = await within(page.evaluate(() => 'answers'), 10000, 'a plain evaluate');
        check(false, `run("${line}"): ${result}; the page ${alive === 'answers'
          ? 'still answers: the line never settled (a wait never met, or the program ended)'
          : 'answers nothing: its main thread is stuck'}`);
        break;
      }
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
    } else if (step === 'viewport') {
      const [w, h] = steps[++i].split('x').map(Number);
      await page.setViewport({ width: w, height: h });
      await page.waitForFunction((w) => document.getElementById('canvas').width === w, { timeout: 30000 }, w)
        .catch(() => {});
      await page.evaluate(() => window.luz.run('wait 2'));
    } else if (step === 'fills') {
      const room = await page.evaluate(() => {
        const c = document.getElementById('canvas'), root = document.documentElement;
        const bottoms = [...document.body.children].map((e) => e.getBoundingClientRect().bottom);
        return { w: c.width, h: c.height, innerW: innerWidth, innerH: innerHeight, bottom: Math.max(...bottoms),
                 scrollW: root.scrollWidth, scrollH: root.scrollHeight };
      });
      // The page's last line within 20 pixels of the window's bottom (its margin), never past it.
      check(room.w === room.innerW && room.bottom >= room.innerH - 20 && room.scrollW <= room.innerW &&
            room.scrollH <= room.innerH,
            `canvas ${room.w}x${room.h} fills the window ${room.innerW}x${room.innerH} (page ${room.scrollW}x${room.scrollH}, ` +
            `its last line ending at ${room.bottom})`);
    } else if (step === 'picture-width') {
      const dataUrl = await page.evaluate(() => window.luz.picture());
      const width = pngWidth(Buffer.from(dataUrl.split(',')[1], 'base64'));
      check(String(width) === steps[++i], `picture ${width} pixels wide, expected ${steps[i]}`);
    } else if (step === 'trace-state') {
      const state = await page.evaluate(() => window.luz.run('dump-state /tmp/luz-test-state.json').then(() =>
        JSON.parse(Module.FS.readFile('/tmp/luz-test-state.json', { encoding: 'utf8' })).panes[0].trace));
      check(state === steps[++i], `trace ${state}, expected ${steps[i]}`);
    } else if (step === 'live') {
      const line = steps[++i], seconds = Number(steps[++i]), limit = Number(steps[++i]);
      const frames = await page.evaluate((l, ms) => new Promise((resolve) => {
        const times = [];
        const frame = (t) => {
          times.push(t);
          if (t - times[0] < ms) requestAnimationFrame(frame);
          else resolve(times);
        };
        requestAnimationFrame((t) => {
          frame(t);
          window.luz.run(l).catch(() => {});
        });
      }), line, seconds * 1000);
      const gaps = frames.slice(1).map((t, k) => t - frames[k]);
      const longest = Math.round(Math.max(...gaps));
      check(frames.length > 2 && longest <= limit,
            `"${line}": ${frames.length} frames in ${seconds} s, the longest gap ${longest} ms (limit ${limit} ms)`);
    } else if (step === 'note-has' || step === 'note-lacks') {
      const text = await note(page), wanted = steps[++i];
      check(text.includes(wanted) === (step === 'note-has'), `note "${text}" ${step === 'note-has' ? 'has' : 'lacks'} "${wanted}"`);
    } else if (step === 'file') {
      const from = steps[++i], to = steps[++i];
      const base64 = await page.evaluate((f) => {
        let bytes;
        try { bytes = Module.FS.readFile(f); } catch (e) { return null; }
        let text = '';
        for (let at = 0; at < bytes.length; at += 0x8000) text += String.fromCharCode(...bytes.subarray(at, at + 0x8000));
        return btoa(text);
      }, from);
      check(base64 !== null, `file ${from} in the page`);
      if (base64 !== null) writeFileSync(to, Buffer.from(base64, 'base64'));
    } else {
      check(false, `unknown step "${step}"`);
      break;
    }
  }
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);
