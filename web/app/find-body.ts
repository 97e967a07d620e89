// Find body: the most likely body of the model with measurement targets, found in the worker and
// put on the sliders — in the whole body's view a whole body, every segment following it; in a
// segment's view that segment's own shape, the rest of the body held.
import type { CoreClient } from '../client/core-client';
import type { Targets } from '../shared/anthropometry';
import type { ShapePanel } from '../ui/shape-panel';
import type { ShapeModel } from './shape-model';
import type { ShapeSliders } from './shape-sliders';
import type { ShownBody } from './shown-body';

export async function findBody(
  client: CoreClient<'core'>,
  shape: { model: ShapeModel; shown: ShownBody; sliders: ShapeSliders; panel: ShapePanel },
  targets: Targets,
): Promise<void> {
  if (!shape.model.loaded) return;
  const page = document.body.dataset;
  const table = shape.panel.measurements;
  shape.shown.reveal();
  page.findBody = 'running';
  try {
    const found = await client.call({ type: 'bodyFromMeasurements', targets, part: shape.panel.currentView });
    table.showFound(targets, found);
    page.findBodyMs = found.workerMs.toFixed(2);
    if (found.part === 'whole') shape.sliders.showWhole(found.sigma);
    else shape.sliders.showSegment(found.part, found.sigma);
    page.findBody = 'done';
  } catch (error) {
    table.showError(error instanceof Error ? error.message : String(error));
    page.findBody = 'error';
  }
}
