// What the core needs of the loaded scan for the warp and the alignment: copies in metres (the
// page keeps its own arrays for the view), sent afresh with every call so a restarted worker
// never lacks them.
import type { ScanInput } from '../shared/align-types';
import type { TemplateResolution } from '../shared/template-data';
import type { Session } from './session';

/** The scan and the current landmark set of `session` in metres, or null until both are there. */
export function scanInput(session: Session, resolution: TemplateResolution): ScanInput | null {
  const scan = session.scan;
  const set = session.edits?.placed();
  if (!scan || !set || set.names.length === 0) return null;
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
