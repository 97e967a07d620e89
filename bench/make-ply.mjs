// Writes the benchmark scan: a closed torus 1.7 m tall in millimetres, 500 × 300 quads split into
// 300,000 triangles (150,000 vertices), binary little-endian PLY. Deterministic: same bytes each run.
// Usage: node bench/make-ply.mjs OUT.ply
import { writeFileSync } from 'node:fs';

const COLS = 500; // around the big circle
const ROWS = 300; // around the tube
const R = 600; // big radius, mm
const r = 250; // tube radius, mm

const out = process.argv[2];
if (!out) {
  console.error('usage: node bench/make-ply.mjs OUT.ply');
  process.exit(2);
}

const vertexCount = COLS * ROWS;
const triangleCount = 2 * COLS * ROWS;
const header =
  'ply\nformat binary_little_endian 1.0\ncomment BodySpace benchmark torus, millimetres\n' +
  `element vertex ${vertexCount}\nproperty float x\nproperty float y\nproperty float z\n` +
  `element face ${triangleCount}\nproperty list uchar int vertex_indices\nend_header\n`;
const body = Buffer.alloc(vertexCount * 12 + triangleCount * 13);
let o = 0;
for (let i = 0; i < COLS; i++) {
  const u = (2 * Math.PI * i) / COLS;
  for (let j = 0; j < ROWS; j++) {
    const v = (2 * Math.PI * j) / ROWS;
    // Stood on its rim: y up, 2(R + r) = 1.7 m tall.
    const x = (R + r * Math.cos(v)) * Math.cos(u);
    const y = (R + r * Math.cos(v)) * Math.sin(u) + R + r;
    const z = r * Math.sin(v);
    o = body.writeFloatLE(x, o);
    o = body.writeFloatLE(y, o);
    o = body.writeFloatLE(z, o);
  }
}
const index = (i, j) => (i % COLS) * ROWS + (j % ROWS);
for (let i = 0; i < COLS; i++) {
  for (let j = 0; j < ROWS; j++) {
    const a = index(i, j);
    const b = index(i + 1, j);
    const c = index(i + 1, j + 1);
    const d = index(i, j + 1);
    for (const [p, q, s] of [
      [a, b, c],
      [a, c, d],
    ]) {
      o = body.writeUInt8(3, o);
      o = body.writeInt32LE(p, o);
      o = body.writeInt32LE(q, o);
      o = body.writeInt32LE(s, o);
    }
  }
}
writeFileSync(out, Buffer.concat([Buffer.from(header, 'ascii'), body]));
console.log(`wrote ${out}: ${vertexCount} vertices, ${triangleCount} triangles`);
