// Area-weighted vertex normals of a triangle mesh, for bodies the core reconstructs (the core
// returns positions only on the morphing path). No DOM.

/** `#V·3` unit normals of `positions` (`#V·3`) over `triangles` (`#F·3`). */
export function vertexNormals(positions: Float32Array, triangles: Uint32Array): Float32Array {
  const n = new Float32Array(positions.length);
  for (let t = 0; t < triangles.length; t += 3) {
    const a = 3 * triangles[t]!;
    const b = 3 * triangles[t + 1]!;
    const c = 3 * triangles[t + 2]!;
    const ux = positions[b]! - positions[a]!;
    const uy = positions[b + 1]! - positions[a + 1]!;
    const uz = positions[b + 2]! - positions[a + 2]!;
    const vx = positions[c]! - positions[a]!;
    const vy = positions[c + 1]! - positions[a + 1]!;
    const vz = positions[c + 2]! - positions[a + 2]!;
    // The cross product's length is twice the area: larger triangles weigh more.
    const x = uy * vz - uz * vy;
    const y = uz * vx - ux * vz;
    const z = ux * vy - uy * vx;
    for (const i of [a, b, c]) {
      n[i] = n[i]! + x;
      n[i + 1] = n[i + 1]! + y;
      n[i + 2] = n[i + 2]! + z;
    }
  }
  for (let i = 0; i < n.length; i += 3) {
    const len = Math.hypot(n[i]!, n[i + 1]!, n[i + 2]!) || 1;
    n[i] = n[i]! / len;
    n[i + 1] = n[i + 1]! / len;
    n[i + 2] = n[i + 2]! / len;
  }
  return n;
}
