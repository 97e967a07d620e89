// Messages between the UI thread and the core worker. No DOM here: shared by both threads.
import type { ParsedLandmarks, ParsedScan } from './results';
import type { LoadedModel, ModelCsv, ReconstructedBody, ShapeCoefficients } from './shape-results';

/** Every request the worker understands, without its `id` (the client adds it). */
export type CoreRequestBody =
  | { type: 'version' }
  | { type: 'caesarNames' }
  /** `bytes` is transferred, not copied: the sender's buffer is detached afterwards. */
  | { type: 'parseScan'; bytes: ArrayBuffer; fileName: string }
  | { type: 'parseLandmarks'; bytes: ArrayBuffer; fileName: string }
  /** Shape models: the worker keeps one; a failed load or build leaves the previous one. */
  | { type: 'loadModel'; bytes: ArrayBuffer; fileName: string }
  /** `positions`: the subjects' bodies concatenated (template order, metres). */
  | { type: 'buildModel'; positions: Float32Array; names: string[]; variance: number }
  | { type: 'reconstruct'; coefficients: ShapeCoefficients }
  | { type: 'modelCsv'; kind: ModelCsv }
  | { type: 'modelGlb'; modes: number }
  | { type: 'modelFile' };

/** A request to the worker; `id` pairs it with its replies. */
export type CoreRequest = CoreRequestBody & { id: number };

/** What each request type resolves to. */
export interface CoreResults {
  version: string;
  caesarNames: string[];
  parseScan: ParsedScan;
  parseLandmarks: ParsedLandmarks;
  loadModel: LoadedModel;
  buildModel: LoadedModel;
  reconstruct: ReconstructedBody;
  modelCsv: string;
  modelGlb: Uint8Array;
  modelFile: Uint8Array;
}

/** The result type of a request body. */
export type ResultOf<R extends CoreRequestBody> = CoreResults[R['type']];

/** A reply from the worker: any number of `progress`, then one `result` or one `error`. */
export type CoreReply =
  | { id: number; type: 'result'; result: unknown }
  /** `fatal`: the core trapped (a WASM panic) and the worker must be replaced. */
  | { id: number; type: 'error'; message: string; fatal?: boolean }
  | { id: number; type: 'progress'; fraction: number; label: string };
