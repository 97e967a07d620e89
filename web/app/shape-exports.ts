// Downloads of the shape-space panel: the body shown (PLY, OBJ, GLB), bodies along a mode, the
// model as GLB with morph targets (whole body, or all seven models), the model file, the model in
// view as statismo HDF5, CSVs.
import type { CoreClient } from '../client/core-client';
import type { LoadedModel, ModelCsv, ModelGlbParts, PartName, ReconstructedBody, ShapeCoefficients } from '../shared/shape-results';
import { download } from '../ui/download';
import { bodiesGlb } from '../view/gltf-export';

export type BodyFormat = 'ply' | 'obj' | 'glb';

export async function csv(client: CoreClient<'core'>, kind: ModelCsv): Promise<void> {
  const text = await client.call({ type: 'modelCsv', kind });
  download(`${kind}.csv`, text, 'text/csv');
}

/** The body shown, at the resolution shown (`triangles` are its own); PLY and OBJ by the core's writers. */
export async function body(client: CoreClient<'core'>, shown: ReconstructedBody, triangles: Uint32Array, format: BodyFormat): Promise<void> {
  if (format === 'ply' || format === 'obj') {
    const bytes = await client.call({ type: 'exportMesh', positions: shown.positions.slice(), triangles: triangles.slice(), format });
    download(`body.${format}`, bytes, format === 'obj' ? 'text/plain' : 'application/octet-stream');
  } else download('body.glb', await bodiesGlb([{ name: 'body', positions: shown.positions, normals: shown.normals, triangles }]), 'model/gltf-binary');
}

/** One GLB with a body per σ step along whole-body mode `mode` (other values as they are). */
export async function alongMode(client: CoreClient<'core'>, coefficients: ShapeCoefficients, triangles: Uint32Array, mode: number, steps: number[]): Promise<void> {
  if (steps.length === 0) return;
  const bodies = [];
  for (const t of steps) {
    const c = structuredClone(coefficients);
    c.whole[mode] = t;
    const made = await client.call({ type: 'reconstruct', coefficients: c });
    bodies.push({ name: `mode${mode + 1}_${t >= 0 ? '+' : ''}${t}sd`, positions: made.positions, normals: made.normals, triangles });
  }
  download(`mode${mode + 1}.glb`, await bodiesGlb(bodies, 0.7), 'model/gltf-binary');
}

/** The model as GLB with its modes as morph targets: the whole body, or all seven models. */
export async function modelGlb(client: CoreClient<'core'>, model: LoadedModel, parts: ModelGlbParts): Promise<void> {
  const modes = Math.max(...model.info.parts.map((p) => p.variances.length));
  const glb = await client.call({ type: 'modelGlb', modes, parts });
  download(parts === 'all' ? 'shape-model-segments.glb' : 'shape-model.glb', glb, 'model/gltf-binary');
}

export async function modelFile(client: CoreClient<'core'>): Promise<void> {
  const bytes = await client.call({ type: 'modelFile' });
  download('shape-model.bsm', bytes);
}

/** The whole body or one segment as a statismo HDF5 file (`shape-model.h5`, `shape-model-head.h5`, …). */
export async function modelStatismo(client: CoreClient<'core'>, part: PartName): Promise<void> {
  const bytes = await client.call({ type: 'modelStatismo', part });
  download(part === 'whole' ? 'shape-model.h5' : `shape-model-${part}.h5`, bytes, 'application/x-hdf5');
}
