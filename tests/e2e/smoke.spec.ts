import { expect, test } from '@playwright/test';

test('the app opens on an empty scene with the core ready and makes no request to another origin', async ({ page }) => {
  const foreign: string[] = [];
  page.on('request', (r) => {
    const url = new URL(r.url());
    if (!['127.0.0.1:4173'].includes(url.host) && url.protocol !== 'data:' && url.protocol !== 'blob:') foreign.push(r.url());
  });
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-core-ready', 'true');
  await expect(page.getByTestId('status')).toContainText('Core 0.1.0 ready');
  await expect(page.getByTestId('open-files')).toBeVisible();
  await expect(page.getByTestId('landmark-list').locator('li')).toHaveCount(73);
  await expect(page.locator('#viewport')).toHaveAttribute('data-frames', /\d+/);
  expect(foreign).toEqual([]);
});
