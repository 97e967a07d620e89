// Parses the benchmark PLY in the real app's worker inside Chromium, RUNS times, and prints the
// timings the page records: the worker round trip (UI thread, around the call) and, inside the
// worker, the core call and the copy-out of the arrays. Usage: node bench/browser-bench.mjs URL PLY RUNS
import { launchBenchPage } from './browser.mjs';

const [url, plyPath, runsArg] = process.argv.slice(2);
const runs = Number(runsArg ?? 7);
const { browser, page } = await launchBenchPage();
await page.goto(url);
await page.waitForFunction(() => document.body.dataset.coreReady === 'true', null, { timeout: 60_000 });
const version = browser.version();

const samples = [];
for (let run = 1; run <= runs; run++) {
  const frames = await page.evaluate(() => Number(document.getElementById('viewport').dataset.frames ?? 0));
  await page.getByTestId('file-input').setInputFiles(plyPath);
  await page.waitForFunction((n) => document.body.dataset.loads === String(n), run, { timeout: 120_000 });
  const error = await page.evaluate(() => document.getElementById('error-banner').hidden ? null : document.getElementById('error-banner').textContent);
  if (error) throw new Error(`the app refused the benchmark file: ${error}`);
  // Let the frame showing the new mesh finish so rendering does not overlap the next run.
  await page.waitForFunction((f) => Number(document.getElementById('viewport').dataset.frames ?? 0) > f, frames, { timeout: 120_000 });
  samples.push(
    await page.evaluate(() => ({
      roundTrip: Number(document.body.dataset.lastScanRoundTripMs),
      core: Number(document.body.dataset.lastScanCoreMs),
      copy: Number(document.body.dataset.lastScanCopyMs),
    })),
  );
}
await browser.close();

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = Math.floor(s.length / 2);
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const row = (label, key) => {
  const xs = samples.map((s) => s[key]);
  return `| ${label.padEnd(48)} | ${median(xs).toFixed(1).padStart(8)} | ${Math.min(...xs).toFixed(1).padStart(8)} | ${Math.max(...xs).toFixed(1).padStart(8)} |`;
};
console.log(`Chromium ${version}, ${runs} runs (ms)`);
console.log(`| ${'browser (WASM in the core worker)'.padEnd(48)} | ${'median'.padStart(8)} | ${'min'.padStart(8)} | ${'max'.padStart(8)} |`);
console.log(`|${'-'.repeat(50)}|${'-'.repeat(10)}|${'-'.repeat(10)}|${'-'.repeat(10)}|`);
console.log(row('round trip, UI thread (post → result)', 'roundTrip'));
console.log(row('in worker: core call (read + normals + summary)', 'core'));
console.log(row('in worker: copy out + scale to metres', 'copy'));
