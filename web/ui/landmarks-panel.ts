// The 73 CAESAR landmarks as found ✓ / missing ✗ in the loaded landmark file, then unknown names.
import type { LandmarkReport } from '../shared/results';
import { byId, h } from './dom';

export interface LandmarkFacts {
  fileName: string;
  report: LandmarkReport;
  /** How the file's coordinates were read (e.g. "millimetres (CAESAR .lnd)"). */
  unitsNote: string;
}

export class LandmarksPanel {
  private readonly root = byId('landmarks-panel');
  private caesarNames: string[] = [];

  constructor() {
    this.render(null);
  }

  /** The canonical names, in `.lnd` order, from the core. */
  setCaesarNames(names: string[]): void {
    this.caesarNames = names;
  }

  render(facts: LandmarkFacts | null): void {
    const title = h('h2', {}, `CAESAR landmarks (${this.caesarNames.length})`);
    const found = new Set(facts?.report.found ?? []);
    const list = h('ul', { class: 'landmark-list', 'data-testid': 'landmark-list' });
    for (const name of this.caesarNames) {
      const status = found.has(name) ? 'found' : 'missing';
      list.append(
        h(
          'li',
          { 'data-status': status, 'data-name': name },
          h('span', { class: 'mark', 'aria-label': status }, status === 'found' ? '✓' : '✗'),
          h('span', { class: 'name' }, name),
        ),
      );
    }
    if (!facts) {
      this.root.replaceChildren(
        title,
        h('p', { class: 'placeholder', 'data-testid': 'landmarks-empty' }, 'No landmark file yet (.lnd, .csv or .json).'),
        list,
      );
      return;
    }
    const unknown = facts.report.unknown;
    const unknownSection = unknown.length
      ? [
          h('h2', {}, `Not CAESAR names (${unknown.length})`),
          h(
            'ul',
            { class: 'landmark-list', 'data-testid': 'landmark-unknown-list' },
            ...unknown.map((name) =>
              h('li', { 'data-status': 'unknown', 'data-name': name }, h('span', { class: 'mark' }, '?'), h('span', { class: 'name' }, name)),
            ),
          ),
        ]
      : [];
    // Unknown names first: they usually need attention, and the 73-line list would bury them.
    this.root.replaceChildren(
      h('h2', {}, 'Landmarks'),
      h('div', { class: 'file-name', 'data-testid': 'landmarks-file' }, facts.fileName),
      h(
        'div',
        { class: 'counts' },
        h('span', { class: 'found' }, '✓ ', h('span', { 'data-testid': 'landmarks-found' }, String(found.size)), ' found'),
        h('span', { class: 'missing' }, '✗ ', h('span', { 'data-testid': 'landmarks-missing' }, String(facts.report.missing.length)), ' missing'),
        h('span', { class: 'unknown' }, '? ', h('span', { 'data-testid': 'landmarks-unknown' }, String(unknown.length)), ' unknown'),
      ),
      h('p', { class: 'note', 'data-testid': 'landmarks-units' }, facts.unitsNote),
      ...unknownSection,
      title,
      list,
    );
  }
}
