// The batch in the browser: six synthetic subjects, a scan without landmarks (its landmarks are
// estimated) and a broken scan dropped at once are aligned by the worker pool, survive a reload,
// and make a model; a worker whose core traps
// mid-batch, or a cancelled one, leaves the others and the shape model alone.
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { shapeReady } from './steps';
import { synthSubjects } from './synth';

const body = (page: Page) => page.locator('body');
const row = (page: Page, subject: string) => page.locator(`[data-testid="batch-row"][data-subject="${subject}"]`);

async function openApp(page: Page): Promise<void> {
  await page.goto('./?debug');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await shapeReady(page);
}

async function waitForBatch(page: Page, total: number): Promise<void> {
  await expect(body(page)).toHaveAttribute('data-batch-total', String(total));
  await expect(body(page)).toHaveAttribute('data-batch-finished', String(total), { timeout: 300_000 });
}

test('six subjects dropped at once are aligned, come back after a reload and build a model', async ({ page }) => {
  test.setTimeout(420_000);
  const files = synthSubjects(7, 13);
  // Subject 7 comes without its landmarks; a broken scan comes with subject 1's.
  const broken = { name: 'broken.ply', bytes: Buffer.from('ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n') };
  const brokenLandmarks = { name: 'broken.lnd', bytes: files.find((f) => f.name === 'landmarks_001.lnd')!.bytes };
  const dropped = [...files.filter((f) => f.name !== 'landmarks_007.lnd'), broken, brokenLandmarks];
  await openApp(page);
  await dropFiles(page, dropped);
  await waitForLoads(page, 1);
  await waitForBatch(page, 8);
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
  await expect(row(page, 'broken')).toHaveAttribute('data-status', 'failed');
  await expect(row(page, 'broken')).toContainText('broken.ply');

  // Sorting by RMS puts the rows in RMS order (the failed subject, without one, last).
  await page.getByTestId('batch-sort-rms').click();
  const sorted = await page.locator('[data-testid="batch-row"]').evaluateAll((rows) => rows.map((r) => r.getAttribute('data-subject')!));
  expect(sorted.at(-1)).toBe('broken');
  const shown = sorted.slice(0, -1).map((s) => Number(before[s]!.rms));
  expect(shown).toEqual([...shown].sort((a, b) => a - b));
  await page.getByTestId('batch-sort-rms').click();
  const descending = await page.locator('[data-testid="batch-row"]').evaluateAll((rows) => rows.map((r) => r.getAttribute('data-subject')!));
  expect(descending[0]).toBe('broken');

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
  await expect(body(page)).toHaveAttribute('data-batch-total', '8');
  for (const s of subjects.filter((s) => s !== 'scan_006')) {
    await expect(row(page, s)).toHaveAttribute('data-status', before[s]!.status);
    await expect(row(page, s).getByTestId('batch-rms')).toHaveText(before[s]!.rms);
  }
  await expect(row(page, 'scan_006')).toHaveAttribute('data-status', 'excluded');
  await expect(row(page, 'broken')).toHaveAttribute('data-status', 'failed');

  await shapeReady(page);
  await page.getByTestId('batch-build').click();
  await expect(page.getByTestId('batch-build-status')).toHaveText('Built from 6 subjects.', { timeout: 120_000 });
  await expect(page.getByTestId('shape-model-name')).not.toHaveText('models/demo.bsm');
  await expect(page.getByTestId('shape-panel')).toContainText('6 subjects');
  await shapeReady(page);

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
  await waitForBatch(page, 5);

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
