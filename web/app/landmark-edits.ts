// The landmark set being edited: one entry per CAESAR landmark, each given (from the file),
// estimated (by the core), edited (placed by hand) or absent, with undo / redo. Positions are in
// metres in the frame the scan is shown in. It lives on the UI thread, so a worker that traps or
// is cancelled never takes the edits with it.
import type { LandmarkEntry, LandmarkState, Point } from '../shared/landmark-entry';

/** One undoable step: entry `index` went from `before` to `after`. */
interface Change {
  readonly index: number;
  before: LandmarkEntry;
  after: LandmarkEntry;
}

export class LandmarkEdits {
  private entries: LandmarkEntry[];
  private readonly undone: Change[] = [];
  private readonly done: Change[] = [];
  /** The entry as it was when a drag began, so the whole drag is one undo step. */
  private dragStart: { index: number; entry: LandmarkEntry } | null = null;

  /** Every name of `names` (the 73 CAESAR landmarks in file order) absent. */
  constructor(readonly names: readonly string[]) {
    this.entries = names.map((name) => ({ name, position: null, state: 'absent', confidence: null }));
  }

  /** A set as it was (`entries`, each by name; names not among them absent), with no history: restored after a reload. */
  static fromEntries(names: readonly string[], entries: readonly LandmarkEntry[]): LandmarkEdits {
    const edits = new LandmarkEdits(names);
    const at = new Map(entries.map((e) => [e.name, e]));
    edits.entries = edits.entries.map((e) => at.get(e.name) ?? e);
    return edits;
  }

  /** The set of a landmark file: `positions` (`#L·3` metres) of `fileNames` given, the rest absent. */
  static fromFile(names: readonly string[], fileNames: readonly string[], positions: ArrayLike<number>): LandmarkEdits {
    const edits = new LandmarkEdits(names);
    const at = new Map(fileNames.map((n, i) => [n, i]));
    edits.entries = edits.entries.map((e) => {
      const i = at.get(e.name);
      return i === undefined ? e : { ...e, position: pointAt(positions, i), state: 'given' };
    });
    return edits;
  }

  get all(): readonly LandmarkEntry[] {
    return this.entries;
  }

  entry(name: string): LandmarkEntry | undefined {
    return this.entries[this.names.indexOf(name)];
  }

  /**
   * Landmarks with a position (of the states `which` accepts: all by default): names and `#L·3`
   * positions in metres, as the core takes them.
   */
  placed(which: (state: LandmarkState) => boolean = () => true): { names: string[]; positions: Float64Array } {
    const present = this.entries.filter((e) => e.position && which(e.state));
    return { names: present.map((e) => e.name), positions: Float64Array.from(present.flatMap((e) => e.position!)) };
  }

  /** Every landmark in order, `#73·3` metres, NaN where absent (what the exporter takes). */
  positionsWithGaps(): Float64Array {
    return Float64Array.from(this.entries.flatMap((e) => e.position ?? [Number.NaN, Number.NaN, Number.NaN]));
  }

  /**
   * Takes the core's estimate (`positions` `#L·3` metres, NaN where it placed nothing; `given[i]`
   * 1 where it kept what it was given) for every landmark neither given nor edited here; a
   * landmark it could not place becomes absent. Not an undo step: it starts the editing.
   */
  fillEstimate(names: readonly string[], positions: ArrayLike<number>, confidence: ArrayLike<number>, given: ArrayLike<number>): void {
    const at = new Map(names.map((n, i) => [n, i]));
    this.entries = this.entries.map((e) => {
      const i = at.get(e.name);
      if (i === undefined || given[i] === 1 || e.state === 'given' || e.state === 'edited') return e;
      const p = pointAt(positions, i);
      return p.some(Number.isNaN)
        ? { ...e, position: null, state: 'absent', confidence: null }
        : { ...e, position: p, state: 'estimated', confidence: confidence[i] ?? null };
    });
  }

  /**
   * Puts landmark `name` at `position`. A `transient` move (a drag under way) is shown but not
   * yet an undo step; the next non-transient `place` closes it as one step.
   */
  place(name: string, position: Point, transient = false): void {
    const index = this.names.indexOf(name);
    if (index < 0) return;
    const before = this.dragStart?.index === index ? this.dragStart.entry : this.entries[index]!;
    const after: LandmarkEntry = { name, position, state: 'edited', confidence: null };
    if (transient) {
      this.dragStart ??= { index, entry: this.entries[index]! };
      this.entries[index] = after;
      return;
    }
    this.dragStart = null;
    this.apply({ index, before, after });
  }

  /** Marks `name` absent: the warp and the alignment go without it. */
  markAbsent(name: string): void {
    const index = this.names.indexOf(name);
    const before = this.entries[index];
    if (!before || before.state === 'absent') return;
    this.apply({ index, before, after: { name, position: null, state: 'absent', confidence: null } });
  }

  get canUndo(): boolean {
    return this.done.length > 0;
  }

  get canRedo(): boolean {
    return this.undone.length > 0;
  }

  /** Undoes the last step; returns the name it touched, or null when there was none. */
  undo(): string | null {
    const change = this.done.pop();
    if (!change) return null;
    this.entries[change.index] = change.before;
    this.undone.push(change);
    return change.before.name;
  }

  redo(): string | null {
    const change = this.undone.pop();
    if (!change) return null;
    this.entries[change.index] = change.after;
    this.done.push(change);
    return change.after.name;
  }

  /** Multiplies the positions of entries `which` accepts by `factor` (the scan's units changed), history included. */
  rescale(factor: number, which: (state: LandmarkState) => boolean): void {
    const scale = (e: LandmarkEntry): LandmarkEntry =>
      e.position && which(e.state) ? { ...e, position: e.position.map((v) => v * factor) as Point } : e;
    this.entries = this.entries.map(scale);
    for (const c of [...this.done, ...this.undone]) {
      c.before = scale(c.before);
      c.after = scale(c.after);
    }
  }

  private apply(change: Change): void {
    this.entries[change.index] = change.after;
    this.done.push(change);
    this.undone.length = 0;
  }
}

function pointAt(positions: ArrayLike<number>, i: number): Point {
  return [positions[3 * i]!, positions[3 * i + 1]!, positions[3 * i + 2]!];
}
