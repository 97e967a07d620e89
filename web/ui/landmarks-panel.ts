// The Landmarks panel: the landmark file read (name, found / missing / unknown counts, units),
// then the landmark editor (its controls, where the hovered landmark sits on the template, and the
// 73 CAESAR landmarks of the current set), then the names that are not CAESAR landmarks.
import type { LandmarkEntry, Sharpness } from '../shared/landmark-entry';
import type { LandmarkReport } from '../shared/results';
import { byId, h } from './dom';
import { LandmarkList, type LandmarkListActions } from './landmark-list';
import { LandmarkTools, type ToolsActions, type ToolsView } from './landmark-tools';
import { TemplateGuide } from './template-guide';

export interface LandmarkFacts {
  fileName: string;
  report: LandmarkReport;
  /** How the file's coordinates were read (e.g. "millimetres (CAESAR .lnd)"). */
  unitsNote: string;
}

/** The editor's state: the current set, the picked landmark, the flagged ones, the controls. */
export interface EditorView {
  entries: readonly LandmarkEntry[];
  selected: string | null;
  flagged: ReadonlySet<string>;
  /** Each landmark's definition sharpness, from the last estimate's report (empty before one). */
  sharpness: ReadonlyMap<string, Sharpness>;
  tools: ToolsView;
  /** Whether a landmark set exists (a scan or a landmark file is open). */
  loaded: boolean;
}

export class LandmarksPanel {
  private readonly root = byId('landmarks-panel');
  readonly guide = new TemplateGuide();
  private readonly tools: LandmarkTools;
  private readonly list: LandmarkList;

  constructor(actions: ToolsActions & LandmarkListActions) {
    this.tools = new LandmarkTools(actions);
    this.list = new LandmarkList(actions);
  }

  /** A new set: the list back at its top. */
  scrollListToTop(): void {
    this.list.scrollToTop();
  }

  render(facts: LandmarkFacts | null, editor: EditorView | null): void {
    const title = h('h2', {}, `CAESAR landmarks (${editor?.entries.length ?? 0})`);
    if (editor) {
      this.tools.render(editor.tools);
      this.list.render(editor.entries, editor.selected, editor.flagged, editor.sharpness, editor.tools.hasScan, editor.loaded);
    }
    const editing = editor ? [h('h2', {}, 'Edit'), this.tools.element, this.guide.element, title, this.list.element] : [];
    if (!facts) {
      this.root.replaceChildren(
        h('h2', {}, 'Landmarks'),
        h('p', { class: 'placeholder', 'data-testid': 'landmarks-empty' }, editor?.tools.hasScan ? 'No landmark file: estimate them, or place them by hand.' : 'No landmark file yet (.lnd, .csv or .json).'),
        ...editing,
      );
      return;
    }
    const found = facts.report.found.length;
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
        h('span', { class: 'found' }, '✓ ', h('span', { 'data-testid': 'landmarks-found' }, String(found)), ' found'),
        h('span', { class: 'missing' }, '✗ ', h('span', { 'data-testid': 'landmarks-missing' }, String(facts.report.missing.length)), ' missing'),
        h('span', { class: 'unknown' }, '? ', h('span', { 'data-testid': 'landmarks-unknown' }, String(unknown.length)), ' unknown'),
      ),
      h('p', { class: 'note', 'data-testid': 'landmarks-units' }, facts.unitsNote),
      ...unknownSection,
      ...editing,
    );
  }
}
