// What is loaded: the scan, its chosen units, the landmark file and the landmark set being edited
// (which the warp and the alignment use). Derives what the view and the panels show; a failed load
// never touches it.
import type { EstimateReport, LandmarkEntry } from '../shared/landmark-entry';
import type { Orientation } from '../shared/orientation';
import { METRES_PER_UNIT, type MeshSummary, type ParsedLandmarks, type ParsedScan, type Units } from '../shared/results';
import { LandmarkEdits } from './landmark-edits';

/**
 * What changed: `files`, a scan or landmark file opened (everything made from the old ones goes:
 * the picked landmark, the warp, the fit, and the view re-aims); `units`, the scan's units chosen;
 * `edited`, a landmark of the set edited (the warp and the fit go, the view stays); `estimated`,
 * the set filled in by the estimate (the warp and the fit go, the view re-aims); `template`,
 * another template resolution loaded under a warp (the warp and the fit made with the old one go);
 * `batchFit`, a batch subject's fit shown in the fit's place (the single scan's fit goes, its warp
 * stays); `aside`, work put aside forgotten (nothing shown changes).
 */
export type SessionChange = 'files' | 'units' | 'edited' | 'estimated' | 'template' | 'batchFit' | 'aside';

/** A scan with its landmarks as they were when another scan replaced it (what "Back to" brings back). */
export interface ScanWork {
  scan: ParsedScan;
  scanUnits: Units;
  landmarks: ParsedLandmarks | null;
  landmarksFor: string | null;
  edits: LandmarkEdits;
  estimateReport: EstimateReport | null;
  orientation: Orientation | null;
}

/** A scan's work as kept across a reload: everything of `ScanWork` but its files, the set as its entries. */
export interface SavedState {
  scanUnits: Units;
  orientation: Orientation | null;
  landmarksFor: string | null;
  entries: LandmarkEntry[];
  estimateReport: EstimateReport | null;
}

/** A scan's work saved before a reload, its files read again. */
export interface SavedScanWork {
  scan: ParsedScan;
  landmarks: ParsedLandmarks | null;
  saved: SavedState;
}

/** What of `work` is kept across a reload beside its files. */
export function savedState(work: ScanWork): SavedState {
  const { scanUnits, orientation, landmarksFor, edits, estimateReport } = work;
  return { scanUnits, orientation, landmarksFor, entries: [...edits.all], estimateReport };
}

export class Session {
  scan: ParsedScan | null = null;
  /** The scan's units as the user chose them (the detected units until overridden). */
  scanUnits: Units = 'metres';
  /** The landmark file as read (its name, report and units), or null when none was opened. */
  landmarks: ParsedLandmarks | null = null;
  /** The current landmark set: the file's, an estimate, and the edits made since. */
  edits: LandmarkEdits | null = null;
  /** The report of the landmark estimate that filled in the set's estimated landmarks, if one did. */
  estimateReport: EstimateReport | null = null;
  /**
   * Which way is up on the scan, as the person chose it (null: auto, the estimate finds it): the
   * landmark estimate and the fit's own estimate use it. A new scan starts at auto, as its units
   * start at the detected ones.
   */
  orientation: Orientation | null = null;
  /**
   * The scan the landmark file belongs to: the one it was opened with or onto (its file name), or
   * null while it waits for the next scan (it was opened with no scan shown).
   */
  landmarksFor: string | null = null;
  /**
   * What was replaced, most recent first, each kept until it is brought back or forgotten: a scan
   * a newly opened one replaced, with its landmarks, or the scan shown with the set a landmark file
   * opened onto it replaced.
   */
  putAside: ScanWork[] = [];

  private readonly listeners: ((change: SessionChange) => void)[] = [];

  /** `caesarNames`: the 73 CAESAR landmark names in file order (from the core). */
  constructor(private readonly caesarNames: () => readonly string[]) {}

  /** Calls `listener` after each change, in the order the listeners were added. */
  onChange(listener: (change: SessionChange) => void): void {
    this.listeners.push(listener);
  }

  /**
   * Opens what was read (a scan, a landmark file, or both) as one change; what it replaces is put
   * aside. `namesPair`: the core pairs the scan's file name with the open landmark file's (`a.ply`
   * and `a.csv`), so the file goes with this scan opened alone.
   */
  open(scan: ParsedScan | null, landmarks: ParsedLandmarks | null, namesPair = false): void {
    if (!scan && !landmarks) return;
    if (scan) this.setScan(scan, namesPair);
    else if (landmarks && this.edits?.placed().names.length) this.setAside(this.work());
    if (landmarks) this.setLandmarks(landmarks);
    this.changed('files');
  }

  /**
   * Whether the open landmark file goes with a scan opened alone now: when it waits for a scan,
   * or when `namesPair` (the core pairs their file names). Otherwise it belongs to the scan shown.
   */
  fileGoesWith(namesPair: boolean): boolean {
    return this.landmarks !== null && (this.landmarksFor === null || namesPair);
  }

  /**
   * The work saved before a reload, as it was (one change, as files opened): `shown`, the scan and
   * its landmark file as read again, the units and frame chosen, and the landmark set; `asides`,
   * the work put aside, most recent first, read again too.
   */
  restore(shown: SavedScanWork, asides: readonly SavedScanWork[]): void {
    this.show(this.workFrom(shown));
    this.putAside = asides.map((a) => this.workFrom(a));
    this.changed('files');
  }

  /** A scan's work as saved, with its files read again. */
  private workFrom({ scan, landmarks, saved }: SavedScanWork): ScanWork {
    return {
      scan,
      scanUnits: saved.scanUnits,
      landmarks,
      landmarksFor: landmarks ? saved.landmarksFor : null,
      edits: LandmarkEdits.fromEntries(this.caesarNames(), saved.entries),
      estimateReport: saved.estimateReport,
      orientation: saved.orientation,
    };
  }

  /** Swaps the scan shown, with its landmarks, for the work put aside at `index` (one change); the shown one goes first among those put aside. */
  bringBack(index = 0): void {
    const back = this.putAside[index];
    if (!back) return;
    this.putAside.splice(index, 1);
    this.setAside(this.work());
    this.show(back);
    this.changed('files');
  }

  /** Makes `work` the scan shown with its landmarks (no change is told). */
  private show(work: ScanWork): void {
    ({
      scan: this.scan,
      scanUnits: this.scanUnits,
      landmarks: this.landmarks,
      landmarksFor: this.landmarksFor,
      edits: this.edits,
      estimateReport: this.estimateReport,
      orientation: this.orientation,
    } = work);
  }

  /** Forgets the work put aside at `index` (nothing else changes; the caller asks first). */
  forget(index: number): void {
    this.putAside.splice(index, 1);
    this.changed('aside');
  }

  /** Puts `work` first among the work put aside. */
  private setAside(work: ScanWork | null): void {
    if (work) this.putAside.unshift(work);
  }

  /** The scan shown with its landmarks, or null without a scan. */
  work(): ScanWork | null {
    const { scan, scanUnits, landmarks, landmarksFor, edits, estimateReport, orientation } = this;
    return scan && edits ? { scan, scanUnits, landmarks, landmarksFor, edits, estimateReport, orientation } : null;
  }

  /** Tells the listeners of a change: one the set being edited (`edits`) had, or one made beside the session (`template`, `batchFit`). */
  changed(change: SessionChange): void {
    for (const listener of this.listeners) listener(change);
  }

  /**
   * A new scan (no change is told: `open` tells it once for what was read together). The scan
   * shown before, with its landmarks, is put aside. A landmark file that goes with the new scan
   * ([`fileGoesWith`]) stays: with its edits when it waited for a scan, as the file alone when it
   * was on the old scan (what was estimated or placed there goes with it). Any other set stays with
   * the old scan, and the new one starts with none.
   */
  setScan(scan: ParsedScan, namesPair = false): void {
    const stays = this.fileGoesWith(namesPair);
    const old = this.work();
    this.setAside(old);
    this.scan = scan;
    this.scanUnits = scan.summary.units_detected;
    this.orientation = null;
    this.estimateReport = null;
    if (!stays) {
      this.landmarks = null;
      this.edits = new LandmarkEdits(this.caesarNames());
    } else if (old || !this.edits) this.setLandmarks(this.landmarks!);
    this.landmarksFor = this.landmarks ? scan.fileName : null;
  }

  /** A landmark file replaces the set being edited: its landmarks given, the rest absent; it belongs to the scan shown, or waits for the next. */
  setLandmarks(landmarks: ParsedLandmarks): void {
    this.landmarks = landmarks;
    this.landmarksFor = this.scan?.fileName ?? null;
    this.estimateReport = null;
    this.edits = LandmarkEdits.fromFile(this.caesarNames(), landmarks.names, this.landmarkPositionsMetres());
  }

  /**
   * Changes the scan's units: what was placed on the scan (estimated, edited) scales with it, and so
   * do landmarks given in a file whose format fixes no units (they follow the scan).
   */
  setScanUnits(units: Units): void {
    const before = this.scanScale;
    this.scanUnits = units;
    const factor = this.scanScale / before;
    const givenFollows = !this.landmarks?.units;
    this.edits?.rescale(factor, (state) => state !== 'given' || givenFollows);
    this.changed('units');
  }

  /** Factor on the worker's positions (metres by the detected units) for the chosen units. */
  get scanScale(): number {
    if (!this.scan) return 1;
    return METRES_PER_UNIT[this.scanUnits] / this.scan.summary.scale_to_metres;
  }

  /** The scan's summary with its bounding box in metres under the chosen units. */
  get scanSummary(): MeshSummary | null {
    if (!this.scan) return null;
    const s = this.scan.summary;
    const k = this.scanScale;
    return {
      ...s,
      bbox_min: s.bbox_min.map((v) => v * k) as MeshSummary['bbox_min'],
      bbox_max: s.bbox_max.map((v) => v * k) as MeshSummary['bbox_max'],
    };
  }

  /**
   * Units of the landmark file: what the format fixes (`.lnd`: millimetres), else the scan's,
   * else a guess from the landmarks' own extent.
   */
  get landmarkUnits(): Units | null {
    const set = this.landmarks;
    if (!set) return null;
    if (set.units) return set.units;
    if (this.scan) return this.scanUnits;
    return set.detected_units;
  }

  /** The landmark file's positions in metres. */
  landmarkPositionsMetres(): Float64Array {
    const set = this.landmarks;
    if (!set) return new Float64Array();
    const k = METRES_PER_UNIT[this.landmarkUnits ?? 'metres'];
    // In double precision, as the core reads the file: a fit is sensitive to 1e-4 mm moves of its
    // landmarks (float rounding alone moved a fit's RMS by 0.015 mm), and must match the CLI's.
    return Float64Array.from(set.positions, (v) => v * k);
  }
}
