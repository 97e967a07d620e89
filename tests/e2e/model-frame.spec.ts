// A model is built in the template's frame whatever the frame of its scans: a batch of CAESAR-
// frame scans (z up, millimetres, as `bodyspace synth` writes them) dropped with their .lnd files,
// aligned, then "Build model" gives an upright body of a person's size, not one lying face down.
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { shapeReady } from './steps';
import { synthSubjects } from './synth';

const body = (page: Page) => page.locator('body');

/** A length reading of the measurement table (`123.4 cm`), in metres; NaN when not taken. */
async function metres(page: Page, name: string): Promise<number> {
  const text = await page.getByTestId(`measure-${name}`).innerText();
  const m = /^(-?\d+(?:\.\d+)?) cm$/.exec(text.trim());
  return m ? Number(m[1]) / 100 : NaN;
}

test('z-up millimetre scans make an upright model of a person', async ({ page }) => {
  test.setTimeout(420_000);
  // Three subjects at the coarse 20 mm step: scan_00i.ply (z up, mm) + landmarks_00i.lnd.
  const files = synthSubjects(3, 32);
  expect(files.filter((f) => f.name.endsWith('.ply'))).toHaveLength(3);
  await page.goto('./?debug');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await shapeReady(page);

  await dropFiles(page, files);
  await waitForLoads(page, 1);
  await expect(body(page)).toHaveAttribute('data-batch-total', '3');
  await expect(body(page)).toHaveAttribute('data-batch-finished', '3', { timeout: 300_000 });
  for (const s of ['scan_001', 'scan_002', 'scan_003']) {
    const row = page.locator(`[data-testid="batch-row"][data-subject="${s}"]`);
    expect(['ok', 'flagged']).toContain(await row.getAttribute('data-status'));
  }

  await page.getByTestId('batch-build').click();
  await expect(page.getByTestId('batch-build-status')).toHaveText('Built from 3 subjects.', { timeout: 120_000 });
  await expect(page.getByTestId('shape-model-name')).not.toHaveText('models/demo.bsm');
  await shapeReady(page);

  // The mean body: a person's stature and hip girth, and a thigh girth that can be taken (a body
  // lying face down measured 38–41 cm tall with a 330 cm hip and no thigh girth).
  const stature = await metres(page, 'stature');
  const hip = await metres(page, 'hip_girth');
  const thigh = await metres(page, 'thigh_girth');
  expect(stature).toBeGreaterThan(1.4);
  expect(stature).toBeLessThan(2.1);
  expect(hip).toBeGreaterThan(0.7);
  expect(hip).toBeLessThan(1.4);
  expect(thigh).toBeGreaterThan(0.35);
  expect(thigh).toBeLessThan(0.9);
});
