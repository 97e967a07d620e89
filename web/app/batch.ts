// The batch: many subjects dropped at once, aligned by a pool of workers, every state kept in
// IndexedDB so a reload loses nothing, and a model built from the kept fits. Scans and landmark
// files are paired by the core's rule (`pairSubjectFiles`); the fits are screened by the core's
// quality flags (`align/quality.rs`, returned with each alignment).
import { CancelledError, type CoreClient } from '../client/core-client';
import { browserPoolSize, WorkerPool } from '../client/worker-pool';
import type { SubjectOptions } from '../shared/align-types';
import { sameOrientation, type Orientation } from '../shared/orientation';
import type { SubjectPairing } from '../shared/results';
import type { TemplateResolution } from '../shared/template-data';
import { qualityText } from '../ui/format';
import { alignSubject } from './batch-job';
import { BatchStore, type BatchRecord } from './batch-store';
import type { AlignedSubject } from './subjects';

/** What the batch needs of the page at each start: the template resolution and the settings. */
export interface BatchSettings {
  resolution: TemplateResolution;
  options: SubjectOptions;
}

/** A subject as the table shows it: its record and, while aligning, its progress. */
export interface BatchRow extends BatchRecord {
  progress: number;
  progressLabel: string;
}

/**
 * Overall progress: subjects finished (aligned: ok, flagged, or failed in the alignment) of all,
 * those that will not finish without the person (cancelled, interrupted), and the time left.
 */
export interface BatchSummary {
  total: number;
  finished: number;
  /** Of `finished`, the failed ones. */
  failed: number;
  /** Cancelled, or interrupted by a reload without their scan: a retry (or the scan again) finishes them. */
  stopped: number;
  /** Stopped subjects whose scan is stored, so "Retry all" can start them again. */
  retryable: number;
  running: number;
  /** Meshes of the last drop that are not scans of a body, left out. */
  notScans: number;
  /** Fraction of the work done, counting the running subjects' progress. */
  fraction: number;
  /** Seconds left at the pace so far; null before anything finished. */
  etaSeconds: number | null;
  workers: number;
}

/** A running subject: its pool slot and worker, and its cancel signal. */
interface Job {
  slot: number;
  client: CoreClient<'batch'>;
  cancel: AbortController;
}

const FINISHED = new Set(['ok', 'flagged', 'failed']);
const STOPPED = new Set(['cancelled', 'interrupted']);
/** Where the batch's orientation is kept between visits. */
const ORIENTATION_KEY = 'bodyspace-batch-orientation';

/** The stored orientation; null (auto) when none or unreadable. */
function storedOrientation(): Orientation | null {
  try {
    const text = localStorage.getItem(ORIENTATION_KEY);
    return text ? (JSON.parse(text) as Orientation) : null;
  } catch {
    return null;
  }
}

export class Batch {
  private readonly rows = new Map<string, BatchRow>();
  private readonly store = new BatchStore();
  private pool: WorkerPool | null = null;
  /** The running subjects' pool slots and clients. */
  private readonly running = new Map<string, Job>();
  /** Most subjects aligned at once; null: the pool's size (cores, memory). */
  workerLimit: number | null = null;
  /** Start of the current run and the work finished in it, for the ETA. */
  private runStart: number | null = null;
  private finishedInRun = 0;
  /** Writes to the browser's storage not yet finished (shown as `data-batch-saving`). */
  private saving = 0;
  /** Meshes of the last drop that are not scans of a body. */
  private notScans = 0;
  /** The files of the last drop that could not be read, as the banner says them. */
  private unreadable: string[] = [];
  /** `?debug`: the next job traps its worker's core instead of aligning (the crash-isolation test). */
  trapNext = false;
  /** Subjects whose job was trapped on purpose: a failure, not an unreadable file. */
  private readonly trapped = new Set<string>();
  /**
   * Which way is up in the batch's scans as the person said it (null: the estimate finds it);
   * every alignment that starts takes it. Kept in the browser between visits.
   */
  private orientationNow: Orientation | null = storedOrientation();

  constructor(
    private readonly pairing: CoreClient<'core'>,
    private readonly settings: () => BatchSettings | null,
    /** `progress`: only a running subject's progress moved (the page may draw it at the next frame). */
    private readonly onChange: (progress?: boolean) => void,
    private readonly onError: (messages: string[]) => void,
  ) {
    // A reload or close while a change is still being written would lose it: the browser asks first.
    window.addEventListener('beforeunload', (event) => {
      if (this.saving > 0) event.preventDefault();
    });
    document.body.dataset.batchSaving = '0';
  }

  /**
   * Brings back the stored batch. Subjects queued or aligning when the page went away are queued
   * again and start by themselves when their scan is stored; without it they are interrupted
   * (their scan must be dropped again).
   */
  async restore(): Promise<void> {
    try {
      for (const record of await this.store.all()) {
        if (record.status === 'queued' || record.status === 'aligning') {
          record.status = record.scan ? 'queued' : 'interrupted';
          record.reason = record.scan ? '' : 'interrupted by a reload; drop its scan again';
        }
        this.rows.set(record.subject, { ...record, progress: 0, progressLabel: '' });
      }
    } catch (error) {
      this.onError([`The stored batch could not be read: ${error instanceof Error ? error.message : String(error)}`]);
    }
    this.onChange();
    this.pump();
  }

  get orientation(): Orientation | null {
    return this.orientationNow;
  }

  /** States which way is up for the alignments that start from now on (see `alignAgain`). */
  setOrientation(orientation: Orientation | null): void {
    this.orientationNow = orientation;
    try {
      if (orientation) localStorage.setItem(ORIENTATION_KEY, JSON.stringify(orientation));
      else localStorage.removeItem(ORIENTATION_KEY);
    } catch {
      // Not kept between visits (storage refused); this visit still uses it.
    }
    this.onChange();
  }

  /**
   * The subjects a change of orientation concerns: finished (ok, flagged or failed), not
   * excluded, aligned without a landmark file (a given file fixes the frame) with another
   * orientation than the batch's now, and with their scan stored.
   */
  alignableAgain(): BatchRow[] {
    return this.all.filter(
      (r) => FINISHED.has(r.status) && !r.excluded && !r.landmarks && r.scan && !sameOrientation(r.orientation ?? null, this.orientationNow),
    );
  }

  /** Aligns `alignableAgain()` again with the batch's orientation; their fits are replaced. */
  alignAgain(): void {
    for (const row of this.alignableAgain()) this.retry(row.subject);
  }

  /** Whether `files` make a batch: more than one scan dropped or picked at once. */
  static wants(files: File[], isScan: (name: string) => boolean): boolean {
    return files.filter((f) => isScan(f.name)).length > 1;
  }

  /**
   * Adds the subjects among `files` (a subject already in the batch is replaced) and starts them.
   * What the core's pairing leaves out (a second scan of a subject, meshes that are not scans,
   * files of no subject) is said in the banner.
   */
  async add(files: File[]): Promise<void> {
    const pairing = await this.pairing.call({ type: 'pairSubjectFiles', fileNames: files.map((f) => f.name) });
    this.unreadable = [];
    const errors = pairing.duplicates.map(
      (d) => `${files[d.file]!.name}: a second scan of subject ${subjectOf(pairing, d.kept)}; ${files[d.kept]!.name} was kept and this one left out`,
    );
    if (pairing.not_scans.length) {
      const names = pairing.not_scans.map((i) => files[i]!.name);
      errors.push(`${names.join(', ')}: not scans of a body (ground truths of synthetic subjects); left out`);
    }
    this.notScans = pairing.not_scans.length;
    document.body.dataset.batchNotScans = String(this.notScans);
    let order = Math.max(-1, ...[...this.rows.values()].map((r) => r.order)) + 1;
    const settings = this.settings();
    for (const s of pairing.subjects) {
      const old = this.rows.get(s.subject);
      if (old && this.running.has(s.subject)) this.cancel(s.subject);
      const row: BatchRow = {
        subject: s.subject,
        order: old?.order ?? order++,
        status: 'queued',
        excluded: false,
        reason: '',
        rmsMm: null,
        seconds: null,
        resolution: settings?.resolution ?? 'base',
        scan: files[s.scan]!,
        landmarks: s.landmarks === null ? null : files[s.landmarks]!,
        fit: null,
        progress: 0,
        progressLabel: '',
      };
      this.rows.set(s.subject, row);
      await this.save(row);
    }
    const unpaired = pairing.unpaired.map((i) => files[i]!.name);
    if (unpaired.length) errors.push(`${unpaired.join(', ')}: no scan of the same base name among the files dropped; left out`);
    if (errors.length) this.onError(errors);
    this.onChange();
    this.pump();
  }

  get all(): BatchRow[] {
    return [...this.rows.values()].sort((a, b) => a.order - b.order);
  }

  row(subject: string): BatchRow | undefined {
    return this.rows.get(subject);
  }

  summary(): BatchSummary {
    const rows = this.all;
    const finished = rows.filter((r) => FINISHED.has(r.status)).length;
    const stopped = rows.filter((r) => STOPPED.has(r.status));
    const inFlight = rows.filter((r) => r.status === 'aligning').reduce((sum, r) => sum + r.progress, 0);
    const work = rows.filter((r) => r.status === 'queued' || r.status === 'aligning').length;
    const doneInRun = this.finishedInRun + inFlight;
    const elapsed = this.runStart === null ? 0 : (performance.now() - this.runStart) / 1e3;
    const left = work - inFlight;
    return {
      total: rows.length,
      finished,
      failed: rows.filter((r) => r.status === 'failed').length,
      stopped: stopped.length,
      retryable: stopped.filter((r) => r.scan).length,
      running: this.running.size,
      notScans: this.notScans,
      fraction: rows.length ? (finished + inFlight) / rows.length : 0,
      etaSeconds: work > 0 && this.finishedInRun > 0 ? (elapsed / doneInRun) * left : null,
      workers: this.workers(),
    };
  }

  /** The subjects a model is built from: ok or flagged, not excluded, with a fit. */
  kept(): AlignedSubject[] {
    return this.all
      .filter((r) => (r.status === 'ok' || r.status === 'flagged') && !r.excluded && r.fit)
      .map((r) => ({ name: r.subject, positions: r.fit!.positions, resolution: r.resolution, source: 'batch', rmsMetres: (r.rmsMm ?? NaN) / 1e3 }));
  }

  cancel(subject: string): void {
    const row = this.rows.get(subject);
    if (!row) return;
    const job = this.running.get(subject);
    // Terminates that worker only (a fresh one takes its slot); the job's call under way rejects.
    if (job) {
      job.cancel.abort();
      job.client.cancel();
    }
    else if (row.status === 'queued') void this.finish(row, 'cancelled', 'cancelled before it started');
  }

  cancelAll(): void {
    for (const row of this.all) if (row.status === 'queued' || row.status === 'aligning') this.cancel(row.subject);
  }

  retry(subject: string): void {
    const row = this.rows.get(subject);
    if (!row || this.running.has(subject) || row.status === 'queued') return;
    if (!row.scan) {
      this.onError([`${subject}: its scan is not stored in this browser; drop it again to align it`]);
      return;
    }
    Object.assign(row, { status: 'queued', reason: '', rmsMm: null, seconds: null, fit: null, progress: 0 });
    void this.save(row);
    this.onChange();
    this.pump();
  }

  /** Retries every cancelled or interrupted subject whose scan is stored. */
  retryAll(): void {
    for (const row of this.all) if (STOPPED.has(row.status) && row.scan) this.retry(row.subject);
  }

  setExcluded(subject: string, excluded: boolean): void {
    const row = this.rows.get(subject);
    if (!row) return;
    row.excluded = excluded;
    void this.save(row);
    this.onChange();
  }

  /** Cancels everything and forgets the batch, here and in the browser's storage. */
  async clear(): Promise<void> {
    this.cancelAll();
    this.rows.clear();
    this.runStart = null;
    this.notScans = 0;
    try {
      await this.store.clear();
    } catch (error) {
      this.onError([`The stored batch could not be cleared: ${error instanceof Error ? error.message : String(error)}`]);
    }
    this.onChange();
  }

  private workers(): number {
    const size = this.pool?.size ?? browserPoolSize(this.settings()?.resolution ?? 'base');
    return Math.min(size, this.workerLimit ?? size);
  }

  /** Starts queued subjects while workers are free (and once the page has its settings). */
  pump(): void {
    const settings = this.settings();
    if (!settings) return;
    this.pool ??= new WorkerPool(browserPoolSize(settings.resolution));
    for (const row of this.all) {
      if (row.status !== 'queued') continue;
      if (this.running.size >= this.workers()) break;
      const taken = this.pool.take();
      if (!taken) break;
      if (this.runStart === null) {
        this.runStart = performance.now();
        this.finishedInRun = 0;
      }
      void this.runJob(row, { ...taken, cancel: new AbortController() }, settings);
    }
    if (this.running.size === 0) this.runStart = null;
  }

  private async runJob(row: BatchRow, job: Job, settings: BatchSettings): Promise<void> {
    this.running.set(row.subject, job);
    Object.assign(row, { status: 'aligning', progress: 0, progressLabel: 'reading', resolution: settings.resolution, orientation: settings.options.orientation ?? null });
    void this.save(row);
    this.onChange();
    const t0 = performance.now();
    // Until the first progress the job only reads the files: a failure then is a file that cannot
    // be read, which no retry mends.
    let reading = true;
    try {
      if (!row.scan) throw new Error('its scan is not stored in this browser; drop it again');
      if (this.trapNext) {
        this.trapNext = false;
        this.trapped.add(row.subject);
        await job.client.call({ type: 'trap' });
      }
      const result = await alignSubject(job.client, { scan: row.scan, landmarks: row.landmarks }, settings.resolution, settings.options, (fraction, label) => {
        reading = false;
        row.progress = fraction;
        row.progressLabel = label;
        this.onChange(true);
      }, job.cancel.signal);
      reading = false;
      row.seconds = (performance.now() - t0) / 1e3;
      row.rmsMm = result.report.fine.scan_to_template.rms_mm;
      row.fit = { positions: result.positions, distances: result.distances, report: result.report, quality: result.quality };
      // The largest worker memory seen, for the pool's per-job estimate (docs/batch.md).
      const mib = Math.round(result.wasmMemoryBytes / 2 ** 20);
      document.body.dataset.batchWasmMemoryMib = String(Math.max(mib, Number(document.body.dataset.batchWasmMemoryMib ?? 0)));
      const flags = result.quality.flags;
      await this.finish(row, flags.length ? 'flagged' : 'ok', flags.length ? qualityText(result.quality) : '', job);
    } catch (error) {
      row.seconds = (performance.now() - t0) / 1e3;
      if (error instanceof CancelledError) await this.finish(row, 'cancelled', 'cancelled', job);
      else if (reading && !this.trapped.delete(row.subject)) await this.dropUnreadable(row, error, job);
      else await this.finish(row, 'failed', error instanceof Error ? error.message : String(error), job);
    }
  }

  private async finish(row: BatchRow, status: BatchRow['status'], reason: string, job?: Job): Promise<void> {
    Object.assign(row, { status, reason, progress: 0, progressLabel: '' });
    if (job) {
      if (this.running.get(row.subject) === job) this.running.delete(row.subject);
      this.pool?.give(job.slot);
      this.finishedInRun++;
    }
    // A subject cleared or replaced meanwhile is not written back.
    if (this.rows.get(row.subject) === row) await this.save(row);
    this.onChange();
    this.pump();
  }

  /**
   * A subject whose files cannot be read leaves the batch: the banner names the file and the
   * problem (every such file of the drop at once), as for a single file.
   */
  private async dropUnreadable(row: BatchRow, error: unknown, job: Job): Promise<void> {
    const message = error instanceof Error ? error.message : String(error);
    const named = [row.scan?.name, row.landmarks?.name].some((n) => n && message.startsWith(n));
    this.unreadable.push(`${named ? '' : `${row.scan?.name ?? row.subject}: `}${message}; left out of the batch`);
    this.onError([...this.unreadable]);
    if (this.running.get(row.subject) === job) this.running.delete(row.subject);
    this.pool?.give(job.slot);
    if (this.rows.get(row.subject) === row) {
      this.rows.delete(row.subject);
      try {
        await this.store.delete(row.subject);
      } catch {
        // Not stored: nothing to forget.
      }
    }
    this.onChange();
    this.pump();
  }

  private async save(row: BatchRow): Promise<void> {
    const { progress: _p, progressLabel: _l, ...record } = row;
    document.body.dataset.batchSaving = String(++this.saving);
    try {
      await this.store.put(record);
    } catch (error) {
      this.onError([`${row.subject}: could not be stored in this browser (${error instanceof Error ? error.message : String(error)}); it will not come back after a reload`]);
    } finally {
      document.body.dataset.batchSaving = String(--this.saving);
    }
  }
}

/** The subject whose scan is file `scan` of the pairing. */
function subjectOf(pairing: SubjectPairing, scan: number): string {
  return pairing.subjects.find((s) => s.scan === scan)?.subject ?? '';
}
