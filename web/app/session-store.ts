// The single scan's work kept in the browser's IndexedDB, so a reload loses nothing: the scan and
// landmark files as they were opened, the units and the frame chosen, the landmark set (each
// landmark given, estimated, edited or absent, where it is) and what the editor showed of it (the
// estimate's verdict, the suspicious ones); and the same of each piece of work put aside, which
// "Back to" brings back. Saved a moment after each change. Each file is a record of its own,
// written once (a scan may weigh tens of MB) and deleted once no work uses it (forgotten); the
// record `current` holds the rest. Read back once, when the page opens.
import type { ParsedLandmarks, ParsedScan } from '../shared/results';
import { IdbStore } from './idb-store';
import type { LandmarkEdits } from './landmark-edits';
import { savedState, type SavedState, type Session } from './session';

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

/** Record `current`: each work's files (their records' keys) and the rest, the shown one first. */
interface StoredState<View> {
  works: (SavedState & { scanFile: string; landmarksFile: string | null; view: View | null })[];
}

/** Quiet time (ms) after a change before the work is saved (a burst of edits is saved once). */
const SAVE_DELAY_MS = 300;

export class SessionStore<View> {
  private readonly db = new IdbStore('bodyspace-session', 'work', 'key');
  /** The file each scan and landmark file shown was read from, with the key of its record. */
  private readonly files = new WeakMap<ParsedScan | ParsedLandmarks, { file: File; key: string }>();
  /** Keys of the file records stored (or found stored when the page opened). */
  private stored = new Set<string>();
  private timer: ReturnType<typeof setTimeout> | null = null;
  /** The saves one after another, so the files and the rest always come from the same moment. */
  private saving: Promise<void> = Promise.resolve();
  /** Saves done (the page's `data-work-saves`). */
  private saves = 0;
  /** The records were read in the one-scan layout: its `files` record goes at the next save. */
  private legacy = false;

  /** `view`: what the editor shows of a set (the current one, or one put aside), stored with it. */
  constructor(
    private readonly session: Session,
    private readonly view: (edits: LandmarkEdits) => View | null,
  ) {}

  /** Remembers the file `parsed` was read from; `key`, its record's when it was read back from one. */
  remember(parsed: ParsedScan | ParsedLandmarks, file: File, key: string = newFileKey()): void {
    this.files.set(parsed, { file, key });
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
    const used = new Map<string, File>();
    const keyOf = (parsed: ParsedScan | ParsedLandmarks | null) => {
      const f = parsed && this.files.get(parsed);
      if (f) used.set(f.key, f.file);
      return f?.key ?? null;
    };
    const state: StoredState<View> = {
      works: works.map((w) => ({ ...savedState(w), scanFile: keyOf(w.scan)!, landmarksFile: keyOf(w.landmarks), view: this.view(w.edits) })),
    };
    // The work is kept on the page whatever happens here (a private window refuses the database).
    try {
      for (const [key, file] of used) {
        if (!this.stored.has(key)) await this.db.run('readwrite', (store) => store.put({ key, file }));
        this.stored.add(key);
      }
      await this.db.run('readwrite', (store) => store.put({ key: 'current', ...state }));
      if (this.legacy) {
        await this.db.run('readwrite', (store) => store.delete('files'));
        this.legacy = false;
      }
      for (const key of [...this.stored].filter((k) => !used.has(k))) {
        await this.db.run('readwrite', (store) => store.delete(key));
        this.stored.delete(key);
      }
    } catch {
      return;
    }
    document.body.dataset.workSaves = String(++this.saves);
  }

  /** The work saved before the page was reloaded, or null; `keys`, the record of each scan and landmark file in it, for [`remember`]. */
  async load(): Promise<(SavedWork<View> & { keys: Map<File, string> }) | null> {
    const get = <T>(key: string) => this.db.run('readonly', (store) => store.get(key) as IDBRequest<T | undefined>).catch(() => undefined);
    const rest = await get<StoredState<View> | OneScanState<View>>('current');
    if (!rest) return null;
    if (!('works' in rest)) {
      const files = await get<OneScanFiles>('files');
      this.legacy = Boolean(files);
      return files ? fromOneScan(files, rest) : null;
    }
    // A file record no work names (a save cut short between its writes) is dropped.
    const named = new Set(rest.works.flatMap((w) => [w.scanFile, w.landmarksFile]));
    const all = await this.db.run('readonly', (store) => store.getAllKeys()).catch(() => []);
    for (const key of all) {
      if (typeof key === 'string' && key.startsWith('file:') && !named.has(key)) await this.db.run('readwrite', (store) => store.delete(key)).catch(() => undefined);
    }
    const keys = new Map<File, string>();
    const byKey = new Map<string, File | null>();
    const file = async (key: string | null) => {
      if (key === null) return null;
      if (!byKey.has(key)) byKey.set(key, (await get<{ file: File }>(key))?.file ?? null);
      const f = byKey.get(key) ?? null;
      if (f) {
        keys.set(f, key);
        this.stored.add(key);
      }
      return f;
    };
    const scans: File[] = [];
    const works: SavedScan<View>[] = [];
    for (const { scanFile, landmarksFile, view, ...saved } of rest.works) {
      const scan = await file(scanFile);
      if (!scan) continue;
      if (!scans.includes(scan)) scans.push(scan);
      works.push({ scan: scans.indexOf(scan), landmarks: await file(landmarksFile), saved, view });
    }
    return works.length ? { scans, works, keys } : null;
  }
}

/** A key for a new file's record (`crypto.randomUUID` needs a secure context; a page served over plain http on a lab's network has none). */
function newFileKey(): string {
  return `file:${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`;
}

/** The records as saved before work put aside was kept (until 2026-12-06): the shown scan's alone. */
interface OneScanFiles {
  scan: File;
  landmarks: File | null;
}
type OneScanState<View> = SavedState & { view: View | null };

function fromOneScan<View>(files: OneScanFiles, rest: OneScanState<View>): SavedWork<View> & { keys: Map<File, string> } {
  const { scanUnits, orientation, landmarksFor, entries, estimateReport, view } = rest;
  return {
    scans: [files.scan],
    works: [{ scan: 0, landmarks: files.landmarks, saved: { scanUnits, orientation, landmarksFor, entries, estimateReport }, view }],
    keys: new Map(),
  };
}
