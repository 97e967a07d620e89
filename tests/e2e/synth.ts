// Synthetic subjects made by the core's own generator (`bodyspace synth`, the native CLI that
// the test command builds before the browser tests), read from disk as a person would drop them.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { TestFile } from './fixtures';

const TARGET = fileURLToPath(new URL('../../crate/target/', import.meta.url));

/** The native CLI: BODYSPACE_BIN, else the release build, else the debug build. */
export function bodyspaceBinary(): string {
  const candidates = [process.env.BODYSPACE_BIN, join(TARGET, 'release/bodyspace'), join(TARGET, 'debug/bodyspace')];
  const found = candidates.find((p): p is string => Boolean(p && existsSync(p)));
  if (!found) throw new Error('no bodyspace binary: run `cargo build --manifest-path crate/Cargo.toml` first');
  return found;
}

/**
 * `n` synthetic subjects of population `seed`, scanned every `stepMm` (20 mm: ≈ 3,500-vertex
 * scans, quick to align): `scan_00i.ply` and `landmarks_00i.lnd` for each. `extra`: more
 * `bodyspace synth` arguments (e.g. `--scanner-class stray`).
 */
export function synthSubjects(n: number, seed: number, stepMm = 20, extra: string[] = []): TestFile[] {
  return synthFolder(n, seed, stepMm, extra).filter((f) => /^(scan_\d+\.ply|landmarks_\d+\.lnd)$/.test(f.name));
}

/**
 * Every file `bodyspace synth` writes for `n` subjects, as "Open folder…" on its output reads them:
 * besides each scan and its landmarks (`.lnd` and `.csv`), the ground truths `surface_ID.ply`
 * and `truth_ID.ply`, and the population's own files.
 */
export function synthFolder(n: number, seed: number, stepMm = 20, extra: string[] = []): TestFile[] {
  const out = mkdtempSync(join(tmpdir(), 'bodyspace-synth-'));
  try {
    execFileSync(bodyspaceBinary(), ['synth', '--n', String(n), '--seed', String(seed), '--step', String(stepMm), ...extra, '--out', out], { stdio: 'ignore' });
    return readdirSync(out, { withFileTypes: true })
      .filter((entry) => entry.isFile())
      .map((entry) => entry.name)
      .sort()
      .map((name) => ({ name, bytes: readFileSync(join(out, name)) }));
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}

/** The parts of a PLY as `bodyspace synth` writes it (binary: float x, y, z; triangles of three ints). */
function plyParts(ply: Buffer): { header: string; vertices: number; faces: number; end: number } {
  const end = ply.indexOf('end_header\n') + 'end_header\n'.length;
  const header = ply.subarray(0, end).toString('latin1');
  const count = (element: string) => Number(new RegExp(`element ${element} (\\d+)`).exec(header)![1]);
  return { header, vertices: count('vertex'), faces: count('face'), end };
}

/** `ply` (as `bodyspace synth` writes it) with the corners of the triangles `turn` picks (by index) in the other order. */
function turnedWhere(ply: Buffer, turn: (k: number) => boolean): Buffer {
  const { vertices, faces, end } = plyParts(ply);
  const out = Buffer.from(ply);
  const first = end + 12 * vertices;
  for (let k = 0; k < faces; k++) {
    if (!turn(k)) continue;
    const at = first + 13 * k + 1;
    const [b, c] = [out.readInt32LE(at + 4), out.readInt32LE(at + 8)];
    out.writeInt32LE(c, at + 4);
    out.writeInt32LE(b, at + 8);
  }
  return out;
}

/** `ply` (as `bodyspace synth` writes it) with every triangle's corners in the other order: wound inwards, as some exporters write. */
export function turnedInsideOut(ply: Buffer): Buffer {
  return turnedWhere(ply, () => true);
}

/** `ply` (as `bodyspace synth` writes it) with about half its triangles, picked by a fixed scramble of the index, in the other order: facing both ways, as a mesh never oriented may. */
export function facingBothWays(ply: Buffer): Buffer {
  return turnedWhere(ply, (k) => Math.imul(k, 0x9e3779b1) >>> 31 === 1);
}

/**
 * `ply` (binary, as `bodyspace synth` writes it: float x, y, z; triangles) with a box turned
 * inside out put beside the body's feet, 30 cm on a side and 20 cm clear of its box: a part
 * wound the other way, as a merged export may bring, so that the scan's parts disagree.
 */
export function withInsideOutBox(ply: Buffer): Buffer {
  const { header, vertices, faces, end } = plyParts(ply);
  let [maxX, minZ] = [-Infinity, Infinity];
  for (let i = 0; i < vertices; i++) {
    maxX = Math.max(maxX, ply.readFloatLE(end + 12 * i));
    minZ = Math.min(minZ, ply.readFloatLE(end + 12 * i + 8));
  }
  const [x0, side] = [maxX + 200, 300];
  const corners = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => [x0 + (k & 1) * side, ((k >> 1) & 1) * side - side / 2, minZ + ((k >> 2) & 1) * side]);
  // Each face's two triangles, counter-clockwise seen from inside the box.
  const quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]];
  const points = Buffer.alloc(8 * 12);
  corners.forEach((c, k) => c.forEach((v, j) => points.writeFloatLE(v, 12 * k + 4 * j)));
  const triangles = Buffer.alloc(12 * 13);
  quads.flatMap(([a, b, c, d]) => [[a, b, c], [a, c, d]]).forEach((t, k) => {
    triangles.writeUInt8(3, 13 * k);
    t.forEach((v, j) => triangles.writeInt32LE(vertices + v!, 13 * k + 1 + 4 * j));
  });
  const newHeader = header.replace(`element vertex ${vertices}`, `element vertex ${vertices + 8}`).replace(`element face ${faces}`, `element face ${faces + 12}`);
  const body = end + 12 * vertices;
  return Buffer.concat([Buffer.from(newHeader, 'latin1'), ply.subarray(end, body), points, ply.subarray(body), triangles]);
}
