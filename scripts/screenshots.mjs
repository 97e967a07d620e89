// Screenshots of the template, RBF warp and Align steps with headless Chromium, for looking at
// the UI (not a test). Needs `npm run preview` running (or BASE_URL set to another server).
// Usage: node scripts/screenshots.mjs OUTDIR [SCAN LANDMARKS] — the sample subject 001 by default.
import { readFileSync } from 'node:fs';
import { chromium } from '@playwright/test';

const out = process.argv[2] ?? 'screenshots';
const [scanPath, landmarksPath] = [process.argv[3] ?? 'public/samples/scan_001.ply.gz', process.argv[4] ?? 'public/samples/landmarks_001.csv'];
const base = process.env.BASE_URL ?? 'http://127.0.0.1:4173/';
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
const page = await browser.newPage({ viewport: { width: 1500, height: 950 } });
const t0 = Date.now();
const stamp = (what) => console.log(`${((Date.now() - t0) / 1000).toFixed(1)} s  ${what}`);
await page.goto(base);
await page.waitForFunction(() => document.body.dataset.templateReady === 'true', undefined, { timeout: 60000 });
stamp('template shown');
await page.waitForTimeout(500);
await page.screenshot({ path: `${out}/1-template.png` });
await page.getByTestId('template-segment-colours').check();
await page.waitForTimeout(500);
await page.screenshot({ path: `${out}/2-segments.png` });
await page.getByTestId('template-segment-colours').uncheck();

const files = [scanPath, landmarksPath].map((path) => ({
  name: path.split('/').pop(),
  data: [...readFileSync(path)],
}));
const dt = await page.evaluateHandle((items) => {
  const d = new DataTransfer();
  for (const f of items) d.items.add(new File([new Uint8Array(f.data)], f.name));
  return d;
}, files);
await page.dispatchEvent('#viewport', 'drop', { dataTransfer: dt });
await page.waitForFunction(() => document.body.dataset.rbfState === 'done', undefined, { timeout: 60000 });
stamp('warp done');
await page.waitForTimeout(800);
await page.screenshot({ path: `${out}/3-warp.png` });
await page.getByTestId('align-run').click();
await page.waitForFunction(() => Number(document.body.dataset.alignIteration ?? 0) >= 15, undefined, { timeout: 120000 });
stamp('align iteration 15');
await page.screenshot({ path: `${out}/4-aligning.png` });
await page.waitForFunction(() => document.body.dataset.alignState === 'done', undefined, { timeout: 300000 });
stamp('align done');
console.log(JSON.stringify(await page.evaluate(() => ({
  rms: document.querySelector('[data-testid="align-rms"]')?.textContent,
  mean: document.querySelector('[data-testid="align-mean"]')?.textContent,
  sd: document.querySelector('[data-testid="align-sd"]')?.textContent,
  points: document.querySelector('[data-testid="align-points"]')?.textContent,
  iterations: document.querySelector('[data-testid="align-iterations"]')?.textContent,
  time: document.querySelector('[data-testid="align-time"]')?.textContent,
}))));
await page.waitForTimeout(800);
await page.screenshot({ path: `${out}/5-aligned.png` });
await page.locator('.left-column').evaluate((e) => (e.scrollTop = e.scrollHeight));
await page.screenshot({ path: `${out}/6-aligned-panel.png` });
await page.evaluate(() => {
  new MutationObserver((_, observer) => {
    if (Number(document.body.dataset.alignIteration ?? 0) < 25) return;
    observer.disconnect();
    document.querySelector('[data-testid="align-cancel"]').click();
  }).observe(document.body, { attributes: true, attributeFilter: ['data-align-iteration'] });
  document.body.dataset.alignIteration = '0';
});
await page.getByTestId('align-run').click();
await page.waitForFunction(() => document.body.dataset.alignState === 'cancelled', undefined, { timeout: 120000 });
stamp('cancelled');
await page.waitForTimeout(800);
await page.locator('.left-column').evaluate((e) => (e.scrollTop = e.scrollHeight));
await page.screenshot({ path: `${out}/7-cancelled.png` });
await browser.close();
