// Downloads of the shape-space panel: the body shown (PLY, OBJ, GLB), bodies along a mode, the
// model as GLB with morph targets (whole body, or all seven models), the model file, the model in
// view as statismo HDF5, CSVs.
import type { CoreClient } from '../client/core-client';
import type { ModelCsv, ModelGlbParts } from '../shared/shape-results';
import { download } from '../ui/download';
import type { ErrorBanner } from '../ui/error-banner';
import type { ShapePanel } from '../ui/shape-panel';
import { bodiesGlb } from '../view/gltf-export';
import type { ShapeModel } from './shape-model';
import type { ShapeSliders } from './shape-sliders';
import type { ShownBody } from './shown-body';

export type BodyFormat = 'ply' | 'obj' | 'glb';

export class ShapeExports {
  constructor(
    private readonly client: CoreClient<'core'>,
    private readonly model: ShapeModel,
    private readonly shown: ShownBody,
    private readonly sliders: ShapeSliders,
    private readonly panel: ShapePanel,
    private readonly banner: ErrorBanner,
  ) {}

  async csv(kind: ModelCsv): Promise<void> {
    const text = await this.client.call({ type: 'modelCsv', kind });
    download(`${kind}.csv`, text, 'text/csv');
  }

  /** The body shown, at the resolution shown (its own triangles); PLY and OBJ by the core's writers. */
  async body(format: BodyFormat): Promise<void> {
    const { body: shown, triangles } = this.shown;
    if (!shown || !triangles) return;
    if (format === 'ply' || format === 'obj') {
      const bytes = await this.client.call({ type: 'exportMesh', positions: shown.positions.slice(), triangles: triangles.slice(), format });
      download(`body.${format}`, bytes, format === 'obj' ? 'text/plain' : 'application/octet-stream');
    } else download('body.glb', await bodiesGlb([{ name: 'body', positions: shown.positions, normals: shown.normals, triangles }]), 'model/gltf-binary');
  }

  /** One GLB with a body per σ step along whole-body mode `mode` (other values as they are). */
  async alongMode(mode: number, steps: number[]): Promise<void> {
    const triangles = this.shown.triangles;
    if (!this.model.loaded || !triangles || steps.length === 0) return;
    const coefficients = this.sliders.values;
    const bodies = [];
    for (const t of steps) {
      const c = structuredClone(coefficients);
      c.whole[mode] = t;
      const made = await this.client.call({ type: 'reconstruct', coefficients: c });
      bodies.push({ name: `mode${mode + 1}_${t >= 0 ? '+' : ''}${t}sd`, positions: made.positions, normals: made.normals, triangles });
    }
    download(`mode${mode + 1}.glb`, await bodiesGlb(bodies, 0.7), 'model/gltf-binary');
  }

  /** The model as GLB with its modes as morph targets: the whole body, or all seven models. */
  async modelGlb(parts: ModelGlbParts): Promise<void> {
    const model = this.model.loaded;
    if (!model) return;
    const modes = Math.max(...model.info.parts.map((p) => p.variances.length));
    const glb = await this.client.call({ type: 'modelGlb', modes, parts });
    download(parts === 'all' ? 'shape-model-segments.glb' : 'shape-model.glb', glb, 'model/gltf-binary');
  }

  async modelFile(): Promise<void> {
    if (!this.model.loaded) return;
    const bytes = await this.client.call({ type: 'modelFile' });
    download('shape-model.bsm', bytes);
  }

  /** The model in view — the whole body, or the segment picked — as statismo HDF5 (`shape-model.h5`, `shape-model-head.h5`, …). */
  async modelStatismo(): Promise<void> {
    if (!this.model.loaded) return;
    const part = this.panel.currentView;
    try {
      const bytes = await this.client.call({ type: 'modelStatismo', part });
      download(part === 'whole' ? 'shape-model.h5' : `shape-model-${part}.h5`, bytes, 'application/x-hdf5');
    } catch (error) {
      this.banner.show([`The statismo file could not be written: ${error instanceof Error ? error.message : String(error)}`]);
    }
  }
}
