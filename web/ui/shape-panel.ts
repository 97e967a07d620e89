// The "Shape space" panel: segment picker, one σ slider per mode of the part in view, reset and
// random, live measurements with targets (Find body), the population and boundary manikins, seam
// quality and timing, quality charts, CSV, exports, link, build.
import type { ModelCsv, ModelGlbParts, ModelPart, PartName, ReconstructedBody, SegmentName, ShapeCoefficients } from '../shared/shape-results';
import type { TemplateResolution } from '../shared/template-data';
import { SEGMENTS } from '../shared/shape-results';
import { byId, h } from './dom';
import type { Targets } from '../shared/anthropometry';
import { MeasurementTable } from './measurement-table';
import { ManikinPanel } from './manikin-panel';
import { PopulationView } from './population-view';
import { qualityCharts } from './quality-charts';

export type { PartName };

export interface ShapeActions {
  onSlider(part: PartName, mode: number, sigma: number): void;
  onView(part: PartName): void;
  onReset(): void;
  onRandom(): void;
  onFollowWhole(part: SegmentName): void;
  onCsv(kind: ModelCsv): void;
  onExportBody(format: 'ply' | 'obj' | 'glb'): void;
  onExportMode(mode: number, steps: number[]): void;
  onExportModelGltf(parts: ModelGlbParts): void;
  /** Show the body at the base or fine template resolution. */
  onResolution(resolution: TemplateResolution): void;
  onSaveModel(): void;
  /** The model in view (whole body or the segment picked) as statismo HDF5. */
  onSaveStatismo(): void;
  onCopyLink(): void;
  onBuild(variance: number): void;
  onAddFits(files: File[]): void;
  onOpenModel(files: File[]): void;
  /** The most likely body with `targets` (m, m³, m²), shown on the sliders. */
  onFindBody(targets: Targets): void;
  /** Compute the population's distributions again, or stop computing them. */
  onComputePopulation(): void;
  onCancelPopulation(): void;
  onManikins(names: string[], coverage: number): void;
  onShowManikin(index: number): void;
  onExportManikins(): void;
}

const LABELS: Record<PartName, string> = {
  whole: 'Whole body',
  head: 'Head',
  left_arm: 'Left arm',
  right_arm: 'Right arm',
  torso: 'Torso',
  left_leg: 'Left leg',
  right_leg: 'Right leg',
};


export class ShapePanel {
  private readonly root = byId('shape-panel');
  private readonly head = h('div', { class: 'shape-head' });
  private readonly sliders = h('div', { class: 'shape-sliders', 'data-testid': 'shape-sliders' });
  readonly measurements: MeasurementTable;
  readonly population: PopulationView;
  readonly manikins: ManikinPanel;
  private readonly facts = h('dl', { class: 'facts', 'data-testid': 'shape-facts' });
  private readonly charts = h('div', {});
  private readonly linkField = h('input', { type: 'text', readonly: '', class: 'shape-link', 'data-testid': 'shape-link', 'aria-label': 'Link to this body' });
  private readonly linkNote = h('p', { class: 'note', 'data-testid': 'shape-link-note' });
  private readonly subjectsNote = h('p', { class: 'note', 'data-testid': 'shape-subjects' }, 'No aligned subjects yet.');
  private readonly buildStatus = h('p', { class: 'note', 'data-testid': 'shape-build-status' });
  /** The model built here before a reload, offered back. */
  private readonly kept = h('div', { 'data-testid': 'shape-kept', hidden: '' });
  private readonly picker = h('select', { 'data-testid': 'shape-segment', 'aria-label': 'Part of the body' });
  private readonly resolutionPicker = h('select', { 'data-testid': 'shape-resolution', 'aria-label': 'Resolution of the body shown' });
  private readonly resolutionStatus = h('p', { class: 'note', 'data-testid': 'shape-resolution-status' });
  private readonly resolutionNote = h('p', { class: 'note', 'data-testid': 'shape-resolution-note' });
  private readonly inputs: HTMLInputElement[] = [];
  private readonly varianceInput = h('input', { type: 'number', min: '50', max: '100', step: '0.5', value: '99', 'data-testid': 'build-variance', class: 'small-input', 'aria-label': 'Variance to keep (%)' });
  private parts: ModelPart[] = [];
  private view: PartName = 'whole';

  constructor(private readonly actions: ShapeActions) {
    this.measurements = new MeasurementTable((targets) => actions.onFindBody(targets));
    this.population = new PopulationView(this.measurements, { onCompute: () => actions.onComputePopulation(), onCancel: () => actions.onCancelPopulation() });
    this.manikins = new ManikinPanel({
      onCompute: (names, coverage) => actions.onManikins(names, coverage),
      onCancel: () => actions.onCancelPopulation(),
      onShow: (index) => actions.onShowManikin(index),
      onExport: () => actions.onExportManikins(),
    });
    for (const part of ['whole', ...SEGMENTS] as PartName[]) this.picker.append(h('option', { value: part }, LABELS[part]));
    this.picker.addEventListener('change', () => actions.onView(this.picker.value as PartName));
    this.resolutionPicker.append(h('option', { value: 'base' }, 'base (13,380 vertices)'), h('option', { value: 'fine' }, 'fine (214,050 vertices)'));
    this.resolutionPicker.addEventListener('change', () => actions.onResolution(this.resolutionPicker.value as TemplateResolution));
    this.root.replaceChildren(
      h('h2', {}, 'Shape space'),
      this.head,
      h('p', { class: 'placeholder', 'data-testid': 'shape-empty' }, 'Loading the demo model…'),
    );
  }

  /** Lays the panel out for a model; `label` names it, `shareable` says whether links work. */
  showModel(label: string, parts: ModelPart[], subjects: number): void {
    this.parts = parts;
    this.head.replaceChildren(
      h('div', { class: 'file-name', 'data-testid': 'shape-model-name' }, label),
      h('p', { class: 'note' }, `${subjects} subjects; ${parts[0]?.variances.length ?? 0} whole-body modes kept.`),
    );
    const button = (text: string, testid: string, run: () => void) => {
      const b = h('button', { class: 'button', type: 'button', 'data-testid': testid }, text);
      b.addEventListener('click', run);
      return b;
    };
    const modeSelect = h('select', { 'data-testid': 'export-mode', 'aria-label': 'Mode to export' });
    parts[0]?.variances.forEach((_, k) => modeSelect.append(h('option', { value: String(k) }, `Mode ${k + 1}`)));
    const steps = h('input', { type: 'text', value: '-3,-1.5,0,1.5,3', 'data-testid': 'export-steps', 'aria-label': 'σ steps', class: 'small-input' });
    const variance = this.varianceInput;
    const fits = h('input', { type: 'file', multiple: '', hidden: '', accept: '.ply,.obj,.gz', 'data-testid': 'fits-input' });
    fits.addEventListener('change', () => {
      this.actions.onAddFits([...(fits.files ?? [])]);
      fits.value = '';
    });
    const modelInput = h('input', { type: 'file', hidden: '', accept: '.bsm,.h5', 'data-testid': 'model-input' });
    modelInput.addEventListener('change', () => {
      this.actions.onOpenModel([...(modelInput.files ?? [])]);
      modelInput.value = '';
    });
    this.root.replaceChildren(
      h('h2', {}, 'Shape space'),
      this.head,
      this.kept,
      h('div', { class: 'row' }, h('label', {}, 'Resolution ', this.resolutionPicker)),
      this.resolutionStatus,
      this.resolutionNote,
      h('div', { class: 'row' }, this.picker),
      h('div', { class: 'row' }, button('Reset to mean', 'shape-reset', () => this.actions.onReset()), button('Random body', 'shape-random', () => this.actions.onRandom())),
      this.sliders,
      h('h2', {}, 'Measurements'),
      h('p', { class: 'note' }, 'Enter targets for any of the measurements (lengths and girths in cm, volume in L, area in m²) and press Find body: the sliders move to the most likely body of the model that has them.'),
      this.measurements.element,
      this.population.element,
      h('h2', {}, 'Boundary manikins'),
      this.manikins.element,
      this.facts,
      h('h2', {}, 'Quality of this part'),
      this.charts,
      h('div', { class: 'row' }, button('Eigenvalues CSV', 'csv-eigenvalues', () => this.actions.onCsv('eigenvalues')), button('Scores CSV', 'csv-scores', () => this.actions.onCsv('scores')), button('Quality CSV', 'csv-quality', () => this.actions.onCsv('quality'))),
      h('h2', {}, 'Export'),
      h('div', { class: 'row' }, button('Body PLY', 'shape-export-ply', () => this.actions.onExportBody('ply')), button('OBJ', 'shape-export-obj', () => this.actions.onExportBody('obj')), button('glTF', 'shape-export-glb', () => this.actions.onExportBody('glb'))),
      h('div', { class: 'row' }, modeSelect, steps, button('Along mode (glTF)', 'export-along', () => this.actions.onExportMode(Number(modeSelect.value), parseSteps(steps.value)))),
      h('div', { class: 'row' }, button('Model as glTF morph targets', 'export-model-gltf', () => this.actions.onExportModelGltf('whole')), button('With the six segments', 'export-model-parts-gltf', () => this.actions.onExportModelGltf('all'))),
      h('p', { class: 'note' }, 'The second file holds seven meshes: the whole body and, 1 m beside it, the six segment models, each with its own modes as morph targets (weight = σ).'),
      h('h2', {}, 'Link'),
      h('div', { class: 'row' }, button('Copy link', 'copy-link', () => this.actions.onCopyLink()), this.linkField),
      this.linkNote,
      h('h2', {}, 'Models'),
      h('div', { class: 'row' }, button('Open model…', 'open-model', () => modelInput.click()), button('Save model file', 'save-model', () => this.actions.onSaveModel()), modelInput),
      h('div', { class: 'row' }, button('Part in view as statismo .h5', 'save-statismo', () => this.actions.onSaveStatismo())),
      h('p', { class: 'note' }, 'statismo HDF5 (millimetres), for Scalismo, statismo and exploreCOSMOS: the whole body, or the segment picked above. Open model… also opens a statismo .h5 made on this template.'),
      this.subjectsNote,
      h('div', { class: 'row' }, button('Add fitted meshes…', 'add-fits', () => fits.click()), fits),
      h('div', { class: 'row' }, h('label', {}, 'Keep ', variance, ' % variance'), button('Build model', 'build-model', () => this.actions.onBuild(Number(variance.value) / 100))),
      this.buildStatus,
    );
  }

  /** Shows the sliders of `view` at `values` (σ), noting whether a segment has its own shape. */
  showView(view: PartName, coefficients: ShapeCoefficients): void {
    this.view = view;
    this.picker.value = view;
    const index = view === 'whole' ? 0 : SEGMENTS.indexOf(view) + 1;
    const part = this.parts[index];
    this.inputs.length = 0;
    if (!part) return;
    const own = view === 'whole' ? coefficients.whole : coefficients.segments[index - 1];
    const total = part.all_variances.reduce((a, b) => a + b, 0) || 1;
    const rows: HTMLElement[] = [];
    if (view !== 'whole') {
      const follow = h('button', { class: 'button', type: 'button', 'data-testid': 'shape-follow-whole' }, 'Follow whole body');
      follow.addEventListener('click', () => this.actions.onFollowWhole(view));
      rows.push(
        h('p', { class: 'note', 'data-testid': 'shape-segment-state' }, own ? `${LABELS[view]} has its own shape, stitched into the body.` : `${LABELS[view]} follows the whole body; moving a slider gives it its own shape (starting from its mean).`),
        follow,
      );
    }
    part.variances.forEach((lambda, k) => {
      const sd = Math.sqrt(lambda);
      const t = own?.[k] ?? 0;
      const input = h('input', { type: 'range', min: '-3', max: '3', step: '0.01', value: String(t), 'data-testid': `shape-slider-${k}`, 'aria-label': `Mode ${k + 1} (σ)` });
      const value = h('span', { class: 'slider-value', 'data-testid': `shape-slider-value-${k}` }, formatSigma(t));
      const row = h(
        'div',
        { class: 'slider-row' },
        h('span', { class: 'slider-label' }, `${k + 1}`),
        input,
        value,
        h('span', { class: 'slider-explained', 'data-testid': `shape-explained-${k}` }, `${((100 * lambda) / total).toFixed(1)}%`),
      );
      const title = (x: number) => `Mode ${k + 1}: t = ${x.toFixed(2)}σ, b = t·√λ = ${(x * sd).toFixed(4)} (√λ = ${sd.toFixed(4)} m); explains ${((100 * lambda) / total).toFixed(2)} % of the variance`;
      row.title = title(t);
      input.addEventListener('input', () => {
        const x = Number(input.value);
        value.textContent = formatSigma(x);
        row.title = title(x);
        this.actions.onSlider(view, k, x);
      });
      this.inputs.push(input);
      rows.push(row);
    });
    this.sliders.replaceChildren(...rows);
    this.charts.replaceChildren(qualityCharts(part.quality));
  }

  get currentView(): PartName {
    return this.view;
  }

  /** The resolution the body is shown at; `vertexCount` of that body. */
  showResolution(resolution: TemplateResolution, vertexCount: number): void {
    this.resolutionPicker.value = resolution;
    this.resolutionNote.textContent =
      resolution === 'fine'
        ? `The model is mapped exactly to the fine template (${vertexCount.toLocaleString('en')} vertices: every mean and mode through the subdivision stencils). Measurements are taken on the base vertices, which are the first vertices of the fine body and sit exactly where the base body's do.`
        : '';
  }

  showResolutionStatus(text: string): void {
    this.resolutionStatus.textContent = text;
  }

  /** Readings of the body on screen; `roundTripMs`: request to vertex buffers on the UI thread. */
  showBody(body: ReconstructedBody, vertexCount: number, roundTripMs: number): void {
    const m = body.measurements;
    const fact = (label: string, testid: string, value: string) => [h('dt', {}, label), h('dd', { 'data-testid': testid }, value)];
    const seam = body.seam.segments && body.seam.max_jump > 0 ? `${(body.seam.max_jump * 1000).toFixed(2)} mm (${body.seam.segments.join(' / ')})` : '0 mm';
    this.measurements.show(m);
    this.facts.replaceChildren(
      ...fact('Largest seam jump', 'seam-jump', seam),
      ...fact('Reconstruction', 'reconstruct-ms', `${body.reconstructMs.toFixed(2)} ms (${body.rebuilt ? 'full rebuild' : `${body.deltas} rank-1 update${body.deltas === 1 ? '' : 's'}`})`),
      ...fact('Normals', 'normals-ms', `${body.normalsMs.toFixed(1)} ms`),
      ...fact('Measuring', 'measure-ms', `${body.measureMs.toFixed(1)} ms`),
      ...fact('Round trip', 'round-trip-ms', `${roundTripMs.toFixed(1)} ms`),
      ...fact('Vertices', 'shape-vertices', String(vertexCount)),
    );
  }

  showLink(text: string, note: string): void {
    this.linkField.value = text;
    this.linkNote.textContent = note;
  }

  showSubjects(aligned: number, dropped: number): void {
    this.subjectsNote.textContent = `${aligned + dropped} subjects in this session (${aligned} aligned, ${dropped} dropped fitted meshes).`;
  }

  /** The share of variance a model built here keeps (the panel's field, a fraction). */
  get buildVariance(): number {
    return Number(this.varianceInput.value) / 100;
  }

  /** Offers a kept model (`text`, a button `label` that opens it); null takes the offer away. */
  showKept(text: string | null, label = '', onOpen: () => void = () => undefined): void {
    this.kept.hidden = text === null;
    if (text === null) {
      this.kept.replaceChildren();
      return;
    }
    const open = h('button', { class: 'button', type: 'button', 'data-testid': 'shape-open-kept' }, label);
    open.addEventListener('click', onOpen);
    this.kept.replaceChildren(h('p', { class: 'note' }, text), h('div', { class: 'row' }, open));
  }

  showBuildStatus(text: string): void {
    this.buildStatus.textContent = text;
  }
}

function formatSigma(t: number): string {
  return `${t >= 0 ? '+' : ''}${t.toFixed(2)}σ`;
}

function parseSteps(text: string): number[] {
  return text
    .split(',')
    .map((s) => Number(s.trim()))
    .filter((x) => Number.isFinite(x) && Math.abs(x) <= 10);
}
