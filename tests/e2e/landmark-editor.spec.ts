// The landmark editor as a person uses it: pick a landmark, click on the scan beside its marker to
// move it there, drag a marker, mark one absent, undo / redo, align with the edited set, export
// the set as .lnd and read it back; before any file nothing is marked absent; after Align a picked
// landmark brings the hidden scan back; a new scan forgets the pick and the list's scroll; a second
// scan opened alone gets its own estimate, and what it replaced comes back with "Back to"; all work
// put aside is kept; a reload brings the scan, its set and the work put aside back as they were;
// Forget asks first.
import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { partialCsv, sampleFile } from './samples';
import { cancelEstimateWhenItRuns, openWithSample } from './steps';
import { synthSubjects } from './synth';

const body = (page: Page) => page.locator('body');
const row = (page: Page, name: string) => page.getByTestId('landmark-list').locator(`li[data-name="${name}"]`);

/** `x,y,z` of a row's `data-position-mm`. */
async function positionMm(page: Page, name: string): Promise<number[]> {
  return (await row(page, name).getAttribute('data-position-mm'))!.split(',').map(Number);
}

/** Picks `name` in the list and returns where its marker is drawn, in page px. */
async function pickMarker(page: Page, name: string): Promise<{ x: number; y: number }> {
  await row(page, name).click();
  await expect(body(page)).toHaveAttribute('data-selected-landmark', name);
  const [x, y] = (await body(page).getAttribute('data-selected-marker-px'))!.split(',').map(Number);
  const canvas = (await page.getByTestId('viewport-canvas').boundingBox())!;
  return { x: canvas.x + x!, y: canvas.y + y! };
}

/** The `.lnd` text as `{name: [x, y, z] | null}` (null for −999), and its number of landmark lines. */
function parseLnd(text: string): { count: number; at: Map<string, number[] | null> } {
  const at = new Map<string, number[] | null>();
  const body = text.split(/\r?\n/);
  const start = body.indexOf('AUX =') + 1;
  const end = body.indexOf('END =');
  for (const line of body.slice(start, end)) {
    const f = line.trim().split(/\s+/);
    const name = f.slice(7).join(' ');
    at.set(name, f[1] === '-999' ? null : f.slice(4, 7).map(Number));
  }
  return { count: end - start, at };
}

/**
 * Clicks Align, waits for the fit and checks its scan→template RMS lies in `rmsRange` (mm); then
 * exports the landmarks as .lnd and returns the file's name and its parsed content.
 */
async function alignThenExportLnd(page: Page, rmsRange: [number, number]): Promise<{ fileName: string } & ReturnType<typeof parseLnd>> {
  await page.getByTestId('align-run').click();
  await expect(body(page)).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
  const rms = Number(await page.getByTestId('align-rms').getAttribute('data-rms-mm'));
  expect(rms).toBeGreaterThan(rmsRange[0]);
  expect(rms).toBeLessThan(rmsRange[1]);
  const download = page.waitForEvent('download');
  await page.getByTestId('landmarks-export-lnd').click();
  const file = await download;
  return { fileName: file.suggestedFilename(), ...parseLnd(readFileSync((await file.path())!, 'latin1')) };
}

/** The sample's true landmarks (`landmarks_001.csv`, millimetres) by name. */
function truth(): Map<string, number[]> {
  const [, ...lines] = sampleFile('landmarks_001.csv').bytes.toString('utf8').trim().split('\n');
  return new Map(
    lines.map((line) => {
      const m = /^(?:"([^"]*)"|([^,]*)),(.*)$/.exec(line.trim())!;
      return [m[1] ?? m[2]!, m[3]!.split(',').map(Number)];
    }),
  );
}

test('a scan without landmarks gets an estimate; move one by clicking, align, export the .lnd', async ({ page }) => {
  test.setTimeout(300_000);
  await openWithSample(page, [sampleFile('scan_001.ply.gz')]);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  // The sample is z-up, facing −y, in millimetres: the panel says what was assumed.
  await expect(page.getByTestId('estimate-assumed')).toContainText("up is the scan's +z axis");
  await expect(page.getByTestId('estimate-assumed')).toContainText('faces -y');
  await expect(page.getByTestId('estimate-assumed')).toContainText('millimetres (detected)');
  const estimated = page.getByTestId('landmark-list').locator('li[data-state="estimated"]');
  await expect(estimated).toHaveCount(73);
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-markers', '73');
  // Each row's tooltip says how sharply its landmark is defined, which its confidence takes in.
  await expect(row(page, 'Waist, Preferred, Post.')).toHaveAttribute('data-sharpness', 'level');
  await expect(row(page, 'Waist, Preferred, Post.')).toHaveAttribute('title', /confidence \d+ %; defined as a level/);
  await expect(row(page, 'Sellion')).toHaveAttribute('data-sharpness', 'point');

  // The estimate against the sample's true landmarks (which the page never saw).
  const truePositions = truth();
  const errors: number[] = [];
  for (const [name, p] of truePositions) {
    const q = await positionMm(page, name);
    errors.push(Math.hypot(...q.map((v, i) => v - p[i]!)));
  }
  const mean = errors.reduce((a, b) => a + b, 0) / errors.length;
  // 18.3 mm mean, 38 mm worst on 2026-11-24 (the browser worker took 4.0 s).
  expect(mean).toBeLessThan(25);

  // The warp ran with the estimated set; move Substernale by clicking beside its marker.
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  const before = await positionMm(page, 'Substernale');
  const marker = await pickMarker(page, 'Substernale');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  expect(Math.hypot(...moved.map((v, i) => v - before[i]!))).toBeGreaterThan(1);
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });

  // Align: 1.01 mm RMS on 2026-11-24; 0.92 mm with the sample's true landmarks (rbf-align.spec.ts).
  const lnd = await alignThenExportLnd(page, [0.7, 1.3]);
  expect(lnd.count).toBe(73);
  expect([...lnd.at.values()].filter((p) => p === null)).toHaveLength(0);
  lnd.at.get('Substernale')!.forEach((v, i) => expect(v).toBeCloseTo(moved[i]!, 2));
});

test('edit a partial landmark set on the scan, align with it and export it as .lnd', async ({ page }) => {
  test.setTimeout(300_000);
  // Every second landmark of the sample's 73 (37 given), as a file clicked by hand might hold: the
  // estimate fills in the other 36 by itself.
  await openWithSample(page, [sampleFile('scan_001.ply.gz'), partialCsv((_, i) => i % 2 === 0)]);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await expect(page.getByTestId('landmark-list').locator('li[data-state="given"]')).toHaveCount(37);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="estimated"]')).toHaveCount(36);

  // Hovering a landmark in the list rings it on the template.
  await row(page, 'Substernale').hover();
  await expect(page.getByTestId('template-guide')).toHaveAttribute('data-landmark', 'Substernale');

  // Pick Substernale and click on the scan a little beside its marker: it moves there.
  const before = await positionMm(page, 'Substernale');
  const marker = await pickMarker(page, 'Substernale');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  const shift = Math.hypot(...moved.map((v, i) => v - before[i]!));
  expect(shift).toBeGreaterThan(1);
  expect(shift).toBeLessThan(80);
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });

  // Undo and redo, by keyboard.
  await page.keyboard.press('Control+z');
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'given');
  expect(await positionMm(page, 'Substernale')).toEqual(before);
  await page.keyboard.press('Control+Shift+z');
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  expect(await positionMm(page, 'Substernale')).toEqual(moved);

  // Drag the Rt. Thelion marker along the surface: one undo step takes the whole drag back.
  const DRAGGED = 'Rt. Thelion/Bustpoint';
  const draggedFrom = await positionMm(page, DRAGGED);
  const dragged = await pickMarker(page, DRAGGED);
  await page.mouse.move(dragged.x, dragged.y);
  await page.mouse.down();
  for (let k = 1; k <= 5; k++) await page.mouse.move(dragged.x + 2 * k, dragged.y - 3 * k);
  await page.mouse.up();
  await expect(row(page, DRAGGED)).toHaveAttribute('data-state', 'edited');
  expect(await positionMm(page, DRAGGED)).not.toEqual(draggedFrom);
  await page.getByTestId('landmarks-undo').click();
  await expect(row(page, DRAGGED)).toHaveAttribute('data-state', 'given');
  expect(await positionMm(page, DRAGGED)).toEqual(draggedFrom);

  // Mark one absent: the warp goes without it.
  await row(page, 'Rt. Radial Styloid').click();
  await page.getByTestId('landmarks-absent').click();
  await expect(row(page, 'Rt. Radial Styloid')).toHaveAttribute('data-state', 'absent');
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await expect(page.getByTestId('rbf-skipped')).toContainText('Rt. Radial Styloid');

  // Align with the edited set: with the full file this sample fits to 0.92 mm RMS
  // (rbf-align.spec.ts); with half the landmarks given, the rest estimated and one moved, 1.04 mm
  // on 2026-11-24. Then export as .lnd: 73 lines in CAESAR order, −999 for the absent one, the
  // moved one where it is now.
  const lnd = await alignThenExportLnd(page, [0.7, 1.3]);
  expect(lnd.fileName).toBe('scan_001-landmarks.lnd');
  expect(lnd.count).toBe(73);
  expect([...lnd.at.values()].filter((p) => p === null)).toHaveLength(1);
  expect(lnd.at.get('Rt. Radial Styloid')).toBeNull();
  const written = lnd.at.get('Substernale')!;
  written.forEach((v, i) => expect(v).toBeCloseTo(moved[i]!, 2));

  // Editing after the alignment invalidates the fit, as a new file does.
  await row(page, 'Rt. Radial Styloid').click();
  await page.keyboard.press('Control+z');
  await expect(row(page, 'Rt. Radial Styloid')).toHaveAttribute('data-state', 'given');
  await expect(body(page)).toHaveAttribute('data-align-state', 'idle');
  await expect(page.locator('#viewport')).not.toHaveAttribute('data-fitted-vertices', /[1-9]/);
});

test('a partial file of 10 landmarks is filled in by the estimate and never moved; a nearly full one is only checked', async ({ page }) => {
  test.setTimeout(300_000);
  // Ten landmarks a person might click by hand, spread over the body.
  const HAND_PICKED = [
    'Sellion', 'Suprasternale', 'Rt. Acromion', 'Lt. Acromion', 'Rt. Radial Styloid',
    'Lt. Radial Styloid', 'Rt. ASIS', 'Lt. ASIS', 'Rt. Lateral Malleolus', 'Lt. Lateral Malleolus',
  ];
  const file = truth();
  await openWithSample(page, [sampleFile('scan_001.ply.gz'), partialCsv((name) => HAND_PICKED.includes(name))]);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  await expect(page.getByTestId('landmark-list').locator('li[data-state="given"]')).toHaveCount(10);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="estimated"]')).toHaveCount(63);
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-markers', '73');
  // The given ones are where the file put them, to the micrometre (the list shows 3 decimals of mm).
  for (const name of HAND_PICKED) {
    await expect(row(page, name)).toHaveAttribute('data-state', 'given');
    (await positionMm(page, name)).forEach((v, i) => expect(Math.abs(v - file.get(name)![i]!)).toBeLessThan(0.002));
  }
  // The estimated ones against the sample's true landmarks, which the page never saw.
  const errors: number[] = [];
  for (const [name, p] of file) {
    if (HAND_PICKED.includes(name)) continue;
    const q = await positionMm(page, name);
    errors.push(Math.hypot(...q.map((v, i) => v - p[i]!)));
  }
  expect(errors).toHaveLength(63);
  expect(errors.reduce((a, b) => a + b, 0) / errors.length).toBeLessThan(25);

  // A CAESAR file missing two landmarks is nearly full: checked, not filled in (the warp runs
  // without the two; "Estimate" would fill them in).
  const MISSING = ['Rt. Gonion', 'Lt. Dactylion'];
  await dropFiles(page, [partialCsv((name) => !MISSING.includes(name))]);
  await waitForLoads(page, 2);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="given"]')).toHaveCount(71);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="absent"]')).toHaveCount(2);
  await expect(body(page)).toHaveAttribute('data-suspicious-state', 'done', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'none');
  await expect(page.getByTestId('landmarks-suspicious-none')).toBeVisible();
  // The right acromion clicked next to the left one: the edit is checked against the first check's
  // prediction and flagged, with its distance; the set is not filled in.
  const left = await pickMarker(page, 'Lt. Acromion');
  await row(page, 'Rt. Acromion').click();
  await page.mouse.click(left.x, left.y + 12);
  await expect(row(page, 'Rt. Acromion')).toHaveAttribute('data-state', 'edited');
  const flagged = page.getByTestId('landmarks-suspicious').locator('li[data-name="Rt. Acromion"]');
  await expect(flagged).toBeVisible({ timeout: 60_000 });
  expect(parseFloat((await flagged.locator('.distance').textContent())!)).toBeGreaterThan(200);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="absent"]')).toHaveCount(2);
});

test('the edited set survives a trap of the alignment worker and a failed landmark file', async ({ page }) => {
  test.setTimeout(180_000);
  await page.goto('./?debug');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await dropFiles(page, [sampleFile('scan_001.ply.gz'), sampleFile('landmarks_001.csv')]);
  await waitForLoads(page, 1);
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  const marker = await pickMarker(page, 'Suprasternale');
  await page.mouse.click(marker.x - 8, marker.y + 6);
  await expect(row(page, 'Suprasternale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Suprasternale');
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });

  // The trap resolves once the worker has been replaced.
  await page.evaluate(() => (window as unknown as { bodyspaceDebug: { trap: (w: string) => Promise<void> } }).bodyspaceDebug.trap('align'));
  await dropFiles(page, [{ name: 'broken.csv', bytes: Buffer.from('name,x,y,z\nSellion,1,2\n') }]);
  await waitForLoads(page, 2);
  await expect(page.getByTestId('error-text')).toContainText('broken.csv');

  await expect(row(page, 'Suprasternale')).toHaveAttribute('data-state', 'edited');
  expect(await positionMm(page, 'Suprasternale')).toEqual(moved);
  // The replaced worker warps with the edited set.
  await page.getByTestId('rbf-run').click();
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
});

test('a failed estimate says why and keeps the scan; a cancelled one can be run again', async ({ page }) => {
  test.setTimeout(180_000);
  // A sliver of a triangle is no body: the core finds nothing to fit, and the scan stays.
  const ply = ['ply', 'format ascii 1.0', 'element vertex 3', 'property float x', 'property float y', 'property float z'];
  ply.push('element face 1', 'property list uchar int vertex_indices', 'end_header', '0 0 0', '0 0 0', '0 1700 0', '3 0 1 2', '');
  await openWithSample(page, [{ name: 'sliver.ply', bytes: Buffer.from(ply.join('\n')) }]);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'error', { timeout: 60_000 });
  await expect(page.getByTestId('estimate-error')).toContainText('is this a whole body?');
  await expect(page.getByTestId('error-text')).toContainText('Landmark estimate');
  await expect(body(page)).toHaveAttribute('data-scan-loaded', 'true');
  await expect(page.getByTestId('scan-vertices')).toHaveText('3');

  // A body scan, its estimate cancelled at once: the scan stays, and Estimate runs again.
  await cancelEstimateWhenItRuns(page);
  await dropFiles(page, [sampleFile('scan_001.ply.gz')]);
  await waitForLoads(page, 2);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'cancelled', { timeout: 60_000 });
  await expect(page.getByTestId('scan-vertices')).toHaveText('47,375');
  await page.getByTestId('landmarks-estimate').click();
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  await expect(page.getByTestId('landmark-list').locator('li[data-state="estimated"]')).toHaveCount(73);
});

test('changing the scan units carries the placed landmarks and those that follow the scan', async ({ page }) => {
  test.setTimeout(120_000);
  await openWithSample(page);
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  const marker = await pickMarker(page, 'Substernale');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  const given = await positionMm(page, 'Sellion');

  // Read as metres, the scan is 1000 times larger: so are the clicked point and the CSV's landmarks.
  await page.getByTestId('scan-units').selectOption('metres');
  await expect(body(page)).toHaveAttribute('data-scan-units', 'metres');
  (await positionMm(page, 'Substernale')).forEach((v, i) => expect(v).toBeCloseTo(moved[i]! * 1000, 1));
  (await positionMm(page, 'Sellion')).forEach((v, i) => expect(v).toBeCloseTo(given[i]! * 1000, 1));
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
});

test('before any file nothing is absent; after Align a picked landmark shows the scan and a click places it; a new scan forgets the pick', async ({ page }) => {
  test.setTimeout(300_000);
  await page.goto('./');
  await expect(body(page)).toHaveAttribute('data-core-ready', 'true', { timeout: 60_000 });
  // No set yet: the 73 names are listed, none marked absent.
  await expect(page.getByTestId('landmark-list').locator('li')).toHaveCount(73);
  await expect(page.getByTestId('landmark-list').locator('li[data-status="missing"]')).toHaveCount(0);
  await expect(page.getByTestId('landmark-list')).not.toContainText('✗');

  const [landmarks, scan] = synthSubjects(1, 21);
  await openWithSample(page, [scan!, landmarks!]);
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await page.getByTestId('align-run').click();
  await expect(body(page)).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
  // The fit's heat map hides the scan ...
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-visible', 'false');
  // ... and picking a landmark to place brings it back, so the click the hint asks for lands on it.
  const before = await positionMm(page, 'Substernale');
  const marker = await pickMarker(page, 'Substernale');
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-visible', 'true');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  expect(Math.hypot(...moved.map((v, i) => v - before[i]!))).toBeGreaterThan(1);

  // The list scrolled to the last landmark and it picked: a new scan starts at the top, nothing picked.
  await row(page, 'Crotch').click();
  await expect(body(page)).toHaveAttribute('data-selected-landmark', 'Crotch');
  const scrolled = await page.getByTestId('landmark-list').evaluate((list) => {
    list.scrollTop = list.scrollHeight;
    return list.scrollTop;
  });
  expect(scrolled).toBeGreaterThan(0);
  const [landmarks2, scan2] = synthSubjects(1, 22);
  await dropFiles(page, [scan2!, landmarks2!]);
  await waitForLoads(page, 2);
  await expect(body(page)).toHaveAttribute('data-selected-landmark', '');
  await expect(page.getByTestId('landmark-list').locator('li[data-selected="true"]')).toHaveCount(0);
  expect(await page.getByTestId('landmark-list').evaluate((list) => list.scrollTop)).toBe(0);
});

test("a second scan opened alone gets its own estimate; the first one's landmarks, or a set a file replaced, are put aside and come back", async ({ page }) => {
  test.setTimeout(300_000);
  const FIVE = ['Sellion', 'Rt. Acromion', 'Lt. Acromion', 'Rt. Lateral Malleolus', 'Lt. Lateral Malleolus'];
  // A landmark file opened with no scan shown waits for the next scan, and goes with it.
  await openWithSample(page, [partialCsv((name) => FIVE.includes(name))]);
  await dropFiles(page, [sampleFile('scan_001.ply.gz')]);
  await waitForLoads(page, 2);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  await expect(page.getByTestId('landmark-list').locator('li[data-state="given"]')).toHaveCount(5);
  await expect(page.getByTestId('landmarks-put-aside')).toHaveCount(0);
  // One landmark moved by hand: work the next scan must not take, nor lose.
  const marker = await pickMarker(page, 'Substernale');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  const list = page.getByTestId('landmark-list');

  // Another person's scan, dropped alone: its landmarks are estimated on it, none carried over.
  const [lnd, scan] = synthSubjects(1, 22, 10);
  const other = { name: 'other.ply', bytes: scan!.bytes };
  await dropFiles(page, [other]);
  await waitForLoads(page, 3);
  await expect(body(page)).toHaveAttribute('data-estimates', '2', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done');
  await expect(list.locator('li[data-state="estimated"]')).toHaveCount(73);
  const truth = parseLnd(lnd!.bytes.toString('latin1')).at;
  const errors: number[] = [];
  for (const [name, p] of truth) {
    if (!p) continue;
    const q = await positionMm(page, name);
    errors.push(Math.hypot(...q.map((v, i) => v - p[i]!)));
  }
  expect(errors.length).toBeGreaterThan(60);
  expect(errors.reduce((a, b) => a + b, 0) / errors.length).toBeLessThan(25);
  const aside = page.getByTestId('landmarks-put-aside');
  await expect(aside).toHaveText(
    'scan_001.ply.gz is put aside with its 73 landmarks (5 from partial.csv, 67 estimated, 1 placed by hand): they stay with it, not with other.ply.',
  );

  // Back to the first: its set as it was, the estimate's verdict with it, no new estimate.
  await page.getByTestId('landmarks-back').click();
  await expect(page.getByTestId('scan-file')).toHaveText('scan_001.ply.gz');
  await expect(list.locator('li[data-state="given"]')).toHaveCount(5);
  await expect(list.locator('li[data-state="edited"]')).toHaveCount(1);
  await expect(list.locator('li[data-state="estimated"]')).toHaveCount(67);
  expect(await positionMm(page, 'Substernale')).toEqual(moved);
  await expect(page.getByTestId('estimate-assumed')).toBeVisible();
  await expect(aside).toContainText('other.ply is put aside with its 73 landmarks (73 estimated)');
  await expect(body(page)).toHaveAttribute('data-estimates', '2');
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });

  // A landmark file named for a scan goes with that scan when it is opened alone after it (the
  // core's pairing of a batch's files), even though it was dropped onto the first one.
  await dropFiles(page, [{ name: 'other.lnd', bytes: lnd!.bytes }]);
  await waitForLoads(page, 4);
  await expect(list.locator('li[data-state="given"]')).toHaveCount(73);
  // The set it replaced is put aside too, and comes back.
  await expect(aside.first()).toHaveText('Another set of landmarks for this scan is put aside (73: 5 from partial.csv, 67 estimated, 1 placed by hand).');
  // The scan put aside before stays put aside, under it.
  await expect(aside.nth(1)).toContainText('other.ply is put aside with its 73 landmarks (73 estimated)');
  await page.getByTestId('landmarks-back').first().click();
  await expect(list.locator('li[data-state="edited"]')).toHaveCount(1);
  expect(await positionMm(page, 'Substernale')).toEqual(moved);
  await expect(aside.first()).toHaveText('Another set of landmarks for this scan is put aside (73: 73 from other.lnd).');
  await page.getByTestId('landmarks-back').first().click();
  await expect(list.locator('li[data-state="given"]')).toHaveCount(73);
  await dropFiles(page, [other]);
  await waitForLoads(page, 5);
  await expect(page.getByTestId('scan-file')).toHaveText('other.ply');
  await expect(list.locator('li[data-state="given"]')).toHaveCount(73);
  await expect(body(page)).toHaveAttribute('data-estimates', '2');
  await expect(aside.first()).toContainText('scan_001.ply.gz is put aside with its 73 landmarks (73 from other.lnd)');
  // Everything put aside is kept, the older ones folded away.
  await expect(aside).toHaveCount(3);
  await expect(page.getByTestId('landmarks-put-aside-more')).toContainText('1 more put aside');
});

test('a reload brings back the scan, its landmark file and the set as it was edited, without estimating again', async ({ page }) => {
  test.setTimeout(300_000);
  const FIVE = ['Sellion', 'Rt. Acromion', 'Lt. Acromion', 'Rt. Lateral Malleolus', 'Lt. Lateral Malleolus'];
  await openWithSample(page, [sampleFile('scan_001.ply.gz'), partialCsv((name) => FIVE.includes(name))]);
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
  const marker = await pickMarker(page, 'Substernale');
  // The work is saved once the changes pause: the first save after the move has it.
  const saves = Number((await body(page).getAttribute('data-work-saves')) ?? '0');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  const gonion = await positionMm(page, 'Rt. Gonion');
  const assumed = await page.getByTestId('estimate-assumed').textContent();
  await page.waitForFunction((n) => Number(document.body.dataset.workSaves ?? '0') > n, saves);
  await page.reload();
  await expect(body(page)).toHaveAttribute('data-restored', 'true', { timeout: 60_000 });
  await expect(page.getByTestId('scan-file')).toHaveText('scan_001.ply.gz');
  await expect(page.getByTestId('landmarks-file')).toHaveText('partial.csv');
  const list = page.getByTestId('landmark-list');
  await expect(list.locator('li[data-state="given"]')).toHaveCount(5);
  await expect(list.locator('li[data-state="edited"]')).toHaveCount(1);
  await expect(list.locator('li[data-state="estimated"]')).toHaveCount(67);
  expect(await positionMm(page, 'Substernale')).toEqual(moved);
  expect(await positionMm(page, 'Rt. Gonion')).toEqual(gonion);
  // The estimate's words as they were, and no estimate ran again.
  await expect(page.getByTestId('estimate-assumed')).toHaveText(assumed!);
  await expect(body(page)).not.toHaveAttribute('data-estimates', /./);
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
});

test('a reload brings back the work put aside, "Back to" still swaps it, and Forget asks first', async ({ page }) => {
  test.setTimeout(180_000);
  const list = page.getByTestId('landmark-list');
  const aside = page.getByTestId('landmarks-put-aside');
  /** Reloads once the work is saved after what was just done, and waits for it to be restored. */
  const reloadSaved = async () => {
    const saves = Number((await body(page).getAttribute('data-work-saves')) ?? '0');
    await page.waitForFunction((n) => Number(document.body.dataset.workSaves ?? '0') > n, saves);
    await page.reload();
    await expect(body(page)).toHaveAttribute('data-restored', 'true', { timeout: 60_000 });
  };
  // Full files, so nothing is estimated: the first scan's set with one landmark moved by hand.
  await openWithSample(page, [sampleFile('scan_001.ply.gz'), partialCsv(() => true)]);
  await expect(list.locator('li[data-state="given"]')).toHaveCount(73);
  const marker = await pickMarker(page, 'Substernale');
  await page.mouse.click(marker.x + 9, marker.y + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const moved = await positionMm(page, 'Substernale');
  const [lnd, scan] = synthSubjects(1, 22);
  await dropFiles(page, [{ name: 'other.ply', bytes: scan!.bytes }, { name: 'other.lnd', bytes: lnd!.bytes }]);
  await waitForLoads(page, 2);
  const firstAside = 'scan_001.ply.gz is put aside with its 73 landmarks (72 from partial.csv, 1 placed by hand): they stay with it, not with other.ply.';
  await expect(aside).toHaveText([firstAside]);

  // The reload shows the second scan and keeps the first aside, its hand-placed landmark with it.
  await reloadSaved();
  await expect(page.getByTestId('scan-file')).toHaveText('other.ply');
  await expect(list.locator('li[data-state="given"]')).toHaveCount(73);
  await expect(aside).toHaveText([firstAside]);
  await expect(body(page)).not.toHaveAttribute('data-estimates', /./);
  await page.getByTestId('landmarks-back').click();
  await expect(page.getByTestId('scan-file')).toHaveText('scan_001.ply.gz');
  await expect(list.locator('li[data-state="edited"]')).toHaveCount(1);
  expect(await positionMm(page, 'Substernale')).toEqual(moved);
  const otherAside = 'other.ply is put aside with its 73 landmarks (73 from other.lnd): they stay with it, not with scan_001.ply.gz.';
  await expect(aside).toHaveText([otherAside]);

  // A landmark file dropped onto the scan puts its set aside: after a reload it comes back too.
  await dropFiles(page, [{ name: 'other.lnd', bytes: lnd!.bytes }]);
  const otherSet = 'Another set of landmarks for this scan is put aside (73: 72 from partial.csv, 1 placed by hand).';
  await expect(aside).toHaveText([otherSet, otherAside]);
  await reloadSaved();
  await expect(page.getByTestId('scan-file')).toHaveText('scan_001.ply.gz');
  await expect(page.getByTestId('landmarks-file')).toHaveText('other.lnd');
  await expect(aside).toHaveText([otherSet, otherAside]);
  await page.getByTestId('landmarks-back').first().click();
  await expect(page.getByTestId('landmarks-file')).toHaveText('partial.csv');
  await expect(list.locator('li[data-state="edited"]')).toHaveCount(1);
  expect(await positionMm(page, 'Substernale')).toEqual(moved);
  await expect(body(page)).not.toHaveAttribute('data-estimates', /./);
  await expect(aside).toHaveText(['Another set of landmarks for this scan is put aside (73: 73 from other.lnd).', otherAside]);

  // Forget asks first, naming what goes; declined, nothing goes; accepted, it is gone after a reload too.
  const questions: string[] = [];
  page.once('dialog', (dialog) => void (questions.push(dialog.message()), dialog.dismiss()));
  await page.getByTestId('landmarks-forget').nth(1).click();
  await expect.poll(() => questions.length).toBe(1);
  expect(questions[0]).toBe("Forget other.ply and its landmarks? Its 73 landmarks (73 from other.lnd) are forgotten here and in this browser's storage; this cannot be undone.");
  await expect(aside).toHaveCount(2);
  page.once('dialog', (dialog) => void dialog.accept());
  await page.getByTestId('landmarks-forget').nth(1).click();
  await expect(aside).toHaveText(['Another set of landmarks for this scan is put aside (73: 73 from other.lnd).']);
  await reloadSaved();
  await expect(page.getByTestId('scan-file')).toHaveText('scan_001.ply.gz');
  await expect(list.locator('li[data-state="edited"]')).toHaveCount(1);
  await expect(aside).toHaveText(['Another set of landmarks for this scan is put aside (73: 73 from other.lnd).']);
  // Its scan no longer takes room in the browser's storage: one record per file still used
  // (scan_001.ply.gz, partial.csv, other.lnd).
  expect((await storedKeys(page)).filter((k) => k.startsWith('file:'))).toHaveLength(3);
});

/** The keys of the records of the single scan's work in the browser's storage. */
async function storedKeys(page: Page): Promise<string[]> {
  return page.evaluate(
    () =>
      new Promise<string[]>((resolve, reject) => {
        const r = indexedDB.open('bodyspace-session', 1);
        r.onsuccess = () => {
          const keys = r.result.transaction('work').objectStore('work').getAllKeys();
          keys.onsuccess = () => resolve(keys.result.map(String));
          keys.onerror = () => reject(keys.error);
        };
        r.onerror = () => reject(r.error);
      }),
  );
}

test('work saved before the work put aside was kept (one scan) still opens after the update', async ({ page }) => {
  test.setTimeout(120_000);
  const [lnd, scan] = synthSubjects(1, 22);
  await page.goto('./');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  // The records as the page wrote them until 2026-12-06: the shown scan's files and its state.
  await page.evaluate(
    async ([scanBytes, lndBytes]) => {
      const db = await new Promise<IDBDatabase>((resolve, reject) => {
        const r = indexedDB.open('bodyspace-session', 1);
        r.onupgradeneeded = () => r.result.createObjectStore('work', { keyPath: 'key' });
        r.onsuccess = () => resolve(r.result);
        r.onerror = () => reject(r.error);
      });
      const tx = db.transaction('work', 'readwrite');
      const store = tx.objectStore('work');
      store.put({ key: 'files', scan: new File([new Uint8Array(scanBytes!)], 'old.ply'), landmarks: new File([new Uint8Array(lndBytes!)], 'old.lnd') });
      store.put({ key: 'current', landmarksFor: 'old.ply', scanUnits: 'metres', orientation: null, entries: [], estimateReport: null, view: null });
      await new Promise((resolve) => (tx.oncomplete = resolve));
    },
    [[...scan!.bytes], [...lnd!.bytes]],
  );
  await page.reload();
  await expect(body(page)).toHaveAttribute('data-restored', 'true', { timeout: 60_000 });
  await expect(page.getByTestId('scan-file')).toHaveText('old.ply');
  await expect(page.getByTestId('landmarks-file')).toHaveText('old.lnd');
  await expect(page.getByTestId('landmarks-put-aside')).toHaveCount(0);
  // The save after the restore writes the new layout and drops the old one's record of the files.
  await page.waitForFunction(() => Number(document.body.dataset.workSaves ?? '0') > 0);
  const keys = await storedKeys(page);
  expect(keys).not.toContain('files');
  expect(keys.filter((k) => k.startsWith('file:'))).toHaveLength(2);
});
