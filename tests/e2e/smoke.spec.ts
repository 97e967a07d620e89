import { expect, test } from '@playwright/test';

test('the app loads the WASM core in its worker', async ({ page }) => {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-ready', 'true');
  await expect(page.locator('#app')).toContainText('BodySpace core 0.1.0');
});
