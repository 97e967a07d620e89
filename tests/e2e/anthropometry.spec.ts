// Anthropometry in the shape panel as a designer uses it: targets entered beside the
// measurements give the most likely body with them (achieved vs target shown), bad entries say
// what is wrong and change nothing.
import { expect, test, type Page } from '@playwright/test';
import { shapeReady } from './steps';

/** A reading as the panel shows it (`168.9 cm`) in cm. */
async function cm(page: Page, name: string): Promise<number> {
  const text = await page.getByTestId(`measure-${name}`).innerText();
  expect(text).toMatch(/^\d+\.\d cm$/);
  return Number.parseFloat(text);
}

test('two targets give a body that meets them; a bad entry is refused with its reason', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const stature = await cm(page, 'stature');
  const waist = await cm(page, 'waist_girth');

  // Not a number: refused, nothing moves.
  const checksum = await page.locator('body').getAttribute('data-shape-checksum');
  await page.getByTestId('target-chest_girth').fill('abc');
  await page.getByTestId('find-body').click();
  await expect(page.getByTestId('find-body-status')).toHaveText('Chest girth: "abc" is not a number (enter cm)');
  await page.getByTestId('target-chest_girth').fill('-3');
  await page.getByTestId('find-body').click();
  await expect(page.getByTestId('find-body-status')).toContainText('a target must be a positive number of cm');
  await expect(page.locator('body')).toHaveAttribute('data-shape-checksum', checksum!);
  await page.getByTestId('target-chest_girth').fill('');

  // Taller and slimmer than the mean, inside the population.
  const targets = { stature: stature + 4, waist_girth: waist - 3 };
  await page.getByTestId('target-stature').fill(targets.stature.toFixed(1));
  await page.getByTestId('target-waist_girth').fill(targets.waist_girth.toFixed(1));
  await page.getByTestId('find-body').click();
  await expect(page.locator('body')).toHaveAttribute('data-find-body', 'done');
  await shapeReady(page);
  await expect(page.getByTestId('find-body-status')).toContainText('2 of 2 targets met');
  for (const [name, target, tolerance] of [
    ['stature', targets.stature, 0.2],
    ['waist_girth', targets.waist_girth, 0.5],
  ] as const) {
    const cell = page.getByTestId(`achieved-${name}`);
    await expect(cell).toHaveAttribute('data-met', 'true');
    await expect(cell).toContainText(': met');
    expect(Math.abs(Number(await cell.getAttribute('data-achieved')) * 100 - Number(target.toFixed(1)))).toBeLessThanOrEqual(tolerance);
    // The reading on screen is the body found.
    expect(Math.abs((await cm(page, name)) - target)).toBeLessThanOrEqual(tolerance + 0.06);
  }
  // The sliders moved to the body found.
  expect(Number(await page.getByTestId('shape-slider-0').inputValue())).not.toBe(0);
  // A row without a target shows no achieved line.
  await expect(page.getByTestId('achieved-hip_girth')).toBeHidden();
});
