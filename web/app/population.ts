// The population of the model in view, in a worker of its own (cancelling it never touches the
// body shown): the measurement distributions over the training subjects and sampled bodies,
// computed once per model with progress, then the body on screen looked up in them on every
// slider move; and the boundary manikins of chosen measurements.
import { CancelledError, type CoreClient } from '../client/core-client';
import type { ManikinSet, MeasurementDistribution } from '../shared/anthropometry';
import { SEGMENTS, type Measurements } from '../shared/shape-results';
import { zip, type ZipEntry } from '../shared/zip';
import { download } from '../ui/download';
import type { ManikinPanel } from '../ui/manikin-panel';
import type { PopulationView } from '../ui/population-view';
import { bodiesGlb } from '../view/gltf-export';

/** A model file as the shape space keeps it. */
export interface ModelFile {
  bytes: ArrayBuffer;
  fileName: string;
}

export class Population {
  private file: ModelFile | null = null;
  /** Whether the worker holds `file` (a cancel replaces the worker, and its model with it). */
  private loaded = false;
  private distribution: MeasurementDistribution | null = null;
  /** Triangles of the model's own bodies (its resolution), for the manikin files. */
  private triangles: Uint32Array | null = null;
  private manikins: ManikinSet | null = null;
  private defaultsAsked = false;
  private measurements: Measurements = [];
  /** Bumped by every new model and cancel, so a late result of an older one is dropped. */
  private generation = 0;
  private readonly page = document.body;

  constructor(
    private readonly client: CoreClient<'population'>,
    private readonly view: PopulationView,
    private readonly manikinPanel: ManikinPanel,
    /** Shows a whole body (σ values) on the sliders. */
    private readonly showWhole: (sigma: number[]) => void,
  ) {}

  /** A new model is in view: its distributions are computed in the background. */
  setModel(file: ModelFile): void {
    this.file = file;
    this.loaded = false;
    this.distribution = null;
    this.manikins = null;
    this.view.clear();
    if (this.client.busy) this.client.cancel();
    void this.compute();
  }

  /** The body on screen changed. */
  showBody(measurements: Measurements): void {
    this.measurements = measurements;
    this.manikinPanel.setMeasurements(measurements);
    if (this.distribution) this.view.update(measurements);
  }

  /** The worker holding the model in view (loaded again after a cancel). */
  async ready(): Promise<CoreClient<'population'>> {
    if (!this.file) throw new Error('no shape model is loaded');
    if (!this.loaded) {
      const loaded = await this.client.call({ type: 'loadModel', bytes: this.file.bytes.slice(0), fileName: this.file.fileName });
      this.triangles = loaded.triangles;
      this.loaded = true;
      if (!this.defaultsAsked) {
        this.defaultsAsked = true;
        this.manikinPanel.setDefaultCoverage((await this.client.call({ type: 'manikinDefaults' })).coverage);
      }
    }
    return this.client;
  }

  async compute(): Promise<void> {
    const generation = ++this.generation;
    this.page.dataset.populationReady = 'false';
    try {
      const client = await this.ready();
      this.view.showProgress(0, 'Measuring the training subjects and sampled bodies');
      const d = await client.call({ type: 'measurementDistribution' }, { onProgress: (f, label) => generation === this.generation && this.view.showProgress(f, label) });
      if (generation !== this.generation) return;
      this.distribution = d;
      this.view.show(d, this.measurements);
      this.page.dataset.populationReady = 'true';
      this.page.dataset.populationMs = d.workerMs.toFixed(0);
    } catch (error) {
      if (generation !== this.generation) return;
      this.view.showStopped(error instanceof CancelledError ? 'Cancelled: the population was not computed.' : `The population could not be computed: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  /** The boundary manikins of `names` at `coverage` (a share); needs the population measured. */
  async computeManikins(names: string[], coverage: number): Promise<void> {
    if (!this.distribution) {
      this.manikinPanel.showError('The population of this model is not measured yet: wait for it above (or press Compute again).');
      return;
    }
    const generation = this.generation;
    this.page.dataset.manikins = 'running';
    try {
      const client = await this.ready();
      const set = await client.call({ type: 'boundaryManikins', names, coverage }, { onProgress: (f, label) => this.manikinPanel.showProgress(f, label) });
      if (generation !== this.generation) return;
      this.manikins = set;
      this.manikinPanel.show(set, this.measurements);
      this.page.dataset.manikins = String(set.manikins.manikins.length);
      this.page.dataset.manikinsMs = set.workerMs.toFixed(0);
    } catch (error) {
      if (generation !== this.generation) return;
      this.manikinPanel.showError(error instanceof CancelledError ? 'Cancelled.' : error instanceof Error ? error.message : String(error));
      this.page.dataset.manikins = 'error';
    }
  }

  showManikin(index: number): void {
    const k = this.manikins?.manikins.manikins[index];
    if (!k) return;
    this.showWhole(k.body.sigma);
    this.manikinPanel.markShown(index);
  }

  /**
   * The manikins found, as one download `manikins.zip` holding `manikins.glb` (every manikin,
   * side by side, one mesh each), `manikin_01.ply` … (the core's PLY writer) and `manikins.csv`
   * (the core's CSV): one file, so the browser does not ask to allow many downloads.
   */
  async exportManikins(): Promise<void> {
    const set = this.manikins;
    if (!set) return;
    try {
      const client = await this.ready();
      const triangles = this.triangles!;
      const bodies = [];
      const files: ZipEntry[] = [];
      for (const k of set.manikins.manikins) {
        const made = await client.call({ type: 'reconstruct', coefficients: { whole: k.body.sigma, segments: SEGMENTS.map(() => null) } });
        bodies.push({ name: k.name, positions: made.positions, normals: made.normals, triangles });
        const ply = await client.call({ type: 'exportMesh', positions: made.positions.slice(), triangles: triangles.slice(), format: 'ply' });
        files.push({ name: `${k.name}.ply`, data: ply });
      }
      files.unshift({ name: 'manikins.glb', data: await bodiesGlb(bodies, 0.7) }, { name: 'manikins.csv', data: set.csv });
      download('manikins.zip', zip(files), 'application/zip');
      this.page.dataset.manikinsExported = String(bodies.length);
    } catch (error) {
      this.manikinPanel.showError(`The manikins could not be exported: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  /** Stops whatever the population worker is doing (it is replaced; the model is sent again when needed). */
  cancel(): void {
    this.generation++;
    this.client.cancel();
    this.loaded = false;
    if (!this.distribution) this.view.showStopped('Cancelled: the population was not computed.');
    else this.manikinPanel.showError('Cancelled.');
    this.page.dataset.populationReady = 'cancelled';
  }
}
