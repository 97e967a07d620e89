import { expect, test } from '@playwright/test';

test('the app opens on an empty scene with the core ready and makes no request to another origin', async ({ page, baseURL }) => {
  const own = new URL(baseURL!).host;
  const foreign: string[] = [];
  page.on('request', (r) => {
    const url = new URL(r.url());
    if (url.host !== own && url.protocol !== 'data:' && url.protocol !== 'blob:') foreign.push(r.url());
  });
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-core-ready', 'true');
  await expect(page.getByTestId('status')).toContainText('Core 0.1.0 ready');
  await expect(page.getByTestId('open-files')).toBeVisible();
  await expect(page.getByTestId('landmark-list').locator('li')).toHaveCount(73);
  // At least one frame rendered: the count starts at 1 after the first render, never 0.
  await expect(page.locator('#viewport')).toHaveAttribute('data-frames', /^[1-9]\d*$/);
  expect(foreign).toEqual([]);
});
