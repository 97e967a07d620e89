// The scan's facts: file name, counts, bounding box, units (with an override), holes, parts, and
// which way its triangles face.
import type { MeshSummary, Units, Winding } from '../shared/results';
import { UNITS } from '../shared/units';
import { byId, h } from './dom';
import { formatCount, formatMetres, formatPoint } from './format';

const WINDING_WORDS: Record<Winding, string> = { outward: 'outwards', inward: 'inwards', mixed: 'mixed' };

export interface ScanFacts {
  fileName: string;
  summary: MeshSummary;
  units: Units;
  /** Timings of the last read, for the note under the facts. */
  readMs: number;
}

export class ScanPanel {
  private readonly root = byId('scan-panel');

  /** `onUnits` is called when the user picks other units for the scan. */
  constructor(private readonly onUnits: (units: Units) => void) {
    this.render(null);
  }

  render(facts: ScanFacts | null): void {
    const title = h('h2', {}, 'Scan');
    if (!facts) {
      this.root.replaceChildren(
        title,
        h('p', { class: 'placeholder', 'data-testid': 'scan-empty' }, 'No scan yet. Drop a PLY, OBJ or STL file anywhere, or use “Open files…”.'),
      );
      return;
    }
    const s = facts.summary;
    const size = s.bbox_max.map((v, i) => v - s.bbox_min[i]!);
    const units = h('select', { 'data-testid': 'scan-units', 'aria-label': 'Scan units' });
    for (const u of UNITS) {
      const label = u === s.units_detected ? `${u} (detected)` : u;
      units.append(h('option', { value: u }, label));
    }
    units.value = facts.units;
    units.addEventListener('change', () => this.onUnits(units.value as Units));

    const fact = (label: string, testid: string, value: Node | string) =>
      [h('dt', {}, label), h('dd', { 'data-testid': testid }, value)] as const;
    this.root.replaceChildren(
      title,
      h('div', { class: 'file-name', 'data-testid': 'scan-file' }, facts.fileName),
      h(
        'dl',
        { class: 'facts' },
        ...fact('Vertices', 'scan-vertices', formatCount(s.vertices)),
        ...fact('Triangles', 'scan-triangles', formatCount(s.triangles)),
        ...fact('Units', 'scan-units-cell', units),
        ...fact('Width (x)', 'scan-size-x', formatMetres(size[0]!)),
        ...fact('Height (y)', 'scan-size-y', formatMetres(size[1]!)),
        ...fact('Depth (z)', 'scan-size-z', formatMetres(size[2]!)),
        ...fact('Holes', 'scan-holes', formatCount(s.boundary_loops)),
        ...fact('Parts', 'scan-components', formatCount(s.components)),
        ...fact('Normals', 'scan-winding', WINDING_WORDS[s.winding]),
      ),
      h('h2', {}, 'Bounding box (m)'),
      h(
        'dl',
        { class: 'facts bbox' },
        ...fact('min', 'scan-bbox-min', formatPoint(s.bbox_min)),
        ...fact('max', 'scan-bbox-max', formatPoint(s.bbox_max)),
      ),
      h(
        'p',
        { class: 'note' },
        `Holes are boundary loops of the surface; parts are connected components; normals are the triangles’ sides, facing out of the body or into it as the scan is seen from outside (mixed: the parts disagree or a part faces both ways; a click through a hole is still told wherever the core can say which way a triangle faces, on every part wound one way and on a part facing both ways once its triangles are brought to agree; before the scan is fitted, triangles that face against their neighbours are turned to agree and a part wound inwards is turned to face out). Read in ${facts.readMs.toFixed(0)} ms.`,
      ),
    );
  }
}
