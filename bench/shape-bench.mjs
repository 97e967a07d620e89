// Times the app's morphing path in the real core worker inside Chromium. Opens a link that gives
// all six segments their own coefficients (0.5σ on every mode: the whole body and six segment
// models reconstructed and stitched), then at `base` and at `fine`:
//   * slider moves: RUNS single-slider moves, whole-body and torso sliders in turn (the worker
//     applies one rank-1 update to the body it holds);
//   * full rebuilds: RUNS presses of "Random body" (every coefficient changes: reconstructed from
//     scratch).
// For each it reads what the page records: the core call in the worker, the copy-out of the
// positions, the vertex normals, measurements + seam report, and the round trip on the UI thread
// (post → the new arrays in the body's vertex buffers; rendering excluded: the bench waits for
// the frame to finish before the next move). Usage: node bench/shape-bench.mjs URL RUNS
import { launchBenchPage } from './browser.mjs';
import { row as tableRow } from './table.mjs';

const [url, runsArg] = process.argv.slice(2);
const runs = Number(runsArg ?? 30);
const { browser, page } = await launchBenchPage();
// 0.5σ on 20 modes of every part (int16 500 little-endian, base64url).
const values = Buffer.alloc(40);
for (let k = 0; k < 20; k++) values.writeInt16LE(500, 2 * k);
const b64 = values.toString('base64url');
const segments = ['head', 'left_arm', 'right_arm', 'torso', 'left_leg', 'right_leg'].map((s) => `${s}.${b64}`).join('~');
await page.goto(`${url}#m=models%2Fdemo.bsm&w=${b64}&s=${segments}&v=whole`);
await page.waitForFunction(() => document.body.dataset.linkRestored === 'true' && document.body.dataset.shapeSettled === 'true', null, { timeout: 120_000 });
// The population worker measures the model's sampled bodies for a few seconds after it opens:
// wait for it, so its work on the other core does not count in these timings.
await page.waitForFunction(() => document.body.dataset.populationReady === 'true', null, { timeout: 300_000 });

const FIELDS = {
  core: 'shapeReconstructMs',
  copy: 'shapeCopyMs',
  normals: 'shapeNormalsMs',
  measure: 'shapeMeasureMs',
  worker: 'shapeWorkerMs',
  roundTrip: 'shapeRoundTripMs',
};

/** Runs `act`, waits for the next body and its frame, returns the page's timings. */
async function timed(act) {
  const before = await page.evaluate(() => ({
    bodies: Number(document.body.dataset.shapeBodies),
    frames: Number(document.getElementById('viewport').dataset.frames ?? 0),
  }));
  await act();
  await page.waitForFunction(
    (b) => Number(document.body.dataset.shapeBodies) > b.bodies && document.body.dataset.shapeSettled === 'true',
    before,
    { timeout: 60_000 },
  );
  await page.waitForFunction((f) => Number(document.getElementById('viewport').dataset.frames ?? 0) > f, before.frames, { timeout: 60_000 });
  return page.evaluate((fields) => {
    const d = document.body.dataset;
    const out = { rebuilt: d.shapeRebuilt === 'true', deltas: Number(d.shapeDeltas) };
    for (const [key, name] of Object.entries(fields)) out[key] = Number(d[name]);
    return out;
  }, FIELDS);
}

async function sliderMoves() {
  const samples = [];
  for (let run = 0; run < runs; run++) {
    const view = run % 2 === 0 ? 'whole' : 'torso';
    if ((await page.getByTestId('shape-segment').inputValue()) !== view) await page.getByTestId('shape-segment').selectOption(view);
    const mode = run % 5;
    const sigma = (((run * 7) % 11) - 5) * 0.5;
    const sample = await timed(() => page.getByTestId(`shape-slider-${mode}`).fill(String(sigma === 0 ? 0.25 : sigma)));
    if (sample.rebuilt) throw new Error(`slider move ${run} rebuilt the body instead of updating it`);
    samples.push(sample);
  }
  return samples;
}

async function rebuilds() {
  const samples = [];
  for (let run = 0; run < runs; run++) {
    const sample = await timed(() => page.getByTestId('shape-random').click());
    if (!sample.rebuilt) throw new Error(`random body ${run} was not rebuilt`);
    samples.push(sample);
  }
  return samples;
}

const row = (label, xs) => tableRow(label, xs, 58);

function table(resolution, moves, full) {
  const info = `${resolution}: ${moves.length} slider moves, ${full.length} full rebuilds (ms)`;
  console.log(info);
  console.log(`| ${'in the worker (WASM) / on the UI thread'.padEnd(58)} | ${'median'.padStart(8)} | ${'min'.padStart(8)} | ${'max'.padStart(8)} |`);
  console.log(`|${'-'.repeat(60)}|${'-'.repeat(10)}|${'-'.repeat(10)}|${'-'.repeat(10)}|`);
  console.log(row('slider move: core update (rank-1, compensated)', moves.map((s) => s.core)));
  console.log(row('slider move: copy positions out', moves.map((s) => s.copy)));
  console.log(row('slider move: vertex normals (core) + copy out', moves.map((s) => s.normals)));
  console.log(row('slider move: measurements + seam report (base vertices)', moves.map((s) => s.measure)));
  console.log(row('slider move: everything in the worker', moves.map((s) => s.worker)));
  console.log(row('slider move: round trip, UI thread (post → vertex buffers)', moves.map((s) => s.roundTrip)));
  console.log(row('full rebuild: core reconstruction (7 × 20 modes, stitched)', full.map((s) => s.core)));
  console.log(row('full rebuild: round trip, UI thread', full.map((s) => s.roundTrip)));
}

const info = await page.evaluate(() => ({ modes: document.body.dataset.shapeModes }));
console.log(`Chromium ${browser.version()}; demo model, ${info.modes} whole-body modes, every part's modes at 0.5σ, six segments overridden and stitched`);
const baseMoves = await sliderMoves();
const baseFull = await rebuilds();
table('base (13,380 vertices)', baseMoves, baseFull);

const t0 = Date.now();
await page.getByTestId('shape-resolution').selectOption('fine');
await page.waitForFunction(() => document.body.dataset.shapeVertices === '214050' && document.body.dataset.shapeSettled === 'true', null, { timeout: 300_000 });
console.log(`\nSwitch to fine (fine template built in the worker + model mapped + first body): ${((Date.now() - t0) / 1000).toFixed(1)} s`);
const fineMoves = await sliderMoves();
const fineFull = await rebuilds();
table('fine (214,050 vertices)', fineMoves, fineFull);
await browser.close();
