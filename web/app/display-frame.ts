// The display-only transform that shows a scan upright beside the template: the inverse of the
// Procrustes rotation and translation (template → scan, y = s·R·x + t), without the scale, so a
// z-up CAESAR scan stands y-up where the template stands, at its own size. Positions sent to the
// core are never transformed.
import type { Similarity } from '../shared/align-types';

/** Column-major 4×4 of y ↦ Rᵀ(y − t). */
export function uprightTransform(similarity: Similarity): number[] {
  const R = similarity.rotation;
  const t = similarity.translation;
  // Rᵀ: row i of Rᵀ is column i of R.
  const m = (i: number, j: number) => R[j]![i]!;
  const tx = -(m(0, 0) * t[0] + m(0, 1) * t[1] + m(0, 2) * t[2]);
  const ty = -(m(1, 0) * t[0] + m(1, 1) * t[1] + m(1, 2) * t[2]);
  const tz = -(m(2, 0) * t[0] + m(2, 1) * t[1] + m(2, 2) * t[2]);
  return [m(0, 0), m(1, 0), m(2, 0), 0, m(0, 1), m(1, 1), m(2, 1), 0, m(0, 2), m(1, 2), m(2, 2), 0, tx, ty, tz, 1];
}

/** Which way the scan's own axes point, in words, from the rotation (for the panel's note). */
export function describeFrame(similarity: Similarity): string {
  const R = similarity.rotation;
  // The template's up (+y) and front (+z) as seen in the scan's frame: columns 1 and 2 of R.
  const up = axisName([R[0]![1]!, R[1]![1]!, R[2]![1]!]);
  const front = axisName([R[0]![2]!, R[1]![2]!, R[2]![2]!]);
  return `scan is ${up}-up, facing ${front}`;
}

function axisName(v: number[]): string {
  let best = 0;
  for (let i = 1; i < 3; i++) if (Math.abs(v[i]!) > Math.abs(v[best]!)) best = i;
  const sign = v[best]! < 0 ? '−' : '+';
  return `${sign}${'xyz'[best]}`;
}
