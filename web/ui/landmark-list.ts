// The 73 CAESAR landmarks of the current set, each given / estimated / edited / absent (with the
// estimate's confidence and, in its tooltip, how sharply the landmark is defined; a flag when the
// core finds it suspicious). A click picks one to place; hovering one shows it on the template.
import type { LandmarkEntry, LandmarkState, Sharpness } from '../shared/landmark-entry';
import { h } from './dom';

export interface LandmarkListActions {
  onSelect: (name: string) => void;
  /** The landmark under the pointer, or null when it leaves the list. */
  onHover: (name: string | null) => void;
}

const MARKS: Record<LandmarkState, string> = { given: '✓', estimated: '≈', edited: '✎', absent: '✗' };

/** Why a landmark's confidence is what it is, by its definition's sharpness (docs/template.md). */
const DEFINED_AS: Record<Sharpness, string> = {
  point: 'defined as a point (a tip, notch or bony point under thin skin): placed within millimetres',
  prominence: 'defined as a prominence felt through soft tissue: placed within about a centimetre',
  level: 'defined as a level on a smooth surface: people placing it differ by centimetres',
};

export class LandmarkList {
  readonly element = h('ul', { class: 'landmark-list editable', 'data-testid': 'landmark-list' });

  constructor(private readonly actions: LandmarkListActions) {
    this.element.addEventListener('mouseleave', () => actions.onHover(null));
  }

  /**
   * `clickable`: whether picking a landmark means anything (a scan to place it on is loaded);
   * `loaded`: whether there is a set at all (before any file the names are listed without marks:
   * nothing is absent from a set that is not there).
   */
  render(
    entries: readonly LandmarkEntry[],
    selected: string | null,
    flagged: ReadonlySet<string>,
    sharpness: ReadonlyMap<string, Sharpness>,
    clickable: boolean,
    loaded = true,
  ): void {
    this.element.replaceChildren(
      ...entries.map((e) => {
        const confidence = e.confidence === null ? '' : `${Math.round(e.confidence * 100)} %`;
        const defined = sharpness.get(e.name);
        const row = h(
          'li',
          {
            // `data-status` says whether the set has the landmark; `data-state` where it came from.
            'data-status': loaded ? (e.position ? 'found' : 'missing') : 'none',
            'data-state': e.state,
            'data-name': e.name,
            'data-selected': String(e.name === selected),
            'data-flagged': String(flagged.has(e.name)),
            'data-position-mm': e.position?.map((v) => (v * 1000).toFixed(4)).join(','),
            'data-sharpness': defined,
            title: !loaded ? `${e.name}: no scan or landmark file yet` : `${e.name}: ${e.state}${confidence ? `, confidence ${confidence}` : ''}${defined ? `; ${DEFINED_AS[defined]}` : ''}`,
          },
          loaded ? h('span', { class: 'mark', 'aria-label': e.state }, MARKS[e.state]) : h('span', { class: 'mark' }),
          h('span', { class: 'name' }, e.name),
          h('span', { class: 'confidence' }, flagged.has(e.name) ? '⚠' : confidence),
        );
        if (clickable) {
          row.tabIndex = 0;
          row.addEventListener('click', () => this.actions.onSelect(e.name));
          row.addEventListener('keydown', (event) => {
            if (event.key === 'Enter' || event.key === ' ') this.actions.onSelect(e.name);
          });
        }
        row.addEventListener('mouseenter', () => this.actions.onHover(e.name));
        return row;
      }),
    );
    // A landmark picked on the scan scrolls into view (the list scrolls on its own, under the tools).
    this.element.querySelector<HTMLElement>('li[data-selected="true"]')?.scrollIntoView({ block: 'nearest' });
  }

  /** Back to the top of the list (a new set). */
  scrollToTop(): void {
    this.element.scrollTop = 0;
  }
}
