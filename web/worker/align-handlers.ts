// The RBF warp and the full alignment in the worker. Progress goes out after every iteration and
// the template's positions after every round (transferred), so a terminated worker loses nothing
// the page has not already got.
import { alignScan, exportMesh, rbfWarp } from '../pkg/bodyspace.js';
import type { AlignResult, AlignStage, FineSettings, RbfSettings, ScanInput, WarpReport, WarpResult } from '../shared/align-types';
import type { CoreEvent } from '../shared/messages';
import { templateHandle } from './template-handlers';

export function runRbfWarp(scan: ScanInput, settings: RbfSettings): WarpResult {
  const t0 = performance.now();
  const outcome = rbfWarp(
    templateHandle(scan.resolution),
    scan.positions,
    scan.triangles,
    scan.landmarkNames.join('\n'),
    scan.landmarkPositions,
    JSON.stringify(settings),
  );
  try {
    return {
      positions: outcome.positions(),
      normals: outcome.normals(),
      report: JSON.parse(outcome.reportJson()) as WarpReport,
      workerMs: performance.now() - t0,
    };
  } finally {
    outcome.free();
  }
}

export function runAlign(
  scan: ScanInput,
  rbf: RbfSettings,
  fine: FineSettings,
  emit: (event: CoreEvent, transfer?: Transferable[]) => void,
): AlignResult {
  let lastIteration = 0;
  const onProgress = (
    iteration: number,
    round: number,
    energy: number,
    dataError: number,
    smoothnessError: number,
    rmsMetres: number,
    elapsedMs: number,
    stage: AlignStage,
    maxIterations: number,
  ): boolean => {
    lastIteration = iteration;
    emit({ kind: 'alignProgress', iteration, round, energy, dataError, smoothnessError, rmsMetres, elapsedMs, stage, maxIterations });
    return true;
  };
  const onRound = (round: number, positions: Float32Array): void => {
    emit({ kind: 'alignRound', round, iteration: lastIteration, positions }, [positions.buffer]);
  };
  const t0 = performance.now();
  const outcome = alignScan(
    templateHandle(scan.resolution),
    scan.positions,
    scan.triangles,
    scan.landmarkNames.join('\n'),
    scan.landmarkPositions,
    JSON.stringify(rbf),
    JSON.stringify(fine),
    onProgress,
    onRound,
  );
  try {
    return {
      positions: outcome.positions(),
      normals: outcome.normals(),
      distances: outcome.distances(),
      report: JSON.parse(outcome.reportJson()) as AlignResult['report'],
      workerMs: performance.now() - t0,
    };
  } finally {
    outcome.free();
  }
}

export function runExport(positions: Float32Array, triangles: Uint32Array, format: 'ply' | 'obj'): Uint8Array {
  return exportMesh(positions, triangles, format);
}
