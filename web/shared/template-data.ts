// The generic template as the worker hands it to the page. No DOM here: shared by both threads.

export type TemplateResolution = 'base' | 'fine';

/** Segment names in the core's order (`template::Segment::ALL`): columns of `segmentWeights`. */
export const SEGMENT_NAMES = ['head', 'left arm', 'right arm', 'torso', 'left leg', 'right leg'] as const;

export interface TemplateData {
  resolution: TemplateResolution;
  /** `#V·3` metres, y up, feet on y = 0, facing +z. */
  positions: Float32Array;
  triangles: Uint32Array;
  normals: Float32Array;
  /** The 73 CAESAR landmarks in `.lnd` order, then the virtual ones. */
  landmarkNames: string[];
  /** `#L·3` metres. */
  landmarkPositions: Float32Array;
  /** How many of the landmarks (the last ones) are virtual. */
  virtualLandmarkCount: number;
  /** `#V·6` blend weights in `SEGMENT_NAMES` order; each row sums to 1. */
  segmentWeights: Float32Array;
  /** `#V` region flags (bits of the core's `template::RegionFlags`). */
  flags: Uint8Array;
}
