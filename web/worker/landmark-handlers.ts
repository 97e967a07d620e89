// The landmark estimate and the check for suspicious landmarks in the worker, both the core's.
// Progress goes out after every iteration of the estimate.
import { estimateLandmarks, flagSuspicious } from '../pkg/bodyspace.js';
import type { AlignProgress, ScanInput } from '../shared/align-types';
import type { EstimateReport, LandmarkEstimate, SuspiciousLandmark } from '../shared/landmark-entry';
import { withScan } from './align-handlers';
import { templateHandle } from './template-handlers';

/** Estimates the landmarks `scan` lacks; `onProgress(fraction, label)` after every iteration. */
export function runEstimate(scan: ScanInput, onProgress: (fraction: number, label: string) => void): LandmarkEstimate {
  const t0 = performance.now();
  const progress = (p: AlignProgress): boolean => {
    onProgress(p.max_iterations > 0 ? Math.min(p.iteration / p.max_iterations, 1) : 0, `Estimating the landmarks: iteration ${p.iteration} of at most ${p.max_iterations}`);
    return true;
  };
  const estimate = withScan(scan, (input) => estimateLandmarks(templateHandle(scan.resolution), input, progress));
  try {
    return {
      names: estimate.names(),
      positions: estimate.positions(),
      confidence: estimate.confidence(),
      given: estimate.given(),
      report: JSON.parse(estimate.reportJson()) as EstimateReport,
      workerMs: performance.now() - t0,
    };
  } finally {
    estimate.free();
  }
}

export function runFlagSuspicious(scan: ScanInput): SuspiciousLandmark[] {
  return JSON.parse(withScan(scan, (input) => flagSuspicious(input))) as SuspiciousLandmark[];
}
