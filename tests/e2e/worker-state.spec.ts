// Cancelling an alignment stops only the alignment's own worker, and a worker whose core traps is
// replaced and given its state again: the shape model, the template, the scan and its landmarks
// stay, and every shape-space action keeps working.
import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { sampleSubject } from './samples';
import { alignAndCancelAtFirstProgress, shapeReady, slide } from './steps';

test('after a fine alignment is cancelled, sliders, segments, links and exports still work', async ({ page }) => {
  test.setTimeout(300_000);
  await page.goto('./');
  await shapeReady(page);
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await page.getByTestId('template-resolution').selectOption('fine');
  await expect(page.locator('body')).toHaveAttribute('data-template-resolution', 'fine', { timeout: 120_000 });
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 120_000 });
  await dropFiles(page, sampleSubject());
  await waitForLoads(page, 1);
  await expect(page.locator('body')).toHaveAttribute('data-rbf-state', 'done', { timeout: 120_000 });
  await slide(page, 0, 1.5);
  const stature = await page.getByTestId('measure-stature').innerText();

  await alignAndCancelAtFirstProgress(page);
  await expect(page.getByTestId('align-cancelled')).toContainText(/Cancelled at iteration \d+/);
  // The model and the body shown are the ones from before the cancel.
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
  await expect(page.getByTestId('measure-stature')).toHaveText(stature);
  await expect(page.locator('body')).toHaveAttribute('data-scan-loaded', 'true');
  await expect(page.locator('body')).toHaveAttribute('data-landmarks-loaded', 'true');

  // A slider still moves the body; a segment still takes its own shape.
  await slide(page, 0, -1.5);
  await expect(page.getByTestId('measure-stature')).not.toHaveText(stature);
  await page.getByTestId('shape-segment').selectOption('torso');
  await slide(page, 1, 1.2);
  await expect(page.getByTestId('shape-segment-state')).toContainText('has its own shape');

  // A link still carries the model and the coefficients.
  await page.getByTestId('copy-link').click();
  const link = await page.getByTestId('shape-link').inputValue();
  expect(link).toContain('m=');

  // The body still exports (the core's PLY writer, in the model's worker).
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('shape-export-ply').click()]);
  expect(download.suggestedFilename()).toBe('body.ply');
  const bytes = readFileSync((await download.path())!);
  expect(bytes.toString('latin1', 0, 300)).toMatch(/element vertex \d+/);
});

/** Traps one worker's core as a bug in the core would (the page's `?debug` hook). */
async function trap(page: Page, which: 'core' | 'align'): Promise<void> {
  await page.evaluate((w) => (window as unknown as { bodyspaceDebug: { trap: (w: string) => Promise<void> } }).bodyspaceDebug.trap(w), which);
}

test('a trap in a core worker is reported, the worker replaced, and the page keeps working', async ({ page }) => {
  test.setTimeout(300_000);
  await page.goto('./?debug');
  await shapeReady(page);
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await dropFiles(page, sampleSubject());
  await waitForLoads(page, 1);
  await expect(page.locator('body')).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await page.getByTestId('shape-segment').selectOption('torso');
  await slide(page, 1, 1.2);
  await page.getByTestId('shape-segment').selectOption('whole');
  await slide(page, 0, 2);
  const stature = await page.getByTestId('measure-stature').innerText();

  // The main core worker (it holds the shape model) traps: the page says so and gives the new
  // worker the model again; the body keeps every slider value.
  await trap(page, 'core');
  await expect(page.getByTestId('error-text')).toContainText('The core stopped unexpectedly and was restarted');
  await expect(page.locator('body')).toHaveAttribute('data-shape-recovered', 'true', { timeout: 60_000 });
  await shapeReady(page);
  await expect(page.getByTestId('measure-stature')).toHaveText(stature);
  await slide(page, 0, -1);
  await expect(page.getByTestId('measure-stature')).not.toHaveText(stature);
  await page.getByTestId('shape-segment').selectOption('left_leg');
  await slide(page, 0, 0.8);
  await page.getByTestId('copy-link').click();
  expect(await page.getByTestId('shape-link').inputValue()).toContain('s=torso.');
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('shape-export-obj').click()]);
  expect(readFileSync((await download.path())!).toString('utf8')).toMatch(/^v /m);

  // The alignment worker traps: the scan and its landmarks stay, and Align still runs.
  await trap(page, 'align');
  await expect(page.locator('body')).toHaveAttribute('data-scan-loaded', 'true');
  await page.getByTestId('align-run').click();
  await expect(page.locator('body')).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
});
