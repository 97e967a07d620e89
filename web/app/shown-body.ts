// The shape body on screen: asked of the worker through the MorphQueue (the worker holds it, so a
// slider move is a rank-1 update), shown at the chosen resolution standing beside the template,
// and kept out of the view while a scan is looked at until a shape action brings it back.
import type { CoreClient } from '../client/core-client';
import type { Bounds } from '../shared/bounds';
import { reading, type ReconstructedBody, type ShapeCoefficients, type ShownResolution } from '../shared/shape-results';
import type { TemplateResolution } from '../shared/template-data';
import type { ErrorBanner } from '../ui/error-banner';
import type { ShapePanel } from '../ui/shape-panel';
import type { Viewer } from '../view/viewer';
import { MorphQueue } from './morph-queue';
import type { ShapeModel } from './shape-model';

/** Model bodies are centred on their centroid (GPA): shown standing on the floor, 1 m to the
 * template's side, so the template and the model body are both in view (display only). */
const SHAPE_BODY_SIDE_OFFSET_M = 1.0;

export class ShownBody {
  body: ReconstructedBody | null = null;
  /** Resolution the body is shown at (chosen in the panel; kept across model loads). */
  resolution: TemplateResolution = 'base';
  /** Triangles of the body shown: the model's own, or the fine template's. */
  triangles: Uint32Array | null = null;
  private vertexCount = 0;
  private readonly morph: MorphQueue;
  /** Set while a scan is being looked at: the shape body stays out of the view until asked for. */
  private suppressed = false;
  private frameNext = false;
  private bodies = 0;
  private readonly page = document.body;

  constructor(
    private readonly client: CoreClient<'core'>,
    private readonly model: ShapeModel,
    private readonly viewer: Viewer,
    private readonly panel: ShapePanel,
    private readonly banner: ErrorBanner,
    /** The slider values of the body to show. */
    private readonly coefficients: () => ShapeCoefficients,
    /** Called after each body is shown. */
    private readonly onShown: (body: ReconstructedBody) => void,
  ) {
    this.morph = new MorphQueue(client, (body, _c, sentAt) => this.show(body, sentAt), (message) => this.banner.show([message]));
  }

  /** Takes the shape body out of the view (a scan was opened); `reveal` brings it back. */
  hide(): void {
    this.suppressed = true;
    this.viewer.removeBody('shape');
    this.page.dataset.shapeShown = 'false';
  }

  /** A shape action: the next body drawn is shown again. */
  reveal(): void {
    this.suppressed = false;
  }

  /** Whether the next body drawn re-aims the camera (a link's own camera wins over a load's framing). */
  set frameNextBody(frame: boolean) {
    this.frameNext = frame;
  }

  /** Asks the worker for the body of the slider values; `frame` re-aims the camera at it; `rebuild`: from scratch. */
  redraw(frame: boolean, rebuild = false): void {
    if (!this.model.loaded) return;
    this.frameNext ||= frame;
    this.page.dataset.shapeSettled = 'false';
    this.morph.request(this.coefficients(), rebuild);
  }

  /** A newly loaded model is shown at its own resolution: go to fine again if that was chosen. */
  async keepResolution(wanted: TemplateResolution): Promise<void> {
    if (wanted === 'fine' && this.model.loaded?.info.template.resolution === 'base') await this.switchResolution('fine', false);
  }

  /**
   * Shows the body at `resolution`: the worker maps the model to the fine template on first
   * use (progress in the panel); the coefficients stay. A failure leaves the resolution as it was.
   */
  async switchResolution(resolution: TemplateResolution, redraw = true): Promise<void> {
    if (!this.model.loaded) return;
    this.suppressed = false;
    this.page.dataset.shapeBusy = 'true';
    this.page.dataset.shapeSettled = 'false';
    const started = performance.now();
    try {
      const shown = await this.client.call(
        { type: 'shapeResolution', resolution },
        { onProgress: (f, label) => this.panel.showResolutionStatus(`${label}… ${Math.round(f * 100)} %`) },
      );
      this.showResolution(shown);
      const seconds = (performance.now() - started) / 1000;
      this.panel.showResolutionStatus(shown.resolution === 'fine' && seconds > 0.05 ? `Mapped to fine in ${seconds.toFixed(1)} s.` : '');
      if (redraw) this.redraw(false, true);
    } catch (error) {
      this.panel.showResolutionStatus('');
      this.panel.showResolution(this.resolution, this.triangles ? this.vertexCount : 0);
      this.banner.show([error instanceof Error ? error.message : String(error)]);
    } finally {
      this.page.dataset.shapeBusy = 'false';
      if (this.morph.idle) this.page.dataset.shapeSettled = 'true';
    }
  }

  /** The resolution the worker now shows bodies at, with its triangles. */
  showResolution(shown: ShownResolution): void {
    this.resolution = shown.resolution;
    this.triangles = shown.triangles;
    this.vertexCount = shown.vertexCount;
    this.panel.showResolution(shown.resolution, shown.vertexCount);
    this.page.dataset.shapeResolution = shown.resolution;
  }

  /** Shows a body from the worker; `sentAt`: when it was asked for (UI-thread round trip). */
  private show(body: ReconstructedBody, sentAt: number): void {
    const triangles = this.triangles;
    if (!this.model.loaded || !triangles) return;
    // A body of the resolution shown before a switch that has just landed: the next one follows.
    if (body.positions.length / 3 !== this.vertexCount) return;
    this.body = body;
    if (!this.suppressed) {
      const mesh = { positions: body.positions, triangles, normals: body.normals, bounds: body.bounds };
      // Back beside a scan after being hidden: the view takes both in, so neither is cut off.
      const returning = this.page.dataset.shapeShown === 'false';
      this.viewer.showBody('shape', { mesh, colour: 0xc8b4a0, transform: standBeside(body.bounds) }, this.frameNext || returning);
    }
    // Post → result → the new arrays in the body's vertex buffers (rendering not included).
    const roundTripMs = performance.now() - sentAt;
    if (!this.suppressed) this.frameNext = false;
    this.page.dataset.shapeShown = String(!this.suppressed);
    this.panel.showBody(body, body.positions.length / 3, roundTripMs);
    const p = this.page.dataset;
    // Made in the worker; published for the body the sliders settle on (tests, links).
    if (this.morph.idle) p.shapeChecksum = body.checksum;
    p.shapeStature = (reading(body.measurements, 'stature') ?? NaN).toFixed(5);
    p.shapeReconstructMs = body.reconstructMs.toFixed(3);
    p.shapeRoundTripMs = roundTripMs.toFixed(3);
    p.shapeNormalsMs = body.normalsMs.toFixed(3);
    p.shapeMeasureMs = body.measureMs.toFixed(3);
    p.shapeCopyMs = body.copyMs.toFixed(3);
    p.shapeWorkerMs = body.workerMs.toFixed(3);
    p.shapeRebuilt = String(body.rebuilt);
    p.shapeDeltas = String(body.deltas);
    p.shapeVertices = String(body.positions.length / 3);
    p.shapeBodies = String(++this.bodies);
    p.shapeReady = 'true';
    const hint = document.getElementById('empty-hint');
    if (hint && !this.suppressed) hint.hidden = true;
    if (this.morph.idle) p.shapeSettled = 'true';
    this.onShown(body);
  }
}

function standBeside(bounds: Bounds): number[] {
  const minY = Number.isFinite(bounds[1]) ? bounds[1] : 0;
  return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, SHAPE_BODY_SIDE_OFFSET_M, -minY, 0, 1];
}
