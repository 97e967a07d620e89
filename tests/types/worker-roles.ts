// Type-level test (run by `npm run typecheck`): each worker's client takes its own role's messages
// and no other. Every `@ts-expect-error` below fails the typecheck if the call it marks compiles.
import type { CoreClient } from '../../web/client/core-client';

export function rolesAreTypes(
  core: CoreClient<'core'>,
  align: CoreClient<'align'>,
  landmarks: CoreClient<'landmarks'>,
  population: CoreClient<'population'>,
  batch: CoreClient<'batch'>,
): void {
  void core.call({ type: 'modelFile' });
  void align.call({ type: 'alignDefaults' });
  void landmarks.call({ type: 'checkLandmarks', names: [], positions: new Float64Array(), prediction: { positions: new Float64Array(), parts: new Uint32Array() } });
  void population.call({ type: 'measurementDistribution' });
  void batch.call({ type: 'trap' });

  // @ts-expect-error an align message to the population worker
  void population.call({ type: 'alignDefaults' });
  // @ts-expect-error the shape model shown lives in the main worker, not the align worker
  void align.call({ type: 'modelFile' });
  // @ts-expect-error the estimate runs in the landmark worker
  void core.call({ type: 'estimateLandmarks', scan: null as never });
  // @ts-expect-error the batch's workers align files, nothing else
  void batch.call({ type: 'version' });
  // @ts-expect-error the landmark worker is never trapped
  void landmarks.call({ type: 'trap' });
}
