// What is loaded: the scan, its chosen units, and the landmarks. Derives what the view and the
// panels show; a failed load never touches it.
import { METRES_PER_UNIT, type MeshSummary, type ParsedLandmarks, type ParsedScan, type Units } from '../shared/results';

export class Session {
  scan: ParsedScan | null = null;
  /** The scan's units as the user chose them (the detected units until overridden). */
  scanUnits: Units = 'metres';
  landmarks: ParsedLandmarks | null = null;

  setScan(scan: ParsedScan): void {
    this.scan = scan;
    this.scanUnits = scan.summary.units_detected;
  }

  setLandmarks(landmarks: ParsedLandmarks): void {
    this.landmarks = landmarks;
  }

  /** Factor on the worker's positions (metres by the detected units) for the chosen units. */
  get scanScale(): number {
    if (!this.scan) return 1;
    return METRES_PER_UNIT[this.scanUnits] / this.scan.summary.scale_to_metres;
  }

  /** The scan's summary with its bounding box in metres under the chosen units. */
  get scanSummary(): MeshSummary | null {
    if (!this.scan) return null;
    const s = this.scan.summary;
    const k = this.scanScale;
    return {
      ...s,
      bbox_min: s.bbox_min.map((v) => v * k) as MeshSummary['bbox_min'],
      bbox_max: s.bbox_max.map((v) => v * k) as MeshSummary['bbox_max'],
    };
  }

  /**
   * Units of the landmark file: what the format fixes (`.lnd`: millimetres), else the scan's,
   * else a guess from the landmarks' own extent.
   */
  get landmarkUnits(): Units | null {
    const set = this.landmarks;
    if (!set) return null;
    if (set.units) return set.units;
    if (this.scan) return this.scanUnits;
    return set.detected_units;
  }

  /** Landmark positions in metres. */
  landmarkPositionsMetres(): Float32Array {
    const set = this.landmarks;
    if (!set) return new Float32Array();
    const k = METRES_PER_UNIT[this.landmarkUnits ?? 'metres'];
    return Float32Array.from(set.positions, (v) => v * k);
  }
}
