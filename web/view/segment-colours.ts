// Vertex colours that mix six segment colours by the template's blend weights, so the bands
// where neighbouring segments overlap show as gradients between their colours.
import * as THREE from 'three';

/** One distinct colour per segment, in the core's order (head, l. arm, r. arm, torso, l. leg, r. leg). */
export const SEGMENT_COLOURS = [0xe4572e, 0x29a8ab, 0x7b6cd9, 0xf3c63f, 0x3fa34d, 0xd6579a] as const;

/** `#V·3` linear RGB from `#V·6` blend weights. */
export function segmentColours(weights: Float32Array): Float32Array {
  const palette = SEGMENT_COLOURS.map((hex) => new THREE.Color(hex));
  const n = weights.length / 6;
  const out = new Float32Array(n * 3);
  for (let v = 0; v < n; v++) {
    let r = 0;
    let g = 0;
    let b = 0;
    for (let k = 0; k < 6; k++) {
      const w = weights[6 * v + k]!;
      const c = palette[k]!;
      r += w * c.r;
      g += w * c.g;
      b += w * c.b;
    }
    out[3 * v] = r;
    out[3 * v + 1] = g;
    out[3 * v + 2] = b;
  }
  return out;
}
