// The slider values of the shape body: the whole body's coefficients and each segment's own (null:
// the segment follows the whole body), σ values in 0.001σ steps; each change shows itself on the
// panel's sliders and asks for the body.
import { quantiseSigma, type ShapeLink } from '../shared/shape-link';
import { SEGMENTS, type LoadedModel, type SegmentName, type ShapeCoefficients } from '../shared/shape-results';
import type { PartName, ShapePanel } from '../ui/shape-panel';
import type { Viewer } from '../view/viewer';
import type { ShapeModel } from './shape-model';
import type { ShownBody } from './shown-body';

export class ShapeSliders {
  values: ShapeCoefficients = { whole: [], segments: SEGMENTS.map(() => null) };
  private readonly page = document.body;

  constructor(
    private readonly model: ShapeModel,
    private readonly shown: ShownBody,
    private readonly panel: ShapePanel,
  ) {}

  /** A new model: its mean body, every segment following the whole (the panel shows it with the model). */
  zero(loaded: LoadedModel): void {
    this.values = { whole: loaded.info.parts[0]!.variances.map(() => 0), segments: SEGMENTS.map(() => null) };
  }

  /** The values and view a link names (each to its 0.001σ step, missing ones 0); the link's camera, if any, wins over framing. */
  restore(link: ShapeLink, viewer: Viewer): void {
    const model = this.model.loaded!;
    const parts = model.info.parts;
    const fit = (values: number[], n: number) => Array.from({ length: n }, (_, k) => quantiseSigma(values[k] ?? 0));
    this.values = {
      whole: fit(link.coefficients.whole, parts[0]!.variances.length),
      segments: link.coefficients.segments.map((s, i) => (s ? fit(s, parts[i + 1]!.variances.length) : null)),
    };
    this.panel.showView(link.view, this.values);
    this.panel.measurements.setTargetable(link.view, model.targetable[link.view]);
    // The load asked to frame the camera; a link's own camera wins over that.
    this.shown.frameNextBody = !link.camera;
    this.shown.redraw(!link.camera, true);
    if (link.camera) viewer.setCameraPose(link.camera);
    this.page.dataset.linkRestored = 'true';
  }

  /** Slider `k` of `part` moved to `t` σ; a segment that followed the whole body takes its own shape. */
  set(part: PartName, k: number, t: number): void {
    this.shown.reveal();
    const value = quantiseSigma(t);
    if (part === 'whole') this.values.whole[k] = value;
    else {
      const i = SEGMENTS.indexOf(part);
      const n = this.model.loaded!.info.parts[i + 1]!.variances.length;
      const own = this.values.segments[i] ?? Array.from({ length: n }, () => 0);
      own[k] = value;
      const wasFollowing = !this.values.segments[i];
      this.values.segments[i] = own;
      if (wasFollowing) this.panel.showView(part, this.values);
    }
    this.shown.redraw(false);
  }

  /** Shows the sliders of `part` (nothing moves). */
  setView(part: PartName): void {
    this.shown.reveal();
    this.panel.showView(part, this.values);
    if (this.model.loaded) this.panel.measurements.setTargetable(part, this.model.loaded.targetable[part]);
    this.page.dataset.shapeView = part;
  }

  /** Segment `part` follows the whole body again. */
  followWhole(part: SegmentName): void {
    this.shown.reveal();
    this.values.segments[SEGMENTS.indexOf(part)] = null;
    this.panel.showView(part, this.values);
    this.shown.redraw(false);
  }

  /** The mean body: every value 0, every segment following the whole. */
  reset(): void {
    this.shown.reveal();
    if (!this.model.loaded) return;
    this.values = { whole: this.values.whole.map(() => 0), segments: SEGMENTS.map(() => null) };
    this.showValues();
  }

  /** b ~ N(0, σ²): standard normal σ values (Box–Muller), clipped to the sliders' ±3σ. */
  random(): void {
    this.shown.reveal();
    if (!this.model.loaded) return;
    const normal = () => Math.sqrt(-2 * Math.log(1 - Math.random())) * Math.cos(2 * Math.PI * Math.random());
    const draw = (n: number) => Array.from({ length: n }, () => quantiseSigma(Math.max(-3, Math.min(3, normal()))));
    this.values = {
      whole: draw(this.values.whole.length),
      segments: this.values.segments.map((s) => (s ? draw(s.length) : null)),
    };
    this.showValues();
  }

  /** Shows the whole body at σ values `sigma` on the sliders; every segment follows it. */
  showWhole(sigma: number[]): void {
    if (!this.model.loaded) return;
    this.shown.reveal();
    this.values = { whole: this.values.whole.map((_, k) => quantiseSigma(sigma[k] ?? 0)), segments: SEGMENTS.map(() => null) };
    this.showValues();
  }

  /** Gives `part` its own shape at σ values `sigma`, the rest of the body as it is. */
  showSegment(part: SegmentName, sigma: number[]): void {
    const i = SEGMENTS.indexOf(part);
    this.values.segments[i] = this.model.loaded!.info.parts[i + 1]!.variances.map((_, k) => quantiseSigma(sigma[k] ?? 0));
    this.showValues();
  }

  /** Values set all at once: the sliders of the view shown, and the body rebuilt from scratch. */
  private showValues(): void {
    this.panel.showView(this.panel.currentView, this.values);
    this.shown.redraw(false, true);
  }
}
