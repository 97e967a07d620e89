// The batch in the browser: six synthetic subjects, a scan without landmarks (its landmarks are
// estimated) and two broken scans dropped at once are aligned by the worker pool (the broken ones
// said in the banner, not aligned), survive a reload, and make a model; Clear batch asks first; a
// reload in the middle of a batch resumes it by itself; a worker whose core traps mid-batch, or a
// cancelled one, leaves the others and the shape model alone; what a drop leaves out (a second
// scan of a subject, the ground truths of `bodyspace synth`) is said and not aligned.
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { shapeReady } from './steps';
import { synthFolder, synthSubjects } from './synth';

const body = (page: Page) => page.locator('body');
const row = (page: Page, subject: string) => page.locator(`[data-testid="batch-row"][data-subject="${subject}"]`);

async function openApp(page: Page): Promise<void> {
  await page.goto('./?debug');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await shapeReady(page);
}

/** At most `n` subjects aligned at once (`?debug`). */
async function setBatchWorkers(page: Page, n: number | null): Promise<void> {
  await page.evaluate((k) => (window as unknown as { bodyspaceDebug: { setBatchWorkers: (n: number | null) => void } }).bodyspaceDebug.setBatchWorkers(k), n);
}

/** Clicks `testid`, declines the question it asks and returns the question. */
async function declined(page: Page, testid: string): Promise<string> {
  const asked = new Promise<string>((resolve) =>
    page.once('dialog', (dialog) => {
      resolve(dialog.message());
      void dialog.dismiss();
    }),
  );
  await page.getByTestId(testid).click();
  return asked;
}

async function waitForBatch(page: Page, total: number): Promise<void> {
  await expect(body(page)).toHaveAttribute('data-batch-total', String(total));
  await expect(body(page)).toHaveAttribute('data-batch-finished', String(total), { timeout: 300_000 });
}

test('six subjects dropped at once are aligned, come back after a reload and build a model', async ({ page }) => {
  test.setTimeout(420_000);
  const files = synthSubjects(7, 13);
  // Subject 7 comes without its landmarks; a broken scan comes with subject 1's, and a second one alone.
  const broken = { name: 'broken.ply', bytes: Buffer.from('ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n') };
  const brokenLandmarks = { name: 'broken.lnd', bytes: files.find((f) => f.name === 'landmarks_001.lnd')!.bytes };
  const broken2 = { name: 'garbled.stl', bytes: Buffer.from('solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n') };
  const dropped = [...files.filter((f) => f.name !== 'landmarks_007.lnd'), broken, brokenLandmarks, broken2];
  await openApp(page);
  await dropFiles(page, dropped);
  await waitForLoads(page, 1);
  // The files that cannot be read leave the batch: the banner names both, as it does for one file.
  await expect(body(page)).toHaveAttribute('data-batch-finished', '7', { timeout: 300_000 });
  await waitForBatch(page, 7);
  await expect(row(page, 'broken')).toHaveCount(0);
  await expect(row(page, 'garbled')).toHaveCount(0);
  await expect(page.getByTestId('error-banner')).toContainText('broken.ply');
  await expect(page.getByTestId('error-banner')).toContainText('garbled.stl');
  await expect(page.getByTestId('error-banner')).toContainText('left out of the batch');
  await expect(page.getByTestId('batch-summary')).toHaveText(/^7 of 7 finished,/);
  expect(Number(await body(page).getAttribute('data-batch-workers'))).toBeGreaterThanOrEqual(1);

  const subjects = ['scan_001', 'scan_002', 'scan_003', 'scan_004', 'scan_005', 'scan_006', 'scan_007'];
  const before: Record<string, { status: string; rms: string }> = {};
  for (const s of subjects) {
    const status = (await row(page, s).getAttribute('data-status'))!;
    expect(['ok', 'flagged']).toContain(status);
    const rms = await row(page, s).getByTestId('batch-rms').innerText();
    // A fit of a 20 mm-step scan with 1 mm noise: a few millimetres at most.
    expect(Number(rms)).toBeGreaterThan(0);
    expect(Number(rms)).toBeLessThan(10);
    before[s] = { status, rms };
  }

  // Sorting by RMS puts the rows in RMS order, and again the other way.
  await page.getByTestId('batch-sort-rms').click();
  const sorted = await page.locator('[data-testid="batch-row"]').evaluateAll((rows) => rows.map((r) => r.getAttribute('data-subject')!));
  const shown = sorted.map((s) => Number(before[s]!.rms));
  expect(shown).toEqual([...shown].sort((a, b) => a - b));
  await page.getByTestId('batch-sort-rms').click();
  const descending = await page.locator('[data-testid="batch-row"]').evaluateAll((rows) => rows.map((r) => r.getAttribute('data-subject')!));
  expect(descending).toEqual([...sorted].reverse());

  // A click on a row shows that fit with its heat map.
  await row(page, 'scan_003').click();
  await expect(body(page)).toHaveAttribute('data-batch-shown', 'scan_003');
  await expect(page.locator('#viewport')).toHaveAttribute('data-fitted-coloured', 'true');
  await expect(page.getByTestId('batch-panel').getByTestId('heat-legend')).toBeVisible();

  // Excluding one leaves six for the model.
  await row(page, 'scan_006').getByTestId('batch-exclude').click();
  await expect(row(page, 'scan_006')).toHaveAttribute('data-status', 'excluded');
  // Every change is in the browser's storage before the reload (until then the page asks first).
  await expect(body(page)).toHaveAttribute('data-batch-saving', '0');

  await page.reload();
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await expect(body(page)).toHaveAttribute('data-batch-total', '7');
  for (const s of subjects.filter((s) => s !== 'scan_006')) {
    await expect(row(page, s)).toHaveAttribute('data-status', before[s]!.status);
    await expect(row(page, s).getByTestId('batch-rms')).toHaveText(before[s]!.rms);
  }
  await expect(row(page, 'scan_006')).toHaveAttribute('data-status', 'excluded');
  // Subject 7's landmarks were estimated: its row counts the measurements not to trust and names
  // them in words (the core's `measurement_trust`, kept through the reload); a subject with its
  // landmark file has fewer.
  const doubtful7 = row(page, 'scan_007').getByTestId('batch-doubtful');
  await expect(doubtful7).toHaveText(/^\d+ doubtful$/);
  const count = async (s: string) => {
    const note = row(page, s).getByTestId('batch-doubtful');
    return (await note.count()) ? parseInt(await note.innerText(), 10) : 0;
  };
  expect(await count('scan_007')).toBeGreaterThanOrEqual(5);
  expect(await doubtful7.getAttribute('title')).toMatch(/shoulder breadth \(biacromial\): from the estimated Rt\. Acromion/);
  expect(await count('scan_001')).toBeLessThan(await count('scan_007'));

  await shapeReady(page);
  await page.getByTestId('batch-build').click();
  await expect(page.getByTestId('batch-build-status')).toHaveText('Built from 6 subjects.', { timeout: 120_000 });
  await expect(page.getByTestId('shape-model-name')).not.toHaveText('models/demo.bsm');
  await expect(page.getByTestId('shape-panel')).toContainText('6 subjects');
  await shapeReady(page);

  // Clear batch asks first: declined, nothing goes; accepted, the batch goes.
  expect(await declined(page, 'batch-clear')).toContain('Clear the batch? Its 7 subjects and 7 fits are forgotten');
  await expect(body(page)).toHaveAttribute('data-batch-total', '7');
  page.once('dialog', (dialog) => void dialog.accept());
  await page.getByTestId('batch-clear').click();
  await expect(body(page)).toHaveAttribute('data-batch-total', '0');
  await page.reload();
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await expect(page.getByTestId('batch-panel')).toBeHidden();
});

test('a trapped or cancelled batch worker leaves the other subjects and the shape model alone', async ({ page }) => {
  test.setTimeout(420_000);
  await openApp(page);
  const model = await page.getByTestId('shape-model-name').innerText();
  const stature = await page.getByTestId('measure-stature').innerText();
  // The first job to start traps its worker's core, as a bug in the core would.
  await page.evaluate(() => (window as unknown as { bodyspaceDebug: { trap: (w: string) => void } }).bodyspaceDebug.trap('batch'));
  // Cancel scan_004 as soon as it aligns.
  await page.evaluate(() => {
    new MutationObserver((_, observer) => {
      const r = document.querySelector('[data-testid="batch-row"][data-subject="scan_004"][data-status="aligning"]');
      if (!r) return;
      observer.disconnect();
      r.querySelector<HTMLButtonElement>('[data-testid="batch-cancel"]')!.click();
    }).observe(document.body, { subtree: true, childList: true, attributes: true });
  });
  await dropFiles(page, synthSubjects(5, 14));
  await waitForLoads(page, 1);
  // Four finish (one by failing); the cancelled one is stopped, not finished.
  await expect(body(page)).toHaveAttribute('data-batch-finished', '4', { timeout: 300_000 });
  await expect(body(page)).toHaveAttribute('data-batch-stopped', '1');

  await expect(row(page, 'scan_001')).toHaveAttribute('data-status', 'failed');
  await expect(row(page, 'scan_001')).toContainText('stopped unexpectedly');
  await expect(row(page, 'scan_004')).toHaveAttribute('data-status', 'cancelled');
  for (const s of ['scan_002', 'scan_003', 'scan_005']) expect(['ok', 'flagged']).toContain(await row(page, s).getAttribute('data-status'));
  // The shape model in view was not touched.
  await expect(page.getByTestId('shape-model-name')).toHaveText(model);
  await expect(page.getByTestId('measure-stature')).toHaveText(stature);
  await expect(body(page)).not.toHaveAttribute('data-shape-recovered', /.*/);

  // The replaced worker and the cancelled subject's fresh one both align on retry.
  await row(page, 'scan_001').getByTestId('batch-retry').click();
  await row(page, 'scan_004').getByTestId('batch-retry').click();
  await expect(row(page, 'scan_004')).not.toHaveAttribute('data-status', 'cancelled');
  await waitForBatch(page, 5);
  for (const s of ['scan_001', 'scan_004']) expect(['ok', 'flagged']).toContain(await row(page, s).getAttribute('data-status'));
});

test('a reload in the middle of a batch resumes it by itself; Cancel all is not counted as finished', async ({ page }) => {
  test.setTimeout(420_000);
  await openApp(page);
  await setBatchWorkers(page, 1);
  await dropFiles(page, synthSubjects(4, 15));
  await waitForLoads(page, 1);
  await expect(body(page)).toHaveAttribute('data-batch-running', '1');

  // Cancel all, pressed while the panel redraws with the worker's progress and released after it
  // has: the button is the one pressed (not a new one each frame), so the click lands. What had
  // not finished is stopped, not counted as finished, and one click starts them again. (The first
  // subject may finish between the press and the release on a loaded machine.)
  const cancelAll = page.getByTestId('batch-cancel-all');
  await cancelAll.scrollIntoViewIfNeeded();
  const pressed = await cancelAll.elementHandle();
  const upList = await page.getByTestId('batch-up').elementHandle();
  const box = (await cancelAll.boundingBox())!;
  const progress = await page.getByTestId('batch-progress').getAttribute('value');
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.waitForFunction((before) => document.querySelector('[data-testid="batch-progress"]')?.getAttribute('value') !== before, progress);
  await page.mouse.up();
  expect(await pressed!.evaluate((e) => e.isConnected)).toBe(true);
  expect(await upList!.evaluate((e) => e.isConnected)).toBe(true);
  await expect(body(page)).toHaveAttribute('data-batch-running', '0');
  const finished = Number(await body(page).getAttribute('data-batch-finished'));
  expect(finished).toBeLessThanOrEqual(1);
  await expect(body(page)).toHaveAttribute('data-batch-stopped', String(4 - finished));
  await expect(page.getByTestId('batch-summary')).toHaveText(new RegExp(`^${finished} of 4 finished, ${4 - finished} stopped`));
  expect(Number(await page.getByTestId('batch-progress').getAttribute('value'))).toBeLessThan(0.25 * (finished + 1));
  await page.getByTestId('batch-retry-all').click();
  await expect(body(page)).toHaveAttribute('data-batch-stopped', '0');

  // Reload while one aligns and the last waits: all four finish without a click.
  await expect(page.locator('[data-testid="batch-row"][data-status="aligning"]')).toHaveCount(1);
  await expect(row(page, 'scan_004')).toHaveAttribute('data-status', 'queued');
  await expect(page.getByTestId('batch-summary')).toHaveText(new RegExp(`^${finished} of 4 finished`));
  await expect(body(page)).toHaveAttribute('data-batch-saving', '0');
  await page.reload();
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await expect(body(page)).toHaveAttribute('data-batch-total', '4');
  await expect(page.locator('[data-testid="batch-row"][data-status="interrupted"]')).toHaveCount(0);
  await waitForBatch(page, 4);
  for (const s of ['scan_001', 'scan_002', 'scan_003', 'scan_004']) expect(['ok', 'flagged']).toContain(await row(page, s).getAttribute('data-status'));
  await expect(page.getByTestId('batch-retry')).toHaveCount(0);
});

test('a second scan of a subject names the one kept; one subject is not offered as a model', async ({ page }) => {
  test.setTimeout(300_000);
  const [landmarks, scan] = synthSubjects(1, 16);
  await openApp(page);
  // The same subject from two folders: the scan and its landmark file twice.
  await dropFiles(page, [scan!, landmarks!, scan!, landmarks!]);
  await waitForLoads(page, 1);
  const banner = page.getByTestId('error-banner');
  await expect(banner).toContainText('scan_001.ply: a second scan of subject scan_001; scan_001.ply was kept and this one left out');
  await expect(banner).not.toContainText('no scan of the same base name');
  await waitForBatch(page, 1);
  expect(['ok', 'flagged']).toContain(await row(page, 'scan_001').getAttribute('data-status'));
  // A model of one subject is not offered: the button says why.
  await expect(page.getByTestId('batch-build')).toBeDisabled();
  await expect(page.getByTestId('batch-build')).toHaveText('Build model');
  await expect(page.getByTestId('batch-build-status')).toHaveText('A model needs at least two kept fits; the batch has 1.');
});

test('the folder bodyspace synth writes gives one subject per scan; its ground truths are left out and said', async ({ page }) => {
  const files = synthFolder(3, 17);
  expect(files.filter((f) => /^(surface|truth)_/.test(f.name))).toHaveLength(6);
  await openApp(page);
  await setBatchWorkers(page, 1);
  await dropFiles(page, files);
  await waitForLoads(page, 1);
  await expect(body(page)).toHaveAttribute('data-batch-total', '3');
  await expect(body(page)).toHaveAttribute('data-batch-not-scans', '6');
  const subjects = await page.locator('[data-testid="batch-row"]').evaluateAll((rows) => rows.map((r) => r.getAttribute('data-subject')));
  expect(subjects).toEqual(['scan_001', 'scan_002', 'scan_003']);
  await expect(page.getByTestId('error-banner')).toContainText('surface_001.ply');
  await expect(page.getByTestId('error-banner')).toContainText('truth_003.ply');
  await expect(page.getByTestId('error-banner')).toContainText('not scans of a body');
  await expect(page.getByTestId('batch-panel')).toContainText('6 meshes that are not scans of a body were left out');
  // The three subjects align (a Cancel all here raced them: they may be done before it).
  await waitForBatch(page, 3);
  for (const s of subjects) expect(['ok', 'flagged']).toContain(await row(page, s!).getAttribute('data-status'));
});

test('scans without landmarks aligned with a wrong up are flagged; the orientation is kept and aligns them again after asking', async ({ page }) => {
  test.setTimeout(420_000);
  // Two z-up scans without their landmark files: the estimate finds the frame by itself (on
  // these 20 mm-step scans it may doubt itself, but it does not fail).
  const scans = synthSubjects(2, 18).filter((f) => f.name.startsWith('scan_'));
  const flagsOf = (s: string) => row(page, s).locator('.batch-flags');
  await openApp(page);
  await dropFiles(page, scans);
  await waitForLoads(page, 1);
  await waitForBatch(page, 2);
  await expect(body(page)).toHaveAttribute('data-batch-orientation', 'auto');
  for (const s of ['scan_001', 'scan_002']) {
    await expect(flagsOf(s)).not.toHaveAttribute('title', /landmark estimate failed/);
    await expect(row(page, s).getByTestId('batch-row-orientation')).toHaveCount(0);
  }
  await expect(page.getByTestId('batch-align-again')).toHaveCount(0);

  // The person says up is the scan's −x (wrong: the body lies on its side there).
  await page.getByTestId('batch-up').selectOption('-x');
  await expect(body(page)).toHaveAttribute('data-batch-orientation', 'up −x, facing auto');
  await expect(page.getByTestId('batch-facing')).toBeEnabled();
  await expect(page.getByTestId('batch-align-again')).toHaveText('Align again with it (2)');
  // Asked first: declined, nothing changes.
  expect(await declined(page, 'batch-align-again')).toBe('Align 2 subjects again with up −x, facing auto? Their fits are replaced by the new ones.');
  await expect(body(page)).toHaveAttribute('data-batch-running', '0');
  await expect(page.getByTestId('batch-summary')).toHaveText(/^2 of 2 finished,/);
  // Accepted: both align again with up −x, and the failed estimate flags their fits in words.
  page.once('dialog', (dialog) => void dialog.accept());
  await page.getByTestId('batch-align-again').click();
  await expect(page.getByTestId('batch-summary')).not.toHaveText(/^2 of 2 finished,/);
  await waitForBatch(page, 2);
  for (const s of ['scan_001', 'scan_002']) {
    await expect(row(page, s)).toHaveAttribute('data-status', 'flagged');
    await expect(flagsOf(s)).toContainText('landmark estimate');
    await expect(flagsOf(s)).toHaveAttribute('title', /landmark estimate failed/);
    await expect(row(page, s).getByTestId('batch-row-orientation')).toHaveText('up −x, facing auto');
  }
  await expect(page.getByTestId('batch-align-again')).toHaveCount(0);

  // A reload keeps the batch's orientation and what each subject was aligned with.
  await expect(body(page)).toHaveAttribute('data-batch-saving', '0');
  await page.reload();
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await expect(page.getByTestId('batch-up')).toHaveValue('-x');
  await expect(row(page, 'scan_001').getByTestId('batch-row-orientation')).toHaveText('up −x, facing auto');
  // Back to auto: both are offered again.
  await page.getByTestId('batch-up').selectOption('auto');
  await expect(page.getByTestId('batch-align-again')).toHaveText('Align again with it (2)');
});
