// Messages between the UI thread and the core worker. No DOM here: shared by both threads.

/** A request to the worker; `id` pairs it with its reply. */
export type CoreRequest = { id: number; type: 'version' };

/** A reply from the worker. */
export type CoreReply =
  | { id: number; type: 'result'; result: unknown }
  | { id: number; type: 'error'; message: string }
  | { id: number; type: 'progress'; fraction: number; label: string };
