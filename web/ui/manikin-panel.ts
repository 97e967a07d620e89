// Boundary manikins: the person picks 2–4 measurements and a coverage, the worker finds the
// bodies on the edge of the region holding that share of the population; each is listed with its
// chosen measurements (click to show it) and all are exported together.
import type { ManikinSet } from '../shared/anthropometry';
import type { Reading } from '../shared/shape-results';
import { button, h } from './dom';
import { formatReading } from './format';

export interface ManikinActions {
  onCompute(names: string[], coverage: number): void;
  onCancel(): void;
  onShow(index: number): void;
  onExport(): void;
}

export class ManikinPanel {
  readonly element = h('div', { class: 'manikin-panel' });
  private readonly picks = h('div', { class: 'manikin-picks', 'data-testid': 'manikin-picks' });
  private readonly coverage = h('input', { type: 'number', min: '1', max: '99.9', step: '1', value: '90', class: 'small-input', 'data-testid': 'manikin-coverage', 'aria-label': 'Coverage (% of the population)' });
  private readonly status = h('p', { class: 'note', 'data-testid': 'manikin-status' });
  private readonly list = h('ol', { class: 'manikin-list', 'data-testid': 'manikin-list' });
  private readonly cancel: HTMLButtonElement;
  private readonly exportButton: HTMLButtonElement;
  private names = '';

  constructor(private readonly actions: ManikinActions) {
    this.cancel = button('manikin-cancel', 'Cancel', 'button', () => actions.onCancel());
    this.exportButton = button('manikin-export', 'Export manikins (glTF, PLY, CSV)', 'button', () => actions.onExport());
    this.cancel.hidden = true;
    this.exportButton.hidden = true;
    this.element.append(
      h('p', { class: 'note' }, 'Pick 2–4 measurements and the share of the population a design must fit: the manikins are the most likely bodies of the model on the edge of the region holding that share (from the sampled bodies above).'),
      this.picks,
      h('div', { class: 'row' }, h('label', {}, 'Coverage ', this.coverage, ' %'), button('manikin-compute', 'Find manikins', 'button primary', () => this.compute()), this.cancel),
      this.status,
      this.list,
      h('div', { class: 'row' }, this.exportButton),
    );
  }

  /** The measurements to choose from (built once per set). */
  setMeasurements(readings: readonly Reading[]): void {
    const names = readings.map((r) => r.name).join(' ');
    if (names === this.names) return;
    this.names = names;
    this.picks.replaceChildren(
      ...readings.map((r) => h('label', { class: 'manikin-pick' }, h('input', { type: 'checkbox', value: r.name, 'data-testid': `manikin-pick-${r.name}` }), ` ${r.label}`)),
    );
  }

  /** The core's default coverage (a share). */
  setDefaultCoverage(share: number): void {
    this.coverage.value = String(Math.round(share * 1000) / 10);
  }

  showProgress(fraction: number, label: string): void {
    this.status.classList.remove('error-note');
    this.status.textContent = `${label}… ${Math.round(fraction * 100)} %`;
    this.cancel.hidden = false;
  }

  showError(text: string): void {
    this.cancel.hidden = true;
    this.status.classList.add('error-note');
    this.status.textContent = text;
  }

  /** The manikins found; `labels` and `kinds` by measurement name. */
  show(set: ManikinSet, readings: readonly Reading[]): void {
    this.cancel.hidden = true;
    this.status.classList.remove('error-note');
    const m = set.manikins;
    const reading = new Map(readings.map((r) => [r.name, r]));
    const label = (n: string) => reading.get(n)?.label ?? n;
    this.status.textContent = `${m.manikins.length} manikins on the boundary holding ${(m.coverage * 100).toFixed(1)} % of the sampled bodies in ${m.measures.map(label).join(', ')} (Mahalanobis radius ${m.radius.toFixed(2)}); found in ${(set.workerMs / 1000).toFixed(1)} s. Click one to show it.`;
    this.list.replaceChildren(
      ...m.manikins.map((k, i) => {
        const values = m.measures.map((n) => `${label(n)} ${formatReading(reading.get(n)?.kind ?? 'length', k.measurements[n] ?? null)}`).join(' · ');
        const item = h('button', { type: 'button', class: 'manikin-item', 'data-testid': `manikin-${i}` }, `${k.name}: ${values}`);
        item.addEventListener('click', () => this.actions.onShow(i));
        return h('li', {}, item);
      }),
    );
    this.exportButton.hidden = false;
  }

  /** Marks manikin `index` as the one shown (−1: none). */
  markShown(index: number): void {
    this.list.querySelectorAll('button.manikin-item').forEach((b, i) => b.classList.toggle('shown', i === index));
  }

  private compute(): void {
    const names = [...this.picks.querySelectorAll<HTMLInputElement>('input:checked')].map((c) => c.value);
    const percent = Number(this.coverage.value);
    if (names.length < 2 || names.length > 4) {
      this.showError(`Pick 2, 3 or 4 measurements (${names.length} picked).`);
      return;
    }
    if (!(percent > 0 && percent < 100)) {
      this.showError(`Coverage "${this.coverage.value}": enter a share of the population between 0 and 100 % (e.g. 90).`);
      return;
    }
    this.actions.onCompute(names, percent / 100);
  }
}
