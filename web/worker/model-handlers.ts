// Shape-model requests of the core worker: keeps the one loaded ShapeSpace, reconstructs stitched
// bodies from slider values, measures them, and exports CSV / GLB / the model file.
import { buildShapeModel, loadShapeModel, type ShapeSpace } from '../pkg/bodyspace.js';
import type { LoadedModel, ModelCsv, ModelInfo, ReconstructedBody, ShapeCoefficients } from '../shared/shape-results';
import { vertexNormals } from '../shared/vertex-normals';

let space: ShapeSpace | null = null;
let triangles: Uint32Array | null = null;

/** Replaces the held model only once the new one is read: a failure leaves the old one. */
function hold(next: ShapeSpace, fileName: string): LoadedModel {
  const info = JSON.parse(next.infoJson()) as ModelInfo;
  const tris = next.triangles();
  space?.free();
  space = next;
  triangles = tris;
  return { info, triangles: tris.slice(), fileName };
}

function current(): ShapeSpace {
  if (!space) throw new Error('no shape model is loaded');
  return space;
}

export function loadModel(bytes: ArrayBuffer, fileName: string): LoadedModel {
  return hold(loadShapeModel(new Uint8Array(bytes), fileName), fileName);
}

export function buildModel(positions: Float32Array, names: string[], variance: number): LoadedModel {
  const built = buildShapeModel(positions, names.length, JSON.stringify(names), variance, true);
  return hold(built, `model of ${names.length} subjects`);
}

/** Flattens slider values into what `ShapeSpace.reconstruct` takes. */
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

export function reconstruct(c: ShapeCoefficients): ReconstructedBody {
  const model = current();
  const [whole, segments, counts] = flat(c);
  const t0 = performance.now();
  const positions = model.reconstruct(whole, segments, counts);
  const t1 = performance.now();
  const measurements = JSON.parse(model.measureJson()) as ReconstructedBody['measurements'];
  const seam = JSON.parse(model.seamJson(whole, segments, counts)) as ReconstructedBody['seam'];
  const t2 = performance.now();
  return {
    positions,
    normals: vertexNormals(positions, triangles!),
    measurements,
    seam,
    reconstructMs: t1 - t0,
    measureMs: t2 - t1,
  };
}

export function modelCsv(kind: ModelCsv): string {
  const model = current();
  if (kind === 'eigenvalues') return model.eigenvaluesCsv();
  if (kind === 'scores') return model.scoresCsv();
  return model.qualityCsv();
}

export function modelGlb(modes: number): Uint8Array {
  return current().modelGlb(modes);
}

export function modelFile(): Uint8Array {
  return current().fileBytes();
}
