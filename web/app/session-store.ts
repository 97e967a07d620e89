// The single scan's work kept in the browser's IndexedDB, so a reload loses nothing: the scan and
// landmark files as they were opened, the units and the frame chosen, the landmark set (each
// landmark given, estimated, edited or absent, where it is) and what the editor showed of it (the
// estimate's verdict, the suspicious ones); and the same of each piece of work put aside, which
// "Back to" brings back. Saved a moment after each change (the files only when they change: a scan
// may weigh tens of MB); read back once, when the page opens.
import type { LandmarkEdits } from './landmark-edits';
import type { ParsedLandmarks, ParsedScan } from '../shared/results';
import { IdbStore } from './idb-store';
import { savedState, type SavedState, type ScanWork, type Session } from './session';

/** One scan's work as stored: its scan (an index into `SavedWork.scans`), its landmark file and the rest. */
export interface SavedScan<View> {
  scan: number;
  landmarks: File | null;
  saved: SavedState;
  /** What the editor showed of its set (null: nothing kept). */
  view: View | null;
}

/** The work as stored: the scan files, each once, and the work on them, the shown one first, then what was put aside, most recent first. */
export interface SavedWork<View> {
  scans: File[];
  works: SavedScan<View>[];
}

/** Record `files`: the scans, each once, and each work's landmark file (the shown one first). */
interface StoredFiles {
  scans: File[];
  landmarks: (File | null)[];
}

/** Record `current`: the rest of each work, in the order of the files' `landmarks`. */
interface StoredState<View> {
  works: (SavedState & { scan: number; view: View | null })[];
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
  private stored: StoredFiles | null = null;

  /** `view`: what the editor shows of a set (the current one, or one put aside), stored with it. */
  constructor(
    private readonly session: Session,
    private readonly view: (edits: LandmarkEdits) => View | null,
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
    const shown = this.session.work();
    if (!shown || !this.files.has(shown.scan)) return;
    // Work whose scan this page did not read (none today) cannot be stored, and is left out.
    const works = [shown, ...this.session.putAside].filter((w) => this.files.has(w.scan));
    const scans: ParsedScan[] = [...new Set(works.map((w) => w.scan))];
    const files: StoredFiles = {
      scans: scans.map((s) => this.files.get(s)!),
      landmarks: works.map((w) => (w.landmarks && this.files.get(w.landmarks)) ?? null),
    };
    const state: StoredState<View> = {
      works: works.map((w: ScanWork) => ({ ...savedState(w), scan: scans.indexOf(w.scan), view: this.view(w.edits) })),
    };
    // The work is kept on the page whatever happens here (a private window refuses the database).
    const filesChanged = !this.stored || !sameFiles(this.stored, files);
    const saved = await (filesChanged ? this.db.run('readwrite', (store) => store.put({ key: 'files', ...files })) : Promise.resolve())
      .then(() => this.db.run('readwrite', (store) => store.put({ key: 'current', ...state })))
      .then(() => true, () => false);
    if (!saved) return;
    this.stored = files;
    document.body.dataset.workSaves = String(++this.saves);
  }

  /** The work saved before the page was reloaded, or null. */
  async load(): Promise<SavedWork<View> | null> {
    const get = <T>(key: string) => this.db.run('readonly', (store) => store.get(key) as IDBRequest<T | undefined>).catch(() => undefined);
    const files = await get<StoredFiles | OneScanFiles>('files');
    const rest = await get<StoredState<View> | OneScanState<View>>('current');
    if (!files || !rest) return null;
    if (!('scans' in files) || !('works' in rest)) return fromOneScan(files as OneScanFiles, rest as OneScanState<View>);
    return { scans: files.scans, works: rest.works.map(({ scan, view, ...saved }, i) => ({ scan, landmarks: files.landmarks[i] ?? null, saved, view })) };
  }
}

function sameFiles(a: StoredFiles, b: StoredFiles): boolean {
  const same = <T>(x: readonly T[], y: readonly T[]) => x.length === y.length && x.every((v, i) => v === y[i]);
  return same(a.scans, b.scans) && same(a.landmarks, b.landmarks);
}

/** The records as saved before work put aside was kept (until 2026-12-06): the shown scan's alone. */
interface OneScanFiles {
  scan: File;
  landmarks: File | null;
}
type OneScanState<View> = SavedState & { view: View | null };

function fromOneScan<View>(files: OneScanFiles, rest: OneScanState<View>): SavedWork<View> {
  const { scanUnits, orientation, landmarksFor, entries, estimateReport, view } = rest;
  return { scans: [files.scan], works: [{ scan: 0, landmarks: files.landmarks, saved: { scanUnits, orientation, landmarksFor, entries, estimateReport }, view }] };
}
