// A perceptual heat scale for distances (viridis-like, dark blue → yellow): per-vertex colours,
// made where the distances are (the worker), and the stops the legend's CSS gradient draws. No DOM.

/** sRGB stops of the scale, low to high. */
export const HEAT_STOPS = ['#440154', '#3b528b', '#21918c', '#5ec962', '#fde725'] as const;

/** The sRGB transfer function undone: an 8-bit sRGB channel → linear (IEC 61966-2-1). */
function linear(byte: number): number {
  const c = byte / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
}

/** The stops in linear RGB, as three.js takes vertex colours. */
const STOPS = HEAT_STOPS.map((hex) => [1, 3, 5].map((i) => linear(Number.parseInt(hex.slice(i, i + 2), 16))));

/** `#V·3` linear RGB for `values` on the scale from `min` to `max` (outside: clamped), interpolated in linear RGB between stops. */
export function heatColours(values: Float32Array, min: number, max: number): Float32Array {
  const out = new Float32Array(values.length * 3);
  const span = max > min ? max - min : 1;
  const last = STOPS.length - 1;
  for (let i = 0; i < values.length; i++) {
    const x = Math.min(Math.max((values[i]! - min) / span, 0), 1) * last;
    const k = Math.min(Math.floor(x), last - 1);
    const f = x - k;
    const [a, b] = [STOPS[k]!, STOPS[k + 1]!];
    out[3 * i] = a[0]! + (b[0]! - a[0]!) * f;
    out[3 * i + 1] = a[1]! + (b[1]! - a[1]!) * f;
    out[3 * i + 2] = a[2]! + (b[2]! - a[2]!) * f;
  }
  return out;
}

/** A fit's distance heat map: `#V·3` colours and the scale's top (mm). */
export interface DistanceHeat {
  colours: Float32Array;
  maxMm: number;
}

/**
 * The heat map of a fit's per-vertex distances to its scan (`#V`, metres): colours from 0 mm to
 * the scale's top, the 98th percentile (a few outliers must not wash out the rest), ≥ 1 mm.
 */
export function distanceHeat(distancesMetres: Float32Array): DistanceHeat {
  const mm = Float32Array.from(distancesMetres, (d) => d * 1e3);
  const sorted = Float32Array.from(mm).sort();
  const maxMm = Math.max(1, Math.ceil(sorted[Math.floor(0.98 * (sorted.length - 1))] ?? 1));
  return { colours: heatColours(mm, 0, maxMm), maxMm };
}
