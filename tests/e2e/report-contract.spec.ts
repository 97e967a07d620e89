// The TypeScript mirrors of the core's JSON (web/shared/align-types.ts) held to the JSON the core
// really writes: `bodyspace align`'s report of a synthetic subject, field by field. Each list
// below must name exactly the keys of its TypeScript type (tsc refuses a missing or extra one), and
// the test fails when the core writes a field the type lacks or lacks one the type requires.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import type { DistanceStatsMm, FineReport, LandmarkPolicyReport, QualityReport, SubjectReport, ToTemplate, WarpReport } from '../../web/shared/align-types';
import { bodyspaceBinary, synthSubjects } from './synth';

/** Every key of `T`: `true` where the core always writes it, `false` where it may leave it out. */
type Keys<T> = { [K in keyof Required<T>]: boolean };

const subject: Keys<SubjectReport> = {
  landmarks: true,
  quality: true,
  to_template: true,
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
const landmarks: Keys<LandmarkPolicyReport> = { source: true, file: true, given: true, left_out: true, unjudged: true, estimated: true, used: true, estimate: false };
const quality: Keys<QualityReport> = {
  rms_mm: true,
  weighted_vertices: true,
  unmatched_vertices: true,
  unmatched_fraction: true,
  compared_triangles: true,
  folded_triangles: true,
  folded_fraction: true,
  suspicious_landmarks: true,
  flags: true,
  thresholds: true,
};
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

test('the TypeScript report types name exactly the fields the core writes', () => {
  test.setTimeout(180_000);
  const files = synthSubjects(1, 41);
  const dir = mkdtempSync(join(tmpdir(), 'bodyspace-contract-'));
  try {
    for (const f of files) writeFileSync(join(dir, f.name), f.bytes);
    const out = execFileSync(
      bodyspaceBinary(),
      ['align', '--scan', join(dir, 'scan_001.ply'), '--landmarks', join(dir, 'landmarks_001.lnd'), '--out', join(dir, 'fit.ply'), '--max-iterations', '20'],
      { encoding: 'utf8', maxBuffer: 64 << 20 },
    );
    const report = JSON.parse(out) as Record<string, Record<string, unknown>>;
    expectKeys('SubjectReport', report, subject);
    expectKeys('LandmarkPolicyReport', report.landmarks!, landmarks);
    expectKeys('QualityReport', report.quality!, quality);
    expectKeys('ToTemplate', report.to_template!, toTemplate);
    expectKeys('WarpReport', report.warp!, warp);
    expectKeys('FineReport', report.fine!, fine);
    expectKeys('DistanceStatsMm', report.fine!.scan_to_template as Record<string, unknown>, distance);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
