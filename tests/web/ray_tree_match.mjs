// The ray tree of a clicked pixel in the page against `luz render --ray-tree` of the same scene,
// camera, size and pixel, and the tree as the page draws it over the picture.
//
// - The JSON (dump-ray-tree in the page, --ray-tree's file): the same pixel and size, the same
//   rays in the same order (kind, depth, parent, the mesh and material hit), and every number
//   within LIMIT relative (of the vector's largest component, or of 1 for a number below 1):
//   the page's Embree is built for SSE2 and the desktop's for the machine's widest ISA, so a hit
//   may differ in its last bits; LIMIT 0 asks for the same JSON, number for number.
// - The drawing, when the pictures are given (two pictures of the page, the tree shown and cleared with X; the camera the
//   scene's first): as tests/test_viewer_whitted.cpp checks the window's, at least 90% of the
//   points sampled along the secondary rays (projected with the scene camera, 4 pixels inside
//   the picture) change by more than 24 codes within one pixel, and no pixel farther than 6
//   pixels from every ray changes by more than 1 code.
//   node tests/web/ray_tree_match.mjs PAGE.json LUZ.json LIMIT [SCENE.gltf WITH_TREE.png WITHOUT.png]
import { readFileSync } from 'node:fs';
import { readPng } from './png.mjs';

const [pageFile, luzFile, limitText, sceneFile, withFile, withoutFile] = process.argv.slice(2);
if (!limitText) {
  console.error('usage: ray_tree_match.mjs PAGE.json LUZ.json LIMIT [SCENE.gltf WITH_TREE.png WITHOUT.png]');
  process.exit(2);
}
const page = JSON.parse(readFileSync(pageFile, 'utf8')), luz = JSON.parse(readFileSync(luzFile, 'utf8'));
const limit = Number(limitText);
let failed = false;
const check = (ok, what) => {
  console.log(`${ok ? 'ok' : 'FAILED'}: ${what}`);
  if (!ok) failed = true;
};

// The first place where a and b differ beyond the limit, as a path and both values; null when none.
function difference(a, b, path) {
  if (Array.isArray(a) && a.every((v) => typeof v === 'number') && Array.isArray(b) && a.length === b.length) {
    const scale = Math.max(1, ...a.map(Math.abs), ...b.map(Math.abs));
    return a.some((v, i) => Math.abs(v - b[i]) > limit * scale) ? `${path}: ${JSON.stringify(a)} against ${JSON.stringify(b)}` : null;
  }
  if (typeof a === 'number' && typeof b === 'number')
    return Math.abs(a - b) > limit * Math.max(1, Math.abs(a), Math.abs(b)) ? `${path}: ${a} against ${b}` : null;
  if (a === null || b === null || typeof a !== 'object' || typeof b !== 'object')
    return a === b ? null : `${path}: ${JSON.stringify(a)} against ${JSON.stringify(b)}`;
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  for (const key of keys) {
    if (!(key in a) || !(key in b)) return `${path}.${key}: only in ${key in a ? 'the page' : 'luz render'}`;
    const found = difference(a[key], b[key], `${path}.${key}`);
    if (found) return found;
  }
  return null;
}

const found = difference(page, luz, 'tree');
check(found === null, `the page's ray tree of pixel ${JSON.stringify(page.pixel)} (${page.nodes?.length} rays) is ` +
      `luz render --ray-tree's within ${limit} relative${found ? ': ' + found : ''}`);
check(page.nodes?.length >= 3, `the tree has at least 3 rays (${page.nodes?.length})`);

if (withoutFile) drawnAlongItsRays();
process.exit(failed ? 1 : 0);

// The tree drawn over the picture: where its rays are, and nowhere else.
function drawnAlongItsRays() {
  // The scene's first camera as a pinhole: world point -> picture pixel (x right, y down), or null
  // behind the camera. glTF's camera looks down its -z; its node's rotation is a quaternion.
  const gltf = JSON.parse(readFileSync(sceneFile, 'utf8'));
  const node = gltf.nodes.find((n) => n.camera === 0);
  const yfov = gltf.cameras[0].perspective.yfov;
  const [qx, qy, qz, qw] = node.rotation ?? [0, 0, 0, 1], t = node.translation ?? [0, 0, 0];
  // v rotated by the conjugate quaternion (world to camera): v + 2w(u x v)... with u = -q.xyz.
  function toCamera(p) {
    const v = [p[0] - t[0], p[1] - t[1], p[2] - t[2]], u = [-qx, -qy, -qz];
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const c1 = cross(u, v), c2 = cross(u, c1);
    return [0, 1, 2].map((k) => v[k] + 2 * (qw * c1[k] + c2[k]));
  }
  const withTree = readPng(withFile), without = readPng(withoutFile);
  const { width, height } = withTree;
  const tanHalf = Math.tan(yfov / 2), aspect = width / height;
  function project(p) {
    const q = toCamera(p);
    if (q[2] >= -1e-6) return null;
    const x = q[0] / -q[2] / (tanHalf * aspect), y = q[1] / -q[2] / tanHalf;
    return [(x * 0.5 + 0.5) * width, (0.5 - y * 0.5) * height];
  }
  const differs = (x, y, tolerance) => {
    const a = withTree.rgb(x, y), b = without.rgb(x, y);
    return a.some((v, k) => Math.abs(v - b[k]) > tolerance);
  };
  check(without.width === width && without.height === height, `both pictures ${width}x${height}`);
  const extent = (() => {  // the scene's size, for a ray that leaves it: its bounds' diagonal
    let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (const n of page.nodes) for (const p of [n.origin, n.hit?.point].filter(Boolean)) {
      lo = lo.map((v, k) => Math.min(v, p[k]));
      hi = hi.map((v, k) => Math.max(v, p[k]));
    }
    return Math.hypot(...hi.map((v, k) => v - lo[k])) || 1;
  })();
  const near = new Uint8Array(width * height);
  let sampled = 0, seen = 0;
  for (const n of page.nodes) {
    const length = n.kind === 'shadow' ? n.distance : n.hit ? n.hit.t : extent;
    for (let i = 0; i <= 400; ++i) {
      const s = (length * i) / 400;
      const at = project([0, 1, 2].map((k) => n.origin[k] + s * n.direction[k]));
      if (!at) continue;
      const x = Math.floor(at[0]), y = Math.floor(at[1]);
      for (let dy = -6; dy <= 6; ++dy)
        for (let dx = -6; dx <= 6; ++dx)
          if (x + dx >= 0 && y + dy >= 0 && x + dx < width && y + dy < height) near[(y + dy) * width + x + dx] = 1;
      if (n.kind === 'primary' || x < 4 || y < 4 || x >= width - 4 || y >= height - 4) continue;
      ++sampled;
      let changed = false;
      for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) changed ||= differs(x + dx, y + dy, 24);
      if (changed) ++seen;
    }
  }
  check(sampled >= 100, `${sampled} points along the secondary rays inside the picture (at least 100)`);
  check(seen >= 0.9 * sampled, `${seen} of them changed by the drawn tree (at least 90%)`);
  let elsewhere = 0;
  for (let y = 0; y < height; ++y) for (let x = 0; x < width; ++x) if (!near[y * width + x] && differs(x, y, 1)) ++elsewhere;
  check(elsewhere === 0, `${elsewhere} pixels away from the rays changed`);
}
