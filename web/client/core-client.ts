// Owns the core worker: typed requests, replies matched by id.
import type { CoreReply, CoreRequest } from '../shared/messages';

export class CoreClient {
  private readonly worker: Worker;
  private nextId = 1;
  private readonly pending = new Map<number, { resolve: (v: unknown) => void; reject: (e: Error) => void }>();

  constructor() {
    this.worker = new Worker(new URL('../worker/core.worker.ts', import.meta.url), { type: 'module' });
    this.worker.onmessage = (event: MessageEvent<CoreReply>) => {
      const reply = event.data;
      const entry = this.pending.get(reply.id);
      if (!entry) return;
      if (reply.type === 'result') {
        this.pending.delete(reply.id);
        entry.resolve(reply.result);
      } else if (reply.type === 'error') {
        this.pending.delete(reply.id);
        entry.reject(new Error(reply.message));
      }
    };
  }

  version(): Promise<string> {
    return this.call({ type: 'version' }) as Promise<string>;
  }

  private call(request: Omit<CoreRequest, 'id'>): Promise<unknown> {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.worker.postMessage({ ...request, id } as CoreRequest);
    });
  }
}
