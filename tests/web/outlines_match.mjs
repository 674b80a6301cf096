// The page's radiosity patch outlines against the window's: each pair of pictures is the same
// flat-patch picture without and with outlines, so the pixels that differ are the outlines.
// The page's (SwiftShader) must be where the window's (llvmpipe, `luz render --outlines`) are:
// the two rasterise the same edges of the same patch mesh, a line's pixels falling on either side
// of it, so each outline pixel must lie within one pixel of the other picture's outlines (both
// ways, all but 2% of them), the outlines must be dark (the outline colour, 0.02), and there must
// be outlines at all (at least 1% of the picture). Measured on the Cornell box at 640x480 with
// uniform 0.6 m patches (tests/web/run_page_tests.sh): 99.8% and 100%; outlines two or three
// pixels off (the window's shifted) give 42-64%.
//   node tests/web/outlines_match.mjs PAGE_PLAIN.png PAGE_OUTLINED.png LUZ_PLAIN.png LUZ_OUTLINED.png
import { readPng } from './png.mjs';

// The pixels where two pictures differ, as a set of y * width + x, and whether each is dark.
function outlines(plainFile, outlinedFile) {
  const plain = readPng(plainFile), outlined = readPng(outlinedFile);
  if (plain.width !== outlined.width || plain.height !== outlined.height) throw new Error('sizes differ');
  const set = new Set();
  let dark = 0;
  for (let y = 0; y < plain.height; ++y)
    for (let x = 0; x < plain.width; ++x) {
      const p = plain.rgb(x, y), o = outlined.rgb(x, y);
      if (p.some((v, k) => v !== o[k])) {
        set.add(y * plain.width + x);
        if (Math.max(...o) <= 60) ++dark;  // 0.02 in sRGB is 39 of 255
      }
    }
  return { set, dark, width: plain.width, height: plain.height };
}

// The share of a's pixels with one of b's within `reach` pixels (0: the same pixel), and the same
// with b shifted by (dx, dy).
function near(a, b, reach = 1, dx0 = 0, dy0 = 0) {
  let found = 0;
  for (const i of a.set) {
    const x = i % a.width, y = Math.floor(i / a.width);
    let hit = false;
    for (let dy = -reach; dy <= reach && !hit; ++dy)
      for (let dx = -reach; dx <= reach && !hit; ++dx) hit = b.set.has((y + dy + dy0) * a.width + x + dx + dx0);
    if (hit) ++found;
  }
  return a.set.size ? found / a.set.size : 0;
}

const [pagePlain, pageOutlined, luzPlain, luzOutlined] = process.argv.slice(2);
const page = outlines(pagePlain, pageOutlined), luz = outlines(luzPlain, luzOutlined);
const share = page.set.size / (page.width * page.height);
const checks = [
  [share >= 0.01, `the page's outlines cover ${(100 * share).toFixed(1)}% of the picture (at least 1%)`],
  [page.dark >= 0.98 * page.set.size, `${page.dark} of the page's ${page.set.size} outline pixels are dark`],
  [near(page, luz) >= 0.98, `${(100 * near(page, luz)).toFixed(1)}% of the page's outline pixels lie on the window's`],
  [near(luz, page) >= 0.98, `${(100 * near(luz, page)).toFixed(1)}% of the window's outline pixels lie on the page's`],
];
let failed = false;
for (const [ok, what] of checks) {
  console.log(`${ok ? 'ok' : 'FAILED'}: ${what}`);
  if (!ok) failed = true;
}
process.exit(failed ? 1 : 0);
