// The template: resolution, counts, and how it is shown (segment colours, visibility).
import { SEGMENT_NAMES, type TemplateResolution } from '../shared/template-data';
import { SEGMENT_COLOURS } from '../view/segment-colours';
import { byId, h, withBackground } from './dom';
import { formatCount } from './format';

export interface TemplateFacts {
  resolution: TemplateResolution;
  vertices: number;
  triangles: number;
  landmarks: number;
  virtualLandmarks: number;
}

export interface TemplateControls {
  onResolution: (resolution: TemplateResolution) => void;
  onSegmentColours: (on: boolean) => void;
  onShow: (on: boolean) => void;
}

export class TemplatePanel {
  private readonly root = byId('template-panel');
  private segmentColours = false;
  private shown = true;
  private showInput: HTMLInputElement | null = null;

  constructor(private readonly controls: TemplateControls) {
    this.render(null);
  }

  /** Reflects a change made elsewhere (e.g. the warp hides the template). */
  setShown(on: boolean): void {
    this.shown = on;
    if (this.showInput) this.showInput.checked = on;
  }

  render(facts: TemplateFacts | null, loading = false): void {
    const title = h('h2', {}, 'Template');
    if (!facts) {
      this.root.replaceChildren(title, h('p', { class: 'placeholder' }, loading ? 'Loading the template…' : 'No template.'));
      return;
    }
    const resolution = h('select', { 'data-testid': 'template-resolution', 'aria-label': 'Template resolution' });
    for (const r of ['base', 'fine'] as const) resolution.append(h('option', { value: r }, r));
    resolution.value = facts.resolution;
    resolution.disabled = loading;
    resolution.addEventListener('change', () => this.controls.onResolution(resolution.value as TemplateResolution));

    const colours = checkbox('template-segment-colours', 'Colour by segment', this.segmentColours, (on) => {
      this.segmentColours = on;
      legend.hidden = !on;
      this.controls.onSegmentColours(on);
    });
    const show = checkbox('template-show', 'Show template', this.shown, (on) => {
      this.shown = on;
      this.controls.onShow(on);
    });
    this.showInput = show.querySelector('input');
    const legend = h(
      'ul',
      { class: 'swatches', 'data-testid': 'segment-legend' },
      ...SEGMENT_NAMES.map((name, i) =>
        h('li', {}, withBackground(h('span', { class: 'swatch' }), `#${SEGMENT_COLOURS[i]!.toString(16).padStart(6, '0')}`), name),
      ),
    );
    legend.hidden = !this.segmentColours;
    this.root.replaceChildren(
      title,
      h(
        'dl',
        { class: 'facts' },
        h('dt', {}, 'Resolution'),
        h('dd', {}, resolution),
        h('dt', {}, 'Vertices'),
        h('dd', { 'data-testid': 'template-vertices' }, formatCount(facts.vertices)),
        h('dt', {}, 'Triangles'),
        h('dd', { 'data-testid': 'template-triangles' }, formatCount(facts.triangles)),
        h('dt', {}, 'Landmarks'),
        h(
          'dd',
          {},
          h('span', { 'data-testid': 'template-landmarks' }, String(facts.landmarks - facts.virtualLandmarks)),
          ' + ',
          h('span', { 'data-testid': 'template-virtual-landmarks' }, String(facts.virtualLandmarks)),
          ' virtual',
        ),
      ),
      h('div', { class: 'toggles' }, show, colours),
      legend,
      h('p', { class: 'note' }, 'Hover a marker for its name; virtual landmarks are drawn in yellow. Overlap bands between segments show as blended colours.'),
    );
  }
}

/** A labelled checkbox calling `onChange` with its new state. */
export function checkbox(testid: string, label: string, checked: boolean, onChange: (on: boolean) => void): HTMLLabelElement {
  const input = h('input', { type: 'checkbox', 'data-testid': testid });
  input.checked = checked;
  input.addEventListener('change', () => onChange(input.checked));
  return h('label', { class: 'toggle' }, input, ` ${label}`);
}
