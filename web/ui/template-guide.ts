// Where a landmark sits on the template: the template's vertices drawn from the front and from the
// side (a 2D canvas, no second WebGL context), with the landmark ringed in both, so a person knows
// what to click on the scan.
import { h } from './dom';

/** The template as the guide needs it: `#V·3` metres, y up, facing +z; its landmarks by name. */
export interface GuideTemplate {
  positions: Float32Array;
  landmarkNames: string[];
  landmarkPositions: Float32Array;
}

const WIDTH = 240;
const HEIGHT = 200;
const PAD = 10;

export class TemplateGuide {
  readonly element: HTMLElement;
  private readonly canvas = h('canvas', { class: 'template-guide', width: String(WIDTH), height: String(HEIGHT), 'data-testid': 'template-guide' });
  private readonly caption = h('p', { class: 'note', 'data-testid': 'template-guide-caption' });
  private template: GuideTemplate | null = null;
  private background: ImageData | null = null;
  private toCanvas: ((x: number, y: number, z: number) => [[number, number], [number, number]]) | null = null;

  constructor() {
    this.element = h('div', { class: 'guide' }, this.canvas, this.caption);
    this.show(null);
  }

  setTemplate(template: GuideTemplate): void {
    this.template = template;
    this.background = null;
  }

  /** Rings landmark `name` on the template (nothing ringed for null or a name it lacks). */
  show(name: string | null): void {
    const context = this.canvas.getContext('2d');
    const template = this.template;
    this.canvas.dataset.landmark = name ?? '';
    if (!context || !template) {
      this.caption.textContent = 'The template appears here once it is loaded.';
      return;
    }
    if (!this.background) this.background = this.drawTemplate(context, template);
    else context.putImageData(this.background, 0, 0);
    const i = name === null ? -1 : template.landmarkNames.indexOf(name);
    if (i < 0 || !this.toCanvas) {
      this.caption.textContent = 'Hover or pick a landmark to see where it sits on the template (front and side views).';
      return;
    }
    const p = template.landmarkPositions;
    const views = this.toCanvas(p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!);
    for (const [x, y] of views) {
      context.beginPath();
      context.arc(x, y, 6, 0, 2 * Math.PI);
      context.lineWidth = 3;
      context.strokeStyle = '#ffffff';
      context.stroke();
      context.beginPath();
      context.arc(x, y, 4, 0, 2 * Math.PI);
      context.fillStyle = '#ff6a3d';
      context.fill();
    }
    this.caption.textContent = `${name}: on the template, seen from the front (left) and from its left side (right).`;
  }

  /** Draws the vertices from the front (x, y) and the side (z, y); returns the picture. */
  private drawTemplate(context: CanvasRenderingContext2D, template: GuideTemplate): ImageData {
    const p = template.positions;
    let [minX, maxX, minY, maxY, minZ, maxZ] = [Infinity, -Infinity, Infinity, -Infinity, Infinity, -Infinity];
    for (let i = 0; i < p.length; i += 3) {
      minX = Math.min(minX, p[i]!);
      maxX = Math.max(maxX, p[i]!);
      minY = Math.min(minY, p[i + 1]!);
      maxY = Math.max(maxY, p[i + 1]!);
      minZ = Math.min(minZ, p[i + 2]!);
      maxZ = Math.max(maxZ, p[i + 2]!);
    }
    const gap = PAD;
    const scale = Math.min((HEIGHT - 2 * PAD) / (maxY - minY), (WIDTH - 2 * PAD - gap) / (maxX - minX + maxZ - minZ));
    const sideLeft = PAD + (maxX - minX) * scale + gap;
    // Front: seen from +z, so +x is to the right. Side: seen from +x, the front (+z) to the left.
    this.toCanvas = (x, y, z) => [
      [PAD + (x - minX) * scale, HEIGHT - PAD - (y - minY) * scale],
      [sideLeft + (maxZ - z) * scale, HEIGHT - PAD - (y - minY) * scale],
    ];
    context.clearRect(0, 0, WIDTH, HEIGHT);
    context.fillStyle = 'rgba(201, 195, 187, 0.25)';
    for (let i = 0; i < p.length; i += 3) {
      for (const [x, y] of this.toCanvas(p[i]!, p[i + 1]!, p[i + 2]!)) context.fillRect(x, y, 1, 1);
    }
    return context.getImageData(0, 0, WIDTH, HEIGHT);
  }
}
