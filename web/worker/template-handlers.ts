// The template in the worker: loaded once per resolution and kept, since the fine one is large.
import { loadTemplate, type TemplateHandle } from '../pkg/bodyspace.js';
import type { TemplateData, TemplateResolution } from '../shared/template-data';

const handles = new Map<TemplateResolution, TemplateHandle>();

/** The core's template at `resolution`, built on first use. */
export function templateHandle(resolution: TemplateResolution): TemplateHandle {
  let handle = handles.get(resolution);
  if (!handle) {
    handle = loadTemplate(resolution);
    handles.set(resolution, handle);
  }
  return handle;
}

/** The template's arrays for the page (copies out of WASM memory, ready to transfer). */
export function templateData(resolution: TemplateResolution): TemplateData {
  const t = templateHandle(resolution);
  return {
    resolution,
    positions: t.positions(),
    triangles: t.triangles(),
    normals: t.normals(),
    landmarkNames: t.landmarkNames().split('\n'),
    landmarkPositions: t.landmarkPositions(),
    virtualLandmarkCount: t.virtualLandmarkCount,
    segmentWeights: t.segmentWeights(),
    flags: t.flags(),
  };
}

/** The buffers of `data` to transfer rather than copy. */
export function templateTransfer(data: TemplateData): Transferable[] {
  return [
    data.positions.buffer,
    data.triangles.buffer,
    data.normals.buffer,
    data.landmarkPositions.buffer,
    data.segmentWeights.buffer,
    data.flags.buffer,
  ];
}
