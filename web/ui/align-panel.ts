// The Align step (paper §3.1 + §3.2): Align / Cancel, progress, the live E/RMS chart, and the
// result — the paper's Table 1 numbers, the fit's own check, the heat-map legend, export and
// "keep as aligned subject" (asking first when the fit is flagged).
import type { AlignReport, AlignStage, SubjectReport } from '../shared/align-types';
import type { TemplateResolution } from '../shared/template-data';
import { button, byId, h } from './dom';
import { EnergyChart } from './energy-chart';
import { formatCount, notFitted, qualityText, turnedWords } from './format';
import { heatLegend } from './heat-legend';
import { keepControl } from './keep-button';

export interface AlignControls {
  onAlign: () => void;
  onCancel: () => void;
  onExport: (format: 'ply' | 'obj') => void;
  onKeep: () => void;
  /** The template resolution Align will fit (chosen in the Template panel). */
  resolution: () => TemplateResolution;
}

export type AlignView =
  | { state: 'unavailable' }
  | { state: 'idle' }
  | { state: 'running'; iteration: number; maxIterations: number; rmsMm: number | null; stage: AlignStage }
  | { state: 'cancelled'; iteration: number; hasPositions: boolean }
  | { state: 'error'; message: string }
  | { state: 'done'; report: SubjectReport; legendMaxMm: number; kept: boolean };

export class AlignPanel {
  private readonly root = byId('align-panel');
  readonly chart = new EnergyChart();

  constructor(private readonly controls: AlignControls) {
    this.render({ state: 'unavailable' });
  }

  /** The progress bar and status line while running, updated in place so Cancel stays put. */
  private live: { bar: HTMLProgressElement; status: HTMLElement } | null = null;

  render(view: AlignView): void {
    const title = h('h2', {}, 'Align');
    document.body.dataset.alignState = view.state;
    if (view.state === 'running' && this.live) {
      this.live.bar.max = view.maxIterations;
      this.live.bar.value = view.iteration;
      this.live.bar.dataset.iteration = String(view.iteration);
      this.live.status.textContent = statusText(view);
      return;
    }
    this.live = null;
    if (view.state === 'unavailable') {
      this.root.replaceChildren(title, h('p', { class: 'placeholder' }, 'Load a scan and its landmarks, then Align fits the template to it (RBF warp, then fine alignment).'));
      return;
    }
    const running = view.state === 'running';
    const align = button('align-run', running ? 'Aligning…' : 'Align', 'button primary', () => this.controls.onAlign());
    align.disabled = running;
    const cancel = button('align-cancel', 'Cancel', 'button', () => this.controls.onCancel());
    cancel.hidden = !running;
    const parts: (HTMLElement | string)[] = [title, resolutionNote(this.controls.resolution()), h('div', { class: 'actions' }, align, cancel)];
    if (view.state === 'running') {
      const bar = h('progress', {
        'data-testid': 'align-progress',
        max: String(view.maxIterations),
        value: String(view.iteration),
        'data-iteration': String(view.iteration),
      });
      const status = h('p', { class: 'note', 'data-testid': 'align-status' }, statusText(view));
      this.live = { bar, status };
      parts.push(bar, status);
    }
    if (view.state !== 'idle') parts.push(this.chart.canvas);
    if (view.state === 'cancelled') {
      parts.push(
        h(
          'p',
          { class: 'warn-note', 'data-testid': 'align-cancelled', 'data-iteration': String(view.iteration) },
          view.hasPositions
            ? `Cancelled at iteration ${view.iteration}: the template is shown as it was at the last round.`
            : `Cancelled at iteration ${view.iteration}, before the first round finished: the RBF warp is shown.`,
        ),
      );
    }
    if (view.state === 'error') parts.push(h('p', { class: 'error-note', 'data-testid': 'align-error' }, view.message));
    if (view.state === 'done') parts.push(...this.result(view.report, view.legendMaxMm, view.kept));
    this.root.replaceChildren(...parts);
  }

  private result(r: SubjectReport, legendMaxMm: number, kept: boolean): HTMLElement[] {
    const s = r.fine.scan_to_template;
    const t = r.fine.template_to_scan;
    const mm = (v: number) => v.toFixed(2);
    return [
      h('h2', {}, 'Scan → template (paper Table 1)'),
      h(
        'dl',
        { class: 'facts' },
        h('dt', {}, 'Points'),
        h('dd', { 'data-testid': 'align-points' }, formatCount(s.count)),
        h('dt', {}, 'Mean signed (mm)'),
        h('dd', { 'data-testid': 'align-mean' }, mm(s.mean_mm)),
        h('dt', {}, 'SD (mm)'),
        h('dd', { 'data-testid': 'align-sd' }, mm(s.std_dev_mm)),
        h('dt', {}, 'RMS (mm)'),
        h('dd', { 'data-testid': 'align-rms', 'data-rms-mm': String(s.rms_mm) }, mm(s.rms_mm)),
        h('dt', {}, 'Template → scan RMS'),
        h('dd', { 'data-testid': 'align-t2s-rms' }, `${mm(t.rms_mm)} mm`),
        h('dt', {}, 'Iterations'),
        h('dd', { 'data-testid': 'align-iterations' }, iterationsText(r)),
        h('dt', {}, 'Time'),
        h('dd', { 'data-testid': 'align-time' }, `${(r.total_ms / 1000).toFixed(2)} s`),
      ),
      checkNote(r),
      measurementsNote(r),
      heatLegend(0, legendMaxMm, `Distance of each template vertex to the scan; ≥ ${legendMaxMm.toFixed(1)} mm in yellow`),
      h(
        'div',
        { class: 'actions' },
        button('export-ply', 'Export PLY', 'button', () => this.controls.onExport('ply')),
        button('export-obj', 'Export OBJ', 'button', () => this.controls.onExport('obj')),
      ),
      keepControl(r.quality, kept, () => this.controls.onKeep()),
      h('p', { class: 'note' }, 'Exports are in metres, in the scan’s frame, in template vertex order.'),
    ];
  }
}

/**
 * The running fit's line. No RMS: the rounds' RMS is over the template vertices matched within
 * reach only (the chart's), not the fit's scan → template RMS, which is measured when it ends.
 */
function statusText(view: { iteration: number; maxIterations: number; stage: AlignStage }): string {
  const stage = view.stage === 'fine' ? ' (fine stage)' : '';
  return view.iteration === 0 ? 'RBF warp and scan index…' : `Iteration ${view.iteration} of at most ${view.maxIterations}${stage}; the fit's RMS is measured when it ends`;
}

/**
 * The fit's own check, in words: the quality flags raised (or none), the landmarks the core's
 * policy left out of the fit as suspicious, each with its distance and suggestion, and what the
 * core took off the scan before fitting it (stray pieces, a floor or turntable under the feet).
 */
function checkNote(r: SubjectReport): HTMLElement {
  const flags = r.quality?.flags ?? [];
  const left = r.landmarks.left_out.map((l) => `${l.name}, ${l.distance_mm.toFixed(0)} mm from where the others put it (${l.suggestion})`);
  const text = flags.length && r.quality ? `Flagged: ${qualityText(r.quality)}.` : 'No quality flag raised.';
  const leftText = left.length ? ` Left out of the fit: ${left.join('; ')}.` : '';
  return h('p', { class: flags.length ? 'warn-note' : 'note', 'data-testid': 'align-check', 'data-flags': flags.join(' ') }, text + leftText + turnedWords(r.turned) + notFitted([r.strays, r.floor]));
}

/**
 * Which measurements of this fit cannot be trusted, in words (the core's `measurement_trust`):
 * those whose expected error — their estimated (or left-out) landmarks' and the fit's own —
 * makes an error over ISO 20685-1's limit likely, and those found on the body where the scan is
 * not under the fit. Not a quality flag: a fit can be good for the model and still doubtful for a
 * tape measure.
 */
function measurementsNote(r: SubjectReport): HTMLElement {
  const doubtful = r.measurement_trust.filter((t) => t.doubtful);
  const attributes = { 'data-testid': 'align-measurements', 'data-doubtful': doubtful.map((t) => t.name).join(' ') };
  if (!doubtful.length) {
    return h('p', { class: 'note', ...attributes }, 'Every measurement of this fit is within ISO 20685-1 by its expected error (its landmarks\' and the fit\'s own), and those found on the body lie where the scan is under the fit.');
  }
  // The names at a glance; why each is doubtful, in words, one click away.
  const names = doubtful.map((t) => t.name.replaceAll('_', ' ')).join(', ');
  return h(
    'div',
    { class: 'warn-note', ...attributes },
    h('details', {}, h('summary', {}, `Measurements not to trust from this fit: ${names}.`), h('ul', { class: 'doubtful-list' }, ...doubtful.map((t) => h('li', {}, t.words)))),
  );
}

/** Which template Align fits, and how: a fine template goes coarse to fine. */
function resolutionNote(resolution: TemplateResolution): HTMLElement {
  const how =
    resolution === 'fine'
      ? 'fine template: the base template is fitted first, carried to fine by subdivision, then fitted briefly at fine'
      : 'base template';
  return h('p', { class: 'note', 'data-testid': 'align-resolution', 'data-resolution': resolution }, `Fits the ${how} (resolution in the Template panel).`);
}

function iterationsText(r: AlignReport): string {
  const stages = r.fine.stages;
  const detail = stages ? `${stages.base.iterations} base + ${stages.fine_iterations} fine, ` : '';
  return `${r.fine.iterations} (${detail}${r.fine.rounds} rounds${r.fine.converged ? ', converged' : ''})`;
}
