// Length units: what one unit is in metres, and a guess from an extent when nothing else says.
import { METRES_PER_UNIT, type Units } from './results';

export const UNITS: readonly Units[] = ['metres', 'millimetres'];

/** A body is 0.3–2.5 m tall; anything over 10 units across must be in millimetres. */
export function guessUnitsFromExtent(extent: number): Units {
  return extent > 10 ? 'millimetres' : 'metres';
}

/** Factor taking a length in `from` units to `to` units. */
export function unitRatio(from: Units, to: Units): number {
  return METRES_PER_UNIT[from] / METRES_PER_UNIT[to];
}
