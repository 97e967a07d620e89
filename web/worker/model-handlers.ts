// Shape-model requests of the core worker: keeps the one loaded ShapeSpace, which holds the body
// shown; morphs it (rank-1 updates per slider move, a full rebuild when asked), switches it to
// the fine template, measures it, and exports CSV / GLB / the model file / statismo HDF5.
import { buildShapeModel, loadShapeModel, loadStatismoModel, manikinDefaultsJson, type ModelPopulation, type ShapeSpace } from '../pkg/bodyspace.js';
import { boundsOf } from '../shared/bounds';
import { positionsChecksum } from '../shared/checksum';
import type {
  ExportBody,
  LoadedModel,
  ModelCsv,
  ModelGlbParts,
  ModelInfo,
  PartName,
  ReconstructedBody,
  ShapeCoefficients,
  ShownResolution,
} from '../shared/shape-results';
import type { TemplateResolution } from '../shared/template-data';
import type { FoundBody, ManikinDefaults, ManikinSet, MeasurementDistribution, Targets, TargetTolerances } from '../shared/anthropometry';
import { isHdf5, readStatismoH5, writeStatismoH5 } from './statismo-h5';
import { templateHandle } from './template-handlers';

let space: ShapeSpace | null = null;
/** The measurement distributions of `space`'s model, once computed (boundary manikins need them). */
let population: ModelPopulation | null = null;

/** Replaces the held model only once the new one is read: a failure leaves the old one. */
function hold(next: ShapeSpace, fileName: string): LoadedModel {
  const info = JSON.parse(next.infoJson()) as ModelInfo;
  const triangles = next.triangles();
  const targetable = JSON.parse(next.targetableJson()) as LoadedModel['targetable'];
  space?.free();
  space = next;
  population?.free();
  population = null;
  return { info, triangles, fileName, targetable };
}

function current(): ShapeSpace {
  if (!space) throw new Error('no shape model is loaded');
  return space;
}

/** A `.bsm` model file, or a statismo HDF5 model (told apart by the HDF5 signature). */
export async function loadModel(bytes: ArrayBuffer, fileName: string): Promise<LoadedModel> {
  const view = new Uint8Array(bytes);
  if (!isHdf5(view)) return hold(loadShapeModel(view, fileName), fileName);
  const arrays = await readStatismoH5(view, fileName);
  try {
    return hold(loadStatismoModel(arrays, fileName), fileName);
  } finally {
    arrays.free();
  }
}

export function buildModel(positions: Float32Array, names: string[], variance: number): LoadedModel {
  const built = buildShapeModel(positions, names.length, JSON.stringify(names), variance, true);
  return hold(built, `model of ${names.length} subjects`);
}

/** Flattens slider values into what `ShapeSpace.morph` / `reconstruct` take. */
function flat(c: ShapeCoefficients): [Float64Array, Float64Array, Int32Array] {
  const counts = new Int32Array(6).fill(-1);
  const values: number[] = [];
  c.segments.slice(0, 6).forEach((s, i) => {
    if (s) {
      counts[i] = s.length;
      values.push(...s);
    }
  });
  return [Float64Array.from(c.whole), Float64Array.from(values), counts];
}

/** Moves the body shown: the core keeps it, so a slider move is a rank-1 update. */
export function morph(c: ShapeCoefficients, rebuild: boolean): ReconstructedBody {
  const model = current();
  const start = performance.now();
  const [whole, segments, counts] = flat(c);
  const t0 = performance.now();
  const update = JSON.parse(model.morph(whole, segments, counts, rebuild)) as { rebuilt: boolean; deltas: number };
  const t1 = performance.now();
  const positions = model.positions();
  const t2 = performance.now();
  const normals = model.normals();
  const t3 = performance.now();
  const bounds = boundsOf(positions);
  const checksum = positionsChecksum(positions);
  const measurements = JSON.parse(model.measureJson()) as ReconstructedBody['measurements'];
  const seam = JSON.parse(model.seamJson()) as ReconstructedBody['seam'];
  const t4 = performance.now();
  return {
    positions,
    normals,
    bounds,
    checksum,
    measurements,
    seam,
    reconstructMs: t1 - t0,
    rebuilt: update.rebuilt,
    deltas: update.deltas,
    copyMs: t2 - t1,
    normalsMs: t3 - t2,
    measureMs: t4 - t3,
    workerMs: performance.now() - start,
  };
}

/** A body for export at the shown resolution, leaving the body shown as it is. */
export function reconstruct(c: ShapeCoefficients): ExportBody {
  const [whole, segments, counts] = flat(c);
  const model = current();
  const positions = model.reconstruct(whole, segments, counts);
  return { positions, normals: model.normalsOf(positions) };
}

/**
 * Shows the body at `resolution`. The fine template is the worker's cached one (built on first
 * use, shared with the template view); mapping the model reports its fraction done.
 */
export function useResolution(
  resolution: TemplateResolution,
  progress: (fraction: number, label: string) => void,
): ShownResolution {
  const model = current();
  const label = 'Mapping the model to the fine template';
  if (resolution === 'fine') progress(0, 'Building the fine template');
  const template = templateHandle(resolution === 'fine' ? 'fine' : 'base');
  model.useResolution(resolution, template, (f: number) => progress(0.2 + 0.8 * f, label));
  return { resolution: model.resolution as 'base' | 'fine', vertexCount: model.vertexCount, triangles: model.triangles() };
}

/**
 * The most likely body with `targets` (m, m³, m²): of the whole-body model, or of the segment
 * `part`'s model with the rest of the body shown held. The body shown is not touched.
 */
export function bodyFromMeasurements(targets: Targets, part: PartName): FoundBody {
  const model = current();
  const start = performance.now();
  const found = JSON.parse(model.bodyFromMeasurementsJson(JSON.stringify(targets), part)) as Omit<FoundBody, 'tolerances' | 'workerMs'>;
  const workerMs = performance.now() - start;
  return { ...found, tolerances: JSON.parse(model.targetTolerancesJson()) as TargetTolerances, workerMs };
}

/** Every measurement over the model's training subjects and sampled bodies (core defaults: count, seed). */
export function measurementDistribution(progress: (fraction: number, label: string) => void): MeasurementDistribution {
  const start = performance.now();
  const label = 'Measuring the training subjects and sampled bodies';
  const next = current().measurePopulation((f: number) => progress(f, label));
  population?.free();
  population = next;
  const d = JSON.parse(next.json()) as Omit<MeasurementDistribution, 'workerMs'>;
  return { ...d, workerMs: performance.now() - start };
}

/** The boundary manikins of `names` at `coverage` of the population measured before. */
export function boundaryManikins(names: string[], coverage: number, progress: (fraction: number, label: string) => void): ManikinSet {
  if (!population) throw new Error('the population of this model has not been measured yet');
  const start = performance.now();
  const label = `Finding the boundary manikins of ${names.join(', ')}`;
  const found = JSON.parse(population.boundaryManikinsJson(current(), JSON.stringify(names), coverage, (f: number) => progress(f, label))) as Omit<ManikinSet, 'workerMs'>;
  return { ...found, workerMs: performance.now() - start };
}

/** The core's defaults of boundary manikins. */
export function manikinDefaults(): ManikinDefaults {
  return JSON.parse(manikinDefaultsJson()) as ManikinDefaults;
}

export function modelCsv(kind: ModelCsv): string {
  const model = current();
  if (kind === 'eigenvalues') return model.eigenvaluesCsv();
  if (kind === 'scores') return model.scoresCsv();
  return model.qualityCsv();
}

export function modelGlb(modes: number, parts: ModelGlbParts): Uint8Array {
  return parts === 'all' ? current().partsGlb(modes) : current().modelGlb(modes);
}

export function modelFile(): Uint8Array {
  return current().fileBytes();
}

/** The loaded model's `part` (whole body or one segment) as a statismo HDF5 file. */
export async function modelStatismo(part: PartName): Promise<Uint8Array> {
  const arrays = current().statismoArrays(part);
  try {
    return await writeStatismoH5(arrays);
  } finally {
    arrays.free();
  }
}
