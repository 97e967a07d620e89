import { expect, test } from '@playwright/test';
import { dropFiles, holedBoxPly, waitForLoads } from './fixtures';

test('hovering a landmark marker names it; a CSV alone is listed and shown', async ({ page }) => {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-core-ready', 'true');
  // One landmark: with no scan loaded the camera frames the markers, so it sits mid-view.
  const csv = 'name,x,y,z\r\n"Rt. Axilla, Ant.",0.12,1.31,0.08\r\n';
  await dropFiles(page, [{ name: 'points.csv', bytes: Buffer.from(csv) }]);
  await waitForLoads(page, 1);
  await expect(page.getByTestId('landmarks-found')).toHaveText('1');
  await expect(page.getByTestId('landmarks-units')).toContainText('metres');
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-markers', '1');

  const tooltip = page.getByTestId('landmark-tooltip');
  await expect(tooltip).toBeHidden();
  const box = (await page.getByTestId('viewport-canvas').boundingBox())!;
  await page.mouse.move(box.x + box.width / 2 - 30, box.y + box.height / 2 - 30);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await expect(tooltip).toBeVisible();
  await expect(tooltip).toHaveText('Rt. Axilla, Ant.');

  await page.mouse.move(box.x + 5, box.y + 5);
  await expect(tooltip).toBeHidden();
});

test('a marker hidden behind the scan surface is not named', async ({ page }) => {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-core-ready', 'true');
  // The box's centre is where the camera looks; a landmark there is behind the front wall.
  const csv = 'name,x,y,z\nCrotch,0,850,0\n';
  await dropFiles(page, [holedBoxPly(), { name: 'inside.csv', bytes: Buffer.from(csv) }]);
  await waitForLoads(page, 1);
  await expect(page.getByTestId('landmarks-units')).toContainText('millimetres (following the scan)');
  // One landmark is a partial file: the estimate fills in the other 72 on the box's walls. Wait for
  // it, so the hover is not raced by the markers it adds (none of them lies at the view's centre).
  await expect(page.locator('body')).toHaveAttribute('data-estimate-state', 'done');
  await expect(page.locator('#viewport')).toHaveAttribute('data-scan-markers', '73');

  const tooltip = page.getByTestId('landmark-tooltip');
  const box = (await page.getByTestId('viewport-canvas').boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await expect(tooltip).toHaveAttribute('data-updates', /[1-9]/);
  await expect(tooltip).toBeHidden();
});
