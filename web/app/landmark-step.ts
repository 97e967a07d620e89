// The landmark editor: the current set's markers on the scan (coloured by where each came from and
// by the estimate's confidence, the picked one and the suspicious ones larger), picking a landmark
// in the list and clicking on the scan to place it, dragging markers along the surface, marking
// one absent, undo / redo (buttons, Ctrl+Z, Ctrl+Shift+Z), export by the core's writers. Every
// committed edit is reported through `onEdited`, which invalidates the warp and the fit as a new
// landmark file does.
import type { CoreClient } from '../client/core-client';
import { baseName } from '../shared/file-kind';
import type { LandmarkEntry, Point, SuspiciousLandmark } from '../shared/landmark-entry';
import { METRES_PER_UNIT } from '../shared/results';
import type { TemplateData } from '../shared/template-data';
import { download } from '../ui/download';
import type { LandmarkFormat, EstimateView } from '../ui/landmark-tools';
import { LandmarksPanel, type LandmarkFacts } from '../ui/landmarks-panel';
import { landmarkStyle } from '../view/landmark-style';
import type { LandmarkPoints, Viewer } from '../view/viewer';
import { LandmarkEdits } from './landmark-edits';
import type { Session } from './session';

export class LandmarkStep {
  readonly panel: LandmarksPanel;
  private selected: string | null = null;
  private facts: LandmarkFacts | null = null;
  private estimate: EstimateView = { state: 'none' };
  private suspicious: SuspiciousLandmark[] | null = null;
  /** What the list shows before anything is loaded: every landmark absent. */
  private empty: LandmarkEdits | null = null;

  constructor(
    private readonly client: CoreClient,
    private readonly viewer: Viewer,
    private readonly session: Session,
    private readonly caesarNames: () => readonly string[],
    private readonly onEdited: () => void,
    private readonly onError: (message: string) => void,
  ) {
    this.panel = new LandmarksPanel({
      onSelect: (name) => this.select(name),
      onHover: (name) => this.panel.guide.show(name ?? this.selected),
      onEstimate: () => undefined,
      onCancelEstimate: () => undefined,
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
    });
    document.addEventListener('keydown', (event) => this.key(event));
  }

  /** The template's landmarks for the guide that shows where each one sits. */
  setTemplate(data: TemplateData): void {
    this.panel.guide.setTemplate(data);
    this.panel.guide.show(this.selected);
  }

  /** A new landmark file or scan: nothing picked, no estimate or check of the old set shown. */
  reset(): void {
    this.selected = null;
    this.suspicious = null;
    this.estimate = { state: 'none' };
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
    const filePositions = file ? this.session.landmarkPositionsMetres() : new Float32Array();
    const unknownPoints = unknown.flatMap((name) => {
      const i = file!.names.indexOf(name);
      return i < 0 ? [] : [{ name, position: [filePositions[3 * i]!, filePositions[3 * i + 1]!, filePositions[3 * i + 2]!] as Point }];
    });
    const flagged = new Set(this.suspicious?.map((s) => s.name) ?? []);
    return landmarkStyle(placed, unknownPoints, this.selected, flagged);
  }

  private render(): void {
    const edits = this.session.edits ?? (this.empty ??= new LandmarkEdits(this.caesarNames()));
    const entries = edits.all;
    const selected = this.selected ? (edits.entry(this.selected) ?? null) : null;
    this.panel.render(this.facts, {
      entries,
      selected: this.selected,
      flagged: new Set(this.suspicious?.map((s) => s.name) ?? []),
      tools: {
        estimate: this.estimate,
        absent: entries.filter((e) => !e.position).length,
        hasScan: Boolean(this.session.scan),
        selected,
        canUndo: edits.canUndo,
        canRedo: edits.canRedo,
        suspicious: this.suspicious,
      },
    });
    this.publishSelected(selected);
  }

  private select(name: string): void {
    this.selected = name;
    this.panel.guide.show(name);
    this.render();
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
    document.body.dataset.landmarkEdits = String(Number(document.body.dataset.landmarkEdits ?? '0') + 1);
    this.showMarkers();
    this.render();
    this.onEdited();
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
