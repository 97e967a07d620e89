// What the core needs of the loaded scan for the warp and the alignment: copies in metres (the
// page keeps its own arrays for the view), sent afresh with every call so a restarted worker
// never lacks them.
import type { ScanInput, SubjectInput } from '../shared/align-types';
import type { TemplateResolution } from '../shared/template-data';
import type { Session } from './session';

/** The scan and the current landmark set of `session` in metres, or null until both are there. */
export function scanInput(session: Session, resolution: TemplateResolution): ScanInput | null {
  const set = session.edits?.placed();
  return set && set.names.length > 0 ? withLandmarks(session, resolution, set) : null;
}

/**
 * The subject for the core's one path (`align`): the scan, the landmarks a person gave or placed,
 * and the landmarks the estimate filled in with its report, so the core applies its landmark
 * policy to them as it does to the same files on the command line; null without a scan.
 */
export function subjectInput(session: Session, resolution: TemplateResolution): SubjectInput | null {
  const scan = session.scan;
  const edits = session.edits;
  if (!scan || !edits) return null;
  const k = session.scanScale;
  const given = edits.placed((state) => state === 'given' || state === 'edited');
  const estimated = edits.placed((state) => state === 'estimated');
  return {
    name: scan.fileName,
    resolution,
    positions: k === 1 ? scan.positions.slice() : Float32Array.from(scan.positions, (v) => v * k),
    triangles: scan.triangles.slice(),
    units: session.scanUnits,
    unitsDetected: session.scanUnits === scan.summary.units_detected,
    given: { ...given, file: session.landmarks?.fileName ?? '' },
    estimate: session.estimateReport && estimated.names.length > 0 ? { ...estimated, report: JSON.stringify(session.estimateReport) } : null,
  };
}

/** The buffers of a `subjectInput` to transfer (they are copies made for this call). */
export function subjectTransfer(input: SubjectInput): Transferable[] {
  const buffers: Transferable[] = [input.positions.buffer, input.triangles.buffer, input.given.positions.buffer];
  if (input.estimate) buffers.push(input.estimate.positions.buffer);
  return buffers;
}

/**
 * What the landmark estimate takes: the scan with the landmarks a person gave or placed (none,
 * or a partial set), which it keeps as they are; null without a scan.
 */
export function estimateInput(session: Session): ScanInput | null {
  const set = session.edits?.placed((state) => state === 'given' || state === 'edited') ?? { names: [], positions: new Float64Array() };
  return withLandmarks(session, 'base', set);
}

function withLandmarks(session: Session, resolution: TemplateResolution, set: { names: string[]; positions: Float64Array }): ScanInput | null {
  const scan = session.scan;
  if (!scan) return null;
  const k = session.scanScale;
  const positions = k === 1 ? scan.positions.slice() : Float32Array.from(scan.positions, (v) => v * k);
  return {
    resolution,
    positions,
    triangles: scan.triangles.slice(),
    landmarkNames: set.names,
    landmarkPositions: set.positions,
  };
}

/** The buffers of `input` to transfer (they are copies made for this call). */
export function scanTransfer(input: ScanInput): Transferable[] {
  return [input.positions.buffer, input.triangles.buffer, input.landmarkPositions.buffer];
}
