// How many batch workers a machine runs at once: its cores, capped by its memory. No DOM here.

/**
 * Peak memory of one batch job, MiB: the worker's WASM memory after aligning a subject, measured
 * with `npm run bench` (batch part) on 116K–185K-vertex synthetic scans — 88 MiB at `base`, 455 MiB
 * at `fine` — rounded up for the worker's own JavaScript heap and the scan copies in flight (that
 * margin is an allowance, not a measurement). docs/batch.md, "In the browser".
 */
export const JOB_MEMORY_MIB = { base: 120, fine: 500 } as const;

/** The share of the device's memory the pool may take (the page, the view and the other workers keep the rest). */
const MEMORY_SHARE = 0.5;

/**
 * How many workers align at once: the machine's cores, at most what memory allows when the browser
 * tells it (`navigator.deviceMemory`, GiB, rounded and capped by the browser), at least one.
 */
export function poolSize(cores: number | undefined, deviceMemoryGib: number | undefined, jobMib: number): number {
  const byCores = Math.max(1, Math.floor(cores ?? 1));
  if (!deviceMemoryGib || !(deviceMemoryGib > 0)) return byCores;
  return Math.max(1, Math.min(byCores, Math.floor((deviceMemoryGib * 1024 * MEMORY_SHARE) / jobMib)));
}
