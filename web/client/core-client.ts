// Owns a core worker of one role: typed requests queued one at a time, replies matched by id,
// progress callbacks, and cancellation by terminating the worker and starting a fresh one.
import type { CoreEvent, CoreReply, CoreRequest, ResultOf } from '../shared/messages';
import type { RoleRequest, WorkerRole } from '../shared/worker-roles';

/** The rejection of every call pending when `cancel()` ran. */
export class CancelledError extends Error {
  constructor() {
    super('cancelled');
    this.name = 'CancelledError';
  }
}

/** The rejection of a call the core refused; `message` is the core's. */
export class CoreError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'CoreError';
  }
}

export interface CallOptions {
  /** Called for each progress reply: fraction in [0, 1] and what the core is doing. */
  onProgress?: (fraction: number, label: string) => void;
  /** Called for each event of a long call (alignment progress, intermediate positions). */
  onEvent?: (event: CoreEvent) => void;
  /** Buffers moved to the worker instead of copied; detached in the caller afterwards. */
  transfer?: Transferable[];
}

interface Pending {
  resolve: (value: unknown) => void;
  reject: (error: Error) => void;
  onProgress?: CallOptions['onProgress'];
  onEvent?: CallOptions['onEvent'];
}

interface Queued {
  request: CoreRequest;
  transfer: Transferable[];
}

/**
 * The client of a worker of role `W` (`shared/worker-roles.ts`): `call` takes only that role's
 * messages, so a message sent to the wrong worker does not typecheck.
 */
export class CoreClient<W extends WorkerRole> {
  private worker: Worker;
  private nextId = 1;
  private readonly pending = new Map<number, Pending>();
  private readonly queue: Queued[] = [];
  private running: number | null = null;
  private readonly restartListeners: (() => void)[] = [];

  constructor(readonly role: W) {
    this.worker = this.start();
  }

  /** Sends `body` to the worker once earlier calls are done; resolves with the core's result. */
  call<R extends RoleRequest<W>>(body: R, options: CallOptions = {}): Promise<ResultOf<R>> {
    const id = this.nextId++;
    return new Promise<ResultOf<R>>((resolve, reject) => {
      this.pending.set(id, {
        resolve: resolve as (value: unknown) => void,
        reject,
        onProgress: options.onProgress,
        onEvent: options.onEvent,
      });
      this.queue.push({ request: { ...body, id } as CoreRequest, transfer: options.transfer ?? [] });
      this.pump();
    });
  }

  /** Stops whatever the worker is doing: every pending call rejects with `CancelledError`. */
  cancel(): void {
    this.worker.terminate();
    this.queue.length = 0;
    this.running = null;
    const pending = [...this.pending.values()];
    this.pending.clear();
    for (const entry of pending) entry.reject(new CancelledError());
    this.worker = this.start();
  }

  /**
   * Called after a worker whose core trapped was replaced by a fresh one (not after `cancel()`):
   * whatever state the old worker held (a loaded model, a template) is gone and must be sent again.
   */
  onRestart(listener: () => void): void {
    this.restartListeners.push(listener);
  }

  /** Whether a call is running or waiting. */
  get busy(): boolean {
    return this.pending.size > 0;
  }

  /** Replaces a worker whose core trapped; queued calls go to the new one. */
  private restart(): void {
    this.worker.terminate();
    this.worker = this.start();
    for (const listener of this.restartListeners) listener();
  }

  private start(): Worker {
    const worker = startWorker(this.role);
    worker.onmessage = (event: MessageEvent<CoreReply>) => this.receive(event.data);
    worker.onerror = (event: ErrorEvent) => {
      event.preventDefault();
      this.failRunning(`the core worker failed: ${event.message || 'it could not start'}`);
    };
    return worker;
  }

  private pump(): void {
    if (this.running !== null) return;
    const next = this.queue.shift();
    if (!next) return;
    this.running = next.request.id;
    this.worker.postMessage(next.request, next.transfer);
  }

  private receive(reply: CoreReply): void {
    const entry = this.pending.get(reply.id);
    if (!entry) return;
    if (reply.type === 'progress') {
      entry.onProgress?.(reply.fraction, reply.label);
      return;
    }
    if (reply.type === 'event') {
      entry.onEvent?.(reply.event);
      return;
    }
    this.pending.delete(reply.id);
    if (this.running === reply.id) this.running = null;
    if (reply.type === 'result') entry.resolve(reply.result);
    else {
      if (reply.fatal) this.restart();
      entry.reject(new CoreError(reply.message));
    }
    this.pump();
  }

  private failRunning(message: string): void {
    if (this.running === null) return;
    const entry = this.pending.get(this.running);
    this.pending.delete(this.running);
    this.running = null;
    entry?.reject(new CoreError(message));
    this.pump();
  }
}

/** The core worker, named by its role (which it holds its requests to; DevTools shows the name). */
function startWorker(role: WorkerRole): Worker {
  return new Worker(new URL('../worker/core.worker.ts', import.meta.url), { type: 'module', name: role });
}
