// Rewrites a PNG as one of at most 256 colours (an indexed PNG), in place: the README's pictures
// of the page are mostly the panel's few flat colours, and a palette makes them a fraction of
// their size. The palette is Heckbert's median cut ("Color image quantization for frame buffer
// display", SIGGRAPH 1982) over the colours at 5 bits a channel; each pixel takes its nearest
// entry, and what it misses is spread to its neighbours (Floyd and Steinberg's error diffusion),
// so that the pictures' gradients show no bands. The panel's flat colours are palette entries
// themselves: they miss nothing, and its text stays crisp.
//   node docs/png_palette.mjs PICTURE.png
import { writeFileSync } from 'node:fs';
import { encodePng, readPng } from '../tests/web/png.mjs';

const file = process.argv[2];
if (!file) {
  console.error('usage: png_palette.mjs PICTURE.png');
  process.exit(2);
}
const picture = readPng(file);
const { width, height } = picture;
const key = ([r, g, b]) => ((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3);

// The colours at 5 bits a channel: how many pixels each, and their sums for the boxes' means.
const count = new Float64Array(32768), sums = new Float64Array(3 * 32768);
for (let y = 0; y < height; ++y)
  for (let x = 0; x < width; ++x) {
    const c = picture.rgb(x, y), k = key(c);
    ++count[k];
    for (let i = 0; i < 3; ++i) sums[3 * k + i] += c[i];
  }
const channel = (k, i) => (k >> (10 - 5 * i)) & 31;

// Median cut: the box with the most pixels times its longest side is cut at its median there.
let boxes = [[...count.keys()].filter((k) => count[k] > 0)];
const weight = (box) => box.reduce((n, k) => n + count[k], 0);
const longest = (box) => {
  let best = { axis: 0, range: -1 };
  for (let i = 0; i < 3; ++i) {
    let lo = 31, hi = 0;
    for (const k of box) { lo = Math.min(lo, channel(k, i)); hi = Math.max(hi, channel(k, i)); }
    if (hi - lo > best.range) best = { axis: i, range: hi - lo };
  }
  return best;
};
while (boxes.length < 256) {
  let pick = -1, score = 0;
  boxes.forEach((box, i) => {
    const s = box.length > 1 ? weight(box) * (longest(box).range + 1) : 0;
    if (s > score) { score = s; pick = i; }
  });
  if (pick < 0) break;  // every box one colour
  const box = boxes[pick], { axis } = longest(box);
  box.sort((a, b) => channel(a, axis) - channel(b, axis));
  const half = weight(box) / 2;
  let at = 0, seen = 0;
  while (at < box.length - 1 && seen + count[box[at]] <= half) seen += count[box[at++]];
  at = Math.max(1, at);
  boxes.splice(pick, 1, box.slice(0, at), box.slice(at));
}
const palette = boxes.map((box) => {
  const n = weight(box);
  return [0, 1, 2].map((i) => Math.round(box.reduce((s, k) => s + sums[3 * k + i], 0) / n));
});

// Each pixel's nearest entry (by its exact colour, remembered).
const nearest = new Map();
const indexOf = (c) => {
  const exact = (c[0] << 16) | (c[1] << 8) | c[2];
  let found = nearest.get(exact);
  if (found === undefined) {
    let best = Infinity;
    palette.forEach((p, i) => {
      const d = (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 + (p[2] - c[2]) ** 2;
      if (d < best) { best = d; found = i; }
    });
    nearest.set(exact, found);
  }
  return found;
};
const rows = Buffer.alloc((width + 1) * height);  // filter 0 (none) before each row
let error = new Float32Array(3 * (width + 2)), below = new Float32Array(3 * (width + 2));
for (let y = 0; y < height; ++y) {
  for (let x = 0; x < width; ++x) {
    const c = picture.rgb(x, y).map((v, i) => Math.min(255, Math.max(0, Math.round(v + error[3 * (x + 1) + i]))));
    const index = indexOf(c), p = palette[index];
    rows[y * (width + 1) + 1 + x] = index;
    for (let i = 0; i < 3; ++i) {
      const e = c[i] - p[i];
      error[3 * (x + 2) + i] += (e * 7) / 16;
      below[3 * x + i] += (e * 3) / 16;
      below[3 * (x + 1) + i] += (e * 5) / 16;
      below[3 * (x + 2) + i] += e / 16;
    }
  }
  [error, below] = [below, error];
  below.fill(0);
}

writeFileSync(file, encodePng(width, height, 3, rows, [['PLTE', Buffer.from(palette.flat())]]));
