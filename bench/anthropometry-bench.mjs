// Times anthropometry in the real core worker inside Chromium, on the demo model at `base`:
//   * measurements of one body: RUNS whole-body slider moves (no segment overridden, so the seam
//     report is trivial), the page's "measurements + seam report" time per body;
//   * a body from measurements: RUNS presses of "Find body" with stature and waist-girth targets
//     spread over ±4 cm around the mean body's (the core call in the worker);
//   * the population (all measurements over the training subjects and the sampled bodies) once, as
//     the model opens (the per-body timings wait for it), and the boundary manikins of stature × waist girth at the default coverage once.
// Usage: node bench/anthropometry-bench.mjs URL RUNS
import { launchBenchPage } from './browser.mjs';
import { row as tableRow } from './table.mjs';

const [url, runsArg] = process.argv.slice(2);
const runs = Number(runsArg ?? 30);
const { browser, page } = await launchBenchPage();
await page.goto(url);
await page.waitForFunction(() => document.body.dataset.shapeSettled === 'true' && document.body.dataset.shapeReady === 'true', null, { timeout: 120_000 });
// The population is measured in its own worker as the model opens: wait for it, so its work on
// the other core does not count in the per-body timings.
await page.waitForFunction(() => document.body.dataset.populationReady === 'true', null, { timeout: 600_000 });
const populationMs = await page.evaluate(() => Number(document.body.dataset.populationMs));

const row = (label, xs) => tableRow(label, xs, 52);
const bodies = () => page.evaluate(() => Number(document.body.dataset.shapeBodies));
const settledAfter = (n) => page.waitForFunction((b) => Number(document.body.dataset.shapeBodies) > b && document.body.dataset.shapeSettled === 'true', n, { timeout: 60_000 });

const measure = [];
for (let run = 0; run < runs; run++) {
  const before = await bodies();
  await page.getByTestId(`shape-slider-${run % 5}`).fill(String(((run * 7) % 11) * 0.5 - 2.5 || 0.25));
  await settledAfter(before);
  measure.push(await page.evaluate(() => Number(document.body.dataset.shapeMeasureMs)));
}
await page.getByTestId('shape-reset').click();
await page.waitForFunction(() => document.body.dataset.shapeSettled === 'true');
const cm = async (name) => Number.parseFloat(await page.getByTestId(`measure-${name}`).innerText());
const [stature, waist] = [await cm('stature'), await cm('waist_girth')];

const find = [];
for (let run = 0; run < runs; run++) {
  const before = await bodies();
  await page.getByTestId('target-stature').fill((stature + ((run % 9) - 4)).toFixed(1));
  await page.getByTestId('target-waist_girth').fill((waist + (((run * 5) % 9) - 4)).toFixed(1));
  await page.evaluate(() => (document.body.dataset.findBody = ''));
  await page.getByTestId('find-body').click();
  await page.waitForFunction(() => document.body.dataset.findBody === 'done', null, { timeout: 60_000 });
  await settledAfter(before);
  find.push(await page.evaluate(() => Number(document.body.dataset.findBodyMs)));
}

await page.getByTestId('manikin-pick-stature').check();
await page.getByTestId('manikin-pick-waist_girth').check();
await page.getByTestId('manikin-compute').click();
await page.waitForFunction(() => /^\d+$/.test(document.body.dataset.manikins ?? ''), null, { timeout: 600_000 });
const manikins = await page.evaluate(() => ({ n: document.body.dataset.manikins, ms: Number(document.body.dataset.manikinsMs) }));

console.log(`Chromium ${browser.version()}; demo model at base, ${runs} runs (ms)`);
console.log(`| ${'in the worker (WASM)'.padEnd(52)} | ${'median'.padStart(8)} | ${'min'.padStart(8)} | ${'max'.padStart(8)} |`);
console.log(`|${'-'.repeat(54)}|${'-'.repeat(10)}|${'-'.repeat(10)}|${'-'.repeat(10)}|`);
console.log(row('one body: all measurements + seam report', measure));
console.log(row('a body from stature + waist girth', find));
console.log(`population (training subjects + sampled bodies), once: ${(populationMs / 1000).toFixed(2)} s`);
console.log(`boundary manikins, stature × waist girth, default coverage, once: ${manikins.n} manikins in ${(manikins.ms / 1000).toFixed(2)} s`);
await browser.close();
