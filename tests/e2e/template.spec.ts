import { expect, test } from '@playwright/test';

test('the page opens on the base template with 73 + 12 landmark markers and its counts', async ({ page }) => {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await expect(page.locator('body')).toHaveAttribute('data-template-resolution', 'base');
  const viewport = page.locator('#viewport');
  await expect(viewport).toHaveAttribute('data-template-markers', '85');
  await expect(viewport).toHaveAttribute('data-template-visible', 'true');
  await expect(page.getByTestId('template-landmarks')).toHaveText('73');
  await expect(page.getByTestId('template-virtual-landmarks')).toHaveText('12');
  const vertices = Number((await page.getByTestId('template-vertices').textContent())!.replace(/,/g, ''));
  const triangles = Number((await page.getByTestId('template-triangles').textContent())!.replace(/,/g, ''));
  expect(vertices).toBeGreaterThan(12_000);
  expect(vertices).toBeLessThan(16_000);
  expect(triangles).toBeGreaterThan(vertices);
  expect(Number(await viewport.getAttribute('data-template-triangles'))).toBe(triangles);
});

test('segment colours and the template toggle change what the viewer shows', async ({ page }) => {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await expect(page.getByTestId('segment-legend')).toBeHidden();
  await page.getByTestId('template-segment-colours').check();
  await expect(page.locator('body')).toHaveAttribute('data-template-segment-colours', 'true');
  await expect(page.locator('#viewport')).toHaveAttribute('data-template-coloured', 'true');
  await expect(page.getByTestId('segment-legend').locator('li')).toHaveCount(6);
  await page.getByTestId('template-segment-colours').uncheck();
  await expect(page.locator('#viewport')).toHaveAttribute('data-template-coloured', 'false');
  await page.getByTestId('template-show').uncheck();
  await expect(page.locator('#viewport')).toHaveAttribute('data-template-visible', 'false');
});
