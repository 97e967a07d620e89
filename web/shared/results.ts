// What the core worker hands back. No DOM here: shared by both threads.

/** Length units the core recognises, and what one unit is in metres. */
export type Units = 'metres' | 'centimetres' | 'millimetres';
export const METRES_PER_UNIT: Record<Units, number> = { metres: 1, centimetres: 0.01, millimetres: 0.001 };

/** The core's mesh summary (`bodyspace::mesh::summary::MeshSummary`), bounding box in metres. */
export interface MeshSummary {
  vertices: number;
  triangles: number;
  bbox_min: [number, number, number];
  bbox_max: [number, number, number];
  units_detected: Units;
  scale_to_metres: number;
  boundary_loops: number;
  components: number;
  /** Which way the triangles face (`mesh::winding`): out of the body, into it, or mixed. */
  winding: Winding;
}

/** Which way a scan's triangles face (core `mesh::winding::Winding`). */
export type Winding = 'outward' | 'inward' | 'mixed';

/** Milliseconds spent in the worker, measured there. */
export interface WorkerTimings {
  /** The core call itself (read, normals, summary). */
  coreMs: number;
  /** Copying the arrays out of WASM memory and scaling positions to metres. */
  copyMs: number;
}

/** A scan as the worker returns it: flat arrays (transferred), positions already in metres. */
export interface ParsedScan {
  fileName: string;
  /** `#V·3` positions in metres (file units × `summary.scale_to_metres`), xyz interleaved. */
  positions: Float32Array;
  /** `#F·3` vertex indices. */
  triangles: Uint32Array;
  /** `#V·3` unit vertex normals. */
  normals: Float32Array;
  /** `#F` per triangle, which way its front faces (`mesh::winding::facings`): 1 out of the body, −1 into it, 0 not known. */
  triangleFacing: Int8Array;
  summary: MeshSummary;
  timings: WorkerTimings;
}

/** The landmark report against the 73 CAESAR landmarks (`LandmarkReport`). */
export interface LandmarkReport {
  found: string[];
  missing: string[];
  unknown: string[];
}

/** A landmark file as the worker returns it, positions in the file's units. */
export interface ParsedLandmarks {
  fileName: string;
  names: string[];
  /** `#L·3` positions in the file's units, xyz interleaved. */
  positions: number[];
  /** Units the file format fixes (CAESAR `.lnd`: millimetres), or null to follow the scan. */
  units: Units | null;
  /** The units the landmarks' own extent suggests (the core's rule for scans). */
  detected_units: Units;
  report: LandmarkReport;
}

/**
 * The subjects among files given together (`pairSubjectFiles`, the core's
 * `io/subject_files.rs`): every number indexes the file names given. `duplicates`: further scans
 * of a listed subject (`kept`: the scan kept); `not_scans`: meshes that are not scans of a body;
 * `unpaired`: files of no subject.
 */
export interface SubjectPairing {
  subjects: { subject: string; scan: number; landmarks: number | null }[];
  duplicates: { file: number; kept: number }[];
  not_scans: number[];
  unpaired: number[];
}
