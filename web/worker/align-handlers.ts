// The RBF warp and the full alignment in the worker, both the core's one pipeline. Progress goes
// out after every iteration and the template's positions after every round (transferred), so a
// terminated worker loses nothing the page has not already got.
import { alignDefaults, alignScan, exportMesh, rbfWarp, ScanWithLandmarks } from '../pkg/bodyspace.js';
import type { AlignDefaults, AlignParams, AlignProgress, AlignReport, AlignResult, QualityReport, ScanInput, WarpResult } from '../shared/align-types';
import { boundsOf } from '../shared/bounds';
import { distanceHeat } from '../shared/heat-scale';
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

export function runAlign(
  scan: ScanInput,
  params: AlignParams,
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
    const normals = roundNormals(scan.resolution, positions);
    emit({ kind: 'alignRound', round, iteration: lastIteration, positions, normals, bounds: boundsOf(positions) }, [positions.buffer, normals.buffer]);
  };
  const t0 = performance.now();
  const outcome = withScan(scan, (input) => alignScan(templateHandle(scan.resolution), input, JSON.stringify(params), onProgress, onRound));
  try {
    const distances = outcome.distances();
    return {
      positions: outcome.positions(),
      normals: outcome.normals(),
      distances,
      heat: distanceHeat(distances),
      report: JSON.parse(outcome.reportJson()) as AlignReport,
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
