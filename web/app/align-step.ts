// The Align step: RBF warp then fine alignment in the worker, with live progress and the
// template's latest positions after every round, so Cancel (which terminates the worker) leaves
// the last good state on screen. The result is shown as a distance heat map.
import { CancelledError, type CoreClient } from '../client/core-client';
import { rbfParams, type AlignResult } from '../shared/align-types';
import type { Bounds } from '../shared/bounds';
import { baseName } from '../shared/file-kind';
import type { CoreEvent } from '../shared/messages';
import { AlignPanel } from '../ui/align-panel';
import type { BodyMesh, Viewer } from '../view/viewer';
import { download } from '../ui/download';
import { subjectInput, subjectTransfer } from './scan-input';
import type { Session } from './session';
import { subjects } from './subjects';
import type { TemplateView } from './template-view';
import { SCAN_OPACITY, type WarpStep } from './warp-step';

/** The fitted template's colour where no heat map is drawn on it. */
export const FITTED_COLOUR = 0x8fd19e;

export class AlignStep {
  readonly panel: AlignPanel;
  private result: AlignResult | null = null;
  private latest: { positions: Float32Array; normals: Float32Array; bounds: Bounds; iteration: number } | null = null;
  private iteration = 0;
  private running = false;
  private drawScheduled = false;
  private kept = false;
  private legendMaxMm = 10;

  constructor(
    private readonly client: CoreClient<'align'>,
    private readonly viewer: Viewer,
    private readonly session: Session,
    private readonly template: TemplateView,
    private readonly warp: WarpStep,
    private readonly onError: (message: string) => void,
  ) {
    this.panel = new AlignPanel({
      onAlign: () => void this.run(),
      onCancel: () => this.cancel(),
      onExport: (format) => void this.export(format),
      onKeep: () => this.keep(),
      resolution: () => this.template.resolution,
    });
    warp.onTransform((transform) => this.viewer.showBody('fitted', { transform }));
  }

  /** A new scan or landmark file: the old fit no longer applies. */
  reset(): void {
    if (this.running) this.cancel();
    this.result = null;
    this.latest = null;
    this.viewer.removeBody('fitted');
    this.panel.render(this.warp.ready ? { state: 'idle' } : { state: 'unavailable' });
  }

  async run(): Promise<void> {
    const template = this.template.data;
    const input = template ? subjectInput(this.session, template.resolution) : null;
    const rbf = this.warp.panel.current;
    if (!template || !input || !rbf) return;
    this.running = true;
    this.result = null;
    this.latest = null;
    this.kept = false;
    this.iteration = 0;
    this.panel.chart.clear();
    this.panel.render({ state: 'running', iteration: 0, maxIterations: 0, rmsMm: null, stage: 'base' });
    this.warp.show('scan', true);
    const triangles = template.triangles;
    let rounds = 0;
    const onEvent = (event: CoreEvent) => {
      if (event.kind === 'alignProgress') {
        this.iteration = event.iteration;
        document.body.dataset.alignIteration = String(event.iteration);
        this.panel.chart.add({ iteration: event.iteration, energy: event.energy, rmsMm: event.rms * 1e3 });
        this.panel.render({
          state: 'running',
          iteration: event.iteration,
          maxIterations: event.max_iterations,
          rmsMm: event.rms * 1e3,
          stage: event.stage,
        });
        document.body.dataset.alignStage = event.stage;
      } else {
        this.latest = { positions: event.positions, normals: event.normals, bounds: event.bounds, iteration: event.iteration };
        document.body.dataset.alignRounds = String(++rounds);
        this.showLatestSoon(triangles);
      }
    };
    try {
      const posted = performance.now();
      const result = await this.client.call(
        { type: 'align', subject: input, options: { params: { rbf: rbfParams(rbf) }, orientation: this.session.orientation } },
        { transfer: subjectTransfer(input), onEvent },
      );
      recordTimings(result, performance.now() - posted);
      this.result = result;
      const heat = result.heat;
      this.legendMaxMm = heat.maxMm;
      this.showFitted({ positions: result.positions, triangles, normals: result.normals }, heat.colours);
      // The see-through scan would speckle the heat map it coincides with; its toggle brings it back.
      this.warp.show('scan', false);
      this.panel.render({ state: 'done', report: result.report, legendMaxMm: this.legendMaxMm, kept: false });
    } catch (error) {
      if (error instanceof CancelledError) this.showCancelled();
      else {
        const message = error instanceof Error ? error.message : String(error);
        this.panel.render({ state: 'error', message });
        this.onError(message);
      }
    } finally {
      this.running = false;
    }
  }

  cancel(): void {
    if (this.running) this.client.cancel();
  }

  /**
   * Draws the newest round at the next frame. Rounds can come faster than a frame of a large
   * template is built and drawn (a fine template without a GPU takes ~1 s): only the newest is
   * drawn, so the page never falls behind the worker.
   */
  private showLatestSoon(triangles: Uint32Array): void {
    if (this.drawScheduled) return;
    this.drawScheduled = true;
    requestAnimationFrame(() => {
      this.drawScheduled = false;
      const latest = this.latest;
      if (this.running && latest) this.showFitted({ positions: latest.positions, normals: latest.normals, bounds: latest.bounds, triangles }, null);
    });
  }

  private showCancelled(): void {
    const template = this.template.data;
    const latest = this.latest;
    if (latest && template) this.showFitted({ positions: latest.positions, normals: latest.normals, bounds: latest.bounds, triangles: template.triangles }, null);
    else this.warp.show('warped', true);
    document.body.dataset.alignCancelledIteration = String(this.iteration);
    this.panel.render({ state: 'cancelled', iteration: this.iteration, hasPositions: Boolean(this.latest) });
  }

  private showFitted(mesh: BodyMesh, colours: Float32Array | null): void {
    this.warp.show('warped', false);
    this.viewer.showBody('scan', { opacity: SCAN_OPACITY });
    this.viewer.showBody('fitted', {
      mesh,
      colour: FITTED_COLOUR,
      vertexColours: colours,
      transform: this.warp.transform,
      visible: true,
    });
  }

  private async export(format: 'ply' | 'obj'): Promise<void> {
    const template = this.template.data;
    if (!this.result || !template) return;
    try {
      const bytes = await this.client.call({
        type: 'exportMesh',
        positions: this.result.positions.slice(),
        triangles: template.triangles.slice(),
        format,
      });
      download(`${baseName(this.session.scan?.fileName ?? 'scan')}-fitted.${format}`, bytes);
    } catch (error) {
      this.onError(`Export: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  private keep(): void {
    const template = this.template.data;
    if (!this.result || !template || this.kept) return;
    subjects.add({
      name: baseName(this.session.scan?.fileName ?? 'scan'),
      positions: this.result.positions.slice(),
      resolution: template.resolution,
      source: 'aligned',
      rmsMetres: this.result.report.fine.scan_to_template.rms_mm / 1e3,
    });
    this.kept = true;
    document.body.dataset.subjects = String(subjects.all.length);
    this.panel.render({ state: 'done', report: this.result.report, legendMaxMm: this.legendMaxMm, kept: true });
  }
}

/** The run's times on the page, for benchmarks (bench/align-bench.mjs) and tests to read. */
function recordTimings(result: AlignResult, roundTripMs: number): void {
  const data = document.body.dataset;
  const report = result.report;
  const stages = report.fine.stages;
  data.alignRoundTripMs = roundTripMs.toFixed(1);
  data.alignWorkerMs = result.workerMs.toFixed(1);
  data.alignTotalMs = report.total_ms.toFixed(1);
  data.alignRoughMs = report.rough_ms.toFixed(1);
  data.alignIndexMs = report.index_ms.toFixed(1);
  data.alignFineMs = report.fine.elapsed_ms.toFixed(1);
  data.alignBaseStageMs = (stages ? stages.base.elapsed_ms : report.fine.elapsed_ms).toFixed(1);
  data.alignIterations = String(report.fine.iterations);
  data.alignTemplateVertices = String(report.fine.template_vertices);
}

