import { expect, test } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { partialCsv, sampleFile } from './samples';
import { openWithSample } from './steps';
import { synthSubjects } from './synth';
for (const width of [1280, 1920]) {
  test(`shot ${width}`, async ({ page }) => {
    test.setTimeout(300_000);
    await page.setViewportSize({ width, height: width === 1280 ? 800 : 1080 });
    await openWithSample(page, [sampleFile('scan_001.ply.gz'), partialCsv((n) => ['Sellion', 'Rt. Acromion', 'Lt. Acromion'].includes(n))]);
    await expect(page.locator('body')).toHaveAttribute('data-estimate-state', 'done', { timeout: 120_000 });
    const [, scan] = synthSubjects(1, 22, 10);
    await dropFiles(page, [{ name: 'other.ply', bytes: scan!.bytes }]);
    await waitForLoads(page, 2);
    await expect(page.locator('body')).toHaveAttribute('data-estimates', '2', { timeout: 120_000 });
    await page.waitForTimeout(1500);
    await page.screenshot({ path: `/work/scratch/aside-${width}.png` });
  });
}
