// Where the body on screen sits in its population: in each measurement row a small histogram of
// the bodies sampled from the model (training subjects as ticks under it) with the current value
// marked and its percentile; below the table, the correlation between measurements as a heat map.
// The distributions are computed once per model; a slider move only looks the values up.
import { percentileOf, PERCENTILE_LEVELS, type MeasurementDistribution, type MeasureDistribution } from '../shared/anthropometry';
import type { Measurements } from '../shared/shape-results';
import { button, h } from './dom';
import { formatReading } from './format';

const BINS = 14;
const HIST_W = 56;
const HIST_H = 16;

/** A canvas of `w × h` CSS pixels drawn at the screen's resolution; returns its context. */
function sized(canvas: HTMLCanvasElement, w: number, hgt: number): CanvasRenderingContext2D | null {
  const ratio = Math.min(window.devicePixelRatio || 1, 2);
  canvas.width = w * ratio;
  canvas.height = hgt * ratio;
  canvas.style.width = `${w}px`;
  canvas.style.height = `${hgt}px`;
  const g = canvas.getContext('2d');
  g?.setTransform(ratio, 0, 0, ratio, 0, 0);
  return g;
}

/** "62nd" */
function ordinal(p: number): string {
  const n = Math.round(p);
  const teen = n % 100 >= 11 && n % 100 <= 13;
  return `${n}${teen ? 'th' : (['th', 'st', 'nd', 'rd'][n % 10] ?? 'th')}`;
}

/** One row's histogram: sampled bodies as bars, training subjects as ticks, the body as a line. */
class MiniHistogram {
  readonly canvas = h('canvas', { class: 'mini-histogram' });
  private readonly lo: number;
  private readonly hi: number;
  private readonly counts: number[];

  constructor(
    private readonly sampled: MeasureDistribution,
    private readonly training: MeasureDistribution,
  ) {
    const all = [...sampled.values, ...training.values];
    this.lo = Math.min(...all);
    this.hi = Math.max(...all);
    const width = this.hi - this.lo || 1;
    this.counts = Array.from({ length: BINS }, () => 0);
    for (const v of sampled.values) this.counts[Math.min(BINS - 1, Math.floor(((v - this.lo) / width) * BINS))]! += 1;
  }

  draw(value: number | null): void {
    const g = sized(this.canvas, HIST_W, HIST_H);
    if (!g) return;
    const x = (v: number) => ((v - this.lo) / (this.hi - this.lo || 1)) * HIST_W;
    const top = Math.max(...this.counts, 1);
    const bar = HIST_W / BINS;
    g.fillStyle = '#4a5566';
    this.counts.forEach((c, i) => {
      const barH = ((HIST_H - 4) * c) / top;
      g.fillRect(i * bar + 0.5, HIST_H - 4 - barH, bar - 1, barH);
    });
    g.fillStyle = '#8fb3d9';
    for (const v of this.training.values) g.fillRect(x(v) - 0.5, HIST_H - 3, 1, 3);
    if (value != null) {
      g.fillStyle = '#f08a4b';
      g.fillRect(Math.max(0, Math.min(HIST_W - 2, x(value) - 1)), 0, 2, HIST_H);
    }
  }
}

interface Cell {
  kind: MeasureDistribution['kind'];
  sampled: MeasureDistribution;
  training: MeasureDistribution;
  histogram: MiniHistogram;
  text: HTMLElement;
  cell: HTMLElement;
}

export class PopulationView {
  /** The section under the table: status, cancel / compute, the heat map. */
  readonly element = h('div', { class: 'population-view' });
  private readonly status = h('p', { class: 'note', 'data-testid': 'population-status' });
  private readonly heat = h('canvas', { class: 'correlation-map', 'data-testid': 'correlation-map', 'aria-label': 'Correlation between measurements' });
  private readonly heatCaption = h('p', { class: 'note', 'data-testid': 'correlation-caption' });
  private readonly cancel: HTMLButtonElement;
  private readonly compute: HTMLButtonElement;
  private cells: Cell[] = [];
  /** Every table cell filled, so `clear` empties them even after the rows were rebuilt. */
  private cellsShown: HTMLElement[] = [];

  constructor(
    private readonly table: { populationCell(name: string): HTMLElement | undefined; label(name: string): string },
    actions: { onCompute(): void; onCancel(): void },
  ) {
    this.cancel = button('population-cancel', 'Cancel', 'button', () => actions.onCancel());
    this.compute = button('population-compute', 'Compute again', 'button', () => actions.onCompute());
    this.cancel.hidden = true;
    this.compute.hidden = true;
    this.heat.hidden = true;
    this.element.append(this.status, h('div', { class: 'row' }, this.cancel, this.compute), this.heat, this.heatCaption);
  }

  /** Computing: `fraction` done. */
  showProgress(fraction: number, label: string): void {
    this.status.textContent = `${label}… ${Math.round(fraction * 100)} %`;
    this.cancel.hidden = false;
    this.compute.hidden = true;
  }

  /** Stopped (cancelled or failed): what happened, and a button to compute again. */
  showStopped(text: string): void {
    this.status.textContent = text;
    this.cancel.hidden = true;
    this.compute.hidden = false;
  }

  /** Nothing to show (a new model is on its way). */
  clear(): void {
    this.cells = [];
    this.heat.hidden = true;
    this.heatCaption.textContent = '';
    for (const c of this.cellsShown) c.replaceChildren();
    this.cellsShown = [];
  }

  /** The distributions of the model in view; `measurements` of the body on screen. */
  show(d: MeasurementDistribution, measurements: Measurements): void {
    this.cancel.hidden = true;
    this.compute.hidden = true;
    this.status.textContent = `Population: ${d.samples.bodies} bodies sampled from the model (bars; seed ${d.params.seed}) and its ${d.training.bodies} training subjects (ticks). The orange line is the body on screen, with its percentile among the sampled bodies. Computed in ${(d.workerMs / 1000).toFixed(1)} s.`;
    this.cells = [];
    d.samples.measures.forEach((sampled, i) => {
      const training = d.training.measures[i]!;
      const cell = this.table.populationCell(sampled.name);
      if (!cell || sampled.values.length === 0) return;
      const histogram = new MiniHistogram(sampled, training);
      const text = h('span', { class: 'percentile', 'data-testid': `percentile-${sampled.name}` });
      cell.replaceChildren(histogram.canvas, text);
      this.cellsShown.push(cell);
      this.cells.push({ kind: sampled.kind, sampled, training, histogram, text, cell });
    });
    this.drawHeatMap(d);
    this.update(measurements);
  }

  /** The body on screen changed: its value and percentile in every row. */
  update(measurements: Measurements): void {
    for (const c of this.cells) {
      const value = measurements.find((r) => r.name === c.sampled.name)?.value ?? null;
      c.histogram.draw(value);
      const p = value == null ? NaN : percentileOf(c.sampled.values, value);
      const pt = value == null ? NaN : percentileOf(c.training.values, value);
      c.text.textContent = Number.isFinite(p) ? `P${Math.round(p)}` : '—';
      c.text.dataset.percentile = Number.isFinite(p) ? p.toFixed(2) : '';
      const levels = c.sampled.percentiles.map((v, k) => `${PERCENTILE_LEVELS[k]} %: ${formatReading(c.kind, v)}`).join(', ');
      c.cell.title = Number.isFinite(p)
        ? `${formatReading(c.kind, value)} is at the ${ordinal(p)} percentile of the sampled bodies and the ${ordinal(pt)} of the training subjects. Sampled bodies: ${levels}.`
        : 'Not taken on this body.';
    }
  }

  /** Measurements × measurements, blue −1 … white 0 … red +1; the caption names the cell pointed at. */
  private drawHeatMap(d: MeasurementDistribution): void {
    const names = d.samples.measures.map((m) => m.name);
    const n = names.length;
    const cellPx = 13;
    const size = n * cellPx;
    const g = sized(this.heat, size, size);
    if (!g) return;
    const r = (i: number, j: number) => d.samples.correlation[i * n + j] ?? null;
    for (let i = 0; i < n; i++) {
      for (let j = 0; j < n; j++) {
        const v = r(i, j);
        g.fillStyle = v == null ? '#2a2f38' : colour(v);
        g.fillRect(j * cellPx, i * cellPx, cellPx - 1, cellPx - 1);
      }
    }
    this.heat.hidden = false;
    const label = (k: number) => this.table.label(names[k]!);
    this.heatCaption.textContent = `Correlation between the measurements over the sampled bodies (rows and columns in the table's order; blue −1, white 0, red +1). Point at a cell to read it.`;
    this.heat.onmousemove = (e) => {
      const rect = this.heat.getBoundingClientRect();
      const j = Math.floor(((e.clientX - rect.left) / rect.width) * n);
      const i = Math.floor(((e.clientY - rect.top) / rect.height) * n);
      if (i < 0 || j < 0 || i >= n || j >= n) return;
      const v = r(i, j);
      const text = `${label(i)} × ${label(j)}: r = ${v == null ? 'undefined' : v.toFixed(2)}`;
      this.heat.title = text;
      this.heatCaption.textContent = text;
    };
  }
}

/** Diverging blue–white–red for a correlation in [−1, 1]. */
function colour(v: number): string {
  const t = Math.max(-1, Math.min(1, v));
  const [a, b] = t >= 0 ? [[245, 245, 245], [214, 69, 65]] : [[245, 245, 245], [59, 118, 196]];
  const s = Math.abs(t);
  const c = a.map((x, k) => Math.round(x + (b[k]! - x) * s));
  return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}
