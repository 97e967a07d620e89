// Cancelling an alignment stops only the alignment's own worker: the shape model, the template,
// the scan and its landmarks stay, and every shape-space action keeps working.
import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
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
