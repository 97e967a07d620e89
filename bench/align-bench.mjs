// Aligns a scan in the real app's worker inside Chromium, RUNS times, at one template resolution,
// and prints the times the app records (RBF warp, scan index, fine alignment, total in the worker,
// round trip on the UI thread) with the scan→template RMS. A `fine` template is aligned coarse to
// fine; its base stage is printed too.
// Usage: node bench/align-bench.mjs URL SCAN LANDMARKS base|fine RUNS
import { launchBenchPage } from './browser.mjs';

const [url, scanPath, landmarksPath, resolution = 'base', runsArg] = process.argv.slice(2);
const runs = Number(runsArg ?? 3);
const { browser, page } = await launchBenchPage();
await page.goto(url);
const waitFor = (attribute, value, timeout) =>
  page.waitForFunction(([a, v]) => document.body.getAttribute(a) === v, [attribute, value], { timeout });
await waitFor('data-template-ready', 'true', 120_000);
if (resolution !== 'base') {
  await page.getByTestId('template-resolution').selectOption(resolution);
  await waitFor('data-template-resolution', resolution, 300_000);
  await waitFor('data-template-ready', 'true', 300_000);
}
await page.getByTestId('file-input').setInputFiles([scanPath, landmarksPath]);
await waitFor('data-loads', '1', 120_000);
const error = await page.evaluate(() => (document.getElementById('error-banner').hidden ? null : document.getElementById('error-banner').textContent));
if (error) throw new Error(`the app refused the benchmark files: ${error}`);
// Loading a scan with landmarks warps once; wait for it so it does not overlap the first run.
await waitFor('data-rbf-state', 'done', 300_000);
const version = browser.version();

const samples = [];
for (let run = 1; run <= runs; run++) {
  await page.getByTestId('align-run').click();
  await waitFor('data-align-state', 'done', 900_000);
  const s = await page.evaluate(() => {
    const d = document.body.dataset;
    return {
      roundTrip: Number(d.alignRoundTripMs),
      worker: Number(d.alignWorkerMs),
      total: Number(d.alignTotalMs),
      rough: Number(d.alignRoughMs),
      index: Number(d.alignIndexMs),
      fine: Number(d.alignFineMs),
      base: Number(d.alignBaseStageMs),
      iterations: Number(d.alignIterations),
      vertices: Number(d.alignTemplateVertices),
      rms: Number(document.querySelector('[data-testid="align-rms"]').dataset.rmsMm),
    };
  });
  samples.push(s);
  console.log(
    `run ${run}: core ${s.total.toFixed(0)} ms (RBF ${s.rough.toFixed(0)}, index ${s.index.toFixed(0)}, fine ${s.fine.toFixed(0)}), ` +
      `worker call ${s.worker.toFixed(0)} ms, round trip ${s.roundTrip.toFixed(0)} ms, ${s.iterations} iterations, RMS ${s.rms.toFixed(3)} mm`,
  );
}
await browser.close();

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = Math.floor(s.length / 2);
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const row = (label, key, digits = 0) => {
  const xs = samples.map((s) => s[key]);
  const f = (x) => x.toFixed(digits).padStart(8);
  return `| ${label.padEnd(52)} | ${f(median(xs))} | ${f(Math.min(...xs))} | ${f(Math.max(...xs))} |`;
};
const first = samples[0];
console.log(`Chromium ${version}; template ${resolution} (${first.vertices} vertices); ${runs} runs (ms)`);
console.log(`| ${'browser (WASM in the core worker)'.padEnd(52)} | ${'median'.padStart(8)} | ${'min'.padStart(8)} | ${'max'.padStart(8)} |`);
console.log(`|${'-'.repeat(54)}|${'-'.repeat(10)}|${'-'.repeat(10)}|${'-'.repeat(10)}|`);
console.log(row('RBF warp', 'rough'));
console.log(row('scan index', 'index'));
if (resolution === 'fine') {
  console.log(row('fine alignment: base stage', 'base'));
  console.log(row('fine alignment: both stages', 'fine'));
} else {
  console.log(row('fine alignment', 'fine'));
}
console.log(row('core total (warp + index + fine + report)', 'total'));
console.log(row('worker call (inputs in, core, outputs copied out)', 'worker'));
console.log(row('round trip, UI thread (post → result)', 'roundTrip'));
console.log(row('scan→template RMS (mm)', 'rms', 3));
console.log(row('iterations', 'iterations'));
