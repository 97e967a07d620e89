// Small line charts of a part's quality curves against the number of modes: compactness,
// generalization and specificity (Styner 2003), drawn on canvases.
import type { QualityCurves } from '../shared/shape-results';
import { h } from './dom';

interface Series {
  title: string;
  values: number[];
  /** Multiplier for display and the unit shown. */
  scale: number;
  unit: string;
}

function draw(canvas: HTMLCanvasElement, series: Series): void {
  const ratio = Math.min(window.devicePixelRatio || 1, 2);
  const w = 260;
  const hgt = 90;
  canvas.width = w * ratio;
  canvas.height = hgt * ratio;
  canvas.style.width = `${w}px`;
  canvas.style.height = `${hgt}px`;
  const g = canvas.getContext('2d');
  if (!g) return;
  g.scale(ratio, ratio);
  g.fillStyle = '#1b1f26';
  g.fillRect(0, 0, w, hgt);
  g.font = '10px system-ui, sans-serif';
  g.fillStyle = '#9aa3b2';
  const values = series.values.map((v) => v * series.scale);
  if (values.length === 0) {
    g.fillText(`${series.title}: not computed for this model`, 8, hgt / 2);
    return;
  }
  const lo = Math.min(0, ...values);
  const hi = Math.max(...values) || 1;
  const [left, right, top, bottom] = [34, w - 8, 16, hgt - 16];
  const x = (i: number) => left + (values.length === 1 ? 0 : (i / (values.length - 1)) * (right - left));
  const y = (v: number) => bottom - ((v - lo) / (hi - lo || 1)) * (bottom - top);
  g.fillText(`${series.title} (${series.unit})`, left, 11);
  g.fillText(hi.toPrecision(3), 2, top + 4);
  g.fillText(lo.toPrecision(2), 2, bottom);
  g.fillText('1', left - 2, hgt - 4);
  g.fillText(`${values.length} modes`, right - 44, hgt - 4);
  g.strokeStyle = '#343b47';
  g.beginPath();
  g.moveTo(left, top);
  g.lineTo(left, bottom);
  g.lineTo(right, bottom);
  g.stroke();
  g.strokeStyle = '#5fb3ff';
  g.lineWidth = 1.5;
  g.beginPath();
  values.forEach((v, i) => (i === 0 ? g.moveTo(x(i), y(v)) : g.lineTo(x(i), y(v))));
  g.stroke();
  g.fillStyle = '#5fb3ff';
  values.forEach((v, i) => g.fillRect(x(i) - 1.5, y(v) - 1.5, 3, 3));
}

/** Three canvases for `curves`; returns the element to place in a panel. */
export function qualityCharts(curves: QualityCurves): HTMLElement {
  const all: Series[] = [
    { title: 'Compactness', values: curves.compactness, scale: 100, unit: '% variance' },
    { title: 'Generalization', values: curves.generalization, scale: 1000, unit: 'mm, leave-one-out' },
    { title: 'Specificity', values: curves.specificity, scale: 1000, unit: 'mm' },
  ];
  const root = h('div', { class: 'quality-charts', 'data-testid': 'quality-charts' });
  for (const series of all) {
    const canvas = h('canvas', { 'data-testid': `chart-${series.title.toLowerCase()}`, 'data-points': String(series.values.length) });
    draw(canvas, series);
    root.append(canvas);
  }
  return root;
}
