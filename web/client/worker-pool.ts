// A pool of core workers for the batch: several subjects aligned at once, each in a Worker of its
// own (one CoreClient each), so cancelling or a crash of one never touches the others, nor the
// page's other workers (the shape model, the single alignment).
import { CoreClient } from './core-client';

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

/** The pool size for this browser at `resolution` (the pool is sized once, at the batch's first start). */
export function browserPoolSize(resolution: keyof typeof JOB_MEMORY_MIB): number {
  const nav = navigator as Navigator & { deviceMemory?: number };
  return poolSize(nav.hardwareConcurrency, nav.deviceMemory, JOB_MEMORY_MIB[resolution]);
}

/** `size` workers, started on first use; a slot is busy from `take` until `give`. */
export class WorkerPool {
  private readonly clients: (CoreClient | null)[];
  private readonly free: number[];

  constructor(size: number) {
    this.clients = Array.from({ length: size }, () => null);
    this.free = this.clients.map((_, i) => i);
  }

  get size(): number {
    return this.clients.length;
  }

  /** A free slot and its client, or null when all are busy. */
  take(): { slot: number; client: CoreClient } | null {
    const slot = this.free.shift();
    if (slot === undefined) return null;
    const client = this.clients[slot] ?? new CoreClient();
    this.clients[slot] = client;
    return { slot, client };
  }

  give(slot: number): void {
    if (!this.free.includes(slot)) this.free.push(slot);
  }
}
