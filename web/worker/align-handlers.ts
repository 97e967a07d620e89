// The RBF warp and the core's one path from a subject to a checked fit, in the worker. Progress
// goes out after every iteration and the template's positions after every round (transferred),
// so a terminated worker loses nothing the page has not already got.
import { alignDefaults, exportMesh, fitSubject, fitSubjectFiles, rbfWarp, ScanWithLandmarks, SubjectScan, type AlignOutcome } from '../pkg/bodyspace.js';
import type { AlignDefaults, AlignParams, AlignProgress, AlignReport, AlignResult, FileBytes, QualityReport, ScanInput, SubjectInput, SubjectOptions, SubjectReport, WarpResult } from '../shared/align-types';
import { boundsOf } from '../shared/bounds';
import { distanceHeat } from '../shared/heat-scale';
import type { TemplateResolution } from '../shared/template-data';
import type { CoreEvent } from '../shared/messages';
import { templateHandle } from './template-handlers';

export function runAlignDefaults(): AlignDefaults {
  return JSON.parse(alignDefaults()) as AlignDefaults;
}

export function runRbfWarp(scan: ScanInput, params: AlignParams): WarpResult {
  const t0 = performance.now();
  const outcome = withScan(scan, (input) => rbfWarp(templateHandle(scan.resolution), input, JSON.stringify(params)));
  try {
    return {
      positions: outcome.positions(),
      normals: outcome.normals(),
      report: (JSON.parse(outcome.reportJson()) as AlignReport).warp,
      workerMs: performance.now() - t0,
    };
  } finally {
    outcome.free();
  }
}

/** The page's subject through the core's one path (`fitSubject`). */
export function runAlign(
  subject: SubjectInput,
  options: SubjectOptions,
  emit: (event: CoreEvent, transfer?: Transferable[]) => void,
): Omit<AlignResult, 'wasmMemoryBytes'> {
  let lastIteration = 0;
  const onProgress = (progress: AlignProgress): boolean => {
    lastIteration = progress.iteration;
    emit({ kind: 'alignProgress', ...progress });
    return true;
  };
  // The round's normals and bounds are made here, so the page's part of a round does not grow
  // with the template (it hands the arrays to the view).
  const onRound = (_stage: string, round: number, positions: Float32Array): void => {
    const normals = roundNormals(subject.resolution, positions);
    emit({ kind: 'alignRound', round, iteration: lastIteration, positions, normals, bounds: boundsOf(positions) }, [positions.buffer, normals.buffer]);
  };
  const t0 = performance.now();
  const scan = new SubjectScan(subject.name, subject.positions, subject.triangles, subject.units, subject.unitsDetected);
  try {
    scan.setGiven(subject.given.names.join('\n'), subject.given.positions, subject.given.file);
    if (subject.estimate) scan.setEstimate(subject.estimate.names.join('\n'), subject.estimate.positions, subject.estimate.report);
    return result(fitSubject(templateHandle(subject.resolution), scan, JSON.stringify(options), onProgress, onRound), t0);
  } finally {
    scan.free();
  }
}

/** A subject's files through the same path (`fitSubjectFiles`): the batch's job. */
export function runAlignFiles(
  scan: FileBytes,
  landmarks: FileBytes | null,
  resolution: TemplateResolution,
  options: SubjectOptions,
  emit: (event: CoreEvent) => void,
): Omit<AlignResult, 'wasmMemoryBytes'> {
  const onProgress = (progress: AlignProgress): boolean => {
    emit({ kind: 'alignProgress', ...progress });
    return true;
  };
  const t0 = performance.now();
  const outcome = fitSubjectFiles(
    templateHandle(resolution),
    new Uint8Array(scan.bytes),
    scan.name,
    landmarks ? new Uint8Array(landmarks.bytes) : undefined,
    landmarks?.name,
    JSON.stringify(options),
    onProgress,
  );
  return result(outcome, t0);
}

function result(outcome: AlignOutcome, t0: number): Omit<AlignResult, 'wasmMemoryBytes'> {
  try {
    const distances = outcome.distances();
    return {
      positions: outcome.positions(),
      normals: outcome.normals(),
      distances,
      heat: distanceHeat(distances),
      report: JSON.parse(outcome.reportJson()) as SubjectReport,
      quality: JSON.parse(outcome.qualityJson()) as QualityReport,
      workerMs: performance.now() - t0,
    };
  } finally {
    outcome.free();
  }
}

/** Vertex normals of a round's `positions` over the template they are of (the base template's during a fine template's first stage, if sent at its size). */
function roundNormals(resolution: ScanInput['resolution'], positions: Float32Array): Float32Array {
  const handle = templateHandle(resolution);
  if (positions.length === 3 * handle.vertexCount || resolution === 'base') return handle.normalsOf(positions);
  return templateHandle('base').normalsOf(positions);
}

/** Runs `f` on the scan and its landmarks copied into the core, freeing the copy afterwards. */
export function withScan<T>(scan: ScanInput, f: (input: ScanWithLandmarks) => T): T {
  const input = new ScanWithLandmarks(scan.positions, scan.triangles, scan.landmarkNames.join('\n'), scan.landmarkPositions);
  try {
    return f(input);
  } finally {
    input.free();
  }
}

export function runExport(positions: Float32Array, triangles: Uint32Array, format: 'ply' | 'obj'): Uint8Array {
  return exportMesh(positions, triangles, format);
}
