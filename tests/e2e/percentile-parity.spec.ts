// Parity of a core rule kept in TypeScript for speed: the UI's `percentileOf`
// (web/shared/anthropometry.ts) against the core's own `percentile_of` (exported by the WASM
// package built into web/pkg), on the same inputs — sorted populations with ties, the values in
// them, between them and beyond them, empty ones. Runs in Node (fast-check).
import { readFileSync } from 'node:fs';
import { test, expect } from '@playwright/test';
import fc from 'fast-check';
import { initSync, percentileOf as corePercentileOf } from '../../web/pkg/bodyspace.js';
import { percentileOf } from '../../web/shared/anthropometry';

test.beforeAll(() => {
  initSync({ module: readFileSync(new URL('../../web/pkg/bodyspace_bg.wasm', import.meta.url)) });
});

/** Both agree exactly (NaN with NaN). */
function same(sorted: number[], value: number): boolean {
  return Object.is(percentileOf(sorted, value), corePercentileOf(Float64Array.from(sorted), value));
}

test('percentileOf gives the core percentile_of on the same inputs', () => {
  // Populations of measurements (a few values often repeated, as rounded readings are) and
  // values from the population itself, near it, or anywhere.
  const reading = fc.oneof(fc.integer({ min: 150, max: 200 }).map((c) => c / 100), fc.double({ min: -1e3, max: 1e3, noNaN: true }));
  const population = fc.array(reading, { maxLength: 300 }).map((xs) => xs.sort((a, b) => a - b));
  fc.assert(
    fc.property(population, fc.nat(), reading, fc.boolean(), (sorted, pick, other, fromPopulation) => {
      const value = fromPopulation && sorted.length > 0 ? sorted[pick % sorted.length]! : other;
      return same(sorted, value);
    }),
    { numRuns: 5_000 },
  );
  // The edges: empty, one value, all equal, infinities and a NaN asked about.
  const cases: [number[], number][] = [
    [[], 1.7],
    [[1.7], 1.7],
    [[1.7], 1.6],
    [[1.7, 1.7, 1.7], 1.7],
    [[-Infinity, 0, Infinity], Infinity],
    [[-Infinity, 0, Infinity], -Infinity],
    [[1, 2, 3], NaN],
  ];
  for (const [sorted, value] of cases) expect(same(sorted, value), `${sorted} / ${value}`).toBe(true);
  expect(percentileOf([1, 2, 2, 3], 2)).toBe(50);
});
