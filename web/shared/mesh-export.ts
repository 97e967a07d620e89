// Meshes as files a person can open elsewhere: binary PLY and OBJ, metres. No DOM.

/** Binary little-endian PLY with float positions and uchar/int triangle lists. */
export function plyBytes(positions: Float32Array, triangles: Uint32Array, comment: string): Uint8Array {
  const v = positions.length / 3;
  const f = triangles.length / 3;
  const header =
    `ply\nformat binary_little_endian 1.0\ncomment ${comment.replace(/\n/g, ' ')}\n` +
    `element vertex ${v}\nproperty float x\nproperty float y\nproperty float z\n` +
    `element face ${f}\nproperty list uchar int vertex_indices\nend_header\n`;
  const head = new TextEncoder().encode(header);
  const out = new Uint8Array(head.length + v * 12 + f * 13);
  out.set(head);
  const view = new DataView(out.buffer);
  let o = head.length;
  for (let i = 0; i < positions.length; i++, o += 4) view.setFloat32(o, positions[i]!, true);
  for (let t = 0; t < triangles.length; t += 3) {
    view.setUint8(o++, 3);
    for (let k = 0; k < 3; k++, o += 4) view.setInt32(o, triangles[t + k]!, true);
  }
  return out;
}

/** Wavefront OBJ text (1-based indices). */
export function objText(positions: Float32Array, triangles: Uint32Array, comment: string): string {
  const lines = [`# ${comment.replace(/\n/g, ' ')}`];
  for (let i = 0; i < positions.length; i += 3) {
    lines.push(`v ${positions[i]!.toFixed(6)} ${positions[i + 1]!.toFixed(6)} ${positions[i + 2]!.toFixed(6)}`);
  }
  for (let t = 0; t < triangles.length; t += 3) {
    lines.push(`f ${triangles[t]! + 1} ${triangles[t + 1]! + 1} ${triangles[t + 2]! + 1}`);
  }
  return `${lines.join('\n')}\n`;
}

/** A short, order-sensitive checksum of positions (FNV-1a over their f32 bits), for tests. */
export function positionsChecksum(positions: Float32Array): string {
  const bits = new Uint32Array(positions.buffer, positions.byteOffset, positions.length);
  let h = 0x811c9dc5;
  for (let i = 0; i < bits.length; i++) {
    h ^= bits[i]!;
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h.toString(16).padStart(8, '0');
}
