// Steps several browser tests take, as a person would: open the sample, cancel an alignment at its
// first progress, wait for the shape space, move a slider.
import { expect, type Page } from '@playwright/test';
import { dropFiles, waitForLoads, type TestFile } from './fixtures';
import { sampleSubject } from './samples';

/** Opens the app and drops `files` (the sample subject by default). */
export async function openWithSample(page: Page, files: TestFile[] = sampleSubject()): Promise<void> {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await dropFiles(page, files);
  await waitForLoads(page, 1);
}

/** Clicks Align and Cancel as soon as the first progress arrives (in the page, so a fast run cannot finish first). */
export async function alignAndCancelAtFirstProgress(page: Page): Promise<void> {
  await page.evaluate(() => {
    new MutationObserver((_, observer) => {
      if (Number(document.body.dataset.alignIteration ?? '0') < 1) return;
      observer.disconnect();
      document.querySelector<HTMLButtonElement>('[data-testid="align-cancel"]')!.click();
    }).observe(document.body, { attributes: true, attributeFilter: ['data-align-iteration'] });
  });
  await page.getByTestId('align-run').click();
  await expect(page.locator('body')).toHaveAttribute('data-align-state', 'cancelled', { timeout: 120_000 });
}

/** The shape space has a model and its body is drawn. */
export async function shapeReady(page: Page): Promise<void> {
  await expect(page.locator('body')).toHaveAttribute('data-shape-ready', 'true');
  await expect(page.locator('body')).toHaveAttribute('data-shape-settled', 'true');
}

/** Moves a slider as a drag would end: sets its value and fires `input`, then waits for the body. */
export async function slide(page: Page, mode: number, sigma: number): Promise<void> {
  const bodies = Number(await page.locator('body').getAttribute('data-shape-bodies'));
  await page.getByTestId(`shape-slider-${mode}`).fill(String(sigma));
  await expect(page.locator('body')).not.toHaveAttribute('data-shape-bodies', String(bodies));
  await shapeReady(page);
}

/** Arms a click on the estimate's Cancel as soon as it shows (in the page, so a fast run cannot finish first). */
export async function cancelEstimateWhenItRuns(page: Page): Promise<void> {
  await page.evaluate(() => {
    new MutationObserver((_, observer) => {
      const cancel = document.querySelector<HTMLButtonElement>('[data-testid="estimate-cancel"]');
      if (!cancel) return;
      observer.disconnect();
      cancel.click();
    }).observe(document.body, { childList: true, subtree: true });
  });
}
