// A checksum of positions, so tests can tell two bodies are the same bits. No DOM.

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
