// The Shape space panel as a person uses it: the demo model opens, sliders change the body and
// its readings, a copied link reproduces the same body elsewhere, and bad inputs say what is wrong.
import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { shapeReady, slide } from './steps';

const READINGS = ['stature', 'chest_girth', 'bust_girth', 'waist_girth', 'hip_girth', 'thigh_girth', 'neck_girth', 'neck_base_girth', 'head_girth', 'arm_length', 'crotch_height', 'volume', 'surface_area'].map((n) => `measure-${n}`);


/** The `c=` (camera) part of a link. */
function camera(url: string): string | undefined {
  return new URL(url).hash.split('&').find((p) => p.startsWith('c='));
}

async function readings(page: Page): Promise<string[]> {
  return Promise.all(READINGS.map((id) => page.getByTestId(id).innerText()));
}


test('the demo model opens at its mean with readings', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
  await expect(page.getByTestId('shape-slider-0')).toBeVisible();
  const stature = Number(await page.locator('body').getAttribute('data-shape-stature'));
  expect(stature).toBeGreaterThan(1.4);
  expect(stature).toBeLessThan(2.0);
  // Every measurement is taken on the demo mean: lengths and girths in cm, volume in L, area in m².
  for (const text of await readings(page)) expect(text).toMatch(/^\d+\.\d cm$|^\d+\.\d L$|^\d\.\d{3} m²$/);
  await expect(page.getByTestId('chart-compactness')).toBeVisible();
  // The paper's coefficient scale and the explained variance on hover.
  const row = page.getByTestId('shape-slider-0').locator('..');
  await expect(row).toHaveAttribute('title', /b = t·√λ = 0\.0000 \(√λ = \d+\.\d{4} m\); explains \d+\.\d\d % of the variance/);
  await expect(page.getByTestId('shape-explained-0')).toHaveText(/^\d+\.\d%$/);
});

test('a slider changes the stature; the copied link shows the same body in a new page', async ({ page, context }) => {
  await page.goto('/');
  await shapeReady(page);
  const before = await page.getByTestId('measure-stature').innerText();
  await slide(page, 0, 2.5);
  await expect(page.getByTestId('measure-stature')).not.toHaveText(before);

  // A segment with its own shape, stitched in.
  await page.getByTestId('shape-segment').selectOption('torso');
  await slide(page, 1, -1.7);
  await expect(page.getByTestId('shape-segment-state')).toContainText('has its own shape');
  await expect(page.getByTestId('seam-jump')).toHaveText(/mm/);

  // Turn the camera, so the link carries a camera that framing alone would not give.
  const box = (await page.getByTestId('viewport-canvas').boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 + 30, { steps: 5 });
  await page.mouse.up();
  const framed = camera(await page.getByTestId('shape-link').inputValue());

  await page.getByTestId('copy-link').click();
  const link = await page.getByTestId('shape-link').inputValue();
  expect(link).toContain('#m=models%2Fdemo.bsm');
  expect(link).toContain('s=torso.');
  expect(camera(link)).not.toBe(framed);
  const checksum = await page.locator('body').getAttribute('data-shape-checksum');
  const values = await readings(page);

  const other = await context.newPage();
  await other.goto(link);
  await expect(other.locator('body')).toHaveAttribute('data-link-restored', 'true');
  await shapeReady(other);
  await expect(other.locator('body')).toHaveAttribute('data-shape-checksum', checksum!);
  expect(await readings(other)).toEqual(values);
  await expect(other.getByTestId('shape-segment')).toHaveValue('torso');
  await expect(other.getByTestId('shape-slider-1')).toHaveValue('-1.7');
  // The camera came with the link: the link the new page offers has the same camera part.
  expect(camera(await other.getByTestId('shape-link').inputValue())).toBe(camera(link));
});

test('a corrupted model file gives the documented message and the demo model keeps working', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const bytes = readFileSync('public/models/demo.bsm');
  const corrupted = Buffer.from(bytes);
  corrupted[corrupted.length - 100] = corrupted[corrupted.length - 100]! ^ 0xff;
  await page.getByTestId('model-input').setInputFiles({ name: 'broken.bsm', mimeType: 'application/octet-stream', buffer: corrupted });
  await expect(page.getByTestId('error-text')).toContainText('broken.bsm: model file is corrupted: data section fails its CRC-32 checksum. The model shown before stays');
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
  const before = await page.locator('body').getAttribute('data-shape-checksum');
  await slide(page, 0, -2);
  await expect(page.locator('body')).not.toHaveAttribute('data-shape-checksum', before!);

  await page.getByTestId('model-input').setInputFiles({ name: 'notes.bsm', mimeType: 'text/plain', buffer: Buffer.from('hello') });
  await expect(page.getByTestId('error-text')).toContainText('notes.bsm: ');
});

test('a link with bad parameters opens the default state and says what was ignored', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const mean = await page.locator('body').getAttribute('data-shape-checksum');

  await page.goto('/#m=..%2F..%2Fetc%2Fpasswd&w=!!&v=elbow&zoom=3');
  await page.reload();
  await shapeReady(page);
  await expect(page.locator('body')).toHaveAttribute('data-link-ignored', 'true');
  const message = page.getByTestId('error-text');
  await expect(message).toContainText('The link was ignored');
  await expect(message).toContainText('unknown parameter "zoom"');
  await expect(message).toContainText('neither a same-origin path nor an https URL');
  await expect(message).toContainText('unknown segment view "elbow"');
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
  await expect(page.locator('body')).toHaveAttribute('data-shape-checksum', mean!);
});

test('fitted meshes dropped in template order build a model in the app; its bodies have no link; a reload offers it back', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  await page.getByTestId('fits-input').setInputFiles(['public/samples/truth_001.ply.gz', 'public/samples/truth_002.ply.gz']);
  await expect(page.getByTestId('shape-subjects')).toContainText('2 subjects in this session (0 aligned, 2 dropped');
  await page.getByTestId('build-variance').fill('100');
  const bodies = Number(await page.locator('body').getAttribute('data-shape-bodies'));
  await page.getByTestId('build-model').click();
  await expect(page.getByTestId('shape-model-name')).toHaveText('model of 2 subjects');
  await expect(page.locator('body')).not.toHaveAttribute('data-shape-bodies', String(bodies));
  await shapeReady(page);
  // Two subjects span one mode.
  await expect(page.locator('body')).toHaveAttribute('data-shape-modes', '1');
  await expect(page.getByTestId('shape-link')).toHaveValue('');
  await expect(page.getByTestId('shape-link-note')).toContainText('has no address');

  // A reload opens the demo model as before, and offers the model built here back.
  await expect(page.locator('body')).toHaveAttribute('data-model-kept', '1');
  await page.reload();
  await shapeReady(page);
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
  const kept = page.getByTestId('shape-kept');
  await expect(kept).toContainText('The model built here from 2 subjects');
  await page.getByTestId('shape-open-kept').click();
  await expect(page.getByTestId('shape-model-name')).toHaveText('model of 2 subjects');
  await expect(page.locator('body')).toHaveAttribute('data-shape-modes', '1');
  await expect(kept).toBeHidden();
});

test('exports: body PLY/OBJ/glTF, bodies along a mode, the model with morph targets, CSVs', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const save = async (testid: string) => {
    const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId(testid).click()]);
    const path = await download.path();
    return { name: download.suggestedFilename(), bytes: readFileSync(path!) };
  };
  const ply = await save('shape-export-ply');
  expect(ply.name).toBe('body.ply');
  expect(ply.bytes.toString('latin1', 0, 300)).toContain('element vertex 13380');
  const obj = await save('shape-export-obj');
  expect(obj.bytes.toString('utf8').split('\n').filter((l) => l.startsWith('v ')).length).toBe(13380);
  const glb = await save('shape-export-glb');
  expect(glb.bytes.toString('latin1', 0, 4)).toBe('glTF');
  const along = await save('export-along');
  expect(along.name).toBe('mode1.glb');
  const json = along.bytes.toString('utf8', 20, 20 + along.bytes.readUInt32LE(12));
  expect((JSON.parse(json) as { meshes: unknown[] }).meshes.length).toBe(5);
  const model = await save('export-model-gltf');
  const modelJson = JSON.parse(model.bytes.toString('utf8', 20, 20 + model.bytes.readUInt32LE(12))) as {
    meshes: { primitives: { targets?: unknown[] }[] }[];
  };
  // One morph target per kept whole-body mode, as the page reports them.
  const modes = Number(await page.locator('body').getAttribute('data-shape-modes'));
  expect(modes).toBeGreaterThan(1);
  expect(modelJson.meshes[0]!.primitives[0]!.targets!.length).toBe(modes);
  // The segment models too: seven meshes, each with its own modes as morph targets.
  const parts = await save('export-model-parts-gltf');
  expect(parts.name).toBe('shape-model-segments.glb');
  expect(parts.bytes.toString('latin1', 0, 4)).toBe('glTF');
  const partsJson = JSON.parse(parts.bytes.toString('utf8', 20, 20 + parts.bytes.readUInt32LE(12))) as {
    meshes: { name: string; primitives: { targets?: unknown[] }[] }[];
  };
  expect(partsJson.meshes.map((m) => m.name)).toEqual(['whole', 'head', 'left_arm', 'right_arm', 'torso', 'left_leg', 'right_leg']);
  for (const mesh of partsJson.meshes) expect(mesh.primitives[0]!.targets!.length).toBeGreaterThan(0);
  const csv = await save('csv-eigenvalues');
  expect(csv.bytes.toString('utf8').split('\n')[0]).toBe('model,mode,eigenvalue,sd,explained,cumulative,kept');
});

test('at fine the 214,050-vertex body follows whole-body and segment sliders by rank-1 updates', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const body = page.locator('body');
  await page.getByTestId('shape-resolution').selectOption('fine');
  await expect(body).toHaveAttribute('data-shape-resolution', 'fine');
  await expect(body).toHaveAttribute('data-shape-vertices', '214050');
  await shapeReady(page);
  // The mesh in the scene has the fine template's vertices.
  await expect(page.locator('#viewport')).toHaveAttribute('data-shape-vertices', '214050');
  await expect(page.getByTestId('shape-vertices')).toHaveText('214050');
  await expect(page.getByTestId('shape-resolution-note')).toContainText('Measurements are taken on the base vertices');

  // A whole-body slider: one rank-1 update in the worker, a new stature.
  const stature = await page.getByTestId('measure-stature').innerText();
  await slide(page, 0, 2.5);
  await expect(page.getByTestId('measure-stature')).not.toHaveText(stature);
  await expect(body).toHaveAttribute('data-shape-rebuilt', 'false');
  await expect(body).toHaveAttribute('data-shape-deltas', '1');

  // A segment slider: its first move gives the head its own coefficients (a rebuild, the blend
  // changes); the next one is a rank-1 update again, and the top of the head moves the stature.
  await page.getByTestId('shape-segment').selectOption('head');
  await slide(page, 1, -1.7);
  await expect(body).toHaveAttribute('data-shape-rebuilt', 'true');
  const before = { stature: await body.getAttribute('data-shape-stature'), checksum: await body.getAttribute('data-shape-checksum') };
  await slide(page, 0, 2.8);
  await expect(body).toHaveAttribute('data-shape-rebuilt', 'false');
  await expect(body).toHaveAttribute('data-shape-deltas', '1');
  await expect(body).not.toHaveAttribute('data-shape-checksum', before.checksum!);
  await expect(body).not.toHaveAttribute('data-shape-stature', before.stature!);
  await expect(page.getByTestId('measure-stature')).toHaveText(/^\d+\.\d cm$/);
  await expect(page.locator('#viewport')).toHaveAttribute('data-shape-vertices', '214050');

  // The link carries the resolution: a new page opens on the same fine body.
  await page.getByTestId('copy-link').click();
  // Copying rebuilds a body made by rank-1 updates, so sender and receiver hold the same bits.
  await expect(body).toHaveAttribute('data-shape-rebuilt', 'true');
  await shapeReady(page);
  const link = await page.getByTestId('shape-link').inputValue();
  expect(link).toContain('r=fine');
  const checksum = await body.getAttribute('data-shape-checksum');
  const other = await page.context().newPage();
  await other.goto(link);
  await expect(other.locator('body')).toHaveAttribute('data-link-restored', 'true');
  await expect(other.locator('body')).toHaveAttribute('data-shape-vertices', '214050');
  await shapeReady(other);
  await expect(other.locator('body')).toHaveAttribute('data-shape-resolution', 'fine');
  await expect(other.locator('body')).toHaveAttribute('data-shape-checksum', checksum!);
  await expect(other.getByTestId('shape-resolution')).toHaveValue('fine');
  await other.close();

  // Back to base: the same coefficients, the same readings (measured on the base vertices).
  const readingsAtFine = await readings(page);
  await page.getByTestId('shape-resolution').selectOption('base');
  await expect(body).toHaveAttribute('data-shape-vertices', '13380');
  await shapeReady(page);
  expect(await readings(page)).toEqual(readingsAtFine);
});
