// The landmark estimate of a bare scan in the real app's landmark worker inside Chromium, RUNS
// times (a fresh page each run: the app estimates once, on the drop), and prints the time the
// worker records (`data-estimate-worker-ms`: scan in, the core's estimate, results out).
// Usage: node bench/estimate-bench.mjs URL SCAN RUNS
import { launchBenchPage } from './browser.mjs';

const [url, scanPath, runsArg] = process.argv.slice(2);
const runs = Number(runsArg ?? 3);
const { browser, page } = await launchBenchPage();
const waitFor = (attribute, value, timeout) =>
  page.waitForFunction(([a, v]) => document.body.getAttribute(a) === v, [attribute, value], { timeout });

const samples = [];
for (let run = 1; run <= runs; run++) {
  await page.goto(url);
  await waitFor('data-template-ready', 'true', 120_000);
  await page.getByTestId('file-input').setInputFiles([scanPath]);
  await waitFor('data-loads', '1', 120_000);
  await waitFor('data-estimate-state', 'done', 300_000);
  const ms = await page.evaluate(() => Number(document.body.dataset.estimateWorkerMs));
  const markers = await page.evaluate(() => document.getElementById('viewport').dataset.scanMarkers);
  samples.push(ms);
  console.log(`run ${run}: estimate in the landmark worker ${ms.toFixed(0)} ms (${markers} markers)`);
}
const version = browser.version();
await browser.close();
const sorted = [...samples].sort((a, b) => a - b);
const median = sorted.length % 2 ? sorted[(sorted.length - 1) / 2] : (sorted[sorted.length / 2 - 1] + sorted[sorted.length / 2]) / 2;
console.log(`Chromium ${version}; ${runs} runs: median ${median.toFixed(0)} ms, min ${sorted[0].toFixed(0)}, max ${sorted.at(-1).toFixed(0)}`);
