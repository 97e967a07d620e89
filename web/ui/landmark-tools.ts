// The landmark editor's controls: the estimate (which way is up, progress, Cancel, the frame and
// units assumed, its verdict on itself in words, or what went wrong; "Estimate again, keeping my
// edits" once it has run), the picked landmark's position, Undo / Redo / Mark absent, export as
// .lnd, CSV or JSON, and the landmarks the core finds suspicious.
import type { LandmarkEntry, SelfCheck, SuspiciousLandmark } from '../shared/landmark-entry';
import type { Orientation } from '../shared/orientation';
import { button, h } from './dom';
import { orientationControl } from './orientation-control';

export type LandmarkFormat = 'lnd' | 'csv' | 'json';

export type EstimateView =
  | { state: 'none' }
  | { state: 'running'; fraction: number; label: string }
  | { state: 'done'; assumed: string; seconds: number; check: SelfCheck }
  | { state: 'cancelled'; kept: SelfCheck | null }
  | { state: 'error'; message: string; kept: SelfCheck | null };

/** Work put aside: the scan a newly opened one replaced (or the scan shown, for a set a file replaced), and what its landmarks were. */
export interface PutAside {
  scan: string;
  /** It is the scan shown: a landmark file replaced its set. */
  sameScan: boolean;
  /** Its landmark file's name, or null. */
  file: string | null;
  given: number;
  estimated: number;
  edited: number;
}

export interface ToolsView {
  /** The work put aside, most recent first. */
  putAside: PutAside[];
  /** The scan shown (its file name), or null. */
  scan: string | null;
  estimate: EstimateView;
  /** Landmarks without a position (what an estimate would fill in). */
  absent: number;
  /** Landmarks the estimate placed (what "Estimate again" places anew). */
  estimated: number;
  /** Which way is up, as the person chose it (null: the estimate finds it). */
  orientation: Orientation | null;
  /** A scan is loaded: landmarks can be estimated and placed. */
  hasScan: boolean;
  selected: LandmarkEntry | null;
  canUndo: boolean;
  canRedo: boolean;
  /** The current set's suspicious landmarks; null when not checked. */
  suspicious: SuspiciousLandmark[] | null;
  /** The landmark the last click meant to place: it fell through a hole in the scan (nothing placed). */
  throughHole: string | null;
}

export interface ToolsActions {
  /** Brings back the work put aside at `index`. */
  onBringBack: (index: number) => void;
  /** Forgets the work put aside at `index`. */
  onForget: (index: number) => void;
  /** Picks landmark `name` to place it on the scan, and shows it up close. */
  onInspect: (name: string) => void;
  onEstimate: () => void;
  onCancelEstimate: () => void;
  onOrientation: (orientation: Orientation | null) => void;
  onUndo: () => void;
  onRedo: () => void;
  onAbsent: () => void;
  onExport: (format: LandmarkFormat) => void;
}

export class LandmarkTools {
  readonly element = h('div', { class: 'landmark-tools', 'data-testid': 'landmark-tools' });
  /** The progress bar and its label while an estimate runs, updated in place so Cancel stays put. */
  private live: { bar: HTMLProgressElement; label: HTMLElement } | null = null;

  constructor(private readonly actions: ToolsActions) {}

  render(view: ToolsView): void {
    document.body.dataset.estimateState = view.estimate.state;
    const e = view.estimate;
    if (e.state === 'running' && this.live) {
      this.live.bar.value = e.fraction;
      this.live.label.textContent = e.label;
      return;
    }
    this.live = null;
    const a = this.actions;
    const running = e.state === 'running';
    const estimate = button('landmarks-estimate', estimateLabel(view), 'button', a.onEstimate);
    estimate.disabled = running || !view.hasScan;
    estimate.hidden = view.absent === 0 && view.estimated === 0;
    estimate.title = 'Landmarks given in a file, placed or moved by hand are kept as they are; the others are estimated (again), in the frame chosen by Up and Facing.';
    const undo = button('landmarks-undo', 'Undo', 'button', a.onUndo);
    undo.disabled = running || !view.canUndo;
    undo.title = 'Ctrl+Z';
    const redo = button('landmarks-redo', 'Redo', 'button', a.onRedo);
    redo.disabled = running || !view.canRedo;
    redo.title = 'Ctrl+Shift+Z';
    const absent = button('landmarks-absent', 'Mark absent', 'button', a.onAbsent);
    absent.disabled = running || !view.selected?.position;
    const exports = (['lnd', 'csv', 'json'] as const).map((f) => {
      const b = button(`landmarks-export-${f}`, `.${f}`, 'button', () => a.onExport(f));
      b.disabled = running;
      return b;
    });
    this.element.replaceChildren(
      ...putAsideParts(view, running, a),
      ...this.estimateParts(e),
      orientationControl(view.orientation, running || !view.hasScan, a.onOrientation),
      h('div', { class: 'actions' }, estimate),
      h('p', { class: 'note', 'data-testid': 'landmarks-selected' }, selectedText(view)),
      ...throughHoleParts(view.throughHole),
      h('div', { class: 'actions' }, undo, redo, absent),
      h('div', { class: 'actions export' }, h('span', { class: 'label' }, 'Export'), ...exports),
      ...suspiciousParts(view.suspicious, (shownCheck(e)?.verdict ?? 'good') === 'good'),
    );
  }

  private estimateParts(e: EstimateView): HTMLElement[] {
    if (e.state === 'running') {
      const bar = h('progress', { 'data-testid': 'estimate-progress', max: '1', value: String(e.fraction) });
      const label = h('span', { 'data-testid': 'estimate-status' }, e.label);
      this.live = { bar, label };
      const cancel = button('estimate-cancel', 'Cancel', 'button', this.actions.onCancelEstimate);
      return [bar, h('div', { class: 'actions estimate-running' }, label, cancel)];
    }
    const checked = (check: SelfCheck) => checkParts(check, this.actions.onInspect);
    if (e.state === 'done')
      return [h('p', { class: 'note', 'data-testid': 'estimate-assumed' }, `Estimated in ${e.seconds.toFixed(1)} s. Assumed: ${e.assumed}`), ...checked(e.check)];
    // The landmarks kept are the last estimate's: its verdict on them still holds.
    const kept = (check: SelfCheck | null) => (check ? checked(check) : []);
    if (e.state === 'cancelled')
      return [h('p', { class: 'warn-note', 'data-testid': 'estimate-cancelled' }, 'Estimate cancelled: the scan and the landmarks placed so far are kept.'), ...kept(e.kept)];
    if (e.state === 'error')
      return [
        h('p', { class: 'error-note', 'data-testid': 'estimate-error' }, `The estimate failed: ${sentence(e.message)} The scan and the landmarks placed so far are kept; place the landmarks by hand or try again.`),
        ...kept(e.kept),
      ];
    return [];
  }
}

/** Work put aside shown in full; the older ones fold under "N more put aside". */
const ASIDE_SHOWN = 2;

/**
 * The work put aside, most recent first: each scan with what its landmarks were, the button that
 * swaps it back, and one that forgets it. Opening a scan or a landmark file never loses the
 * landmarks placed before: they are kept here until forgotten.
 */
function putAsideParts(view: ToolsView, running: boolean, a: Pick<ToolsActions, 'onBringBack' | 'onForget'>): HTMLElement[] {
  if (view.putAside.length === 0) return [];
  const items = view.putAside.map((aside, index) => putAsideItem(aside, index, view.scan, running, a));
  const older = items.splice(ASIDE_SHOWN);
  if (older.length === 0) return items;
  const more = h('details', { class: 'put-aside-more', 'data-testid': 'landmarks-put-aside-more' }, h('summary', {}, `${older.length} more put aside`), ...older);
  return [...items, more];
}

/** The landmarks of work put aside in words: how many, and the parts (from a file, estimated, placed by hand). */
function asideLandmarks(aside: PutAside): { total: number; parts: string[] } {
  const parts = [
    aside.given ? `${aside.given} from ${aside.file ?? 'a file'}` : '',
    aside.estimated ? `${aside.estimated} estimated` : '',
    aside.edited ? `${aside.edited} placed by hand` : '',
  ].filter(Boolean);
  return { total: aside.given + aside.estimated + aside.edited, parts };
}

/** What to ask before work put aside is forgotten; null when it has no landmark to lose. */
export function forgetQuestion(aside: PutAside): string | null {
  const { total, parts } = asideLandmarks(aside);
  if (total === 0) return null;
  const what = aside.sameScan ? 'the other set of landmarks of this scan' : `${aside.scan} and its landmarks`;
  return `Forget ${what}? Its ${total} landmarks (${parts.join(', ')}) are forgotten here and in this browser's storage; this cannot be undone.`;
}

function putAsideItem(aside: PutAside, index: number, shown: string | null, running: boolean, a: Pick<ToolsActions, 'onBringBack' | 'onForget'>): HTMLElement {
  const { total, parts } = asideLandmarks(aside);
  const what = total ? `with its ${total} landmarks (${parts.join(', ')})` : 'with no landmarks placed';
  const label = aside.sameScan ? 'Back to the other set' : `Back to ${aside.scan}`;
  const back = button('landmarks-back', label, 'button', () => a.onBringBack(index));
  back.disabled = running;
  back.title = aside.sameScan
    ? 'Shows the other set of landmarks of this scan as it was, and puts this one aside; the warp runs again, a fit is not kept.'
    : `Shows ${aside.scan} again with its landmarks as they were, and puts ${shown ?? 'this scan'} aside with its own; the warp runs again, a fit is not kept.`;
  const forget = button('landmarks-forget', 'Forget', 'button', () => a.onForget(index));
  forget.disabled = running;
  forget.title = aside.sameScan ? 'Forgets the other set of landmarks of this scan (it asks first).' : `Forgets ${aside.scan} and its landmarks here and in this browser's storage (it asks first).`;
  const text = aside.sameScan
    ? `Another set of landmarks for this scan is put aside (${total ? `${total}: ${parts.join(', ')}` : 'none placed'}).`
    : `${aside.scan} is put aside ${what}: they stay with it, not with ${shown ?? 'this scan'}.`;
  return h('div', { class: 'put-aside', 'data-index': String(index) }, h('p', { class: 'note', 'data-testid': 'landmarks-put-aside' }, text), h('div', { class: 'actions' }, back, forget));
}

/** The self-check that speaks for the landmarks shown: the estimate's just done, or after a cancelled or failed one the last done one's. */
export function shownCheck(e: EstimateView): SelfCheck | null {
  if (e.state === 'done') return e.check;
  if (e.state === 'cancelled' || e.state === 'error') return e.kept;
  return null;
}

/** "Estimate landmarks" on a bare set; once an estimate placed some, "Estimate again, keeping my edits". */
function estimateLabel(view: ToolsView): string {
  if (view.absent === 73) return 'Estimate landmarks';
  if (view.estimated > 0) return 'Estimate again, keeping my edits';
  return `Estimate the ${view.absent} absent`;
}

/**
 * The estimate's verdict on itself in words: nothing for a good one; a warning with its reasons
 * for a doubtful one, an error for a failed one (its landmarks must not be trusted); then the
 * landmarks to check first, each a button that picks it and shows it up close (`onInspect`),
 * and the way out the reasons point to: Up and Facing when the frame is in doubt, else placing
 * those landmarks by hand and estimating again.
 */
function checkParts(check: SelfCheck, onInspect: (name: string) => void): HTMLElement[] {
  if (check.verdict === 'good') return [];
  const failed = check.verdict === 'failed';
  const headline = failed
    ? 'The estimate failed its own check: do not trust these landmarks.'
    : 'The estimate doubts itself: check these landmarks before you trust them.';
  const lopsided = check.lowered.length
    ? ` (those it takes for misplaced — ${check.lowered.length} of them — to ${(Math.min(check.lopsided_factor, check.confidence_factor) * 100).toFixed(0)} %)`
    : '';
  const confidence = `Their confidences are lowered to ${(check.confidence_factor * 100).toFixed(0)} % of what they would be${lopsided}.`;
  return [
    h(
      'div',
      { class: failed ? 'error-note' : 'warn-note', 'data-testid': 'estimate-check', 'data-verdict': check.verdict },
      h('p', {}, `${headline} ${confidence}`),
      h('ul', { class: 'check-reasons' }, ...check.reasons.map((r) => h('li', {}, sentence(capitalised(r))))),
      ...checkFirstParts(check.check_first, onInspect),
      h('p', { 'data-testid': 'estimate-way-out' }, wayOut(check)),
    ),
  ];
}

/** The landmarks to check first as buttons that pick each one and show it up close; nothing when there are none. */
function checkFirstParts(names: readonly string[], onInspect: (name: string) => void): HTMLElement[] {
  if (names.length === 0) return [];
  return [
    h('p', {}, `Check these first (${names.length}):`),
    h(
      'div',
      { class: 'check-first', 'data-testid': 'estimate-check-first' },
      ...names.map((name) => {
        const pick = button(`check-first-${name}`, name, 'button', () => onInspect(name));
        pick.dataset.name = name;
        pick.title = `Pick ${name} and show it up close, then click on the scan where it belongs ("Whole body" in the view goes back)`;
        return pick;
      }),
    ),
  ];
}

/** What to do about the estimate's doubts, by what they put in doubt. */
function wayOut(check: SelfCheck): string {
  const estimateAgain = 'then "Estimate again, keeping my edits": the landmarks placed by hand anchor the rest.';
  if (check.frame_in_doubt)
    return `The frame may be wrong: choose which way is up and the facing below, or place a few landmarks by hand (Sellion, the Acromions, the Malleoli), ${estimateAgain}`;
  if (check.check_first.length)
    return `Pick each landmark named above and click on the scan where it belongs (its marker may be far from it), ${estimateAgain}`;
  return `Look at the markers on the scan and place those that are off by hand, ${estimateAgain}`;
}

function capitalised(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}

function selectedText(view: ToolsView): string {
  const s = view.selected;
  if (!view.hasScan) return 'Open a scan to place landmarks on it.';
  if (!s) return 'Pick a landmark in the list, then click on the scan to place it there; drag a marker to move it.';
  const where = s.position ? `at (${s.position.map((v) => (v * 1000).toFixed(1)).join(', ')}) mm, ${s.state}` : 'absent';
  return `${s.name}: ${where}. Click on the scan to place it.`;
}

/** What a click that fell through a hole in the scan did: nothing, and why. */
function throughHoleParts(name: string | null): HTMLElement[] {
  if (!name) return [];
  return [
    h(
      'p',
      { class: 'warn-note', 'data-testid': 'landmark-through-hole' },
      `${name} was not placed: that click went through a hole in the scan onto the inside of its far side. Click on the surface beside the hole, or turn the view.`,
    ),
  ];
}

/**
 * The suspicious landmarks; none is said only while the prediction they are checked against is
 * `trusted` (an estimate that doubts itself predicts nothing worth agreeing with).
 */
function suspiciousParts(list: SuspiciousLandmark[] | null, trusted: boolean): HTMLElement[] {
  if (!list || (list.length === 0 && !trusted)) return [];
  if (list.length === 0) return [h('p', { class: 'note', 'data-testid': 'landmarks-suspicious-none' }, 'No landmark is far from where the others predict it.')];
  return [
    h('h2', {}, `Suspicious (${list.length})`),
    h(
      'ul',
      { class: 'suspicious-list', 'data-testid': 'landmarks-suspicious' },
      ...list.map((s) =>
        h('li', { 'data-name': s.name }, h('span', { class: 'name' }, s.name), h('span', { class: 'distance' }, `${s.distance_mm.toFixed(0)} mm`), h('span', { class: 'suggestion' }, s.suggestion)),
      ),
    ),
  ];
}

/** `message` ending in a full stop (or the question or exclamation mark it has). */
export function sentence(message: string): string {
  return /[.?!]$/.test(message) ? message : `${message}.`;
}
