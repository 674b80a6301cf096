// Where the page's frame time goes, by taking GL calls away: a measurement, never part of the
// build or the tests. Each variant opens the page, runs its `run:LINE` script lines, and from then
// on drops the WebGL calls it names (NAME, NAME@fbo or NAME@canvas for the bound framebuffer,
// NAME@fbo#6 or #!6 for a draw's index count; `one-output` keeps only the first of two draw
// buffers), then times `wait 30` as docs/bench_page.mjs does. The pictures are wrong; the times say
// what the dropped work cost.
//
//   python3 src/app/web/serve.py build-web 8000 &
//   NODE_PATH=build-web/npm/node_modules node docs/ablate_page.mjs \
//       'http://127.0.0.1:8000/luz.html?scene=cornell_box&model=phong&size=1280x720' \
//       '[[], ["blitFramebuffer"], ["drawElements@fbo"], ["one-output"], ["run:display-copy off"]]'
import { openPage } from '../tests/web/browser.mjs';
const url = process.argv[2];
for (const skip of JSON.parse(process.argv[3])) {
const { browser, page } = await openPage(() => {});
await page.evaluateOnNewDocument((skip) => {
  window.__on = false; let fbCanvas = true;
  const P = WebGL2RenderingContext.prototype;
  for (const name of Object.getOwnPropertyNames(P)) {
    const d = Object.getOwnPropertyDescriptor(P, name);
    if (typeof d.value !== 'function') continue;
    const f = d.value;
    P[name] = function (...a) {
      if (name === 'bindFramebuffer' && (a[0] === 0x8D40 || a[0] === 0x8CA9)) fbCanvas = !a[1];
      if (window.__on && name === 'drawBuffers' && skip.includes('one-output') && a[0].length === 2) return f.call(this, [a[0][0]]);
      if (window.__on) for (const s of skip) { const [n, rest] = s.split('@'); const [where, cnt] = (rest||'').split('#'); if (n === name && (!where || (where === 'canvas') === fbCanvas) && (!cnt || (cnt[0]==='!' ? a[1] != +cnt.slice(1) : a[1] == +cnt))) return; }
      return f.apply(this, a);
    };
  }
}, skip);
try {
  await page.goto(url);
  await page.evaluate(() => window.luz.ready);
  for (const l of skip.filter(x => x.startsWith('run:'))) await page.evaluate((l) => window.luz.run(l), l.slice(4)); await page.evaluate(() => window.luz.run('wait 20'));
  const ms = await page.evaluate(async () => {
    window.__on = true; await window.luz.run('wait 5');
    const t = performance.now(); await window.luz.run('wait 30'); return (performance.now() - t) / 30;
  });
  console.log(JSON.stringify(skip).padEnd(60), ms.toFixed(1), 'ms a frame');
} finally { await browser.close(); }
}
