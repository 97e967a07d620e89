// The heat scale's CSS gradient for legends; its vertex colours are made in the workers
// (`web/shared/heat-scale.ts`, the same stops).
import { HEAT_STOPS } from '../shared/heat-scale';

export { distanceHeat } from '../shared/heat-scale';

/** The CSS gradient of the scale, left (low) to right (high). */
export function heatGradientCss(): string {
  return `linear-gradient(to right, ${HEAT_STOPS.join(', ')})`;
}
