// The aligned subjects of this session: fitted templates in template vertex order, kept by the
// Align step or dropped as fitted meshes, and used to build a shape model in the app.

/** One aligned subject: the template's vertices fitted to a scan, in metres, template order. */
export interface AlignedSubject {
  /** A name a person recognises, e.g. the scan's file name. */
  name: string;
  /** `#V × 3` positions, xyz interleaved, metres, in template vertex order. */
  positions: Float32Array;
  /** Template resolution the fit was made at ("base" or "fine"). */
  resolution: string;
  /** Where it came from: aligned in this session, dropped as a fitted mesh, or fitted by the batch. */
  source: 'aligned' | 'dropped' | 'batch';
  /** Scan-to-template RMS of the fit in metres, when known. */
  rmsMetres?: number;
}

type Listener = (subjects: readonly AlignedSubject[]) => void;

/** A small observable list; the Align step adds to it, the shape-model panel reads it. */
export class SubjectStore {
  private readonly items: AlignedSubject[] = [];
  private readonly listeners = new Set<Listener>();

  get all(): readonly AlignedSubject[] {
    return this.items;
  }

  add(subject: AlignedSubject): void {
    this.items.push(subject);
    this.emit();
  }

  remove(index: number): void {
    this.items.splice(index, 1);
    this.emit();
  }

  subscribe(listener: Listener): () => void {
    this.listeners.add(listener);
    listener(this.items);
    return () => this.listeners.delete(listener);
  }

  private emit(): void {
    for (const listener of this.listeners) listener(this.items);
  }
}

/** The one store of the page. */
export const subjects = new SubjectStore();

