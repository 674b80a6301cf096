// Cuts one pane out of a side-by-side picture (the page's luz.picture(), `luz render --model
// A,B,...`'s grid: the headless grid's layout in both), below its label, into a PNG of its own,
// for `luz compare` to hold one model's pane to another picture.
//   node tests/web/cut_pane.mjs PANES.json MODEL PICTURE.png OUT.png
// PANES.json is the page's `dump-panes`: each pane's place in the picture ("screenshot": x, y,
// width, height) and its label's box within it ("screenshot_label").
import { readFileSync } from 'node:fs';
import { readPng, writePng } from './png.mjs';

const [panesFile, model, pictureFile, outFile] = process.argv.slice(2);
if (!outFile) {
  console.error('usage: cut_pane.mjs PANES.json MODEL PICTURE.png OUT.png');
  process.exit(2);
}
const pane = JSON.parse(readFileSync(panesFile, 'utf8')).panes.find((p) => p.model === model);
if (!pane) {
  console.error(`${panesFile}: no pane shows ${model}`);
  process.exit(1);
}
const [x0, y0, width, height] = pane.screenshot;
const top = pane.screenshot_label[1] + pane.screenshot_label[3];  // the rows under the label
const picture = readPng(pictureFile);
if (x0 + width > picture.width || y0 + height > picture.height) {
  console.error(`${pictureFile}: ${picture.width}x${picture.height}, smaller than ${model}'s pane at ${pane.screenshot}`);
  process.exit(1);
}
const rows = height - top;
const rgb = Buffer.alloc(width * rows * 3);
for (let y = 0; y < rows; ++y)
  for (let x = 0; x < width; ++x) rgb.set(picture.rgb(x0 + x, y0 + top + y), (y * width + x) * 3);
writePng(outFile, width, rows, rgb);
