// Messages between the UI thread and the core worker. No DOM here: shared by both threads.
import type { Bounds } from './bounds';
import type { AlignDefaults, AlignParams, AlignProgress, AlignResult, FileBytes, ScanInput, SubjectInput, SubjectOptions, WarpResult } from './align-types';
import type { LandmarkEstimate, LandmarkPrediction, SuspiciousLandmark } from './landmark-entry';
import type { Orientation } from './orientation';
import type { ParsedLandmarks, ParsedScan, SubjectPairing } from './results';
import type { TemplateData, TemplateResolution } from './template-data';
import type { FoundBody, ManikinDefaults, ManikinSet, MeasurementDistribution, Targets } from './anthropometry';
import type { ExportBody, LoadedModel, ModelCsv, ModelGlbParts, PartName, ReconstructedBody, ShapeCoefficients, ShownResolution } from './shape-results';

/** Every request the worker understands, without its `id` (the client adds it). */
export type CoreRequestBody =
  | { type: 'version' }
  | { type: 'caesarNames' }
  /** `bytes` is transferred, not copied: the sender's buffer is detached afterwards. */
  | { type: 'parseScan'; bytes: ArrayBuffer; fileName: string }
  | { type: 'parseLandmarks'; bytes: ArrayBuffer; fileName: string }
  /** Which of `fileNames` make one subject: the batch's pairing rule (`io/subject_files.rs`). */
  | { type: 'pairSubjectFiles'; fileNames: string[] }
  | { type: 'loadTemplate'; resolution: TemplateResolution }
  /** The core's alignment parameters with their defaults. */
  | { type: 'alignDefaults' }
  | { type: 'rbfWarp'; scan: ScanInput; params: AlignParams }
  /**
   * The core's one path from a subject to a checked fit (landmark policy, RBF warp, fine
   * alignment, quality check, frame); replies with `alignProgress` and `alignRound` events.
   */
  | { type: 'align'; subject: SubjectInput; options: SubjectOptions }
  /** The same path on a subject's files (the batch): `bytes` are transferred. */
  | { type: 'alignFiles'; scan: FileBytes; landmarks: FileBytes | null; resolution: TemplateResolution; options: SubjectOptions }
  /**
   * The 73 CAESAR landmarks of a scan with a partial or empty set (kept as given), in the frame a
   * person stated (`orientation`; null: the core finds it); replies with progress.
   */
  | { type: 'estimateLandmarks'; scan: ScanInput; orientation: Orientation | null }
  /** The suspicious landmarks of a set (`positions` `#names·3`, metres) against an estimate's prediction. */
  | { type: 'checkLandmarks'; names: string[]; positions: Float64Array; prediction: LandmarkPrediction }
  | { type: 'exportMesh'; positions: Float32Array; triangles: Uint32Array; format: 'ply' | 'obj' }
  /**
   * A landmark set as a file by the core's writer of `format`: `names` with `positions` (`#L·3`,
   * written as given; all three NaN for an absent landmark).
   */
  | { type: 'writeLandmarks'; names: string[]; positions: Float64Array; format: 'lnd' | 'csv' | 'json'; subjectId: string }
  /**
   * Shape models: the worker keeps one; a failed load or build leaves the previous one. `bytes`
   * is a `.bsm` model file or a statismo HDF5 model made on the template.
   */
  | { type: 'loadModel'; bytes: ArrayBuffer; fileName: string }
  /** `positions`: the subjects' bodies concatenated (template order, metres). */
  | { type: 'buildModel'; positions: Float32Array; names: string[]; variance: number }
  /**
   * Moves the body shown to `coefficients`: rank-1 updates of the held body for the changed
   * values, or a full reconstruction when `rebuild` (reset, random body, link, new model).
   */
  | { type: 'morph'; coefficients: ShapeCoefficients; rebuild: boolean }
  /** A body for export at the shown resolution; the body shown is not touched. */
  | { type: 'reconstruct'; coefficients: ShapeCoefficients }
  /** Shows the body at `resolution` (maps the model to fine on first use, with progress). */
  | { type: 'shapeResolution'; resolution: TemplateResolution }
  /**
   * The most likely body of the loaded model with `targets` (m, m³, m²): of the whole-body model,
   * or of segment `part`'s with the rest of the body shown held; nothing shown changes.
   */
  | { type: 'bodyFromMeasurements'; targets: Targets; part: PartName }
  /** Every measurement over the training subjects and bodies sampled from the loaded model; replies with progress. */
  | { type: 'measurementDistribution' }
  /** The boundary manikins of 2–4 measurements at `coverage` (a share) of the population measured before; replies with progress. */
  | { type: 'boundaryManikins'; names: string[]; coverage: number }
  | { type: 'manikinDefaults' }
  | { type: 'modelCsv'; kind: ModelCsv }
  | { type: 'modelGlb'; modes: number; parts: ModelGlbParts }
  | { type: 'modelFile' }
  /** The loaded model's whole body or one segment as a statismo HDF5 file (millimetres). */
  | { type: 'modelStatismo'; part: PartName }
  /** Traps the core as a bug would (the crash-recovery test); never resolves with a result. */
  | { type: 'trap' };

/** A request to the worker; `id` pairs it with its replies. */
export type CoreRequest = CoreRequestBody & { id: number };

/** What each request type resolves to. */
export interface CoreResults {
  version: string;
  caesarNames: string[];
  parseScan: ParsedScan;
  parseLandmarks: ParsedLandmarks;
  pairSubjectFiles: SubjectPairing;
  loadTemplate: TemplateData;
  alignDefaults: AlignDefaults;
  rbfWarp: WarpResult;
  align: AlignResult;
  alignFiles: AlignResult;
  estimateLandmarks: LandmarkEstimate;
  checkLandmarks: SuspiciousLandmark[];
  exportMesh: Uint8Array;
  writeLandmarks: Uint8Array;
  loadModel: LoadedModel;
  buildModel: LoadedModel;
  morph: ReconstructedBody;
  reconstruct: ExportBody;
  shapeResolution: ShownResolution;
  bodyFromMeasurements: FoundBody;
  measurementDistribution: MeasurementDistribution;
  boundaryManikins: ManikinSet;
  manikinDefaults: ManikinDefaults;
  modelCsv: string;
  modelGlb: Uint8Array;
  modelFile: Uint8Array;
  modelStatismo: Uint8Array;
  trap: never;
}

/** The result type of a request body. */
export type ResultOf<R extends CoreRequestBody> = CoreResults[R['type']];

/** Events a long call sends before its result. */
export type CoreEvent =
  | ({ kind: 'alignProgress' } & AlignProgress)
  /**
   * The template's current positions (metres, scan frame) at the start of a round, with their
   * vertex normals and bounds, made in the worker so the page only hands them to the view.
   */
  | { kind: 'alignRound'; round: number; iteration: number; positions: Float32Array; normals: Float32Array; bounds: Bounds };

/** A reply from the worker: any number of `progress` / `event`, then one `result` or one `error`. */
export type CoreReply =
  | { id: number; type: 'result'; result: unknown }
  /** `fatal`: the core trapped (a WASM panic) and the worker must be replaced. */
  | { id: number; type: 'error'; message: string; fatal?: boolean }
  | { id: number; type: 'progress'; fraction: number; label: string }
  | { id: number; type: 'event'; event: CoreEvent };
