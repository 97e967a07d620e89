// One landmark of the set being edited, as the page holds and shows it. No DOM here.

/** Where a landmark's position came from: the file, the core's estimate, a hand edit, or none. */
export type LandmarkState = 'given' | 'estimated' | 'edited' | 'absent';

export type Point = [number, number, number];

export interface LandmarkEntry {
  readonly name: string;
  /** Metres, in the frame the scan is shown in; null when absent. */
  readonly position: Point | null;
  readonly state: LandmarkState;
  /** The core's confidence in an estimate, 0..1; null for given, edited and absent ones. */
  readonly confidence: number | null;
}

/** A landmark of the current set far from where the others predict it (the core's check). */
export interface SuspiciousLandmark {
  name: string;
  /** How far it is from where the others predict it, in millimetres. */
  distance_mm: number;
  /** What a person might do (e.g. "swapped with Lt. Acromion?"). */
  suggestion: string;
}
