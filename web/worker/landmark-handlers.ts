// The landmark estimate and the check of an edited set for suspicious landmarks in the worker, both
// the core's. Progress goes out after every iteration of the estimate; the check needs no fit.
import { checkLandmarks, estimateLandmarks } from '../pkg/bodyspace.js';
import type { AlignProgress, ScanInput } from '../shared/align-types';
import type { EstimateReport, LandmarkEstimate, LandmarkPrediction, SuspiciousLandmark } from '../shared/landmark-entry';
import { orientationArgument, type Orientation } from '../shared/orientation';
import { withScan } from './align-handlers';
import { templateHandle } from './template-handlers';

/**
 * Estimates the landmarks `scan` lacks, in the frame `orientation` states (null: the core finds
 * it); `onProgress(fraction, label)` after every iteration.
 */
export function runEstimate(scan: ScanInput, orientation: Orientation | null, onProgress: (fraction: number, label: string) => void): LandmarkEstimate {
  const t0 = performance.now();
  const progress = (p: AlignProgress): boolean => {
    onProgress(p.max_iterations > 0 ? Math.min(p.iteration / p.max_iterations, 1) : 0, `Estimating the landmarks: iteration ${p.iteration} of at most ${p.max_iterations}`);
    return true;
  };
  const estimate = withScan(scan, (input) => estimateLandmarks(templateHandle(scan.resolution), input, orientationArgument(orientation), progress));
  try {
    return {
      names: estimate.names(),
      positions: estimate.positions(),
      confidence: estimate.confidence(),
      given: estimate.given(),
      prediction: { positions: estimate.predicted(), parts: estimate.parts() },
      report: JSON.parse(estimate.reportJson()) as EstimateReport,
      workerMs: performance.now() - t0,
    };
  } finally {
    estimate.free();
  }
}

/** The suspicious landmarks of `names` / `positions` (metres) against an estimate's `prediction`. */
export function runCheck(names: string[], positions: Float64Array, prediction: LandmarkPrediction): SuspiciousLandmark[] {
  const json = checkLandmarks(templateHandle('base'), names.join('\n'), positions, prediction.positions, prediction.parts);
  return JSON.parse(json) as SuspiciousLandmark[];
}
