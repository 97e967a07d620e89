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

/** A landmark of the current set far from where a fit of the scan predicts it (`SuspiciousLandmark`). */
export interface SuspiciousLandmark {
  name: string;
  /** How far it is from where it is predicted, in millimetres. */
  distance_mm: number;
  kind: 'swapped' | 'coordinate' | 'other_landmark' | 'far';
  /** What a person could do, in words. */
  suggestion: string;
  /** The predicted position (metres, the frame the scan was sent in). */
  expected: [number, number, number];
}

/**
 * How sharply a landmark's definition pins it on a body (`DefinitionSharpness` in the core): part of
 * the estimate's confidence.
 */
export type Sharpness = 'point' | 'prominence' | 'level';

/** The estimate's verdict on itself (`Verdict`, crate/src/estimate/self_check.rs). */
export type Verdict = 'good' | 'doubtful' | 'failed';

/**
 * The estimate's check of itself (`SelfCheck`): its verdict, the reasons in sentences for a
 * person, the factor its confidences were multiplied by (1 when good), and what it judged.
 */
export interface SelfCheck {
  verdict: Verdict;
  reasons: string[];
  confidence_factor: number;
  /** The factor of the landmarks in `lowered` instead. */
  lopsided_factor: number;
  /** The landmarks the check takes for misplaced: a lopsided segment's ends, the head's when the face is turned. */
  lowered: string[];
  /** The landmarks a person should look at first when the estimate is not good, most suspect first (empty when good). */
  check_first: string[];
  /** The reasons put the frame in doubt: choosing Up and Facing is the way out. */
  frame_in_doubt: boolean;
  evidence: SelfCheckEvidence;
}

/** A limb segment much longer on one side than on the other (`Asymmetry`, estimate/bilateral.rs). */
export interface Asymmetry {
  segment: string;
  left_mm: number;
  right_mm: number;
  /** The four landmarks that make its two lengths. */
  landmarks: string[];
}

/** What the self-check looks at (`Evidence`): lengths in mm, the stature in metres. */
export interface SelfCheckEvidence {
  /** RMS (mm) of the landmark-free fit, template → scan. */
  fit_rms_mm: number;
  /** RMS (mm) of how far that fit bent the template from the segment-wise fit. */
  fit_moved_mm: number;
  /** Height (m) of the fitted template along the frame's up. */
  stature_m: number;
  /** Estimated landmarks far from where the others of their rigid part put them. */
  contradicting: string[];
  /** Limb segments whose left and right lengths disagree. */
  asymmetric: Asymmetry[];
  /** Limb parts whose fit lies much farther from the scan on one side. */
  uneven: UnevenFit[];
  /** When only the fits chose which way the body faces: how close the two facings came (the
   * difference of their energies over the best's); `null` when the feet, the legs, the person or
   * given landmarks said. */
  facing_margin: number | null;
  /** The scan the landmark-free fit left uncovered (more than 20 mm from it). */
  uncovered: Uncovered | null;
  /** How far (degrees) the fitted head's ear-to-eye line is pitched from the template's (+ up). */
  head_pitch_deg: number | null;
}

/** The scan a fit left uncovered (the core's `align::Uncovered`): how many of its vertices, their
 * share of the scan, and the template part nearest most of them. */
export interface Uncovered {
  vertices: number;
  share: number;
  near: string | null;
}

/** A limb's part whose fit lies much farther from the scan on one side than on the other (the
 * core's `align::UnevenFit`): its part without the side (`lower leg`) and both sides' RMS (mm). */
export interface UnevenFit {
  part: string;
  left_rms_mm: number;
  right_rms_mm: number;
}

/** What the core took off a scan before fitting it (stray pieces, a floor), and that in words. */
export interface ScanRemoval {
  vertices: number;
  words: string;
}

/** The triangles the core turned before fitting: to agree with their neighbours, and parts wound inwards to face out (`mesh::winding::Reorientation`). */
export interface Reorientation {
  /** Parts (pieces) turned whole, wound inwards. */
  parts: number;
  /** Triangles that face otherwise than in the file, all told. */
  triangles: number;
  /** Of the turning, the triangles turned to agree with their neighbours. */
  against_neighbours: number;
  words: string;
}

/** The core's report of a landmark estimate (`EstimateReport`; the fields the page uses). */
export interface EstimateReport {
  /** The 73 CAESAR landmarks in file order. */
  landmarks: { name: string; sharpness: Sharpness }[];
  /** The frame assumed: the scan's axis nearest the body's up and facing directions. */
  frame: { up_axis: string; facing_axis: string };
  /**
   * What said the frame's up and its facing, in words: "chosen", "given landmarks", "the scan's
   * shape" (up), "the feet" or "the legs" (facing), "the fits".
   */
  frame_from: { up: string; facing: string };
  given: number;
  estimated: number;
  flagged: SuspiciousLandmark[];
  /** The estimate's verdict on itself; its confidences already carry the verdict's factor. */
  self_check: SelfCheck;
  /** RMS distance (mm) of the fitted template to the scan after the landmark-free fit. */
  fit_rms_mm: number;
  total_ms: number;
  /** The stray pieces taken off the scan before anything else, when there were any. */
  strays?: ScanRemoval;
  /** The parts wound inwards turned to face out, when there were any. */
  turned?: Reorientation;
  /** The floor or turntable under the feet taken off once the frame was chosen, when one was found. */
  floor?: ScanRemoval;
}

/** A landmark estimate as the worker returns it: the 73 CAESAR landmarks in file order. */
/**
 * The estimate's own prediction of the 73 landmarks, which `checkLandmarks` checks an edited set
 * against without a new fit: positions `73·3` (metres, the frame the scan was sent in) and the rigid
 * part of the fit each belongs to.
 */
export interface LandmarkPrediction {
  positions: Float64Array;
  parts: Uint32Array;
}

export interface LandmarkEstimate {
  names: string[];
  /** `73·3` metres, the frame the scan was sent in; NaN where nothing was placed. */
  positions: Float64Array;
  /** `73` values in 0..1 (1 for a given landmark). */
  confidence: Float64Array;
  /** `73` flags: 1 = kept as given. */
  given: Uint8Array;
  /** Where the landmark-free part fit puts each landmark: what an edited set is checked against. */
  prediction: LandmarkPrediction;
  report: EstimateReport;
  /** The whole call in the worker. */
  workerMs: number;
}
