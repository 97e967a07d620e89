// The RBF warp step (paper §3.1): kernel, its parameter, λ, affine term; what is shown; and the
// landmark residuals before (after Procrustes) and after the warp, in millimetres.
import { kernelParam, type AlignDefaults, type KernelName, type RbfSettings, type WarpReport } from '../shared/align-types';
import { byId, h } from './dom';
import { checkbox } from './template-panel';

export interface RbfControls {
  onRun: (settings: RbfSettings) => void;
  onShow: (what: 'scan' | 'template' | 'warped', on: boolean) => void;
}

export interface RbfOutcome {
  report: WarpReport;
  /** What was assumed about the scan's frame, in words. */
  frameNote: string;
  workerMs: number;
}

const KERNELS: { name: KernelName; label: string; param: string | null }[] = [
  { name: 'gaussian', label: 'Gaussian exp(−r²/c²)', param: 'c (m)' },
  { name: 'thin-plate', label: 'Thin-plate r² log r', param: null },
  { name: 'multiquadric', label: 'Multiquadric √(r²+s²)', param: 's (m)' },
];

export class RbfPanel {
  private readonly root = byId('rbf-panel');
  /** The core's default parameter of each kernel. */
  private readonly kernelDefaults = new Map<KernelName, number | null>();
  /** Null until the core's defaults have arrived ({@link setDefaults}). */
  private settings: RbfSettings | null = null;
  private readonly shown = { scan: true, template: false, warped: true };

  constructor(private readonly controls: RbfControls) {
    this.render(false, null, null);
  }

  /** Takes the core's defaults (the one source of them). */
  setDefaults(defaults: AlignDefaults): void {
    for (const kernel of defaults.kernels) this.kernelDefaults.set(kernel.kind, kernelParam(kernel));
    const rbf = defaults.params.rbf;
    this.settings = { kernel: rbf.kernel.kind, param: kernelParam(rbf.kernel), lambda: rbf.lambda, affine: rbf.affine };
  }

  /** The settings shown, or null before the core's defaults have arrived. */
  get current(): RbfSettings | null {
    return this.settings && { ...this.settings };
  }

  /** `ready`: a scan and landmarks are loaded. `error`: the core's message of the last run. */
  render(ready: boolean, outcome: RbfOutcome | null, error: string | null, running = false): void {
    const title = h('h2', {}, 'RBF warp');
    if (!ready || !this.settings) {
      this.root.replaceChildren(title, h('p', { class: 'placeholder' }, 'Load a scan and its landmarks to warp the template onto it.'));
      return;
    }
    this.root.replaceChildren(title, this.form(running), this.toggles(), ...this.result(outcome, error));
  }

  private form(running: boolean): HTMLElement {
    const s = this.settings!;
    const kernel = h('select', { 'data-testid': 'rbf-kernel', 'aria-label': 'Kernel' });
    for (const k of KERNELS) kernel.append(h('option', { value: k.name }, k.label));
    kernel.value = s.kernel;
    const info = KERNELS.find((k) => k.name === s.kernel)!;
    const param = h('input', { type: 'number', step: 'any', min: '0', 'data-testid': 'rbf-param', 'aria-label': 'Kernel parameter' });
    param.value = s.param === null ? '' : String(s.param);
    param.disabled = info.param === null;
    const lambda = h('input', { type: 'number', step: 'any', min: '0', 'data-testid': 'rbf-lambda', 'aria-label': 'λ' });
    lambda.value = String(s.lambda);
    const affine = h('input', { type: 'checkbox', 'data-testid': 'rbf-affine' });
    affine.checked = s.affine;
    const run = h('button', { class: 'button primary', type: 'button', 'data-testid': 'rbf-run' }, running ? 'Warping…' : 'Run warp');
    run.disabled = running;

    const read = (): RbfSettings => ({
      kernel: kernel.value as KernelName,
      param: param.disabled || param.value === '' ? null : Number(param.value),
      lambda: lambda.value === '' ? 0 : Number(lambda.value),
      affine: affine.checked,
    });
    kernel.addEventListener('change', () => {
      this.settings = { ...read(), param: this.kernelDefaults.get(kernel.value as KernelName) ?? null };
      this.root.replaceChild(this.form(running), this.root.children[1]!);
    });
    run.addEventListener('click', () => {
      this.settings = read();
      this.controls.onRun(read());
    });
    return h(
      'div',
      { class: 'rbf-form' },
      h(
        'dl',
        { class: 'facts' },
        h('dt', {}, 'Kernel'),
        h('dd', {}, kernel),
        h('dt', {}, info.param ?? 'parameter'),
        h('dd', {}, param),
        h('dt', {}, 'λ (smoothing)'),
        h('dd', {}, lambda),
        h('dt', {}, 'Affine term'),
        h('dd', {}, affine),
      ),
      h('div', { class: 'actions' }, run),
    );
  }

  private readonly inputs = new Map<string, HTMLInputElement>();

  private toggles(): HTMLElement {
    const make = (what: 'scan' | 'template' | 'warped', label: string) => {
      const toggle = checkbox(`show-${what}`, label, this.shown[what], (on) => {
        this.shown[what] = on;
        this.controls.onShow(what, on);
      });
      this.inputs.set(what, toggle.querySelector('input')!);
      return toggle;
    };
    return h('div', { class: 'toggles' }, make('scan', 'Scan'), make('template', 'Template'), make('warped', 'Warped'));
  }

  /** Reflects a change made elsewhere (the template panel's toggle, the Align result). */
  setShown(what: 'scan' | 'template' | 'warped', on: boolean): void {
    this.shown[what] = on;
    const input = this.inputs.get(what);
    if (input) input.checked = on;
  }

  private result(outcome: RbfOutcome | null, error: string | null): HTMLElement[] {
    if (error) return [h('p', { class: 'error-note', 'data-testid': 'rbf-error' }, error)];
    if (!outcome) return [];
    const r = outcome.report;
    const rows = r.residuals.map((x) =>
      h(
        'tr',
        { 'data-name': x.name, 'data-before-mm': x.before_mm.toFixed(4), 'data-after-mm': x.after_mm.toFixed(4) },
        h('td', { class: 'name' }, x.name),
        h('td', {}, x.before_mm.toFixed(1)),
        h('td', {}, x.after_mm < 0.05 ? x.after_mm.toExponential(0) : x.after_mm.toFixed(1)),
      ),
    );
    const skipped = r.skipped.length
      ? [h('p', { class: 'note', 'data-testid': 'rbf-skipped' }, `Skipped (not on both sides): ${r.skipped.join(', ')}`)]
      : [];
    return [
      h('p', { class: 'note', 'data-testid': 'rbf-frame-note' }, outcome.frameNote),
      h(
        'dl',
        { class: 'facts' },
        h('dt', {}, 'Landmarks used'),
        h('dd', { 'data-testid': 'rbf-used-count' }, String(r.used.length)),
        h('dt', {}, 'Skipped'),
        h('dd', { 'data-testid': 'rbf-skipped-count' }, String(r.skipped.length)),
        h('dt', {}, 'Max before (mm)'),
        h('dd', { 'data-testid': 'rbf-max-before' }, r.max_residual_before_mm.toFixed(1)),
        h('dt', {}, 'Max after (mm)'),
        h('dd', { 'data-testid': 'rbf-max-after' }, r.max_residual_after_mm.toExponential(1)),
        h('dt', {}, 'Time'),
        h('dd', {}, `${outcome.workerMs.toFixed(0)} ms`),
      ),
      ...skipped,
      h(
        'div',
        { class: 'residuals-box' },
        h(
          'table',
          { class: 'residuals', 'data-testid': 'rbf-residuals' },
          h('thead', {}, h('tr', {}, h('th', {}, 'Landmark'), h('th', {}, 'before mm'), h('th', {}, 'after mm'))),
          h('tbody', {}, ...rows),
        ),
      ),
    ];
  }
}
