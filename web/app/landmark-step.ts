// The landmark editor: the current set's markers on the scan (coloured by where each came from and
// by the estimate's confidence, the picked one and the suspicious ones larger), picking a landmark
// in the list and clicking on the scan to place it, dragging markers along the surface, marking
// one absent, undo / redo (buttons, Ctrl+Z, Ctrl+Shift+Z), export by the core's writers. A scan
// without landmarks gets the core's estimate, in a worker of its own (Cancel stops that worker
// alone), in the frame the person chose (Up / Facing; auto: the core finds it); the estimate's
// verdict on itself is shown in words, and "Estimate again" re-runs it keeping what was given,
// placed or moved by hand. The set is checked for suspicious landmarks there after every change,
// against the estimate's prediction (no new fit). Every committed
// change is reported through `onEdited`, which invalidates the warp and the fit as a new landmark
// file does.
import { CancelledError, type CoreClient } from '../client/core-client';
import { baseName } from '../shared/file-kind';
import type { EstimateReport, LandmarkEntry, LandmarkPrediction, Point, Sharpness, SuspiciousLandmark } from '../shared/landmark-entry';
import type { Orientation } from '../shared/orientation';
import { METRES_PER_UNIT } from '../shared/results';
import type { TemplateData } from '../shared/template-data';
import { download } from '../ui/download';
import { basisWords, notFitted, turnedWords } from '../ui/format';
import { forgetQuestion, sentence, shownCheck, type EstimateView, type LandmarkFormat, type PutAside } from '../ui/landmark-tools';
import { LandmarksPanel, type LandmarkFacts } from '../ui/landmarks-panel';
import { landmarkStyle } from '../view/landmark-style';
import type { LandmarkPoints, Viewer } from '../view/viewer';
import { LandmarkEdits } from './landmark-edits';
import { estimateInput, scanInput, scanTransfer } from './scan-input';
import type { ScanWork, Session } from './session';

/** What the editor showed of one set (kept when another replaces it, and across a reload). */
export interface Shown {
  estimate: EstimateView;
  suspicious: SuspiciousLandmark[] | null;
  sharpness: ReadonlyMap<string, Sharpness>;
  prediction: (LandmarkPrediction & { scale: number }) | null;
}

/** Quiet time (ms) after an edit before the set is checked for suspicious landmarks. */
const CHECK_DELAY_MS = 400;

export class LandmarkStep {
  readonly panel: LandmarksPanel;
  private selected: string | null = null;
  /** The landmark the last click meant to place fell through a hole in the scan (nothing placed), until the next change or pick. */
  private throughHole: string | null = null;
  private facts: LandmarkFacts | null = null;
  private estimate: EstimateView = { state: 'none' };
  private suspicious: SuspiciousLandmark[] | null = null;
  /** Each landmark's definition sharpness, from the last estimate's report (a property of the name). */
  private sharpness: ReadonlyMap<string, Sharpness> = new Map();
  /** The last estimate's prediction for this scan, with the scan scale it was made at. */
  private prediction: (LandmarkPrediction & { scale: number }) | null = null;
  /**
   * What was shown of each set (its estimate's verdict, the suspicious ones, the prediction), kept
   * when another scan replaces it, so "Back to" shows it as it was.
   */
  private readonly shown = new WeakMap<LandmarkEdits, Shown>();
  /** The set the shown estimate, suspicious list and prediction are of. */
  private shownFor: LandmarkEdits | null = null;
  /** Called before a landmark is shown up close on the scan (the page hides what would cover the scan). */
  onCloseUp: (() => void) | null = null;
  /** Called when Up or Facing is chosen (nothing runs, but the choice is kept). */
  onOriented: (() => void) | null = null;
  /** Called when the person asks for the work put aside at `index` back. */
  onBringBack: ((index: number) => void) | null = null;
  /** What the list shows before anything is loaded: every landmark absent. */
  private empty: LandmarkEdits | null = null;
  /** A check for suspicious landmarks is running / another is wanted after it. */
  private checking = false;
  private recheck = false;
  /** Called when a landmark is picked on a loaded scan (the page shows the scan, so a click can place it). */
  onPick: ((name: string) => void) | null = null;
  /** Counts estimates and resets, so a stale estimate's reply is dropped. */
  private generation = 0;
  /** The check waiting for a pause in the edits (a burst of clicks or undos is checked once). */
  private checkTimer: ReturnType<typeof setTimeout> | null = null;
  /**
   * A landmark file with at least this many of the 73 is nearly full: checked, not filled in by
   * itself — the core's rule (`SubjectOptions.nearly_full`, from `alignDefaults`).
   */
  nearlyFull = Number.NaN;

  /**
   * `client` writes the exports; `estimator` is the landmark worker's client (estimate and check).
   * `onEdited(keepView)`: the set changed; `keepView` unless it is a new set (an estimate).
   */
  constructor(
    private readonly client: CoreClient<'core'>,
    private readonly estimator: CoreClient<'landmarks'>,
    private readonly viewer: Viewer,
    private readonly session: Session,
    private readonly caesarNames: () => readonly string[],
    private readonly onEdited: (keepView: boolean) => void,
    private readonly onError: (message: string) => void,
  ) {
    this.panel = new LandmarksPanel({
      onBringBack: (index) => this.onBringBack?.(index),
      onForget: (index) => this.forget(index),
      onSelect: (name) => this.select(name),
      onInspect: (name) => this.inspect(name),
      onHover: (name) => this.panel.guide.show(name ?? this.selected),
      onEstimate: () => void this.estimateLandmarks(),
      onCancelEstimate: () => this.estimator.cancel(),
      onOrientation: (orientation) => this.orient(orientation),
      onUndo: () => this.step(() => this.session.edits?.undo() ?? null),
      onRedo: () => this.step(() => this.session.edits?.redo() ?? null),
      onAbsent: () => this.markAbsent(),
      onExport: (format) => void this.export(format),
    });
    viewer.editMarkers('scan', {
      selected: () => (this.session.scan ? this.selected : null),
      enabled: () => Boolean(this.session.scan && this.session.edits) && this.estimate.state !== 'running',
      onGrab: (name) => {
        if (!this.session.edits?.entry(name)) return false;
        this.select(name);
        return true;
      },
      onPlace: (name, point, transient) => this.place(name, point, transient),
      onThroughHole: (name) => {
        this.throughHole = name;
        this.render();
      },
    });
    document.addEventListener('keydown', (event) => this.key(event));
  }

  /** The template's landmarks for the guide that shows where each one sits. */
  setTemplate(data: TemplateData): void {
    this.panel.guide.setTemplate(data);
    this.panel.guide.show(this.selected);
  }

  /** A new landmark file or scan: nothing picked, no estimate or check of the old set running or shown. */
  reset(): void {
    this.generation++;
    if (this.checkTimer !== null) clearTimeout(this.checkTimer);
    this.checkTimer = null;
    if (this.shownFor) {
      this.shown.set(this.shownFor, this.shownNow());
      this.shownFor = null;
    }
    if (this.estimator.busy) this.estimator.cancel();
    this.selected = null;
    this.throughHole = null;
    this.suspicious = null;
    this.prediction = null;
    this.estimate = { state: 'none' };
    delete document.body.dataset.estimateVerdict;
    this.panel.guide.show(null);
    this.panel.scrollListToTop();
  }

  /**
   * After a load: a scan without landmarks, or with a partial file (fewer than
   * `nearlyFull` CAESAR landmarks), gets an estimate of the rest, the given ones kept as given
   * (the estimate also flags the suspicious ones); a nearly full file (a CAESAR file missing a
   * few) is only checked: its missing landmarks stay absent, the warp runs without them, and
   * "Estimate" fills them in on request.
   */
  afterLoad(): void {
    if (!this.session.scan) return;
    if ((this.session.edits?.placed().names.length ?? 0) >= this.nearlyFull) this.check();
    else void this.estimateLandmarks();
  }

  /** After "Back to": the set brought back as it was shown (its estimate's verdict, the suspicious ones), else as after a load. */
  afterBringBack(): void {
    const edits = this.session.edits;
    this.showAgain(edits ? (this.shown.get(edits) ?? null) : null);
  }

  /** What the editor shows of the current set now (an estimate cut short leaves the last finished one's landmarks and verdict). */
  shownNow(): Shown {
    const e = this.estimate;
    const estimate: EstimateView = e.state === 'running' ? { state: 'cancelled', kept: this.session.estimateReport?.self_check ?? null } : e;
    return { estimate, suspicious: this.suspicious, sharpness: this.sharpness, prediction: this.prediction };
  }

  /** What the editor shows of `edits`: the current set's now, one put aside's as it was when put aside (null: nothing kept). */
  shownOf(edits: LandmarkEdits): Shown | null {
    return edits === this.session.edits ? this.shownNow() : (this.shown.get(edits) ?? null);
  }

  /** Keeps what the editor showed of `edits`, a set put aside (restored after a reload), for "Back to". */
  keepShown(edits: LandmarkEdits, shown: Shown | null): void {
    if (shown) this.shown.set(edits, shown);
  }

  /** Shows the current set as `before` showed it (a set brought back or restored after a reload); without it, as after a load. */
  showAgain(before: Shown | null): void {
    if (!before) {
      this.afterLoad();
      return;
    }
    ({ estimate: this.estimate, suspicious: this.suspicious, sharpness: this.sharpness, prediction: this.prediction } = before);
    const check = shownCheck(this.estimate);
    if (check) document.body.dataset.estimateVerdict = check.verdict;
    this.showMarkers();
    this.render();
  }

  /**
   * Estimates every landmark neither given nor edited (again, after an estimate: what it placed
   * is replaced, what a person gave, placed or moved is kept as given), in the landmark worker, in
   * the frame the person chose.
   */
  async estimateLandmarks(): Promise<void> {
    const edits = this.session.edits;
    const input = estimateInput(this.session);
    if (!edits || !input || this.estimate.state === 'running') return;
    const generation = ++this.generation;
    const current = () => generation === this.generation && this.session.edits === edits;
    this.estimate = { state: 'running', fraction: 0, label: 'Starting the estimate' };
    this.render();
    try {
      const result = await this.estimator.call(
        { type: 'estimateLandmarks', scan: input, orientation: this.session.orientation },
        {
          transfer: scanTransfer(input),
          onProgress: (fraction, label) => {
            if (!current()) return;
            this.estimate = { state: 'running', fraction, label };
            this.render();
          },
        },
      );
      if (!current()) return;
      edits.fillEstimate(result.names, result.positions, result.confidence, result.given);
      this.session.estimateReport = result.report;
      this.suspicious = result.report.flagged;
      this.sharpness = new Map(result.report.landmarks.map((l) => [l.name, l.sharpness]));
      this.prediction = { ...result.prediction, scale: this.session.scanScale };
      this.estimate = { state: 'done', assumed: this.assumed(result.report), seconds: result.workerMs / 1000, check: result.report.self_check };
      const data = document.body.dataset;
      data.estimateWorkerMs = result.workerMs.toFixed(0);
      data.estimateVerdict = result.report.self_check.verdict;
      data.estimates = String(Number(data.estimates ?? '0') + 1);
      this.showMarkers();
      this.render();
      this.onEdited(false);
    } catch (error) {
      if (!current()) return;
      // The landmarks left are the last finished estimate's, and so is the verdict on them.
      const kept = this.session.estimateReport?.self_check ?? null;
      if (error instanceof CancelledError) this.estimate = { state: 'cancelled', kept };
      else {
        const message = error instanceof Error ? error.message : String(error);
        this.estimate = { state: 'error', message, kept };
        this.onError(`Landmark estimate: ${sentence(message)} The scan and the landmarks placed so far are kept.`);
      }
      this.render();
    }
  }

  /** Up and Facing chosen: remembered for the next estimate and the fit (nothing runs by itself). */
  private orient(orientation: Orientation | null): void {
    this.session.orientation = orientation;
    this.onOriented?.();
    this.render();
  }

  /** What the estimate assumed of the scan, and what of it it did not fit, in words. */
  private assumed(report: EstimateReport): string {
    const s = this.session;
    const units = s.scan && s.scanUnits === s.scan.summary.units_detected ? `${s.scanUnits} (detected)` : `${s.scanUnits} (as chosen)`;
    const up = basisWords(report.frame_from.up, s.orientation?.up ?? null);
    const facing = basisWords(report.frame_from.facing, s.orientation?.facing ?? null);
    return (
      `the body's up is the scan's ${report.frame.up_axis} axis${up} and it faces ${report.frame.facing_axis}${facing}; units ${units}. ` +
      `${report.given} landmarks kept as given, ${report.estimated} estimated (markers from red, low confidence, to green, high); ` +
      `the landmark-free fit is ${report.fit_rms_mm.toFixed(1)} mm RMS from the scan.` +
      turnedWords(report.turned) +
      notFitted([report.strays, report.floor])
    );
  }

  /**
   * Checks the current set for suspicious landmarks in the landmark worker; a change made while
   * a check runs is checked after it.
   */
  private check(): void {
    if (this.checking) {
      this.recheck = true;
      return;
    }
    const edits = this.session.edits;
    if (!edits || !this.session.scan || edits.placed().names.length === 0) return;
    this.checking = true;
    const data = document.body.dataset;
    data.suspiciousState = 'checking';
    this.suspiciousIn(edits)
      .then((list) => {
        if (this.session.edits !== edits) return;
        this.suspicious = list;
        data.suspiciousState = 'done';
        this.showMarkers();
        this.render();
      })
      // The check is advice: when it cannot run (too few landmarks, a cancelled worker) the list goes.
      .catch(() => {
        this.suspicious = null;
        data.suspiciousState = 'failed';
        this.render();
      })
      .finally(() => {
        this.checking = false;
        if (this.recheck) {
          this.recheck = false;
          this.check();
        }
      });
  }

  /**
   * The suspicious landmarks of the set placed so far: against the last estimate's prediction
   * (milliseconds); before any estimate of this scan (a nearly full file), a landmark-free fit of the
   * scan finds them (seconds) and its prediction is kept for the checks after it.
   */
  private async suspiciousIn(edits: LandmarkEdits): Promise<SuspiciousLandmark[]> {
    const set = edits.placed();
    const prediction = this.prediction;
    if (prediction) {
      const k = this.session.scanScale / prediction.scale;
      const positions = k === 1 ? prediction.positions.slice() : prediction.positions.map((v) => v * k);
      return this.estimator.call(
        { type: 'checkLandmarks', names: set.names, positions: set.positions.slice(), prediction: { positions, parts: prediction.parts.slice() } },
      );
    }
    const input = scanInput(this.session, 'base');
    if (!input) throw new Error('no scan or no landmark to check');
    const generation = this.generation;
    const fit = await this.estimator.call({ type: 'estimateLandmarks', scan: input, orientation: this.session.orientation }, { transfer: scanTransfer(input) });
    if (generation === this.generation) this.prediction = { ...fit.prediction, scale: this.session.scanScale };
    return fit.report.flagged;
  }

  /** Shows the set with the landmark file's `facts` (null without a file). */
  show(facts: LandmarkFacts | null): void {
    this.facts = facts;
    this.render();
  }

  /** The current set's markers for the scan layer (with the file's non-CAESAR names flagged). */
  markers(): LandmarkPoints | null {
    const edits = this.session.edits;
    const file = this.session.landmarks;
    if (!edits && !file) return null;
    const placed = (edits?.all ?? []).filter((e) => e.position);
    const unknown = file ? file.report.unknown : [];
    const filePositions = file ? this.session.landmarkPositionsMetres() : new Float64Array();
    const unknownPoints = unknown.flatMap((name) => {
      const i = file!.names.indexOf(name);
      return i < 0 ? [] : [{ name, position: [filePositions[3 * i]!, filePositions[3 * i + 1]!, filePositions[3 * i + 2]!] as Point }];
    });
    const flagged = new Set(this.suspicious?.map((s) => s.name) ?? []);
    return landmarkStyle(placed, unknownPoints, this.selected, flagged);
  }

  private render(): void {
    this.shownFor = this.session.edits;
    const edits = this.session.edits ?? (this.empty ??= new LandmarkEdits(this.caesarNames()));
    const entries = edits.all;
    const selected = this.selected ? (edits.entry(this.selected) ?? null) : null;
    const o = this.session.orientation;
    document.body.dataset.orientation = o ? `${o.up} ${o.facing ?? 'auto'}` : 'auto';
    this.panel.render(this.facts, {
      entries,
      selected: this.selected,
      flagged: new Set(this.suspicious?.map((s) => s.name) ?? []),
      sharpness: this.sharpness,
      loaded: Boolean(this.session.edits),
      tools: {
        putAside: this.session.putAside.map((aside) => this.asideView(aside)),
        scan: this.session.scan?.fileName ?? null,
        estimate: this.estimate,
        absent: entries.filter((e) => !e.position).length,
        estimated: entries.filter((e) => e.state === 'estimated').length,
        orientation: this.session.orientation,
        hasScan: Boolean(this.session.scan),
        selected,
        canUndo: edits.canUndo,
        canRedo: edits.canRedo,
        suspicious: this.suspicious,
        throughHole: this.throughHole,
      },
    });
    this.publishSelected(selected);
  }

  /** What the panel says of work put aside. */
  private asideView(aside: ScanWork): PutAside {
    const count = (state: LandmarkEntry['state']) => aside.edits.all.filter((e) => e.state === state && e.position).length;
    return {
      scan: aside.scan.fileName,
      sameScan: aside.scan === this.session.scan,
      file: aside.landmarks?.fileName ?? null,
      given: count('given'),
      estimated: count('estimated'),
      edited: count('edited'),
    };
  }

  /** Forgets the work put aside at `index`, once the person says so when it has landmarks. */
  private forget(index: number): void {
    const aside = this.session.putAside[index];
    if (!aside) return;
    const question = forgetQuestion(this.asideView(aside));
    if (question && !window.confirm(question)) return;
    this.session.forget(index);
    this.render();
  }

  private select(name: string): void {
    this.selected = name;
    this.throughHole = null;
    this.panel.guide.show(name);
    if (this.session.scan) this.onPick?.(name);
    this.render();
  }

  /** Picks `name` and turns the view to it up close (where the set has it: on the scan, or on the template's guess). */
  private inspect(name: string): void {
    this.select(name);
    const at = this.session.edits?.entry(name)?.position;
    this.onCloseUp?.();
    if (at) this.viewer.closeUp('scan', at);
    this.publishSelected(this.session.edits?.entry(name) ?? null);
  }

  private place(name: string, point: Point, transient: boolean): void {
    const edits = this.session.edits;
    if (!edits) return;
    edits.place(name, point, transient);
    if (transient) this.showMarkers();
    else this.edited();
  }

  private markAbsent(): void {
    if (!this.selected || !this.session.edits) return;
    this.session.edits.markAbsent(this.selected);
    this.edited();
  }

  /** Undo or redo: the landmark it touched becomes the picked one. */
  private step(apply: () => string | null): void {
    const name = apply();
    if (name === null) return;
    this.selected = name;
    this.edited();
  }

  /** A committed change of the set: markers, panel, and the fit made with the old set is gone. */
  private edited(): void {
    this.throughHole = null;
    document.body.dataset.landmarkEdits = String(Number(document.body.dataset.landmarkEdits ?? '0') + 1);
    this.showMarkers();
    this.render();
    this.onEdited(true);
    this.scheduleCheck();
  }

  /**
   * Checks the set once the edits pause for `CHECK_DELAY_MS`, so a burst of clicks is checked once
   * (the first check of a scan without an estimate fits the template to it: seconds).
   */
  private scheduleCheck(): void {
    if (this.checkTimer !== null) clearTimeout(this.checkTimer);
    document.body.dataset.suspiciousState = 'pending';
    this.checkTimer = setTimeout(() => {
      this.checkTimer = null;
      this.check();
    }, CHECK_DELAY_MS);
  }

  private showMarkers(): void {
    this.viewer.showBody('scan', { landmarks: this.markers() });
  }

  private key(event: KeyboardEvent): void {
    if (!(event.ctrlKey || event.metaKey) || event.key.toLowerCase() !== 'z') return;
    const target = event.target as HTMLElement | null;
    if (target && (target.isContentEditable || ['INPUT', 'SELECT', 'TEXTAREA'].includes(target.tagName))) return;
    if (!this.session.edits || this.estimate.state === 'running') return;
    event.preventDefault();
    if (event.shiftKey) this.step(() => this.session.edits!.redo());
    else this.step(() => this.session.edits!.undo());
  }

  /**
   * Writes the set by the core's writer of `format`: `.lnd` in millimetres (as the format
   * expects), CSV and JSON in the scan's units (the landmark file's without a scan).
   */
  private async export(format: LandmarkFormat): Promise<void> {
    const edits = this.session.edits;
    if (!edits) return;
    const units = format === 'lnd' ? 'millimetres' : this.session.scan ? this.session.scanUnits : (this.session.landmarkUnits ?? 'metres');
    const k = 1 / METRES_PER_UNIT[units];
    const positions = edits.positionsWithGaps().map((v) => v * k);
    const subject = baseName(this.session.scan?.fileName ?? this.session.landmarks?.fileName ?? 'landmarks');
    try {
      const bytes = await this.client.call(
        { type: 'writeLandmarks', names: [...edits.names], positions, format, subjectId: subject },
        { transfer: [positions.buffer] },
      );
      download(`${subject}-landmarks.${format}`, bytes);
    } catch (error) {
      this.onError(`Landmark export: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  /** The picked landmark's marker on the canvas (CSS px), for tests that click beside it. */
  private publishSelected(entry: LandmarkEntry | null): void {
    const at = entry?.position ? this.viewer.canvasPoint('scan', entry.position) : null;
    const data = document.body.dataset;
    if (at) data.selectedMarkerPx = at.map((v) => v.toFixed(1)).join(',');
    else delete data.selectedMarkerPx;
    data.selectedLandmark = entry?.name ?? '';
  }
}
