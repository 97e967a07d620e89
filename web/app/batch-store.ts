// The batch kept in the browser's IndexedDB, so a reload loses nothing: one record per subject
// with its state, its input files (File objects are stored as blobs) and, once fitted, its fit
// (positions and distances as Float32Array, the core's report and quality flags).
import type { QualityReport, SubjectReport } from '../shared/align-types';
import type { Orientation } from '../shared/orientation';
import type { TemplateResolution } from '../shared/template-data';
import { IdbStore } from './idb-store';

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

/** The batch's records in IndexedDB; every method resolves once the transaction is done. */
export class BatchStore {
  private readonly db = new IdbStore('bodyspace-batch', 'subjects', 'subject');

  /** Every stored subject, in batch order. */
  async all(): Promise<BatchRecord[]> {
    const records = await this.db.run('readonly', (s) => s.getAll() as IDBRequest<BatchRecord[]>);
    return records.sort((a, b) => a.order - b.order);
  }

  put(record: BatchRecord): Promise<IDBValidKey> {
    return this.db.run('readwrite', (s) => s.put(record));
  }

  delete(subject: string): Promise<undefined> {
    return this.db.run('readwrite', (s) => s.delete(subject));
  }

  clear(): Promise<undefined> {
    return this.db.run('readwrite', (s) => s.clear());
  }
}
