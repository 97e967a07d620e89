// Length units: the choices a scan offers, and a guess from an extent when nothing else says.
import type { Units } from './results';

export const UNITS: readonly Units[] = ['metres', 'millimetres'];

/** A body is 0.3–2.5 m tall; anything over 10 units across must be in millimetres. */
export function guessUnitsFromExtent(extent: number): Units {
  return extent > 10 ? 'millimetres' : 'metres';
}
