// Inputs and results of the RBF warp (paper §3.1) and fine alignment (§3.2). No DOM here.
import type { TemplateResolution } from './template-data';

export type KernelName = 'gaussian' | 'thin-plate' | 'multiquadric';

/** RBF settings; `param` is the Gaussian width c or the multiquadric stiffness s, in metres. */
export interface RbfSettings {
  kernel: KernelName;
  param: number | null;
  lambda: number;
  affine: boolean;
}

/** The core's kernel parameters (docs/rbf.md): Gaussian c = 0.1 m, multiquadric s = 0.01 m. */
/** The core's default kernel, chosen by measurement after the full pipeline (docs/rbf.md). */
export const DEFAULT_KERNEL: KernelName = 'thin-plate';

export const DEFAULT_KERNEL_PARAM: Record<KernelName, number | null> = {
  gaussian: 0.1,
  'thin-plate': null,
  multiquadric: 0.01,
};

/**
 * Fine-alignment settings; absent fields keep the core's defaults (a = 0.96, b = 0.04).
 * `max_iterations` limits the (base) fit; `fine_iterations` the fine stage of a fine template.
 */
export interface FineSettings {
  a?: number;
  b?: number;
  max_iterations?: number;
  fine_iterations?: number;
}

/**
 * A fine template is aligned coarse to fine: the base template is fitted first ('base'), carried
 * to fine by the subdivision operator and fitted briefly there ('fine'). A base template has only
 * the 'base' stage.
 */
export type AlignStage = 'base' | 'fine';

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
  used: string[];
  skipped: string[];
  virtual_off_surface: string[];
  residuals: LandmarkResidual[];
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
  iterations: number;
  rounds: number;
  converged: boolean;
  cancelled: boolean;
  elapsed_ms: number;
}

export interface AlignReport {
  warp: WarpReport;
  rough_ms: number;
  index_ms: number;
  total_ms: number;
  fine: FineReport & {
    /** Coarse to fine only: the base stage, the subdivision and the fine stage's iterations. */
    stages?: {
      base: FineReport;
      subdivide_ms: number;
      fine_iterations: number;
      fine_max_iterations: number;
    };
  };
}

/** The fitted template and the per-vertex distance (metres) to the scan. */
export interface AlignResult {
  positions: Float32Array;
  normals: Float32Array;
  distances: Float32Array;
  report: AlignReport;
  /** The whole core call in the worker: inputs in, alignment, outputs copied out. */
  workerMs: number;
}

/** Sent after every L-BFGS iteration. */
export interface AlignProgress {
  iteration: number;
  round: number;
  energy: number;
  dataError: number;
  smoothnessError: number;
  rmsMetres: number;
  elapsedMs: number;
  stage: AlignStage;
  /** The most iterations this run can take (both stages of coarse to fine). */
  maxIterations: number;
}
