// The page is safe to open from a link: a Content-Security-Policy that the whole app lives within,
// no request to another origin unless the person agrees to the host, and nothing a link, a file
// name or a landmark name carries ever becomes markup or script.
import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { sampleSubject } from './samples';
import { shapeReady } from './steps';

/** Records CSP violations in the page (`window.cspViolations`) from its first script on. */
async function recordViolations(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const w = window as unknown as { cspViolations: string[] };
    w.cspViolations = [];
    document.addEventListener('securitypolicyviolation', (e) => w.cspViolations.push(`${e.violatedDirective} ${e.blockedURI}`));
  });
}

async function violations(page: Page): Promise<string[]> {
  return page.evaluate(() => (window as unknown as { cspViolations: string[] }).cspViolations);
}

/** Every URL the page requests that is not on `origin` (data: and blob: URLs are the page's own). */
function foreignRequests(page: Page, origin: string): string[] {
  const foreign: string[] = [];
  page.on('request', (request) => {
    const url = request.url();
    if (!url.startsWith(origin) && !url.startsWith('data:') && !url.startsWith('blob:')) foreign.push(url);
  });
  return foreign;
}

test('a whole visit stays within the Content-Security-Policy and the page origin', async ({ page, baseURL }) => {
  test.setTimeout(300_000);
  const origin = new URL(baseURL!).origin;
  const foreign = foreignRequests(page, origin);
  await recordViolations(page);
  await page.goto('./');
  const policy = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
  expect(policy).toContain("script-src 'self' 'wasm-unsafe-eval'");
  expect(policy).not.toContain('unsafe-inline');
  await shapeReady(page);
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });

  // Copy a link of the demo model's body.
  await page.getByTestId('copy-link').click();
  expect(await page.getByTestId('shape-link').inputValue()).toContain('m=models');
  // Open a scan and its landmarks, warp, align, keep, export the fit.
  await dropFiles(page, sampleSubject());
  await waitForLoads(page, 1);
  await expect(page.locator('body')).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await page.getByTestId('align-run').click();
  await expect(page.locator('body')).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
  const [fit] = await Promise.all([page.waitForEvent('download'), page.getByTestId('export-ply').click()]);
  expect(fit.suggestedFilename()).toBe('scan_001-fitted.ply');
  await page.getByTestId('align-keep').click();
  // Build a model from the kept fit and a dropped one, and export a body of it.
  await page.getByTestId('fits-input').setInputFiles(['public/samples/truth_002.ply.gz']);
  await expect(page.getByTestId('shape-subjects')).toContainText('2 subjects in this session (1 aligned, 1 dropped');
  await page.getByTestId('build-variance').fill('100');
  await page.getByTestId('build-model').click();
  await expect(page.getByTestId('shape-model-name')).toHaveText('model of 2 subjects');
  await shapeReady(page);
  const [body] = await Promise.all([page.waitForEvent('download'), page.getByTestId('shape-export-glb').click()]);
  expect(readFileSync((await body.path())!).toString('latin1', 0, 4)).toBe('glTF');

  expect(await violations(page)).toEqual([]);
  expect(foreign).toEqual([]);
});

test('a link to a model on another host asks first and fetches nothing until the person agrees', async ({ page, baseURL }) => {
  const origin = new URL(baseURL!).origin;
  const remote = 'https://models.example.org/population.bsm';
  const foreign = foreignRequests(page, origin);
  // The "other host" is served by the test itself: nothing leaves this machine.
  await page.route('https://models.example.org/**', (route) =>
    route.fulfill({ status: 200, contentType: 'application/octet-stream', body: readFileSync('public/models/demo.bsm') }),
  );
  await page.goto(`./#m=${encodeURIComponent(remote)}&w=`);
  await expect(page.getByTestId('host-prompt')).toBeVisible();
  await expect(page.getByTestId('host-name')).toHaveText('models.example.org');
  expect(foreign).toEqual([]);
  await page.getByTestId('host-load').click();
  await shapeReady(page);
  await expect(page.getByTestId('shape-model-name')).toHaveText(remote);
  expect(foreign).toEqual([remote]);

  // Declining keeps the page on its own origin and opens the demo model.
  foreign.length = 0;
  await page.goto(`./?again#m=${encodeURIComponent(remote)}&w=`);
  await page.getByTestId('host-keep').click();
  await expect(page.locator('body')).toHaveAttribute('data-shape-foreign-declined', 'models.example.org');
  await shapeReady(page);
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
  expect(foreign).toEqual([]);
});

test('markup in a file name, a landmark name or a link stays text', async ({ page }) => {
  await page.goto('./');
  await expect(page.locator('body')).toHaveAttribute('data-core-ready', 'true');
  const trap = '<img src=x onerror="document.body.dataset.pwned=1">';
  // A broken scan whose name is markup: the banner names it as text.
  await dropFiles(page, [{ name: `${trap}.ply`, bytes: Buffer.from('ply\nformat nonsense\n') }]);
  await expect(page.getByTestId('error-text')).toContainText(trap);
  await expect(page.getByTestId('error-banner').locator('img')).toHaveCount(0);
  // A landmark name that is markup: listed as an unknown name, as text.
  const name = '<b><img src=x onerror=alert(1)></b>';
  const csv = `name,x,y,z\n"${name}",1,2,3\nSellion,0,0,1700\n`;
  await dropFiles(page, [{ name: 'landmarks.csv', bytes: Buffer.from(csv) }]);
  await expect(page.getByTestId('landmark-unknown-list')).toContainText(name);
  await expect(page.getByTestId('landmark-unknown-list').locator('b, img')).toHaveCount(0);
  // A link whose parts are markup: the problems are reported as text.
  await page.goto(`./?markup#m=${encodeURIComponent(trap)}&w=`);
  await expect(page.getByTestId('error-text')).toContainText('<img src=x');
  await expect(page.locator('#error-banner img')).toHaveCount(0);
  await expect(page.locator('body')).not.toHaveAttribute('data-pwned', '1');
});

test('a model file on this origin is loaded too, within the size limit', async ({ page }) => {
  await page.goto(`./#m=${encodeURIComponent('models/demo.bsm')}&w=`);
  await shapeReady(page);
  await expect(page.getByTestId('host-prompt')).toBeHidden();
  await expect(page.getByTestId('shape-model-name')).toHaveText('models/demo.bsm');
});
