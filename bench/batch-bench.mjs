// A batch in the real app inside Chromium: every scan and landmark file of DIR picked at once
// ("Open files…"), aligned by the worker pool, then "Build model"; the wall time from the pick to
// the built model, with the pool (as many workers as the browser's cores and memory allow) and
// with one worker, alternately, RUNS times each. Each run opens a fresh browser context (an empty
// IndexedDB). Prints each run and the medians.
// Usage: node bench/batch-bench.mjs URL DIR [RUNS] [base|fine]
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import { launchBenchPage } from './browser.mjs';

const [url, dir, runsArg, resolution = 'base'] = process.argv.slice(2);
const runs = Number(runsArg ?? 2);
const files = readdirSync(dir)
  .filter((name) => /^(scan_\d+\.ply|landmarks_\d+\.lnd)$/.test(name))
  .map((name) => join(dir, name));
const subjects = files.filter((f) => /scan_/.test(f)).length;
const { browser, page: first } = await launchBenchPage();
await first.close();

async function run(workers) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const waitFor = (attribute, value, timeout) =>
    page.waitForFunction(([a, v]) => document.body.getAttribute(a) === v, [attribute, value], { timeout });
  await page.goto(`${url}?debug`);
  await waitFor('data-template-ready', 'true', 120_000);
  await waitFor('data-shape-ready', 'true', 120_000);
  if (resolution !== 'base') {
    await page.getByTestId('template-resolution').selectOption(resolution);
    await waitFor('data-template-resolution', resolution, 300_000);
    await waitFor('data-template-ready', 'true', 300_000);
  }
  if (workers === 1) await page.evaluate(() => window.bodyspaceDebug.setBatchWorkers(1));
  const t0 = Date.now();
  await page.getByTestId('file-input').setInputFiles(files);
  await waitFor('data-batch-total', String(subjects), 120_000);
  await waitFor('data-batch-finished', String(subjects), 1_800_000);
  const aligned = (Date.now() - t0) / 1e3;
  await page.getByTestId('batch-build').click();
  await page.waitForFunction((n) => document.querySelector('[data-testid="batch-build-status"]')?.textContent === `Built from ${n} subjects.`, subjects, { timeout: 300_000 });
  const total = (Date.now() - t0) / 1e3;
  const s = await page.evaluate(() => {
    const rows = [...document.querySelectorAll('[data-testid="batch-row"]')];
    const rms = rows.map((r) => Number(r.querySelector('[data-testid="batch-rms"]').textContent));
    return {
      workers: Number(document.body.dataset.batchWorkers),
      statuses: rows.map((r) => r.dataset.status),
      meanRms: rms.reduce((a, b) => a + b, 0) / rms.length,
      memoryMib: Number(document.body.dataset.batchWasmMemoryMib),
    };
  });
  await context.close();
  const ok = s.statuses.filter((x) => x === 'ok').length;
  const flagged = s.statuses.filter((x) => x === 'flagged').length;
  console.log(
    `${s.workers} worker${s.workers === 1 ? '' : 's'}: aligned in ${aligned.toFixed(1)} s, model built at ${total.toFixed(1)} s ` +
      `(${ok} ok, ${flagged} flagged of ${subjects}; mean RMS ${s.meanRms.toFixed(3)} mm; largest worker WASM memory ${s.memoryMib} MiB)`,
  );
  return { workers: s.workers, aligned, total };
}

const results = [];
for (let i = 0; i < runs; i++) for (const workers of [null, 1]) results.push({ ...(await run(workers)), pool: workers === null });
await browser.close();

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = Math.floor(s.length / 2);
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const pool = results.filter((r) => r.pool);
const one = results.filter((r) => !r.pool);
console.log(`\n${subjects} subjects at ${resolution}, ${runs} runs each (median wall time to the built model):`);
console.log(`  pool of ${pool[0].workers}: ${median(pool.map((r) => r.total)).toFixed(1)} s (aligned ${median(pool.map((r) => r.aligned)).toFixed(1)} s)`);
console.log(`  1 worker:  ${median(one.map((r) => r.total)).toFixed(1)} s (aligned ${median(one.map((r) => r.aligned)).toFixed(1)} s)`);
console.log(`  speed-up:  ${(median(one.map((r) => r.total)) / median(pool.map((r) => r.total))).toFixed(2)}×`);
