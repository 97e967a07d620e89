// The Batch panel: one row per subject (status with progress, RMS, flags and how many measurements
// are doubtful, time), sortable by any
// column; a click on a row shows that fit; overall progress with the ETA; cancel, retry, exclude,
// build the model, clear the batch; which way is up in scans without a landmark file, and their
// alignment again once it is said.
import type { BatchRow, BatchSummary } from '../app/batch';
import type { MeasurementTrust } from '../shared/align-types';
import { orientationText, type Orientation } from '../shared/orientation';
import { byId, h, morphChildren } from './dom';
import { doubtfulMeasurementsText } from './format';
import { heatLegend } from './heat-legend';
import { orientationControl } from './orientation-control';

export interface BatchActions {
  onSelect(subject: string): void;
  onCancel(subject: string): void;
  onRetry(subject: string): void;
  onExclude(subject: string, excluded: boolean): void;
  /** The batch's orientation, said by the person (null: auto). */
  onOrientation(orientation: Orientation | null): void;
  /** Aligns again, after asking, the finished subjects whose orientation was another. */
  onAlignAgain(): void;
  onCancelAll(): void;
  /** Retries every cancelled or interrupted subject whose scan is stored. */
  onRetryAll(): void;
  onBuild(): void;
  onClear(): void;
}

type Column = 'subject' | 'status' | 'rms' | 'flags' | 'time';

const COLUMNS: { key: Column; label: string; title: string }[] = [
  { key: 'subject', label: 'Subject', title: 'The subject, from the scan file name' },
  { key: 'status', label: 'Status', title: 'Queued, aligning (with progress), ok, flagged, failed, cancelled or excluded' },
  { key: 'rms', label: 'RMS', title: 'Scan → template RMS distance of the fit, mm' },
  { key: 'flags', label: 'Flags', title: "Quality flags of the fit, or why it failed; and how many of its measurements cannot be trusted (landmarks estimated, expected error over ISO 20685-1's limit; hover for which)" },
  { key: 'time', label: 'Time', title: 'Time the alignment took, s' },
];

/** The status as the table writes it: `excluded` over the fit's own, progress while aligning. */
export function statusText(row: BatchRow): string {
  if (row.excluded) return 'excluded';
  if (row.status === 'aligning') return `aligning ${Math.round(row.progress * 100)} %`;
  if (row.status === 'interrupted') return row.scan ? 'interrupted' : 'interrupted — drop its scan again';
  return row.status;
}

/** The summary line: finished (with the failed among them), stopped, aligning, time left. */
function summaryText(s: BatchSummary, eta: string): string {
  const failed = s.failed ? ` (${s.failed} failed)` : '';
  const stopped = s.stopped ? `, ${s.stopped} stopped (cancelled or interrupted)` : '';
  return `${s.finished} of ${s.total} finished${failed}${stopped}, ${s.running} aligning on ${s.workers} worker${s.workers === 1 ? '' : 's'}${eta}.`;
}

function sortValue(row: BatchRow, column: Column): string | number {
  switch (column) {
    case 'subject':
      return row.subject;
    case 'status':
      return statusText(row);
    case 'rms':
      return row.rmsMm ?? Infinity;
    case 'flags':
      return row.fit?.quality.flags.join(' ') ?? '';
    case 'time':
      return row.seconds ?? Infinity;
  }
}

/** The fit's doubtful measurements (`measure/trust.rs`); none for a record stored before them. */
function doubtful(row: BatchRow): MeasurementTrust[] {
  return (row.fit?.report.measurement_trust ?? []).filter((t) => t.doubtful);
}

function formatSeconds(s: number): string {
  return s < 90 ? `${Math.round(s)} s` : `${Math.floor(s / 60)} min ${Math.round(s % 60)} s`;
}

/** The batch's orientation and how many finished subjects were aligned with another one. */
export interface BatchOrientation {
  orientation: Orientation | null;
  alignableAgain: number;
}

export class BatchPanel {
  private readonly root = byId('batch-panel');
  private sort: { column: Column; descending: boolean } = { column: 'subject', descending: false };
  private selected: { subject: string; legendMaxMm: number } | null = null;
  private buildStatus = '';
  private last: { rows: BatchRow[]; summary: BatchSummary; orientation: BatchOrientation } | null = null;

  constructor(private readonly actions: BatchActions) {}

  /** Marks `subject` as the fit in view, with its heat map's top (mm). */
  select(subject: string | null, legendMaxMm = 0): void {
    this.selected = subject ? { subject, legendMaxMm } : null;
    this.redraw();
  }

  showBuildStatus(text: string): void {
    this.buildStatus = text;
    this.redraw();
  }

  render(rows: BatchRow[], summary: BatchSummary, orientation: BatchOrientation): void {
    this.last = { rows, summary, orientation };
    const data = document.body.dataset;
    data.batchOrientation = orientationText(orientation.orientation);
    data.batchTotal = String(summary.total);
    data.batchFinished = String(summary.finished);
    data.batchStopped = String(summary.stopped);
    data.batchRunning = String(summary.running);
    data.batchWorkers = String(summary.workers);
    this.redraw();
  }

  private redraw(): void {
    const last = this.last;
    this.root.hidden = !last || last.rows.length === 0;
    if (!last || last.rows.length === 0) {
      this.root.replaceChildren();
      return;
    }
    const { rows, summary, orientation } = last;
    const button = (text: string, testid: string, run: () => void, disabled = false) => {
      const b = h('button', { class: 'button', type: 'button', 'data-testid': testid, disabled: disabled ? '' : undefined }, text);
      b.addEventListener('click', (e) => {
        e.stopPropagation();
        run();
      });
      return b;
    };
    const active = summary.running > 0 || rows.some((r) => r.status === 'queued');
    const eta = summary.etaSeconds === null ? '' : ` · about ${formatSeconds(summary.etaSeconds)} left`;
    const kept = rows.filter((r) => (r.status === 'ok' || r.status === 'flagged') && !r.excluded && r.fit).length;
    const build = button(kept < 2 ? 'Build model' : `Build model (${kept})`, 'batch-build', () => this.actions.onBuild(), kept < 2);
    if (kept < 2) build.title = `A model needs at least two kept fits; the batch has ${kept}.`;
    // Redrawn every frame while the workers report progress: the live elements are kept where they
    // stay the same, so a click on Cancel or an open Up list is not lost to the next frame.
    const next = h(
      'div',
      {},
      h('h2', {}, 'Batch'),
      h('p', { class: 'note', 'data-testid': 'batch-summary' }, summaryText(summary, eta)),
      ...(summary.notScans
        ? [h('p', { class: 'note', 'data-testid': 'batch-not-scans' }, `${summary.notScans} meshes that are not scans of a body were left out (surface_* and truth_*: ground truths of synthetic subjects).`)]
        : []),
      h('progress', { max: '1', value: summary.fraction.toFixed(3), class: 'batch-progress', 'data-testid': 'batch-progress' }),
      h(
        'div',
        { class: 'row' },
        button('Cancel all', 'batch-cancel-all', () => this.actions.onCancelAll(), !active),
        ...(summary.retryable > 0 ? [button(`Retry all (${summary.retryable})`, 'batch-retry-all', () => this.actions.onRetryAll())] : []),
        build,
        button('Clear batch', 'batch-clear', () => this.actions.onClear()),
      ),
      this.orientationRow(orientation, button),
      h(
        'p',
        { class: 'note', 'data-testid': 'batch-build-status' },
        this.buildStatus || (kept < 2 && summary.running === 0 && !active ? `A model needs at least two kept fits; the batch has ${kept}.` : ''),
      ),
      this.table(rows, button),
      ...(this.selected ? [heatLegend(0, this.selected.legendMaxMm, `${this.selected.subject}: distance of each template vertex to its scan`)] : []),
    );
    morphChildren(this.root, next);
  }

  /**
   * Up and Facing for the scans that come without a landmark file (their landmarks are
   * estimated), and "Align again" for the finished ones aligned with another orientation.
   */
  private orientationRow(o: BatchOrientation, button: (text: string, testid: string, run: () => void) => HTMLButtonElement): HTMLElement {
    const control = orientationControl(o.orientation, false, (next) => this.actions.onOrientation(next), {
      id: 'batch',
      title: 'Which way the body stands in scans dropped without a landmark file: auto lets the estimate find it; alignments that start from now on use what is chosen here',
    });
    const again = button(`Align again with it (${o.alignableAgain})`, 'batch-align-again', () => this.actions.onAlignAgain());
    again.title = `Aligns again, after asking, the ${o.alignableAgain} finished subject${o.alignableAgain === 1 ? '' : 's'} without a landmark file that were aligned with another orientation than ${orientationText(o.orientation)}`;
    return h(
      'div',
      { class: 'batch-orientation' },
      h('span', { class: 'label' }, 'Scans without landmarks:'),
      control,
      ...(o.alignableAgain > 0 ? [again] : []),
    );
  }

  private table(rows: BatchRow[], button: (text: string, testid: string, run: () => void) => HTMLButtonElement): HTMLElement {
    const { column, descending } = this.sort;
    const sorted = [...rows].sort((a, b) => {
      const [x, y] = [sortValue(a, column), sortValue(b, column)];
      const order = typeof x === 'number' && typeof y === 'number' ? x - y : String(x).localeCompare(String(y));
      return descending ? -order : order;
    });
    const head = h(
      'tr',
      {},
      ...COLUMNS.map(({ key, label, title }) => {
        const th = h('th', { 'data-testid': `batch-sort-${key}`, title, 'aria-sort': key === column ? (descending ? 'descending' : 'ascending') : undefined }, label);
        th.addEventListener('click', () => {
          const now = this.sort;
          this.sort = { column: key, descending: key === now.column ? !now.descending : false };
          this.redraw();
        });
        return th;
      }),
    );
    const body = sorted.map((row) => {
      const status = h('td', { 'data-testid': 'batch-status', title: row.reason || row.progressLabel }, statusText(row));
      const flags = row.fit?.quality.flags.map((f) => f.replace('_', ' ')).join(', ') ?? (row.status === 'failed' ? row.reason : '');
      const tr = h(
        'tr',
        {
          'data-testid': 'batch-row',
          'data-subject': row.subject,
          'data-status': row.excluded ? 'excluded' : row.status,
          class: this.selected?.subject === row.subject ? 'selected' : undefined,
        },
        h(
          'td',
          { class: 'batch-subject' },
          h('div', {}, row.subject),
          ...(row.orientation ? [h('div', { class: 'note', 'data-testid': 'batch-row-orientation', title: 'Which way is up, as said for its alignment' }, orientationText(row.orientation))] : []),
          h('div', { class: 'batch-actions' }, ...this.rowActions(row, button)),
        ),
        status,
        h('td', { 'data-testid': 'batch-rms' }, row.rmsMm === null ? '—' : row.rmsMm.toFixed(2)),
        h('td', { class: 'batch-flags', title: row.reason }, flags, ...doubtfulNote(row)),
        h('td', { class: 'batch-time' }, row.seconds === null ? '—' : row.seconds.toFixed(1)),
      );
      const subject = row.subject;
      tr.addEventListener('click', () => {
        if (this.last?.rows.some((r) => r.subject === subject && r.fit)) this.actions.onSelect(subject);
      });
      return tr;
    });
    return h('div', { class: 'batch-scroll' }, h('table', { class: 'batch-table', 'data-testid': 'batch-table' }, h('thead', {}, head), h('tbody', {}, ...body)));
  }

  private rowActions(row: BatchRow, button: (text: string, testid: string, run: () => void) => HTMLButtonElement): HTMLButtonElement[] {
    const s = row.subject;
    if (row.status === 'queued' || row.status === 'aligning') return [button('Cancel', 'batch-cancel', () => this.actions.onCancel(s))];
    if (row.status === 'failed' || row.status === 'cancelled' || row.status === 'interrupted') return [button('Retry', 'batch-retry', () => this.actions.onRetry(s))];
    return [button(row.excluded ? 'Include' : 'Exclude', 'batch-exclude', () => this.actions.onExclude(s, !row.excluded))];
  }
}

/** Under the flags: how many measurements of the fit are doubtful ("11 doubtful"), which in words on hover. */
function doubtfulNote(row: BatchRow): HTMLElement[] {
  const d = doubtful(row);
  if (!d.length) return [];
  return [h('div', { class: 'note', 'data-testid': 'batch-doubtful', title: doubtfulMeasurementsText(d) }, `${d.length} doubtful`)];
}
