import { gzipSync } from 'node:zlib';
import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import {
  LND_FOUND,
  LND_MISSING_IN_FILE,
  LND_UNKNOWN,
  dropFiles,
  gzipped,
  holedBoxPly,
  subjectLnd,
  truncated,
  waitForLoads,
  type TestFile,
} from './fixtures';

async function openApp(page: Page): Promise<void> {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-core-ready', 'true');
}

const byTestId = (page: Page, id: string) => page.getByTestId(id);

test('a dropped PLY and .lnd show their counts, box, units, holes, parts and landmarks', async ({ page }) => {
  await openApp(page);
  await dropFiles(page, [subjectLnd(), holedBoxPly()]);
  await waitForLoads(page, 1);

  await expect(byTestId(page, 'error-banner')).toBeHidden();
  await expect(byTestId(page, 'scan-file')).toHaveText('subject.ply');
  await expect(byTestId(page, 'scan-vertices')).toHaveText('12');
  await expect(byTestId(page, 'scan-triangles')).toHaveText('14');
  await expect(byTestId(page, 'scan-units')).toHaveValue('millimetres');
  await expect(byTestId(page, 'scan-bbox-min')).toHaveText('(-0.200, 0.000, -0.150)');
  await expect(byTestId(page, 'scan-bbox-max')).toHaveText('(0.200, 1.700, 0.150)');
  await expect(byTestId(page, 'scan-size-y')).toHaveText('1.700 m');
  await expect(byTestId(page, 'scan-holes')).toHaveText('1');
  await expect(byTestId(page, 'scan-components')).toHaveText('2');
  await expect(byTestId(page, 'scan-winding')).toHaveText('outwards');

  await expect(byTestId(page, 'landmarks-file')).toHaveText('subject.lnd');
  await expect(byTestId(page, 'landmarks-found')).toHaveText(String(LND_FOUND.length));
  await expect(byTestId(page, 'landmarks-missing')).toHaveText(String(73 - LND_FOUND.length));
  await expect(byTestId(page, 'landmarks-unknown')).toHaveText(String(LND_UNKNOWN.length));
  const list = byTestId(page, 'landmark-list');
  await expect(list.locator('li')).toHaveCount(73);
  // A partial file (5 of 73) is filled in by the estimate: the file's landmarks stay given, the
  // ones it lacks are estimated.
  await expect(page.locator('body')).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  for (const name of LND_FOUND) await expect(list.locator(`li[data-name="${name}"]`)).toHaveAttribute('data-state', 'given');
  for (const name of LND_MISSING_IN_FILE)
    await expect(list.locator(`li[data-name="${name}"]`)).toHaveAttribute('data-state', 'estimated');
  await expect(list.locator('li[data-state="given"]')).toHaveCount(LND_FOUND.length);
  await expect(byTestId(page, 'landmark-unknown-list').locator('li')).toHaveText(LND_UNKNOWN.map((n) => `?${n}`));

  // What the scene holds: the scan's triangles and one marker per landmark, given or estimated,
  // and per unknown name in the file.
  const viewport = page.locator('#viewport');
  await expect(viewport).toHaveAttribute('data-scan-triangles', '14');
  await expect(viewport).toHaveAttribute('data-scan-markers', String(73 + LND_UNKNOWN.length));
});

test('a broken file names the file and the problem, and what was loaded stays', async ({ page }) => {
  await openApp(page);
  const scan = holedBoxPly();
  await dropFiles(page, [scan]);
  await waitForLoads(page, 1);
  await expect(byTestId(page, 'scan-triangles')).toHaveText('14');

  await dropFiles(page, [truncated(scan, 'broken.ply')]);
  await waitForLoads(page, 2);
  const banner = byTestId(page, 'error-banner');
  await expect(banner).toBeVisible();
  await expect(byTestId(page, 'error-text')).toContainText('broken.ply');
  await expect(byTestId(page, 'error-text')).toContainText(/declares|ends|truncated|short/i);
  // The status line does not read as if the open scan were gone.
  await expect(page.locator('#status')).toHaveText('Not opened: see the message above. What was open stays as it was.');

  await expect(byTestId(page, 'scan-file')).toHaveText('subject.ply');
  await expect(byTestId(page, 'scan-vertices')).toHaveText('12');
  await expect(byTestId(page, 'scan-triangles')).toHaveText('14');
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-triangles', '14');

  await byTestId(page, 'error-dismiss').click();
  await expect(banner).toBeHidden();
});

test('an unsupported file is refused by name', async ({ page }) => {
  await openApp(page);
  await dropFiles(page, [{ name: 'notes.txt', bytes: Buffer.from('hello') }]);
  await waitForLoads(page, 1);
  await expect(byTestId(page, 'error-text')).toContainText('notes.txt: unsupported file type');
  await expect(byTestId(page, 'scan-empty')).toBeVisible();
});

test('overriding the units re-scales the bounding box shown', async ({ page }) => {
  await openApp(page);
  await dropFiles(page, [holedBoxPly()]);
  await waitForLoads(page, 1);
  await expect(byTestId(page, 'scan-bbox-max')).toHaveText('(0.200, 1.700, 0.150)');

  await byTestId(page, 'scan-units').selectOption('metres');
  await expect(byTestId(page, 'scan-bbox-max')).toHaveText('(200.000, 1700.000, 150.000)');
  await expect(byTestId(page, 'scan-size-y')).toHaveText('1700.000 m');
  await expect(page.locator('body')).toHaveAttribute('data-scan-units', 'metres');

  await byTestId(page, 'scan-units').selectOption('millimetres');
  await expect(byTestId(page, 'scan-bbox-min')).toHaveText('(-0.200, 0.000, -0.150)');
});

test('a gzip-compressed scan opens like the plain one, picked with the button', async ({ page }) => {
  await openApp(page);
  const file = gzipped(holedBoxPly());
  await byTestId(page, 'file-input').setInputFiles({ name: file.name, mimeType: 'application/gzip', buffer: file.bytes });
  await waitForLoads(page, 1);
  await expect(byTestId(page, 'scan-file')).toHaveText('subject.ply.gz');
  await expect(byTestId(page, 'scan-triangles')).toHaveText('14');
  await expect(byTestId(page, 'scan-holes')).toHaveText('1');
  await expect(byTestId(page, 'scan-bbox-max')).toHaveText('(0.200, 1.700, 0.150)');
});

/** A broken file of every kind the app reads, each with what its message must name. */
const BROKEN: { file: TestFile; problem: RegExp }[] = [
  { file: truncated(holedBoxPly(), 'cut.ply'), problem: /declares .* but the file ends/ },
  { file: { name: 'ascii.ply', bytes: Buffer.from('ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 five 6\n') }, problem: /vertex 1: cannot read "five" as a number/ },
  { file: { name: 'bad-index.obj', bytes: Buffer.from('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n') }, problem: /refers to vertex 9 but the file has 3 vertices/ },
  { file: { name: 'cut.stl', bytes: Buffer.concat([Buffer.alloc(80), Buffer.from([10, 0, 0, 0]), Buffer.alloc(100)]) }, problem: /declares 10 triangles but the file ends/ },
  { file: { name: 'corrupt.ply.gz', bytes: Buffer.from([0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 3, 1, 2, 3, 4, 5]) }, problem: /gzip data is corrupt .*re-compress/ },
  { file: { name: 'broken.lnd', bytes: Buffer.from('SUBJECT_ID = 1\r\nAUX =\r\n1 0 0 0.5 10 x 30 Sellion\r\nEND =\r\n') }, problem: /line 3: cannot read "x" as a number/ },
  { file: { name: 'broken.csv', bytes: Buffer.from('name,x,y,z\nSellion,1,two,3\n') }, problem: /cannot read "two" as a coordinate .*expected name,x,y,z/ },
  { file: { name: 'broken.json', bytes: Buffer.from('{"Sellion": [1, 2]}') }, problem: /expected \{"name": \[x, y, z\]/ },
];

test('a broken file of every kind is named with its problem, and the scan and landmarks stay', async ({ page }) => {
  await openApp(page);
  await dropFiles(page, [holedBoxPly(), subjectLnd()]);
  await waitForLoads(page, 1);
  await expect(byTestId(page, 'scan-triangles')).toHaveText('14');
  let loads = 1;
  for (const { file, problem } of BROKEN) {
    await dropFiles(page, [file]);
    await waitForLoads(page, ++loads);
    const text = byTestId(page, 'error-text');
    await expect(text, file.name).toContainText(file.name);
    await expect(text, file.name).toContainText(problem);
    await expect(text, file.name).toContainText(/drop (it|the file) again/);
    // What was loaded before is still there.
    await expect(byTestId(page, 'scan-file')).toHaveText('subject.ply');
    await expect(byTestId(page, 'scan-triangles')).toHaveText('14');
    await expect(byTestId(page, 'landmarks-file')).toHaveText('subject.lnd');
    await byTestId(page, 'error-dismiss').click();
  }
});

test('a small gzip file that would inflate far beyond any scan is refused, and the tab keeps working', async ({ page }) => {
  await openApp(page);
  await dropFiles(page, [holedBoxPly()]);
  await waitForLoads(page, 1);
  // 256 MB of zeros behind a PLY header, gzip-compressed to about 250 KB.
  const header = Buffer.from('ply\nformat binary_little_endian 1.0\nelement vertex 22000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n');
  const bomb = gzipSync(Buffer.concat([header, Buffer.alloc(256 * 1024 * 1024)]));
  expect(bomb.length).toBeLessThan(1024 * 1024);
  await dropFiles(page, [{ name: 'bomb.ply.gz', bytes: bomb }]);
  await waitForLoads(page, 2);
  await expect(byTestId(page, 'error-text')).toContainText('bomb.ply.gz');
  await expect(byTestId(page, 'error-text')).toContainText(/decompression bomb|inflate/);
  await expect(byTestId(page, 'scan-file')).toHaveText('subject.ply');
  await expect(byTestId(page, 'scan-triangles')).toHaveText('14');
});

test('"Lt. Bustpoint" and "Rt. Bustpoint" are read as the CAESAR Thelion/Bustpoint landmarks', async ({ page }) => {
  await openApp(page);
  const csv = readFileSync(new URL('../../public/samples/landmarks_001.csv', import.meta.url), 'utf8')
    .replace('Lt. Thelion/Bustpoint', 'Lt. Bustpoint')
    .replace('Rt. Thelion/Bustpoint', 'Rt. Bustpoint');
  await dropFiles(page, [{ name: 'bust.csv', bytes: Buffer.from(csv) }]);
  await waitForLoads(page, 1);
  await expect(byTestId(page, 'landmarks-found')).toHaveText('73');
  await expect(byTestId(page, 'landmarks-unknown')).toHaveText('0');
  const list = byTestId(page, 'landmark-list');
  for (const side of ['Lt.', 'Rt.']) await expect(list.locator(`li[data-name="${side} Thelion/Bustpoint"]`)).toHaveAttribute('data-state', 'given');
});
