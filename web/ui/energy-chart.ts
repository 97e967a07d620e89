// A small live chart of the alignment: E (log scale, left) and RMS distance in mm (right) per
// iteration, drawn on a canvas; no chart library needed for two lines.

export interface ChartPoint {
  iteration: number;
  energy: number;
  rmsMm: number;
}

const E_COLOUR = '#ff8a5c';
const RMS_COLOUR = '#6cc4ff';

export class EnergyChart {
  readonly canvas: HTMLCanvasElement;
  private points: ChartPoint[] = [];

  constructor() {
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'energy-chart';
    this.canvas.width = 540;
    this.canvas.height = 240;
    this.canvas.dataset.testid = 'align-chart';
  }

  clear(): void {
    this.points = [];
    this.draw();
  }

  add(point: ChartPoint): void {
    this.points.push(point);
    this.canvas.dataset.points = String(this.points.length);
    this.draw();
  }

  private draw(): void {
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    const { width: w, height: h } = this.canvas;
    const pad = { l: 48, r: 48, t: 26, b: 26 };
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = '#12151a';
    ctx.fillRect(0, 0, w, h);
    ctx.font = '18px system-ui, sans-serif';
    ctx.fillStyle = E_COLOUR;
    ctx.fillText('E (log)', pad.l, 19);
    ctx.fillStyle = RMS_COLOUR;
    ctx.textAlign = 'right';
    ctx.fillText('matched RMS mm', w - pad.r, 19);
    ctx.textAlign = 'left';
    const pts = this.points;
    if (pts.length < 1) return;
    const maxIt = Math.max(pts[pts.length - 1]!.iteration, 1);
    const x = (it: number) => pad.l + ((w - pad.l - pad.r) * it) / maxIt;
    const logE = pts.map((p) => Math.log10(Math.max(p.energy, 1e-30)));
    const eMin = Math.min(...logE);
    const eMax = Math.max(...logE);
    const rMax = Math.max(...pts.map((p) => p.rmsMm), 1e-6);
    const y = (v: number, lo: number, hi: number) => h - pad.b - ((h - pad.t - pad.b) * (v - lo)) / (hi - lo || 1);
    ctx.strokeStyle = '#343b47';
    ctx.strokeRect(pad.l, pad.t, w - pad.l - pad.r, h - pad.t - pad.b);
    line(ctx, pts.map((p, i) => [x(p.iteration), y(logE[i]!, eMin, eMax)]), E_COLOUR);
    line(ctx, pts.map((p) => [x(p.iteration), y(p.rmsMm, 0, rMax)]), RMS_COLOUR);
    ctx.font = '16px system-ui, sans-serif';
    ctx.fillStyle = '#9aa3af';
    ctx.fillText(`${maxIt} it`, w - pad.r - 40, h - 6);
    ctx.fillStyle = RMS_COLOUR;
    ctx.textAlign = 'right';
    ctx.fillText(rMax.toFixed(1), w - 4, pad.t + 12);
    ctx.fillText('0', w - 4, h - pad.b);
    ctx.textAlign = 'left';
  }
}

function line(ctx: CanvasRenderingContext2D, xy: [number, number][], colour: string): void {
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2.5;
  ctx.beginPath();
  xy.forEach(([px, py], i) => (i === 0 ? ctx.moveTo(px, py) : ctx.lineTo(px, py)));
  ctx.stroke();
}
