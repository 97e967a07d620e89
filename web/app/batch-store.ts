// The batch kept in the browser's IndexedDB, so a reload loses nothing: one record per subject
// with its state, its input files (File objects are stored as blobs) and, once fitted, its fit
// (positions and distances as Float32Array, the core's report and quality flags).
import type { QualityReport, SubjectReport } from '../shared/align-types';
import type { Orientation } from '../shared/orientation';
import type { TemplateResolution } from '../shared/template-data';

/** Where a subject stands. `interrupted`: it was queued or aligning when the page went away. */
export type BatchStatus = 'queued' | 'aligning' | 'ok' | 'flagged' | 'failed' | 'cancelled' | 'interrupted';

/** A finished fit: the template's vertices fitted to the scan. */
export interface BatchFit {
  /** `#V·3` positions, metres, the scan's frame, template order. */
  positions: Float32Array;
  /** `#V` distance of each fitted vertex to the scan, metres. */
  distances: Float32Array;
  /** The core's subject report (records stored before it carried `measurement_trust` lack it). */
  report: SubjectReport;
  quality: QualityReport;
}

/** One subject of the batch as stored. */
export interface BatchRecord {
  subject: string;
  /** Position in the batch (the order subjects were added). */
  order: number;
  status: BatchStatus;
  /** Left out of the model by the person (the status stays what the fit was). */
  excluded: boolean;
  /** Why it failed, or what the flags mean, for the table. */
  reason: string;
  rmsMm: number | null;
  seconds: number | null;
  resolution: TemplateResolution;
  /**
   * Which way is up as the person said it for this subject's last alignment (null: auto; absent
   * in records stored before the batch took an orientation). Used only where the landmarks are
   * estimated: a scan without a landmark file.
   */
  orientation?: Orientation | null;
  scan: File | null;
  landmarks: File | null;
  fit: BatchFit | null;
}

const DB_NAME = 'bodyspace-batch';
const STORE = 'subjects';

function request<T>(r: IDBRequest<T>): Promise<T> {
  return new Promise((resolve, reject) => {
    r.onsuccess = () => resolve(r.result);
    r.onerror = () => reject(r.error ?? new Error('IndexedDB request failed'));
  });
}

/** The batch's records in IndexedDB; every method resolves once the transaction is done. */
export class BatchStore {
  private db: Promise<IDBDatabase> | null = null;

  private open(): Promise<IDBDatabase> {
    this.db ??= new Promise((resolve, reject) => {
      const r = indexedDB.open(DB_NAME, 1);
      r.onupgradeneeded = () => r.result.createObjectStore(STORE, { keyPath: 'subject' });
      r.onsuccess = () => resolve(r.result);
      r.onerror = () => reject(r.error ?? new Error('the browser refused its database (private mode?)'));
    });
    return this.db;
  }

  private async run<T>(mode: IDBTransactionMode, f: (store: IDBObjectStore) => IDBRequest<T>): Promise<T> {
    const db = await this.open();
    const tx = db.transaction(STORE, mode);
    const result = request(f(tx.objectStore(STORE)));
    await new Promise<void>((resolve, reject) => {
      tx.oncomplete = () => resolve();
      tx.onerror = tx.onabort = () => reject(tx.error ?? new Error('IndexedDB transaction failed'));
    });
    return result;
  }

  /** Every stored subject, in batch order. */
  async all(): Promise<BatchRecord[]> {
    const records = await this.run('readonly', (s) => s.getAll() as IDBRequest<BatchRecord[]>);
    return records.sort((a, b) => a.order - b.order);
  }

  put(record: BatchRecord): Promise<IDBValidKey> {
    return this.run('readwrite', (s) => s.put(record));
  }

  delete(subject: string): Promise<undefined> {
    return this.run('readwrite', (s) => s.delete(subject));
  }

  clear(): Promise<undefined> {
    return this.run('readwrite', (s) => s.clear());
  }
}
