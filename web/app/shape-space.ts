// The shape-space workflow: loads the demo model (or the one a link names), keeps the slider
// values, morphs through the MorphQueue, and runs exports, CSV, links and in-app model builds.
import type { CoreClient } from '../client/core-client';
import { fetchBounded, foreignHost, MODEL_DOWNLOAD_LIMIT } from '../shared/bounded-fetch';
import type { Bounds } from '../shared/bounds';
import { HostPrompt } from '../ui/host-prompt';
import { decodeShapeLink, encodeShapeLink, isShareableModel, quantiseSigma, type ShapeLink } from '../shared/shape-link';
import {
  SEGMENTS,
  reading,
  type LoadedModel,
  type ModelCsv,
  type ModelGlbParts,
  type ReconstructedBody,
  type SegmentName,
  type ShapeCoefficients,
  type ShownResolution,
} from '../shared/shape-results';
import type { TemplateResolution } from '../shared/template-data';
import type { Targets } from '../shared/anthropometry';
import type { ErrorBanner } from '../ui/error-banner';
import { ShapePanel, type PartName } from '../ui/shape-panel';
import type { Viewer } from '../view/viewer';
import { MorphQueue } from './morph-queue';
import { Population } from './population';
import * as shapeExports from './shape-exports';
import type { BodyFormat } from './shape-exports';
import { readFits } from './read-fits';
import { subjects, type AlignedSubject } from './subjects';

/** Where the app finds its embedded model, relative to the page. */
const DEMO_MODEL = 'models/demo.bsm';

export class ShapeSpace {
  private model: LoadedModel | null = null;
  /** Same-origin path or https URL of the model, `null` when dropped or built here. */
  private source: string | null = null;
  private coefficients: ShapeCoefficients = { whole: [], segments: SEGMENTS.map(() => null) };
  private body: ReconstructedBody | null = null;
  /** Resolution the body is shown at (chosen in the panel; kept across model loads). */
  private resolution: TemplateResolution = 'base';
  /** Triangles of the body shown: the model's own, or the fine template's. */
  private triangles: Uint32Array | null = null;
  private readonly panel: ShapePanel;
  private readonly population: Population;
  private readonly morph: MorphQueue;
  private readonly page = document.body;
  private readonly hostPrompt = new HostPrompt();
  /** A copy of the model file in view, so a replaced worker (its core trapped) can be given it again. */
  private modelFile: { bytes: ArrayBuffer; fileName: string } | null = null;
  private bodies = 0;
  /** Set while a scan is being looked at: the shape body stays out of the view until asked for. */
  private suppressed = false;

  constructor(
    private readonly client: CoreClient<'core'>,
    private readonly viewer: Viewer,
    private readonly banner: ErrorBanner,
    /** The worker of population work (distributions, manikins), which Cancel may replace. */
    populationClient: CoreClient<'population'>,
  ) {
    this.morph = new MorphQueue(client, (body, _c, sentAt) => this.show(body, sentAt), (message) => this.banner.show([message]));
    this.panel = new ShapePanel({
      onSlider: (part, k, t) => this.setValue(part, k, t),
      onView: (part) => this.setView(part),
      onReset: () => this.reset(),
      onRandom: () => this.random(),
      onFollowWhole: (part) => this.followWhole(part),
      onCsv: (kind) => void this.csv(kind),
      onExportBody: (format) => void this.exportBody(format),
      onExportMode: (mode, steps) => void this.exportMode(mode, steps),
      onExportModelGltf: (parts) => void this.exportModelGltf(parts),
      onResolution: (resolution) => void this.switchResolution(resolution),
      onSaveModel: () => void this.saveModel(),
      onSaveStatismo: () => void this.saveStatismo(),
      onCopyLink: () => void this.copyLink(),
      onBuild: (variance) => void this.build(variance),
      onAddFits: (files) => void this.addFits(files),
      onOpenModel: (files) => void this.openModelFiles(files),
      onFindBody: (targets) => void this.findBody(targets),
      onComputePopulation: () => void this.population.compute(),
      onCancelPopulation: () => this.population.cancel(),
      onManikins: (names, coverage) => void this.population.computeManikins(names, coverage),
      onShowManikin: (index) => this.population.showManikin(index),
      onExportManikins: () => void this.population.exportManikins(),
    });
    this.population = new Population(populationClient, this.panel.population, this.panel.manikins, (sigma) => this.showWhole(sigma));
    client.onRestart(() => void this.recover());
    subjects.subscribe((all) => {
      const dropped = all.filter((s) => s.source === 'dropped').length;
      this.panel.showSubjects(all.length - dropped, dropped);
    });
  }

  /** Opens the model and body a link names, else the demo model at its mean. */
  async start(hash: string): Promise<void> {
    const decoded = decodeShapeLink(hash);
    if (decoded && decoded.problems.length) {
      this.banner.show([`The link was ignored and the app opened in its default state: ${decoded.problems.join('; ')}.`]);
      this.page.dataset.linkIgnored = 'true';
    }
    const link = decoded?.link ?? null;
    // A link's resolution applies as the model loads (a base model is mapped to fine).
    if (link) this.resolution = link.resolution;
    const loaded = await this.fetchModel(link?.model ?? DEMO_MODEL);
    if (!loaded && link && link.model !== DEMO_MODEL) await this.fetchModel(DEMO_MODEL);
    this.page.dataset.shapeStarted = 'true';
    if (link && loaded) this.restore(link);
    else this.redraw(true, true);
  }

  /**
   * The worker was replaced after its core trapped: gives the new one the model in view again and
   * rebuilds the body shown, with every slider value and the resolution kept, and says so.
   */
  private async recover(): Promise<void> {
    const file = this.modelFile;
    if (!file) return;
    this.page.dataset.shapeRecovered = 'false';
    try {
      await this.client.call({ type: 'loadModel', bytes: file.bytes.slice(0), fileName: file.fileName });
      const wanted = this.resolution;
      if (wanted === 'fine' && this.model?.info.template.resolution === 'base') {
        await this.client.call({ type: 'shapeResolution', resolution: 'fine' });
      }
      this.redraw(false, true);
      this.banner.show([`The core stopped unexpectedly and was restarted; the shape model (${file.fileName}) was loaded again and the body shown was rebuilt with every slider value.`]);
      this.page.dataset.shapeRecovered = 'true';
    } catch (error) {
      this.banner.show([`The core stopped unexpectedly and the shape model could not be loaded again: ${error instanceof Error ? error.message : String(error)}`]);
    }
  }

  /** Takes the shape body out of the view (a scan was opened); any shape action brings it back. */
  hide(): void {
    this.suppressed = true;
    this.viewer.removeBody('shape');
    this.page.dataset.shapeShown = 'false';
  }

  /** Whether `name` is a model file for this panel (dropped with other files): `.bsm` or statismo `.h5`. */
  static isModelFile(name: string): boolean {
    return /\.(bsm|h5)$/i.test(name);
  }

  async openModelFiles(files: File[]): Promise<void> {
    this.suppressed = false;
    const file = files.at(-1);
    if (!file) return;
    const bytes = await file.arrayBuffer();
    await this.load(bytes, file.name, null);
  }

  /**
   * Loads the model at `location`. A model on another host is fetched only when the person agrees
   * (the prompt names the host); every download has a size limit, and the bytes are checked by the
   * core like a dropped file.
   */
  private async fetchModel(location: string): Promise<boolean> {
    const host = foreignHost(new URL(location, document.baseURI).href, window.location.origin);
    if (host && !(await this.hostPrompt.ask(host, 'shape model'))) {
      this.page.dataset.shapeForeignDeclined = host;
      return false;
    }
    try {
      return await this.load(await fetchBounded(location, MODEL_DOWNLOAD_LIMIT), location, location);
    } catch (error) {
      this.banner.show([`The shape model could not be loaded: ${error instanceof Error ? error.message : String(error)}`]);
      return false;
    }
  }

  /** Loads a model; on failure the banner shows the core's message and the old model stays. */
  private async load(bytes: ArrayBuffer, fileName: string, source: string | null): Promise<boolean> {
    this.page.dataset.shapeBusy = 'true';
    const copy = bytes.slice(0);
    try {
      const loaded = await this.client.call({ type: 'loadModel', bytes, fileName }, { transfer: [bytes] });
      this.modelFile = { bytes: copy, fileName };
      this.population.setModel(this.modelFile);
      const wanted = this.resolution;
      this.adopt(loaded, source, fileName);
      await this.keepResolution(wanted);
      this.redraw(true, true);
      return true;
    } catch (error) {
      const message = error instanceof Error ? error.message : String(error);
      this.banner.show([`${message}. The model shown before stays; download the model file again (or build it again) and open it.`]);
      this.page.dataset.shapeLoadFailed = String(Number(this.page.dataset.shapeLoadFailed ?? '0') + 1);
      return false;
    } finally {
      this.page.dataset.shapeBusy = 'false';
    }
  }

  private adopt(loaded: LoadedModel, source: string | null, label: string): void {
    this.model = loaded;
    this.triangles = loaded.triangles;
    this.source = source;
    this.coefficients = { whole: loaded.info.parts[0]!.variances.map(() => 0), segments: SEGMENTS.map(() => null) };
    this.panel.showModel(label, loaded.info.parts, loaded.info.subjects.length);
    this.panel.showView('whole', this.coefficients);
    this.panel.measurements.clear();
    this.panel.measurements.setTargetable('whole', loaded.targetable.whole);
    this.page.dataset.shapeModel = label;
    this.page.dataset.shapeModes = String(loaded.info.parts[0]!.variances.length);
    this.showResolution({ resolution: loaded.info.template.resolution as TemplateResolution, vertexCount: loaded.info.template.vertex_count, triangles: loaded.triangles });
  }

  /** A newly loaded model is shown at its own resolution: go to fine again if that was chosen. */
  private async keepResolution(wanted: TemplateResolution): Promise<void> {
    if (wanted === 'fine' && this.model?.info.template.resolution === 'base') await this.switchResolution('fine', false);
  }

  /**
   * Shows the body at `resolution`: the worker maps the model to the fine template on first
   * use (progress in the panel); the coefficients stay. A failure leaves the resolution as it was.
   */
  private async switchResolution(resolution: TemplateResolution, redraw = true): Promise<void> {
    if (!this.model) return;
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
      this.panel.showResolution(this.resolution, this.triangles ? this.vertexCountShown : 0);
      this.banner.show([error instanceof Error ? error.message : String(error)]);
    } finally {
      this.page.dataset.shapeBusy = 'false';
      if (this.morph.idle) this.page.dataset.shapeSettled = 'true';
    }
  }

  private vertexCountShown = 0;

  private showResolution(shown: ShownResolution): void {
    this.resolution = shown.resolution;
    this.triangles = shown.triangles;
    this.vertexCountShown = shown.vertexCount;
    this.panel.showResolution(shown.resolution, shown.vertexCount);
    this.page.dataset.shapeResolution = shown.resolution;
  }

  private restore(link: ShapeLink): void {
    const parts = this.model!.info.parts;
    const fit = (values: number[], n: number) => Array.from({ length: n }, (_, k) => quantiseSigma(values[k] ?? 0));
    this.coefficients = {
      whole: fit(link.coefficients.whole, parts[0]!.variances.length),
      segments: link.coefficients.segments.map((s, i) => (s ? fit(s, parts[i + 1]!.variances.length) : null)),
    };
    this.panel.showView(link.view, this.coefficients);
    this.panel.measurements.setTargetable(link.view, this.model!.targetable[link.view]);
    // The load asked to frame the camera; a link's own camera wins over that.
    this.frameNext = !link.camera;
    this.redraw(!link.camera, true);
    if (link.camera) this.viewer.setCameraPose(link.camera);
    this.page.dataset.linkRestored = 'true';
  }

  private setValue(part: PartName, k: number, t: number): void {
    this.suppressed = false;
    const value = quantiseSigma(t);
    if (part === 'whole') this.coefficients.whole[k] = value;
    else {
      const i = SEGMENTS.indexOf(part);
      const n = this.model!.info.parts[i + 1]!.variances.length;
      const own = this.coefficients.segments[i] ?? Array.from({ length: n }, () => 0);
      own[k] = value;
      const wasFollowing = !this.coefficients.segments[i];
      this.coefficients.segments[i] = own;
      if (wasFollowing) this.panel.showView(part, this.coefficients);
    }
    this.redraw(false);
  }

  private setView(part: PartName): void {
    this.suppressed = false;
    this.panel.showView(part, this.coefficients);
    if (this.model) this.panel.measurements.setTargetable(part, this.model.targetable[part]);
    this.page.dataset.shapeView = part;
  }

  private followWhole(part: SegmentName): void {
    this.suppressed = false;
    this.coefficients.segments[SEGMENTS.indexOf(part)] = null;
    this.panel.showView(part, this.coefficients);
    this.redraw(false);
  }

  private reset(): void {
    this.suppressed = false;
    if (!this.model) return;
    this.coefficients = { whole: this.coefficients.whole.map(() => 0), segments: SEGMENTS.map(() => null) };
    this.panel.showView(this.panel.currentView, this.coefficients);
    this.redraw(false, true);
  }

  /** b ~ N(0, σ²): standard normal σ values (Box–Muller), clipped to the sliders' ±3σ. */
  private random(): void {
    this.suppressed = false;
    if (!this.model) return;
    const normal = () => Math.sqrt(-2 * Math.log(1 - Math.random())) * Math.cos(2 * Math.PI * Math.random());
    const draw = (n: number) => Array.from({ length: n }, () => quantiseSigma(Math.max(-3, Math.min(3, normal()))));
    this.coefficients = {
      whole: draw(this.coefficients.whole.length),
      segments: this.coefficients.segments.map((s) => (s ? draw(s.length) : null)),
    };
    this.panel.showView(this.panel.currentView, this.coefficients);
    this.redraw(false, true);
  }

  /**
   * Moves the sliders to the most likely body with `targets` (found in the worker): in the whole
   * body's view a whole body, every segment following it; in a segment's view that segment's own
   * shape, the rest of the body held.
   */
  private async findBody(targets: Targets): Promise<void> {
    if (!this.model) return;
    this.suppressed = false;
    this.page.dataset.findBody = 'running';
    try {
      const found = await this.client.call({ type: 'bodyFromMeasurements', targets, part: this.panel.currentView });
      this.panel.measurements.showFound(targets, found);
      this.page.dataset.findBodyMs = found.workerMs.toFixed(2);
      if (found.part === 'whole') this.showWhole(found.sigma);
      else this.showSegment(found.part, found.sigma);
      this.page.dataset.findBody = 'done';
    } catch (error) {
      this.panel.measurements.showError(error instanceof Error ? error.message : String(error));
      this.page.dataset.findBody = 'error';
    }
  }

  /** Shows the whole body at σ values `sigma` on the sliders; every segment follows it. */
  private showWhole(sigma: number[]): void {
    if (!this.model) return;
    this.suppressed = false;
    this.coefficients = { whole: this.coefficients.whole.map((_, k) => quantiseSigma(sigma[k] ?? 0)), segments: SEGMENTS.map(() => null) };
    this.panel.showView(this.panel.currentView, this.coefficients);
    this.redraw(false, true);
  }

  /** Gives `part` its own shape at σ values `sigma`, the rest of the body as it is. */
  private showSegment(part: SegmentName, sigma: number[]): void {
    const i = SEGMENTS.indexOf(part);
    this.coefficients.segments[i] = this.model!.info.parts[i + 1]!.variances.map((_, k) => quantiseSigma(sigma[k] ?? 0));
    this.panel.showView(this.panel.currentView, this.coefficients);
    this.redraw(false, true);
  }

  private frameNext = false;

  /** Asks the worker for the body of the current coefficients; `rebuild`: from scratch. */
  private redraw(frame: boolean, rebuild = false): void {
    if (!this.model) return;
    this.frameNext ||= frame;
    this.page.dataset.shapeSettled = 'false';
    this.morph.request(this.coefficients, rebuild);
  }

  /** Shows a body from the worker; `sentAt`: when it was asked for (UI-thread round trip). */
  private show(body: ReconstructedBody, sentAt: number): void {
    const triangles = this.triangles;
    if (!this.model || !triangles) return;
    // A body of the resolution shown before a switch that has just landed: the next one follows.
    if (body.positions.length / 3 !== this.vertexCountShown) return;
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
    this.population.showBody(body.measurements);
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
    this.updateLink();
  }

  private updateLink(): void {
    if (!this.model) return;
    if (!this.source || !isShareableModel(this.source)) {
      this.panel.showLink('', 'This model was opened from a local file or built in this session: it has no address, so a link could not show it to anyone else. Put the model file on a web server (https) to share bodies of it.');
      this.page.dataset.shapeLink = '';
      return;
    }
    const hash = encodeShapeLink({
      model: this.source,
      coefficients: this.coefficients,
      view: this.panel.currentView,
      camera: this.viewer.cameraPose(),
      resolution: this.resolution,
    });
    const url = `${location.origin}${location.pathname}${hash}`;
    this.panel.showLink(url, 'The link holds the model location, every coefficient (0.001σ steps), the segment view, the camera and the resolution.');
    this.page.dataset.shapeLink = url;
  }

  private async copyLink(): Promise<void> {
    // The body on screen may hold rank-1 updates (within 1e-7 m of a reconstruction); whoever
    // opens the link reconstructs from scratch, so rebuild here and both see the same bits.
    if (this.body && !this.body.rebuilt) this.redraw(false, true);
    this.updateLink();
    const url = this.page.dataset.shapeLink;
    if (!url) return;
    history.replaceState(null, '', url);
    try {
      await navigator.clipboard.writeText(url);
    } catch {
      // No clipboard permission (e.g. headless): the text field holds the link to copy by hand.
    }
  }

  private async csv(kind: ModelCsv): Promise<void> {
    await shapeExports.csv(this.client, kind);
  }

  private async exportBody(format: BodyFormat): Promise<void> {
    if (!this.body || !this.triangles) return;
    await shapeExports.body(this.client, this.body, this.triangles, format);
  }

  private async exportMode(mode: number, steps: number[]): Promise<void> {
    if (!this.model || !this.triangles) return;
    await shapeExports.alongMode(this.client, this.coefficients, this.triangles, mode, steps);
  }

  private async exportModelGltf(parts: ModelGlbParts): Promise<void> {
    if (this.model) await shapeExports.modelGlb(this.client, this.model, parts);
  }

  private async saveModel(): Promise<void> {
    if (this.model) await shapeExports.modelFile(this.client);
  }

  /** The model in view — the whole body, or the segment picked — as statismo HDF5. */
  private async saveStatismo(): Promise<void> {
    if (!this.model) return;
    try {
      await shapeExports.modelStatismo(this.client, this.panel.currentView);
    } catch (error) {
      this.banner.show([`The statismo file could not be written: ${error instanceof Error ? error.message : String(error)}`]);
    }
  }

  private async addFits(files: File[]): Promise<void> {
    const model = this.model;
    const vertexCount = model?.info.template.vertex_count ?? 13380;
    const resolution = model?.info.template.resolution ?? 'base';
    const errors = await readFits(this.client, subjects, files, vertexCount, resolution);
    if (errors.length) this.banner.show(errors);
  }

  /**
   * Builds a model from `list` (the batch's kept subjects) with the panel's variance, shows it and
   * reports each step through `onStatus`; resolves with whether a model was built.
   */
  async buildFrom(list: readonly AlignedSubject[], onStatus: (text: string) => void): Promise<boolean> {
    this.suppressed = false;
    return this.build(this.panel.buildVariance, list, onStatus);
  }

  private async build(
    variance: number,
    all: readonly AlignedSubject[] = subjects.all,
    onStatus: (text: string) => void = (text) => this.panel.showBuildStatus(text),
  ): Promise<boolean> {
    if (all.length < 2) {
      onStatus('A model needs at least 2 aligned subjects; add fitted meshes or align scans first.');
      return false;
    }
    const v = all[0]!.positions.length;
    if (all.some((s) => s.positions.length !== v)) {
      onStatus('The subjects are at different template resolutions; a model needs one.');
      return false;
    }
    const positions = new Float32Array(v * all.length);
    all.forEach((s, i) => positions.set(s.positions, i * v));
    this.page.dataset.shapeBuilding = 'true';
    try {
      const wanted = this.resolution;
      const built = await this.client.call(
        { type: 'buildModel', positions, names: all.map((s) => s.name), variance },
        { transfer: [positions.buffer], onProgress: (f, label) => onStatus(`${label} (${Math.round(f * 100)} %)`) },
      );
      this.adopt(built, null, built.fileName);
      this.modelFile = { bytes: (await this.client.call({ type: 'modelFile' })).slice().buffer, fileName: built.fileName };
      this.population.setModel(this.modelFile);
      onStatus(`Built from ${all.length} subjects.`);
      await this.keepResolution(wanted);
      this.redraw(true, true);
      return true;
    } catch (error) {
      onStatus('');
      this.banner.show([error instanceof Error ? error.message : String(error)]);
      return false;
    } finally {
      this.page.dataset.shapeBuilding = 'false';
    }
  }
}

/** Model bodies are centred on their centroid (GPA): shown standing on the floor, 1 m to the
 * template's side, so the template and the model body are both in view (display only). */
const SHAPE_BODY_SIDE_OFFSET_M = 1.0;

function standBeside(bounds: Bounds): number[] {
  const minY = Number.isFinite(bounds[1]) ? bounds[1] : 0;
  return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, SHAPE_BODY_SIDE_OFFSET_M, -minY, 0, 1];
}
