// The single scan's work kept in the browser's IndexedDB, so a reload loses nothing: the scan and
// landmark files as they were opened, the units and the frame chosen, the landmark set (each
// landmark given, estimated, edited or absent, where it is) and what the editor showed of it (the
// estimate's verdict, the suspicious ones). Saved a moment after each change; read back once,
// when the page opens.
import type { EstimateReport, LandmarkEntry } from '../shared/landmark-entry';
import type { Orientation } from '../shared/orientation';
import type { ParsedLandmarks, ParsedScan, Units } from '../shared/results';
import { IdbStore } from './idb-store';
import type { Session } from './session';

/** The work as stored (one record). */
export interface SavedWork<View> {
  key: 'current';
  scan: File;
  landmarks: File | null;
  landmarksFor: string | null;
  scanUnits: Units;
  orientation: Orientation | null;
  entries: LandmarkEntry[];
  estimateReport: EstimateReport | null;
  view: View | null;
}

/** Quiet time (ms) after a change before the work is saved (a burst of edits is saved once). */
const SAVE_DELAY_MS = 300;

export class SessionStore<View> {
  private readonly db = new IdbStore('bodyspace-session', 'work', 'key');
  /** The file each scan and landmark file shown was read from. */
  private readonly files = new WeakMap<ParsedScan | ParsedLandmarks, File>();
  private timer: ReturnType<typeof setTimeout> | null = null;
  /** Saves done (the page's `data-work-saves`). */
  private saves = 0;

  /** `view`: what the editor shows of the current set, stored with it. */
  constructor(
    private readonly session: Session,
    private readonly view: () => View | null,
  ) {}

  /** Remembers the file `parsed` was read from. */
  remember(parsed: ParsedScan | ParsedLandmarks, file: File): void {
    this.files.set(parsed, file);
  }

  /** Saves the work a moment from now (again after each call). */
  saveSoon(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(() => {
      this.timer = null;
      void this.save();
    }, SAVE_DELAY_MS);
  }

  private async save(): Promise<void> {
    const s = this.session;
    const scan = s.scan && this.files.get(s.scan);
    if (!scan || !s.edits) return;
    const record: SavedWork<View> = {
      key: 'current',
      scan,
      landmarks: (s.landmarks && this.files.get(s.landmarks)) ?? null,
      landmarksFor: s.landmarksFor,
      scanUnits: s.scanUnits,
      orientation: s.orientation,
      entries: [...s.edits.all],
      estimateReport: s.estimateReport,
      view: this.view(),
    };
    // The work is kept on the page whatever happens here (a private window refuses the database).
    const saved = await this.db.run('readwrite', (store) => store.put(record)).then(() => true, () => false);
    if (saved) document.body.dataset.workSaves = String(++this.saves);
  }

  /** The work saved before the page was reloaded, or null. */
  async load(): Promise<SavedWork<View> | null> {
    const record = await this.db.run('readonly', (store) => store.get('current') as IDBRequest<SavedWork<View> | undefined>).catch(() => undefined);
    return record ?? null;
  }
}
