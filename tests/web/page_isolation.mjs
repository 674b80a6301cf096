// The page with and without cross-origin isolation (docs/web.md, "Threads"). Usage:
//   node tests/web/page_isolation.mjs headers URL SHOT.png         served with the headers: the
//        page is isolated at once and draws
//   node tests/web/page_isolation.mjs service-worker URL SHOT.png  served without them: the
//        service worker reloads the page isolated, and it draws
//   node tests/web/page_isolation.mjs one-thread URL SHOT.png      without them, in a browser
//        with no service workers: the one-thread Luz starts (luz-1thread.wasm, reading luz.data)
//        and draws, and the page says, in the URL's language (lang=es or English), that it
//        runs on one thread and which headers give it every core
// The threaded page shows no such note. (NODE_PATH=build-web/npm/node_modules.)
import { openPage } from './browser.mjs';

const [how, url, screenshot] = process.argv.slice(2);
if (!['headers', 'service-worker', 'one-thread'].includes(how) || !url || !screenshot) {
  console.error('usage: page_isolation.mjs headers|service-worker|one-thread URL SHOT.png');
  process.exit(2);
}

// What the page settles to: its ready promise's outcome, whether it is isolated and whether a
// service worker serves it, asked again across the service worker's reload.
async function settled(page) {
  const deadline = Date.now() + 90000;
  for (;;) {
    try {
      return await page.evaluate(async () => {
        const outcome = await Promise.race([
          window.luz.ready.then(() => 'ready', (error) => `rejected: ${error.message}`),
          new Promise((resolve) => setTimeout(() => resolve('neither ready nor rejected in 60 s'), 60000))]);
        return { outcome, isolated: window.crossOriginIsolated,
                 controlled: Boolean(navigator.serviceWorker && navigator.serviceWorker.controller),
                 status: document.getElementById('status').textContent,
                 note: document.getElementById('note').classList.contains('shown') ?
                   document.getElementById('note').textContent : '',
                 loaded: performance.getEntriesByType('resource').map((r) => r.name.slice(r.name.lastIndexOf('/') + 1))
                   .filter((name) => /^luz/.test(name)) };
      });
    } catch (error) {  // the page reloaded while it was asked
      if (Date.now() > deadline) throw error;
      await new Promise((resolve) => setTimeout(resolve, 250));
    }
  }
}

let failed = false;
const { browser, page } = await openPage(() => { failed = true; });
try {
  if (how === 'one-thread')
    await page.evaluateOnNewDocument(() => Object.defineProperty(navigator, 'serviceWorker', { value: undefined }));
  const started = Date.now();
  await page.goto(url);
  const state = await settled(page);
  console.log(`${how}: after ${Date.now() - started} ms ${JSON.stringify(state)}`);
  const threads = await page.evaluate(() => typeof SharedArrayBuffer === 'function');
  if (how === 'one-thread') {
    const spanish = new URL(url).searchParams.get('lang') === 'es';
    const says = spanish ? /un solo hilo/ : /one thread/;
    failed ||= state.outcome !== 'ready' || state.isolated || threads || !says.test(state.note) ||
               !/Cross-Origin-Opener-Policy: same-origin/.test(state.note) ||
               !/Cross-Origin-Embedder-Policy: require-corp/.test(state.note) || !/https:\/\//.test(state.note) ||
               !state.loaded.includes('luz-1thread.wasm') || !state.loaded.includes('luz.data') ||
               state.loaded.includes('luz-1thread.data') || state.loaded.includes('luz.wasm');
  } else {
    failed ||= state.outcome !== 'ready' || !state.isolated || state.controlled !== (how === 'service-worker') ||
               state.note !== '' || !state.loaded.includes('luz.wasm');
    failed ||= !threads;
  }
  await page.screenshot({ path: screenshot });
} finally {
  await browser.close();
}
console.log(failed ? `page ${how}: FAILED` : `page ${how}: as expected`);
process.exit(failed ? 1 : 0);
