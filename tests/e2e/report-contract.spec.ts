// The TypeScript mirrors of the core's JSON (web/shared/align-types.ts, landmark-entry.ts) held to
// the JSON the core really writes: `bodyspace align`'s report of a synthetic subject, field by
// field — with its landmark file, and without one in a wrong frame forced (the estimate's report
// and its failed self-check). Each list below must name exactly the keys of its TypeScript type
// (tsc refuses a missing or extra one), and the test fails when the core writes a field the type
// lacks or lacks one the type requires. The estimate's report is mirrored only in the fields the
// page reads: those must be there.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import type { DistanceStatsMm, FineReport, LandmarkPolicyReport, MeasurementSupport, MeasurementTrust, QualityReport, SubjectReport, ToTemplate, UnplacedLandmark, WarpReport } from '../../web/shared/align-types';
import type { EstimateReport, SelfCheck, SelfCheckEvidence, Uncovered } from '../../web/shared/landmark-entry';
import { bodyspaceBinary, synthSubjects } from './synth';

/** Every key of `T`: `true` where the core always writes it, `false` where it may leave it out. */
type Keys<T> = { [K in keyof Required<T>]: boolean };

const subject: Keys<SubjectReport> = {
  landmarks: true,
  floor: false,
  strays: false,
  turned: false,
  quality: true,
  to_template: true,
  measurement_trust: true,
  template_resolution: true,
  coarse_to_fine: true,
  template_vertices: true,
  scan_vertices: true,
  units: true,
  units_detected: true,
  params: true,
  warp: true,
  anchors: true,
  fine: true,
  correspondence: true,
  rough_ms: true,
  index_ms: true,
  total_ms: true,
};
const landmarks: Keys<LandmarkPolicyReport> = {
  source: true,
  file: true,
  given: true,
  left_out: true,
  unjudged: true,
  estimated: true,
  used: true,
  estimate: false,
  estimate_check: false,
};
/** With no landmark file the warp uses the estimate: its report and its verdict are written. */
const estimatedLandmarks: Keys<LandmarkPolicyReport> = { ...landmarks, estimate: true, estimate_check: true };
const quality: Keys<QualityReport> = {
  rms_mm: true,
  weighted_vertices: true,
  unmatched_vertices: true,
  unmatched_fraction: true,
  compared_triangles: true,
  folded_triangles: true,
  folded_fraction: true,
  scan_vertices: true,
  uncovered_scan_vertices: true,
  uncovered_share: true,
  uncovered_near: true,
  uneven_limbs: true,
  suspicious_landmarks: true,
  landmark_estimate: true,
  flags: true,
  thresholds: true,
};
const selfCheck: Keys<SelfCheck> = { verdict: true, reasons: true, confidence_factor: true, lopsided_factor: true, lowered: true, check_first: true, frame_in_doubt: true, evidence: true };
const evidence: Keys<SelfCheckEvidence> = { fit_rms_mm: true, fit_moved_mm: true, stature_m: true, contradicting: true, asymmetric: true, uneven: true, facing_margin: true, uncovered: true, head_pitch_deg: true };
const uncovered: Keys<Uncovered> = { vertices: true, share: true, near: true };
const estimateRead: Keys<EstimateReport> = { landmarks: true, frame: true, frame_from: true, given: true, estimated: true, flagged: true, self_check: true, fit_rms_mm: true, total_ms: true, strays: false, turned: false, floor: false };
const trust: Keys<MeasurementTrust> = { name: true, trust: true, landmarks: true, fit_error_mm: true, expected_error_mm: true, limit_mm: true, chance_over_limit: true, support: true, doubtful: true, words: true };
const support: Keys<MeasurementSupport> = { at: true, vertices: true, unsupported: true, unsupported_share: true, max_distance_mm: true, doubtful: true };
const unplaced: Keys<UnplacedLandmark> = { name: true, origin: true, typical_error_mm: true };
const toTemplate: Keys<ToTemplate> = { scale_to_metres: true, rotation: true, translation: true };
const warp: Keys<WarpReport> = {
  kernel: true,
  param: true,
  lambda: true,
  affine: true,
  virtual_landmarks: true,
  used: true,
  skipped: true,
  virtual_off_surface: true,
  residuals: true,
  max_residual_before_mm: true,
  max_residual_after_mm: true,
  similarity: true,
  rcond: true,
};
const fine: Keys<FineReport> = {
  template_vertices: true,
  scan_vertices: true,
  scan_to_template: true,
  template_to_scan: true,
  matched_vertices: true,
  iterations: true,
  rounds: true,
  converged: true,
  cancelled: true,
  elapsed_ms: true,
  curve: false,
  stages: false,
};
const distance: Keys<DistanceStatsMm> = { count: true, mean_mm: true, std_dev_mm: true, rms_mm: true, max_abs_mm: true };

function expectKeys(what: string, json: Record<string, unknown>, keys: Record<string, boolean>): void {
  const extra = Object.keys(json).filter((k) => !(k in keys));
  const missing = Object.entries(keys)
    .filter(([k, required]) => required && !(k in json))
    .map(([k]) => k);
  expect(extra, `${what}: fields the core writes that the TypeScript type lacks`).toEqual([]);
  expect(missing, `${what}: fields the TypeScript type requires that the core does not write`).toEqual([]);
}

/** The fields of `keys` the core must write are all in `json` (it may write more). */
function expectRequired(what: string, json: Record<string, unknown>, keys: Record<string, boolean>): void {
  const missing = Object.entries(keys)
    .filter(([k, required]) => required && !(k in json))
    .map(([k]) => k);
  expect(missing, `${what}: fields the page reads that the core does not write`).toEqual([]);
}

/** `bodyspace align` of the synthetic subject in `dir` with `args`, 20 iterations: its report. */
function align(dir: string, args: string[]): Record<string, Record<string, unknown>> {
  const out = execFileSync(bodyspaceBinary(), ['align', '--scan', join(dir, 'scan_001.ply'), '--out', join(dir, 'fit.ply'), '--max-iterations', '20', ...args], {
    encoding: 'utf8',
    maxBuffer: 64 << 20,
  });
  return JSON.parse(out) as Record<string, Record<string, unknown>>;
}

test('the TypeScript report types name exactly the fields the core writes', () => {
  test.setTimeout(180_000);
  const files = synthSubjects(1, 41);
  const dir = mkdtempSync(join(tmpdir(), 'bodyspace-contract-'));
  try {
    for (const f of files) writeFileSync(join(dir, f.name), f.bytes);
    const report = align(dir, ['--landmarks', join(dir, 'landmarks_001.lnd')]);
    expectKeys('SubjectReport', report, subject);
    expectKeys('LandmarkPolicyReport', report.landmarks!, landmarks);
    expectKeys('QualityReport', report.quality!, quality);
    expectKeys('ToTemplate', report.to_template!, toTemplate);
    expectKeys('WarpReport', report.warp!, warp);
    expectKeys('FineReport', report.fine!, fine);
    expectKeys('DistanceStatsMm', report.fine!.scan_to_template as Record<string, unknown>, distance);
    const trusted = report.measurement_trust as unknown as Record<string, unknown>[];
    expect(trusted).toHaveLength(20);
    for (const t of trusted) expectKeys(`MeasurementTrust ${String(t.name)}`, t, trust);
    // A body-defined measurement with a limit carries the scan's support where it is taken.
    const chest = trusted.find((t) => t.name === 'chest_girth')!;
    expectKeys('MeasurementSupport', chest.support as Record<string, unknown>, support);

    // No landmark file, and up stated as −z on this z-up scan: the estimate runs in a wrong frame,
    // says it failed and why, and the fit's quality carries it.
    const wrong = align(dir, ['--up=-z']);
    expectKeys('LandmarkPolicyReport (estimated)', wrong.landmarks!, estimatedLandmarks);
    expectKeys('QualityReport (estimated)', wrong.quality!, quality);
    const check = wrong.landmarks!.estimate_check as Record<string, unknown>;
    expectKeys('SelfCheck', check, selfCheck);
    expectKeys('SelfCheck.evidence', check.evidence as Record<string, unknown>, evidence);
    expectKeys('SelfCheck.evidence.uncovered', (check.evidence as Record<string, unknown>).uncovered as Record<string, unknown>, uncovered);
    expectRequired('EstimateReport', wrong.landmarks!.estimate as Record<string, unknown>, estimateRead);
    expectKeys('EstimateReport.self_check', (wrong.landmarks!.estimate as Record<string, unknown>).self_check as Record<string, unknown>, selfCheck);
    const typed = wrong as unknown as SubjectReport;
    // Every landmark estimated: shoulder breadth comes from the estimated acromia, doubtful, in words.
    const shoulder = typed.measurement_trust.find((t) => t.name === 'shoulder_breadth')!;
    expectKeys('MeasurementTrust (estimated)', shoulder as unknown as Record<string, unknown>, trust);
    expectKeys('UnplacedLandmark', shoulder.landmarks[0] as unknown as Record<string, unknown>, unplaced);
    expect(shoulder.trust).toBe('estimated');
    expect(shoulder.doubtful).toBe(true);
    expect(shoulder.words).toContain('Acromion');
    expect(typed.landmarks.estimate_check?.verdict).toBe('failed');
    expect(typed.landmarks.estimate_check?.reasons.length).toBeGreaterThan(0);
    expect(typed.quality?.flags).toContain('landmark_estimate');
    expect(typed.quality?.landmark_estimate.length).toBeGreaterThan(0);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
