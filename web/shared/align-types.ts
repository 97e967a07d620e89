// Inputs and results of the RBF warp (paper §3.1) and fine alignment (§3.2). No DOM here.
import type { DistanceHeat } from './heat-scale';
import type { Reorientation, ScanRemoval, SelfCheck, UnevenFit } from './landmark-entry';
import type { Orientation } from './orientation';
import type { TemplateResolution } from './template-data';
import type { Units } from './results';

export type KernelName = 'gaussian' | 'thin-plate' | 'multiquadric';

/** A kernel as the core writes and reads it (its parameter c or s in metres). */
export type Kernel = { kind: 'thin-plate' } | { kind: 'gaussian'; c: number } | { kind: 'multiquadric'; s: number };

/** The RBF panel's settings; `param` is the Gaussian width c or the multiquadric stiffness s, in metres. */
export interface RbfSettings {
  kernel: KernelName;
  param: number | null;
  lambda: number;
  affine: boolean;
}

/** The parameters the app sends: any part of the core's `AlignParams` (absent fields keep the core's defaults). */
export interface AlignParams {
  rbf?: { kernel?: Kernel; lambda?: number; affine?: boolean; virtual_landmarks?: boolean };
  fine?: { a?: number; b?: number; max_iterations?: number; [name: string]: unknown };
  fine_stage?: { max_iterations?: number; [name: string]: unknown };
}

/** The core's defaults (`alignDefaults`): every parameter, and each kernel with its default parameter. */
export interface AlignDefaults {
  params: {
    rbf: { kernel: Kernel; lambda: number; affine: boolean; virtual_landmarks: boolean; min_rcond: number };
    fine: { a: number; b: number; max_iterations: number; [name: string]: unknown };
    fine_stage: { max_iterations: number; [name: string]: unknown };
    rough_only: boolean;
  };
  kernels: Kernel[];
  /** The core's `SubjectOptions` defaults beyond the parameters. */
  subject: { check_landmarks: boolean; nearly_full: number };
}

/** The kernel's parameter, or null for the thin-plate spline. */
export function kernelParam(kernel: Kernel): number | null {
  return kernel.kind === 'gaussian' ? kernel.c : kernel.kind === 'multiquadric' ? kernel.s : null;
}

/** The panel's settings as the core's RBF parameters. */
export function rbfParams(settings: RbfSettings): NonNullable<AlignParams['rbf']> {
  const kernel: Kernel =
    settings.kernel === 'gaussian'
      ? { kind: 'gaussian', c: settings.param ?? Number.NaN }
      : settings.kernel === 'multiquadric'
        ? { kind: 'multiquadric', s: settings.param ?? Number.NaN }
        : { kind: 'thin-plate' };
  return { kernel, lambda: settings.lambda, affine: settings.affine };
}

/**
 * A fine template is aligned coarse to fine: the base template is fitted first ('base'), carried
 * to fine by the subdivision operator and fitted briefly there ('fine'). A base template has only
 * the 'base' stage. A landmark estimate on a bare scan reports its own 'estimate' stage.
 */
export type AlignStage = 'base' | 'fine' | 'estimate';

/**
 * A subject as the page holds it, for the core's one path from a subject to a checked fit
 * (`crate/src/subject/`): the scan in metres under the units the person chose, the landmarks
 * given or placed (metres), and the estimate the landmark worker already made, if any.
 */
export interface SubjectInput {
  name: string;
  resolution: TemplateResolution;
  positions: Float32Array;
  triangles: Uint32Array;
  units: Units;
  /** Whether `units` are the detected ones (not chosen by the person). */
  unitsDetected: boolean;
  given: { names: string[]; positions: Float64Array; file: string };
  estimate: { names: string[]; positions: Float64Array; report: string } | null;
}

/** The core's `SubjectOptions` (absent fields keep the core's defaults). */
export interface SubjectOptions {
  params?: AlignParams;
  check_landmarks?: boolean;
  thresholds?: Partial<QualityReport['thresholds']>;
  nearly_full?: number;
  /** Which way is up on the scan, when a person said so (null: the estimate finds the frame). */
  orientation?: Orientation | null;
}

/** A file's bytes and name, as the batch hands a subject's files to the core. */
export interface FileBytes {
  bytes: ArrayBuffer;
  name: string;
}

/** The scan and its landmarks as the core needs them, all in metres. */
export interface ScanInput {
  resolution: TemplateResolution;
  positions: Float32Array;
  triangles: Uint32Array;
  landmarkNames: string[];
  landmarkPositions: Float64Array;
}

export interface LandmarkResidual {
  name: string;
  /** After the similarity (Procrustes) alone. */
  before_mm: number;
  /** After the RBF warp. */
  after_mm: number;
}

/** Template → scan similarity y = scale·R·x + t (metres). */
export interface Similarity {
  scale: number;
  rotation: [number, number, number][];
  translation: [number, number, number];
}

export interface WarpReport {
  kernel: KernelName;
  param: number | null;
  lambda: number;
  affine: boolean;
  virtual_landmarks: boolean;
  used: string[];
  skipped: string[];
  virtual_off_surface: string[];
  residuals: LandmarkResidual[];
  max_residual_before_mm: number;
  max_residual_after_mm: number;
  similarity: Similarity;
  rcond: number;
}

/** The warped template: positions and normals in the scan's frame, metres, template order. */
export interface WarpResult {
  positions: Float32Array;
  normals: Float32Array;
  report: WarpReport;
  workerMs: number;
}

/** The paper's Table 1 statistics of a distance, in millimetres. */
export interface DistanceStatsMm {
  count: number;
  mean_mm: number;
  std_dev_mm: number;
  rms_mm: number;
  max_abs_mm: number;
}

/** What one fine alignment reports (for coarse to fine: the whole run, or its base stage). */
export interface FineReport {
  template_vertices: number;
  scan_vertices: number;
  scan_to_template: DistanceStatsMm;
  template_to_scan: DistanceStatsMm;
  /** Of the `template_to_scan.count` weighted template vertices, those with a usable scan match
   * in the last correspondence round. */
  matched_vertices: number;
  iterations: number;
  rounds: number;
  converged: boolean;
  cancelled: boolean;
  elapsed_ms: number;
  /** E and RMS after every iteration (the whole run only). */
  curve?: { iteration: number; elapsed_ms: number; energy: number; rms_mm: number }[];
  /** Coarse to fine only: the base stage, the subdivision and the fine stage's iterations. */
  stages?: {
    base: FineReport;
    subdivide_ms: number;
    fine_iterations: number;
    fine_max_iterations: number;
  };
}

/** The core's report of one alignment (`AlignmentReport`): lengths in mm, times in ms. */
export interface AlignReport {
  template_resolution: TemplateResolution;
  coarse_to_fine: boolean;
  template_vertices: number;
  scan_vertices: number;
  units: Units;
  units_detected: boolean;
  params: AlignDefaults['params'];
  warp: WarpReport;
  anchors: number;
  fine: FineReport;
  /** The correspondence error against a ground truth (`--truth`, synthetic subjects); else null. */
  correspondence: unknown;
  rough_ms: number;
  index_ms: number;
  total_ms: number;
}

/** How the warp's landmarks were chosen (`subject/policy.rs`). */
export interface LandmarkPolicyReport {
  source: 'estimated' | 'filled_in' | 'checked' | 'as_given';
  file: string;
  given: number;
  left_out: { name: string; distance_mm: number; kind: string; suggestion: string; expected: [number, number, number] }[];
  /** Given landmarks the check could not judge (too few others in their rigid groups): used as given. */
  unjudged: string[];
  estimated: number;
  used: number;
  estimate?: unknown;
  /** The estimate's verdict on itself, when the warp used landmarks it estimated. */
  estimate_check?: SelfCheck;
}

/** From the scan's frame and units into the template's: x_t = R·(s·x) + t (`subject/frame.rs`). */
export interface ToTemplate {
  scale_to_metres: number;
  rotation: [number, number, number][];
  translation: [number, number, number];
}

/** A defining landmark of a measurement that was not placed (`measure/trust.rs`). */
export interface UnplacedLandmark {
  name: string;
  origin: 'placed' | 'estimated' | 'left_out' | 'absent';
  /** The estimate's typical error of this landmark (mm). */
  typical_error_mm: number;
}

/**
 * Whether the scan is under the fit where a body-defined measurement is taken
 * (`measure/support.rs`): of the fit's vertices there, those farther from the scan than the
 * rule's distance (5 mm by default, 20 mm at the soles).
 */
export interface MeasurementSupport {
  /** The part judged: the measurement's place, or the soles (a height's other end) when they failed and the place did not. */
  at: 'place' | 'soles';
  vertices: number;
  unsupported: number;
  unsupported_share: number;
  /** The largest distance to the scan among them (mm). */
  max_distance_mm: number;
  /** The unsupported share above the rule's (more than half by default). */
  doubtful: boolean;
}

/**
 * One measurement's trust on a fit (`measure/trust.rs`): placed, found on the body
 * (`body_defined`) or estimated, by where its landmarks came from; its expected error is its
 * unplaced landmarks' and the fit's own together. Doubtful when that error makes an error over
 * ISO 20685-1's limit likely, or, for a body-defined one, when the fit where it is taken is mostly
 * not on the scan. A per-measurement verdict, not a quality flag.
 */
export interface MeasurementTrust {
  /** The measurement's snake_case name (`shoulder_breadth`). */
  name: string;
  trust: 'placed' | 'body_defined' | 'estimated';
  landmarks: UnplacedLandmark[];
  /** The fit's own typical error (measured on the tuning subjects), part of `expected_error_mm`. */
  fit_error_mm: number | null;
  /** The unplaced landmarks' error and the fit's own in quadrature; null without a limit. */
  expected_error_mm: number | null;
  limit_mm: number | null;
  /** The chance that this body's error exceeds the limit, when both are known. */
  chance_over_limit: number | null;
  /** For a body-defined measurement with a limit on a finished fit: the scan's support there. */
  support: MeasurementSupport | null;
  doubtful: boolean;
  /** In words, for an estimated or doubtful measurement (empty otherwise). */
  words: string;
}

/** The floor or turntable remnant the core took off the scan before the fit (`mesh/floor.rs`). */
export interface FloorRemoval extends ScanRemoval {
  triangles: number;
  /** The plane's height along its normal, in the scan's units. */
  height: number;
  above_lowest_mm: number;
  area_cm2: number;
}

/** The core's report of one subject (`SubjectReport`): the alignment's report and what the path added. */
export interface SubjectReport extends AlignReport {
  landmarks: LandmarkPolicyReport;
  /** Present when a floor or turntable was found under the feet and taken off. */
  floor?: FloorRemoval;
  /** The stray pieces taken off the scan before the fit (`mesh/strays.rs`), when there were any. */
  strays?: ScanRemoval;
  /** The parts wound inwards turned to face out before the fit (`mesh/winding.rs`), when there were any. */
  turned?: Reorientation;
  quality: QualityReport | null;
  to_template: ToTemplate;
  /** Every measurement's trust, in the core's order of measurements. */
  measurement_trust: MeasurementTrust[];
}

/** The fitted template and the per-vertex distance (metres) to the scan. */
export interface AlignResult {
  positions: Float32Array;
  normals: Float32Array;
  distances: Float32Array;
  /** The distances' heat map (`distanceHeat`), made in the worker. */
  heat: DistanceHeat;
  report: SubjectReport;
  /** The core's quality flags of the fit (`align/quality.rs`, its default thresholds). */
  quality: QualityReport;
  /** The whole core call in the worker: inputs in, alignment, outputs copied out. */
  workerMs: number;
  /** The worker's WASM memory after the call: its peak, since WASM memory never shrinks. */
  wasmMemoryBytes: number;
}

/** A reason to look at a fit again (`align/quality.rs` `QualityFlag`, docs/batch.md). */
export type QualityFlag = 'high_rms' | 'unmatched' | 'fold_overs' | 'uncovered_scan' | 'uneven_limb' | 'suspicious_landmarks' | 'landmark_estimate';

/** The core's `QualityReport`: the measures behind the flags and the flags raised. */
export interface QualityReport {
  rms_mm: number | null;
  weighted_vertices: number;
  unmatched_vertices: number;
  unmatched_fraction: number;
  compared_triangles: number;
  folded_triangles: number;
  folded_fraction: number;
  scan_vertices: number;
  /** Scan vertices farther than `thresholds.uncovered_mm` from the fit: part of the body the fit did not reach. */
  uncovered_scan_vertices: number;
  uncovered_share: number;
  /** The template part nearest most of them (`left forearm`, `head`, …); null when there are none. */
  uncovered_near: string | null;
  /** Limb parts that fit much farther from the scan than on the other side (soles left out). */
  uneven_limbs: UnevenFit[];
  suspicious_landmarks: string[];
  /** Why the landmark estimate the warp used doubts itself, in words (empty: it did not, or none ran). */
  landmark_estimate: string[];
  flags: QualityFlag[];
  thresholds: {
    max_rms_mm: number;
    max_unmatched_fraction: number;
    max_folded_fraction: number;
    uncovered_mm: number;
    max_uncovered_share: number;
    uneven_limb_ratio: number;
    uneven_limb_mm: number;
  };
}

/** Sent after every L-BFGS iteration: the core's `Progress`. */
export interface AlignProgress {
  stage: AlignStage;
  iteration: number;
  /** The most iterations this run can take (both stages of coarse to fine). */
  max_iterations: number;
  round: number;
  energy: number;
  data_error: number;
  smoothness_error: number;
  /** RMS distance (m) of matched template vertices to their closest scan points. */
  rms: number;
  matched: number;
  elapsed_ms: number;
}
