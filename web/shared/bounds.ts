// The axis-aligned bounds of flat positions, found where the positions are made (a worker), so
// the page need not pass over every vertex again to draw them.

/** `[minX, minY, minZ, maxX, maxY, maxZ]`, metres; all NaN for no positions. */
export type Bounds = [number, number, number, number, number, number];

/** The bounds of `positions` (`#V·3`, xyz interleaved). */
export function boundsOf(positions: Float32Array): Bounds {
  if (positions.length < 3) return [NaN, NaN, NaN, NaN, NaN, NaN];
  let [x0, y0, z0] = [Infinity, Infinity, Infinity];
  let [x1, y1, z1] = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < positions.length; i += 3) {
    const x = positions[i]!;
    const y = positions[i + 1]!;
    const z = positions[i + 2]!;
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  return [x0, y0, z0, x1, y1, z1];
}
