// The single scan's work kept in the browser's IndexedDB, so a reload loses nothing: the scan and
// landmark files as they were opened, the units and the frame chosen, the landmark set (each
// landmark given, estimated, edited or absent, where it is) and what the editor showed of it (the
// estimate's verdict, the suspicious ones). Saved a moment after each change (the files only when
// they change: a scan may weigh tens of MB); read back once, when the page opens.
import type { EstimateReport, LandmarkEntry } from '../shared/landmark-entry';
import type { Orientation } from '../shared/orientation';
import type { ParsedLandmarks, ParsedScan, Units } from '../shared/results';
import { IdbStore } from './idb-store';
import type { Session } from './session';

/** The work as stored: the files (record `files`) and the rest (record `current`). */
export interface SavedWork<View> {
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
  /** The saves one after another, so the files and the rest always come from the same moment. */
  private saving: Promise<void> = Promise.resolve();
  /** Saves done (the page's `data-work-saves`). */
  private saves = 0;
  /** The files as last stored. */
  private stored: { scan: File; landmarks: File | null } | null = null;

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
      this.saving = this.saving.then(() => this.save());
    }, SAVE_DELAY_MS);
  }

  private async save(): Promise<void> {
    const s = this.session;
    const scan = s.scan && this.files.get(s.scan);
    if (!scan || !s.edits) return;
    const landmarks = (s.landmarks && this.files.get(s.landmarks)) ?? null;
    const state = {
      key: 'current',
      landmarksFor: s.landmarksFor,
      scanUnits: s.scanUnits,
      orientation: s.orientation,
      entries: [...s.edits.all],
      estimateReport: s.estimateReport,
      view: this.view(),
    };
    // The work is kept on the page whatever happens here (a private window refuses the database).
    const filesChanged = this.stored?.scan !== scan || this.stored.landmarks !== landmarks;
    const saved = await (filesChanged ? this.db.run('readwrite', (store) => store.put({ key: 'files', scan, landmarks })) : Promise.resolve())
      .then(() => this.db.run('readwrite', (store) => store.put(state)))
      .then(() => true, () => false);
    if (!saved) return;
    this.stored = { scan, landmarks };
    document.body.dataset.workSaves = String(++this.saves);
  }

  /** The work saved before the page was reloaded, or null. */
  async load(): Promise<SavedWork<View> | null> {
    const get = <T>(key: string) => this.db.run('readonly', (store) => store.get(key) as IDBRequest<T | undefined>).catch(() => undefined);
    const files = await get<{ scan: File; landmarks: File | null }>('files');
    const rest = await get<Omit<SavedWork<View>, 'scan' | 'landmarks'>>('current');
    return files && rest ? { ...rest, scan: files.scan, landmarks: files.landmarks } : null;
  }
}
