// The shape-space panel put together: the model in view (shape-model.ts), its slider values
// (shape-sliders.ts), the body shown (shown-body.ts), Find body (find-body.ts), the population
// (population.ts), the link (shape-share.ts) and the downloads (shape-exports.ts). Here: what
// happens when a model arrives (the demo model or a link's at start, a dropped file, a build, the
// model built before a reload, model-store.ts) or when the worker holding it is replaced.
import type { CoreClient } from '../client/core-client';
import { decodeShapeLink } from '../shared/shape-link';
import type { LoadedModel } from '../shared/shape-results';
import type { TemplateResolution } from '../shared/template-data';
import type { ErrorBanner } from '../ui/error-banner';
import { ShapePanel } from '../ui/shape-panel';
import type { Viewer } from '../view/viewer';
import { findBody } from './find-body';
import { ModelStore, type KeptModel } from './model-store';
import { Population } from './population';
import { ShapeExports } from './shape-exports';
import { cannotBuild, ShapeModel } from './shape-model';
import { ShapeShare } from './shape-share';
import { ShapeSliders } from './shape-sliders';
import { ShownBody } from './shown-body';
import { subjects, type AlignedSubject } from './subjects';

/** Where the app finds its embedded model, relative to the page. */
const DEMO_MODEL = 'models/demo.bsm';

export class ShapeSpace {
  private readonly model: ShapeModel;
  private readonly shown: ShownBody;
  private readonly sliders: ShapeSliders;
  private readonly panel: ShapePanel;
  private readonly population: Population;
  private readonly page = document.body;
  /** The last model built here, kept across a reload. */
  private readonly kept = new ModelStore();

  constructor(
    client: CoreClient<'core'>,
    private readonly viewer: Viewer,
    private readonly banner: ErrorBanner,
    /** The worker of population work (distributions, manikins), which Cancel may replace. */
    populationClient: CoreClient<'population'>,
  ) {
    const model = (this.model = new ShapeModel(client));
    const panel = (this.panel = new ShapePanel({
      onSlider: (part, k, t) => this.sliders.set(part, k, t),
      onView: (part) => this.sliders.setView(part),
      onReset: () => this.sliders.reset(),
      onRandom: () => this.sliders.random(),
      onFollowWhole: (part) => this.sliders.followWhole(part),
      onCsv: (kind) => void shapeExports.csv(kind),
      onExportBody: (format) => void shapeExports.body(format),
      onExportMode: (mode, steps) => void shapeExports.alongMode(mode, steps),
      onExportModelGltf: (parts) => void shapeExports.modelGlb(parts),
      onResolution: (resolution) => void this.shown.switchResolution(resolution),
      onSaveModel: () => void shapeExports.modelFile(),
      onSaveStatismo: () => void shapeExports.modelStatismo(),
      onCopyLink: () => void share.copy(),
      onBuild: (variance) => void this.build(variance),
      onAddFits: (files) => void this.addFits(files),
      onOpenModel: (files) => void this.openModelFiles(files),
      onFindBody: (targets) => void findBody(client, { model, shown: this.shown, sliders: this.sliders, panel }, targets),
      onComputePopulation: () => void this.population.compute(),
      onCancelPopulation: () => this.population.cancel(),
      onManikins: (names, coverage) => void this.population.computeManikins(names, coverage),
      onShowManikin: (index) => this.population.showManikin(index),
      onExportManikins: () => void this.population.exportManikins(),
    }));
    this.shown = new ShownBody(client, model, viewer, panel, banner, () => this.sliders.values, (body) => {
      this.population.showBody(body.measurements);
      share.update();
    });
    this.sliders = new ShapeSliders(model, this.shown, panel);
    const share = new ShapeShare(model, this.sliders, this.shown, panel, viewer);
    const shapeExports = new ShapeExports(client, model, this.shown, this.sliders, panel, banner);
    this.population = new Population(populationClient, panel.population, panel.manikins, (sigma) => this.sliders.showWhole(sigma));
    client.onRestart(() => void this.recover());
    subjects.subscribe((all) => {
      const dropped = all.filter((s) => s.source === 'dropped').length;
      panel.showSubjects(all.length - dropped, dropped);
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
    if (link) this.shown.resolution = link.resolution;
    const loaded = await this.fetchModel(link?.model ?? DEMO_MODEL);
    if (!loaded && link && link.model !== DEMO_MODEL) await this.fetchModel(DEMO_MODEL);
    this.page.dataset.shapeStarted = 'true';
    if (link && loaded) this.sliders.restore(link, this.viewer);
    else this.shown.redraw(true, true);
    await this.offerKept();
  }

  /** Offers the model built here before the page was reloaded, if one is kept. */
  private async offerKept(): Promise<void> {
    const kept = await this.kept.load();
    if (!kept) return;
    const when = new Date(kept.builtAt).toLocaleString();
    this.panel.showKept(
      `The model built here from ${kept.subjects} subjects (${when}) is kept in this browser.`,
      `Open ${kept.fileName}`,
      () => void this.openKept(kept),
    );
  }

  private async openKept(kept: KeptModel): Promise<void> {
    this.shown.reveal();
    if (await this.load(kept.bytes.slice(0), kept.fileName, null)) this.panel.showKept(null);
  }

  /** Takes the shape body out of the view (a scan was opened); any shape action brings it back. */
  hide(): void {
    this.shown.hide();
  }

  /** Whether `name` is a model file for this panel (dropped with other files): `.bsm` or statismo `.h5`. */
  static isModelFile(name: string): boolean {
    return /\.(bsm|h5)$/i.test(name);
  }

  async openModelFiles(files: File[]): Promise<void> {
    this.shown.reveal();
    const file = files.at(-1);
    if (!file) return;
    const bytes = await file.arrayBuffer();
    await this.load(bytes, file.name, null);
  }

  /**
   * Builds a model from `list` (the batch's kept subjects) with the panel's variance, shows it and
   * reports each step through `onStatus`; resolves with whether a model was built.
   */
  async buildFrom(list: readonly AlignedSubject[], onStatus: (text: string) => void): Promise<boolean> {
    this.shown.reveal();
    return this.build(this.panel.buildVariance, list, onStatus);
  }

  /**
   * The worker was replaced after its core trapped: gives the new one the model in view again and
   * rebuilds the body shown, with every slider value and the resolution kept, and says so.
   */
  private async recover(): Promise<void> {
    const file = this.model.file;
    if (!file) return;
    this.page.dataset.shapeRecovered = 'false';
    try {
      await this.model.reload(this.shown.resolution);
      this.shown.redraw(false, true);
      this.banner.show([`The core stopped unexpectedly and was restarted; the shape model (${file.fileName}) was loaded again and the body shown was rebuilt with every slider value.`]);
      this.page.dataset.shapeRecovered = 'true';
    } catch (error) {
      this.banner.show([`The core stopped unexpectedly and the shape model could not be loaded again: ${error instanceof Error ? error.message : String(error)}`]);
    }
  }

  /** Loads the model at `location` (see `ShapeModel.fetch`), checked by the core like a dropped file. */
  private async fetchModel(location: string): Promise<boolean> {
    try {
      const bytes = await this.model.fetch(location);
      return bytes ? await this.load(bytes, location, location) : false;
    } catch (error) {
      this.banner.show([`The shape model could not be loaded: ${error instanceof Error ? error.message : String(error)}`]);
      return false;
    }
  }

  /** Loads a model; on failure the banner shows the core's message and the old model stays. */
  private async load(bytes: ArrayBuffer, fileName: string, source: string | null): Promise<boolean> {
    this.page.dataset.shapeBusy = 'true';
    try {
      const loaded = await this.model.load(bytes, fileName, source);
      this.population.setModel(this.model.file!);
      const wanted = this.shown.resolution;
      this.adopt(loaded, fileName);
      await this.shown.keepResolution(wanted);
      this.shown.redraw(true, true);
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

  /** A new model in view: its mean body on the sliders, its facts on the panel, at its own resolution. */
  private adopt(loaded: LoadedModel, label: string): void {
    this.sliders.zero(loaded);
    this.panel.showModel(label, loaded.info.parts, loaded.info.subjects.length);
    this.panel.showView('whole', this.sliders.values);
    this.panel.measurements.clear();
    this.panel.measurements.setTargetable('whole', loaded.targetable.whole);
    this.page.dataset.shapeModel = label;
    this.page.dataset.shapeModes = String(loaded.info.parts[0]!.variances.length);
    this.shown.showResolution({ resolution: loaded.info.template.resolution as TemplateResolution, vertexCount: loaded.info.template.vertex_count, triangles: loaded.triangles });
  }

  private async addFits(files: File[]): Promise<void> {
    const errors = await this.model.addFits(files);
    if (errors.length) this.banner.show(errors);
  }

  private async build(
    variance: number,
    all: readonly AlignedSubject[] = subjects.all,
    onStatus: (text: string) => void = (text) => this.panel.showBuildStatus(text),
  ): Promise<boolean> {
    const problem = cannotBuild(all);
    if (problem) {
      onStatus(problem);
      return false;
    }
    this.page.dataset.shapeBuilding = 'true';
    try {
      const wanted = this.shown.resolution;
      const built = await this.model.build(all, variance, (f, label) => onStatus(`${label} (${Math.round(f * 100)} %)`));
      this.adopt(built, built.fileName);
      const file = await this.model.keepBuiltFile(built.fileName);
      this.population.setModel(file);
      this.panel.showKept(null);
      onStatus(`Built from ${all.length} subjects.`);
      // Kept for after a reload; the page's `data-model-kept` says when it is stored.
      void this.kept.keep({ bytes: file.bytes.slice(0), fileName: file.fileName, subjects: all.length, builtAt: new Date().toISOString() }).then((done) => {
        if (done) this.page.dataset.modelKept = String(Number(this.page.dataset.modelKept ?? '0') + 1);
      });
      await this.shown.keepResolution(wanted);
      this.shown.redraw(true, true);
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
