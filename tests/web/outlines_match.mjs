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
import { readFileSync } from 'node:fs';
import { inflateSync } from 'node:zlib';

// An 8-bit RGB or RGBA, non-interlaced PNG (what Luz writes): { width, height, rgb(x, y) }.
function readPng(file) {
  const bytes = readFileSync(file);
  let at = 8, width = 0, height = 0, channels = 0;
  const data = [];
  while (at < bytes.length) {
    const length = bytes.readUInt32BE(at), type = bytes.toString('latin1', at + 4, at + 8);
    const chunk = bytes.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = chunk.readUInt32BE(0);
      height = chunk.readUInt32BE(4);
      if (chunk[8] !== 8 || chunk[12] !== 0 || (chunk[9] !== 2 && chunk[9] !== 6))
        throw new Error(`${file}: not an 8-bit RGB(A) non-interlaced PNG`);
      channels = chunk[9] === 6 ? 4 : 3;
    } else if (type === 'IDAT') data.push(chunk);
    at += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(data)), stride = width * channels;
  const pixels = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {  // undo the rows' filters (PNG specification, section 9)
    const filter = raw[y * (stride + 1)], row = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? pixels[y * stride + i - channels] : 0;
      const b = y > 0 ? pixels[(y - 1) * stride + i] : 0;
      const c = i >= channels && y > 0 ? pixels[(y - 1) * stride + i - channels] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const predicted = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
      pixels[y * stride + i] = (row[i] + predicted) & 255;
    }
  }
  return { width, height, rgb: (x, y) => [0, 1, 2].map((k) => pixels[(y * width + x) * channels + k]) };
}

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
