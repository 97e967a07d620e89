// Files built in the test, as a person would drop them: a holed scan in millimetres and its
// CAESAR .lnd landmarks (with name variants, missing entries and CRLF line ends).
import { gzipSync } from 'node:zlib';
import type { Page } from '@playwright/test';

export interface TestFile {
  name: string;
  bytes: Buffer;
}

/**
 * A binary little-endian PLY in millimetres: an open-topped box 400 × 1700 × 300 mm (8 vertices,
 * 10 triangles, one hole where the lid would be) and a separate closed tetrahedron inside it
 * (4 vertices, 4 triangles). 12 vertices, 14 triangles, 1 hole, 2 components. Bounding box in
 * metres: (−0.2, 0, −0.15) to (0.2, 1.7, 0.15).
 */
export function holedBoxPly(name = 'subject.ply'): TestFile {
  const [x, y, z] = [200, 1700, 150];
  const positions = [
    [-x, 0, -z], [x, 0, -z], [x, 0, z], [-x, 0, z],
    [-x, y, -z], [x, y, -z], [x, y, z], [-x, y, z],
    [0, 100, 0], [50, 100, 0], [0, 150, 0], [0, 100, 50],
  ];
  const triangles = [
    [0, 1, 2], [0, 2, 3], // bottom
    [0, 4, 5], [0, 5, 1], [1, 5, 6], [1, 6, 2], [2, 6, 7], [2, 7, 3], [3, 7, 4], [3, 4, 0], // sides
    [8, 10, 9], [8, 9, 11], [8, 11, 10], [9, 10, 11], // tetrahedron
  ];
  return { name, bytes: binaryPly(positions, triangles) };
}

/** A binary little-endian PLY with float vertices and uchar/int face lists. */
function binaryPly(positions: number[][], triangles: number[][]): Buffer {
  const header =
    'ply\nformat binary_little_endian 1.0\ncomment built by the BodySpace tests\n' +
    `element vertex ${positions.length}\nproperty float x\nproperty float y\nproperty float z\n` +
    `element face ${triangles.length}\nproperty list uchar int vertex_indices\nend_header\n`;
  const body = Buffer.alloc(positions.length * 12 + triangles.length * 13);
  let o = 0;
  for (const p of positions) for (const v of p) o = body.writeFloatLE(v, o);
  for (const t of triangles) {
    o = body.writeUInt8(3, o);
    for (const i of t) o = body.writeInt32LE(i, o);
  }
  return Buffer.concat([Buffer.from(header, 'ascii'), body]);
}

/** The same bytes gzip-compressed, named `<name>.gz`. */
export function gzipped(file: TestFile): TestFile {
  return { name: `${file.name}.gz`, bytes: gzipSync(file.bytes) };
}

/** The first `fraction` of a file's bytes, as a download cut short would leave it. */
export function truncated(file: TestFile, name: string, fraction = 0.6): TestFile {
  return { name, bytes: file.bytes.subarray(0, Math.floor(file.bytes.length * fraction)) };
}

/** Landmarks of `subjectLnd`: found under their canonical names, missing, unknown. */
export const LND_FOUND = ['Sellion', 'Rt. Metacarpal Phal. II', 'Rt. Acromion', 'Lt. Axilla, Ant.', 'Crotch'];
export const LND_MISSING_IN_FILE = ['Rt. Tragion', 'Cervicale'];
export const LND_UNKNOWN = ['Navel Point'];

/**
 * A CAESAR .lnd in millimetres with CRLF line ends: name variants (`Rt. Acromio` truncated,
 * `Lt. Axilla, An`, `Metacarpal-Phal.`, trailing spaces), two landmarks marked −999 and one
 * name that is not a CAESAR landmark.
 */
export function subjectLnd(name = 'subject.lnd'): TestFile {
  const lines = [
    'SUBJECT_ID = 00042',
    'STD_LAND = 73',
    'AUX_LAND = 0',
    'STANDARD =',
    'AUX =',
    '  1    1    1   0.500    0.0 1600.0  110.0 Sellion',
    '  5 -999 -999   0.000    0.0    0.0    0.0 Rt. Tragion',
    ' 24 -999 -999   0.000    0.0    0.0    0.0 Cervicale',
    ' 29    1    1   0.500 -180.0 1450.0    0.0 Rt. Acromio',
    ' 37    1    1   0.500 -190.0  800.0   20.0 Rt. Metacarpal-Phal. II',
    ' 42    1    1   0.500  150.0 1350.0   80.0 Lt. Axilla, An',
    ' 73    1    1   0.500    0.0  820.0    0.0 Crotch   ',
    ' 74    1    1   0.500    0.0 1050.0  140.0 Navel Point',
    'END =',
    '',
  ];
  return { name, bytes: Buffer.from(lines.join('\r\n'), 'latin1') };
}

/** Drops `files` on the page as a drag from the desktop would. */
export async function dropFiles(page: Page, files: TestFile[]): Promise<void> {
  // The bytes cross into the page as base64 text: an array of numbers is serialised number by
  // number, which took over a minute for the 7.4 MB scan of responsive.spec.ts on a loaded machine.
  const payload = files.map((f) => ({ name: f.name, base64: f.bytes.toString('base64') }));
  const dataTransfer = await page.evaluateHandle((items) => {
    const dt = new DataTransfer();
    for (const item of items) {
      const text = atob(item.base64);
      const bytes = new Uint8Array(text.length);
      for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
      dt.items.add(new File([bytes], item.name));
    }
    return dt;
  }, payload);
  await page.dispatchEvent('#viewport', 'dragenter', { dataTransfer });
  await page.dispatchEvent('#viewport', 'drop', { dataTransfer });
}

/** Waits until the page has finished `n` loads (drops or picks) since it opened. */
export async function waitForLoads(page: Page, n: number): Promise<void> {
  await page.waitForFunction((count) => document.body.dataset.loads === String(count), n);
}
