// Times stitched reconstruction of the app's shape model in the real core worker inside Chromium:
// opens a link that gives all six segments their own coefficients (so the whole body and six
// segment models are reconstructed and blended), then presses "Random body" RUNS times and reads
// the worker's reconstruction time from the page. Usage: node bench/shape-bench.mjs URL RUNS
import { chromium } from '@playwright/test';

const [url, runsArg] = process.argv.slice(2);
const runs = Number(runsArg ?? 30);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
// 0.5σ on 20 modes of every part (int16 500 = 0xf401 little-endian, base64url "9AE").
const values = Buffer.alloc(40);
for (let k = 0; k < 20; k++) values.writeInt16LE(500, 2 * k);
const b64 = values.toString('base64url');
const segments = ['head', 'left_arm', 'right_arm', 'torso', 'left_leg', 'right_leg'].map((s) => `${s}.${b64}`).join('~');
await page.goto(`${url}#m=models%2Fdemo.bsm&w=${b64}&s=${segments}&v=whole`);
await page.waitForFunction(() => document.body.dataset.linkRestored === 'true' && document.body.dataset.shapeSettled === 'true', null, { timeout: 120_000 });
const info = await page.evaluate(() => ({
  vertices: document.querySelector('[data-testid=shape-vertices]')?.textContent,
  modes: document.body.dataset.shapeModes,
}));
const samples = [];
for (let run = 0; run < runs; run++) {
  const bodies = await page.evaluate(() => Number(document.body.dataset.shapeBodies));
  await page.getByTestId('shape-random').click();
  await page.waitForFunction((n) => Number(document.body.dataset.shapeBodies) > n && document.body.dataset.shapeSettled === 'true', bodies, { timeout: 60_000 });
  samples.push(await page.evaluate(() => Number(document.body.dataset.shapeReconstructMs)));
}
await browser.close();
const sorted = [...samples].sort((a, b) => a - b);
const median = sorted[Math.floor(sorted.length / 2)];
console.log(`Shape model: ${info.vertices} vertices, ${info.modes} whole-body modes kept (all of each part's kept modes used), six segments overridden and stitched`);
console.log(`| stitched reconstruction in the worker (WASM) | median ${median.toFixed(2)} ms | min ${sorted[0].toFixed(2)} ms | max ${sorted.at(-1).toFixed(2)} ms | ${runs} runs |`);
