// What the worker returns about shape models. No DOM: shared by both threads.
import type { Bounds } from './bounds';

/** Segment names in the core's order (`template::Segment::ALL`). */
export const SEGMENTS = ['head', 'left_arm', 'right_arm', 'torso', 'left_leg', 'right_leg'] as const;
export type SegmentName = (typeof SEGMENTS)[number];

/** Quality curves of one part (Styner 2003), index m−1 for m modes. */
export interface QualityCurves {
  compactness: number[];
  generalization: number[];
  generalization_sd: number[];
  specificity: number[];
  specificity_sd: number[];
}

/** One of the seven models by name: the whole body or a segment. */
export type PartName = 'whole' | SegmentName;

/** One part of the model: `whole` or a segment. Variances in m². */
export interface ModelPart {
  name: PartName;
  vertex_count: number;
  variances: number[];
  all_variances: number[];
  quality: QualityCurves;
}

export interface ModelInfo {
  template: { name: string; hash: string; resolution: string; vertex_count: number };
  settings: { variance: number; max_modes: number | null; modes?: number | null; gpa: { pose: string } };
  subjects: string[];
  triangle_count: number;
  /** Whole body first, then the segments in `SEGMENTS` order. */
  parts: ModelPart[];
}

/** A model now held by the worker, shown at its own resolution. */
export interface LoadedModel {
  info: ModelInfo;
  triangles: Uint32Array;
  fileName: string;
  /** The measurements a target may name in each part's view (whole: all; a segment: those that act on its model). */
  targetable: Record<PartName, string[]>;
}

/** The resolution the body is shown at, with its triangles (`#F·3`). */
export interface ShownResolution {
  resolution: 'base' | 'fine';
  vertexCount: number;
  triangles: Uint32Array;
}

/** What "model as glTF" exports: the whole-body model, or it and the six segment models. */
export type ModelGlbParts = 'whole' | 'all';

/** Slider values in σ units; `segments[s] === null`: that segment follows the whole body. */
export interface ShapeCoefficients {
  whole: number[];
  segments: (number[] | null)[];
}

/** One measurement of the body (core `measure::Reading`): length and girth in m, volume in m³,
 * area in m²; `value` is `null` for a girth whose plane found no section. */
export interface Reading {
  name: string;
  label: string;
  kind: 'length' | 'girth' | 'volume' | 'area';
  value: number | null;
}

/** Every measurement, in the core's order (docs/measurements.md). */
export type Measurements = Reading[];

/** The value of the measurement `name` (`null` when missing or not taken). */
export function reading(m: Measurements, name: string): number | null {
  return m.find((r) => r.name === name)?.value ?? null;
}

export interface SeamReport {
  max_jump: number;
  segments: [string, string] | null;
  vertex: number | null;
}

/** The body shown, with its readings and what it cost in the worker. */
export interface ReconstructedBody {
  positions: Float32Array;
  normals: Float32Array;
  /** The positions' bounds, found in the worker (the page stands the body on the floor by them). */
  bounds: Bounds;
  /** `positionsChecksum` of the positions, made in the worker (tests and links compare bodies by it). */
  checksum: string;
  measurements: Measurements;
  seam: SeamReport;
  /** Core morph call in the worker (rank-1 updates or a full reconstruction), ms. */
  reconstructMs: number;
  /** Whether the core reconstructed from scratch, and how many rank-1 updates it applied. */
  rebuilt: boolean;
  deltas: number;
  /** Copy of the positions out of WASM memory, ms. */
  copyMs: number;
  /** Vertex normals (core) and their copy-out, ms. */
  normalsMs: number;
  /** Measurements + seam report, ms. */
  measureMs: number;
  /** Everything the worker did for this body (the above and the JSON), ms. */
  workerMs: number;
}

/** A body made for export (not the one shown). */
export interface ExportBody {
  positions: Float32Array;
  normals: Float32Array;
}

export type ModelCsv = 'eigenvalues' | 'scores' | 'quality';
