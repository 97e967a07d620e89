// A pool of core workers for the batch: several subjects aligned at once, each in a Worker of its
// own (one CoreClient each), so cancelling or a crash of one never touches the others, nor the
// page's other workers (the shape model, the single alignment).
import { JOB_MEMORY_MIB, poolSize } from '../shared/pool-size';
import { CoreClient } from './core-client';

/** The pool size for this browser at `resolution` (the pool is sized once, at the batch's first start). */
export function browserPoolSize(resolution: keyof typeof JOB_MEMORY_MIB): number {
  const nav = navigator as Navigator & { deviceMemory?: number };
  return poolSize(nav.hardwareConcurrency, nav.deviceMemory, JOB_MEMORY_MIB[resolution]);
}

/** `size` workers, started on first use; a slot is busy from `take` until `give`. */
export class WorkerPool {
  private readonly clients: (CoreClient<'batch'> | null)[];
  private readonly free: number[];

  constructor(size: number) {
    this.clients = Array.from({ length: size }, () => null);
    this.free = this.clients.map((_, i) => i);
  }

  get size(): number {
    return this.clients.length;
  }

  /** A free slot and its client, or null when all are busy. */
  take(): { slot: number; client: CoreClient<'batch'> } | null {
    const slot = this.free.shift();
    if (slot === undefined) return null;
    const client = this.clients[slot] ?? new CoreClient('batch');
    this.clients[slot] = client;
    return { slot, client };
  }

  give(slot: number): void {
    if (!this.free.includes(slot)) this.free.push(slot);
  }
}
