// The browser every web test drives: Debian's chromium, headless, drawing WebGL 2 through
// SwiftShader (the software path many students' machines and CI have), the page's console and
// errors echoed. `onError` is called for an uncaught error in the page, and for Emscripten's
// warning that the browser's main thread joined a thread or waited on a condition variable: the
// page's main thread never waits for another thread (docs/web.md, "Threads"). With
// LUZ_PAGE_NO_SERVICE_WORKERS=1 in the environment the browser has no service workers (as some
// private windows): a page served without the isolation headers then runs the one-thread Luz.
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const puppeteer = require('puppeteer-core');

export async function openPage(onError) {
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    // /dev/shm is small in containers (CI): Chromium keeps its shared memory in /tmp instead.
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', ...(process.env.EXTRA_ARGS ? process.env.EXTRA_ARGS.split(' ') : [])],
  });
  const page = await browser.newPage();
  if (process.env.LUZ_PAGE_NO_SERVICE_WORKERS === '1')
    await page.evaluateOnNewDocument(() => Object.defineProperty(navigator, 'serviceWorker', { value: undefined }));
  page.on('console', (message) => {
    console.log(`page: ${message.text()}`);
    if (message.text().startsWith('Blocking on the main thread')) {
      console.log('page error: its main thread waited for another thread');
      onError();
    }
  });
  page.on('pageerror', (error) => { console.log(`page error: ${error.message}`); onError(); });
  return { browser, page };
}

// Opens url and waits for luz.ready: { ok, message, ms } (message when it rejected, ms since
// the page was asked for).
export async function openLuz(page, url) {
  const opened = Date.now();
  await page.goto(url);
  const outcome = await page.evaluate(() =>
    window.luz.ready.then(() => ({ ok: true }), (error) => ({ ok: false, message: error.message })));
  return { ...outcome, ms: Date.now() - opened };
}
