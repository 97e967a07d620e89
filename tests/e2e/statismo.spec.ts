// Statismo HDF5 models across the two writers and readers: a file written by the command line
// (the HDF5 C library) is read here by h5wasm — its layout, and mean + basis giving the body the
// core reconstructs — and opened in the app; a file the app writes (h5wasm in the worker) is read
// by the command line's reader. Segment files are their own vertices and are refused as a body.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import h5wasm from 'h5wasm/node';
import { shapeReady, slide } from './steps';

const dir = mkdtempSync(join(tmpdir(), 'bodyspace-statismo-e2e-'));
test.afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** Runs the native `bodyspace` (built by cargo if needed) and parses its JSON; throws with its stderr. */
function bodyspace(...args: string[]): Record<string, unknown> {
  const out = execFileSync('cargo', ['run', '--quiet', '--manifest-path', 'crate/Cargo.toml', '--bin', 'bodyspace', '--', ...args], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  return JSON.parse(out) as Record<string, unknown>;
}

function bodyspaceError(...args: string[]): string {
  try {
    bodyspace(...args);
  } catch (error) {
    return String((error as { stderr?: string }).stderr);
  }
  throw new Error(`bodyspace ${args.join(' ')} succeeded`);
}

interface H5Read {
  shape: number[];
  values: Float32Array | Uint32Array | Int32Array;
  attrs: Record<string, unknown>;
}

/** Every dataset (and group attributes) of an HDF5 file, read with h5wasm. */
async function readH5(path: string): Promise<Map<string, H5Read>> {
  await h5wasm.ready;
  const file = new h5wasm.File(path, 'r');
  const out = new Map<string, H5Read>();
  const walk = (group: InstanceType<typeof h5wasm.Group>, prefix: string) => {
    for (const key of group.keys()) {
      const entity = group.get(key);
      const name = `${prefix}/${key}`;
      if (entity instanceof h5wasm.Group) {
        out.set(`${name}/`, { shape: [], values: new Float32Array(), attrs: Object.fromEntries(Object.entries(entity.attrs).map(([k, a]) => [k, a.value])) });
        walk(entity, name);
      } else if (entity instanceof h5wasm.Dataset) {
        const value = entity.value;
        const values = typeof value === 'number' ? new Float32Array([value]) : ArrayBuffer.isView(value) ? (value as Float32Array) : new Float32Array();
        out.set(name, { shape: entity.shape ?? [], values, attrs: { dtype: entity.dtype } });
      }
    }
  };
  walk(file, '');
  file.close();
  return out;
}

/** Positions of a binary little-endian PLY written by the core (float x, y, z first). */
function plyPositions(path: string): Float32Array {
  const bytes = readFileSync(path);
  const end = bytes.indexOf('end_header\n') + 'end_header\n'.length;
  const header = bytes.toString('latin1', 0, end);
  const n = Number(/element vertex (\d+)/.exec(header)![1]);
  const stride = header.split('element face')[0]!.split('\n').filter((l) => l.startsWith('property')).length * 4;
  const out = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) for (let d = 0; d < 3; d++) out[3 * i + d] = bytes.readFloatLE(end + i * stride + 4 * d);
  return out;
}

async function save(page: Page, testid: string): Promise<{ name: string; path: string }> {
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testid).click()]);
  const path = join(dir, download.suggestedFilename());
  await download.saveAs(path);
  return { name: download.suggestedFilename(), path };
}

test('a statismo file written by the command line has the layout, the body, and opens in the app', async ({ page }) => {
  const whole = join(dir, 'cli-demo.h5');
  const head = join(dir, 'cli-head.h5');
  bodyspace('export-statismo', '--model', 'public/models/demo.bsm', '--out', whole);
  const headInfo = bodyspace('export-statismo', '--model', 'public/models/demo.bsm', '--out', head, '--segment', 'head');

  const h5 = await readH5(whole);
  const n = 13380;
  const k = 20;
  expect(h5.get('/representer/')!.attrs).toEqual({ name: 'itkStandardMeshRepresenter', version: '1.0', datasetType: 'POLYGON_MESH' });
  expect(h5.get('/representer/points')!.shape).toEqual([3, n]);
  expect(h5.get('/representer/cells')!.shape).toEqual([3, 26756]);
  expect(h5.get('/representer/cells')!.attrs.dtype).toBe('<I');
  expect(h5.get('/model/mean')!.shape).toEqual([3 * n]);
  expect(h5.get('/model/pcaBasis')!.shape).toEqual([3 * n, k]);
  expect(h5.get('/model/pcaBasis')!.attrs.dtype).toBe('<f');
  expect(h5.get('/model/pcaVariance')!.shape).toEqual([k]);
  expect(h5.get('/model/noiseVariance')!.shape).toEqual([]);
  expect(h5.get('/modelinfo/scores')!.shape).toEqual([k, 100]);
  expect(h5.get('/version/majorVersion')!.values[0]).toBe(0);
  expect(h5.get('/version/minorVersion')!.values[0]).toBe(9);

  // Orthonormal basis: column 0 has unit length, columns 0 and 1 are orthogonal.
  const basis = h5.get('/model/pcaBasis')!.values;
  let norm = 0;
  let dot = 0;
  for (let i = 0; i < 3 * n; i++) {
    norm += basis[i * k]! ** 2;
    dot += basis[i * k]! * basis[i * k + 1]!;
  }
  expect(Math.abs(norm - 1)).toBeLessThan(1e-4);
  expect(Math.abs(dot)).toBeLessThan(1e-4);

  // mean + Σ basis·√λ·t (millimetres) is the body the core reconstructs at t = (2, −1, 0.5) σ.
  const sigma = [2, -1, 0.5];
  const ply = join(dir, 'cli-body.ply');
  bodyspace('reconstruct', '--model', 'public/models/demo.bsm', '--coefficients', sigma.join(','), '--sigma', '--out', ply);
  const core = plyPositions(ply);
  const mean = h5.get('/model/mean')!.values;
  const variance = h5.get('/model/pcaVariance')!.values;
  let worst = 0;
  for (let i = 0; i < 3 * n; i++) {
    let x = mean[i]!;
    sigma.forEach((t, j) => (x += basis[i * k + j]! * Math.sqrt(variance[j]!) * t));
    worst = Math.max(worst, Math.abs(x / 1000 - core[i]!));
  }
  expect(worst).toBeLessThan(2e-5);

  // The head file is the head's own vertices.
  const headH5 = await readH5(head);
  expect(headH5.get('/representer/points')!.shape).toEqual([3, headInfo.points]);
  expect(headH5.get('/model/pcaBasis')!.shape).toEqual([3 * Number(headInfo.points), k]);

  // The app opens the whole-body file: the same mean body and the same body after a slider.
  // h5wasm is fetched only then, not with the page.
  const fetched: string[] = [];
  page.on('request', (request) => fetched.push(request.url()));
  await page.goto('/');
  await shapeReady(page);
  expect(fetched.filter((url) => url.includes('hdf5'))).toEqual([]);
  const body = page.locator('body');
  const statureOf = async () => Number(await body.getAttribute('data-shape-stature'));
  const demoMean = await statureOf();
  await page.getByTestId('model-input').setInputFiles({ name: 'cli-demo.h5', mimeType: 'application/x-hdf5', buffer: readFileSync(whole) });
  await expect(page.getByTestId('shape-model-name')).toHaveText('cli-demo.h5');
  await shapeReady(page);
  await expect(body).toHaveAttribute('data-shape-modes', '20');
  expect(fetched.filter((url) => url.includes('hdf5')).length).toBeGreaterThan(0);
  expect(Math.abs((await statureOf()) - demoMean)).toBeLessThan(1e-5);
  await slide(page, 0, 2);
  const statismoAt2 = await statureOf();

  // A segment file is refused with what it is; the model shown stays.
  await page.getByTestId('model-input').setInputFiles({ name: 'cli-head.h5', mimeType: 'application/x-hdf5', buffer: readFileSync(head) });
  await expect(page.getByTestId('error-text')).toContainText("cli-head.h5: statismo model: the model has");
  await expect(page.getByTestId('error-text')).toContainText("BodySpace's head segment model");
  await expect(page.getByTestId('shape-model-name')).toHaveText('cli-demo.h5');

  // An HDF5 file cut short, and a file that is not HDF5 inside, are refused by name.
  await page.getByTestId('model-input').setInputFiles({ name: 'cut.h5', mimeType: 'application/x-hdf5', buffer: readFileSync(whole).subarray(0, 4000) });
  await expect(page.getByTestId('error-text')).toContainText('cut.h5: not a statismo model: ');
  await expect(page.getByTestId('shape-model-name')).toHaveText('cli-demo.h5');
  await page.getByTestId('model-input').setInputFiles({ name: 'notes.h5', mimeType: 'text/plain', buffer: Buffer.from('hello') });
  await expect(page.getByTestId('error-text')).toContainText('notes.h5: ');
  await expect(page.getByTestId('shape-model-name')).toHaveText('cli-demo.h5');

  // The same slider on the demo model gives the same stature.
  await page.goto('/');
  await shapeReady(page);
  await slide(page, 0, 2);
  expect(Math.abs((await statureOf()) - statismoAt2)).toBeLessThan(1e-5);
});

test('the app saves the whole body or the segment in view as statismo; the command line reads it', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const whole = await save(page, 'save-statismo');
  expect(whole.name).toBe('shape-model.h5');
  const info = bodyspace('info', whole.path) as { subjects: number; parts: { name: string; vertices: number; modes: number }[] };
  expect(info.subjects).toBe(100);
  expect(info.parts[0]).toMatchObject({ name: 'whole', vertices: 13380, modes: 20 });

  // The Rust reader's body from the app's file is the demo model's.
  const fromApp = join(dir, 'app-body.ply');
  const fromBsm = join(dir, 'bsm-body.ply');
  bodyspace('reconstruct', '--model', whole.path, '--coefficients', '1.5,-2,1', '--sigma', '--out', fromApp);
  bodyspace('reconstruct', '--model', 'public/models/demo.bsm', '--coefficients', '1.5,-2,1', '--sigma', '--out', fromBsm);
  const a = plyPositions(fromApp);
  const b = plyPositions(fromBsm);
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i]! - b[i]!));
  expect(worst).toBeLessThan(2e-5);

  // The torso in view: its own vertices, written by the app, read by h5wasm and by the CLI.
  await page.getByTestId('shape-segment').selectOption('torso');
  const torso = await save(page, 'save-statismo');
  expect(torso.name).toBe('shape-model-torso.h5');
  const torsoVertices = info.parts.find((p) => p.name === 'torso')!.vertices;
  const h5 = await readH5(torso.path);
  expect(h5.get('/representer/points')!.shape).toEqual([3, torsoVertices]);
  expect(h5.get('/model/pcaBasis')!.shape).toEqual([3 * torsoVertices, 20]);
  expect(h5.get('/version/minorVersion')!.values[0]).toBe(9);
  expect(bodyspaceError('info', torso.path)).toContain("BodySpace's torso segment model");

  // A broken .h5 reaches the Rust reader as an error, not a crash.
  const cut = join(dir, 'cut.h5');
  writeFileSync(cut, readFileSync(whole.path).subarray(0, 4000));
  expect(bodyspaceError('info', cut)).toContain('cut.h5');
});
