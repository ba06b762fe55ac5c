import fs from 'node:fs';
import { PNG } from 'pngjs';
const [a, b, out] = process.argv.slice(2).map((f, i) => i < 2 ? PNG.sync.read(fs.readFileSync(f)) : f);
const w = Math.min(a.width, b.width), h = Math.min(a.height, b.height);
const o = new PNG({ width: w * 3, height: h });
for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
  const ia = (y * a.width + x) * 4, ib = (y * b.width + x) * 4;
  let d = 0;
  for (let c = 0; c < 3; c++) { d = Math.max(d, Math.abs(a.data[ia + c] - b.data[ib + c])); }
  for (let c = 0; c < 4; c++) {
    o.data[(y * w * 3 + x) * 4 + c] = a.data[ia + c];
    o.data[(y * w * 3 + w + x) * 4 + c] = b.data[ib + c];
    o.data[(y * w * 3 + 2 * w + x) * 4 + c] = c === 3 ? 255 : (d > 24 ? 255 : 0);
  }
}
fs.writeFileSync(out, PNG.sync.write(o));
