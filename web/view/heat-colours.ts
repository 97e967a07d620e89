// A perceptual heat scale for distances (viridis-like, dark blue → yellow): vertex colours for
// the mesh and the CSS gradient of its legend come from the same stops.
import * as THREE from 'three';

/** sRGB stops of the scale, low to high. */
const HEAT_STOPS = ['#440154', '#3b528b', '#21918c', '#5ec962', '#fde725'] as const;

const stops = HEAT_STOPS.map((hex) => new THREE.Color(hex));

/** The scale's colour at `t` ∈ [0, 1] (linear RGB, for vertex colours). */
function heatColour(t: number, target = new THREE.Color()): THREE.Color {
  const x = Math.min(Math.max(t, 0), 1) * (stops.length - 1);
  const i = Math.min(Math.floor(x), stops.length - 2);
  return target.copy(stops[i]!).lerp(stops[i + 1]!, x - i);
}

/** `#V·3` colours for `values` on the scale from `min` to `max` (values outside are clamped). */
export function heatColours(values: Float32Array, min: number, max: number): Float32Array {
  const out = new Float32Array(values.length * 3);
  const span = max > min ? max - min : 1;
  const c = new THREE.Color();
  for (let i = 0; i < values.length; i++) {
    heatColour((values[i]! - min) / span, c);
    out[3 * i] = c.r;
    out[3 * i + 1] = c.g;
    out[3 * i + 2] = c.b;
  }
  return out;
}

/** The CSS gradient of the scale, left (low) to right (high). */
export function heatGradientCss(): string {
  return `linear-gradient(to right, ${HEAT_STOPS.join(', ')})`;
}

/**
 * The heat map of a fit's per-vertex distances to its scan (`#V`, metres): colours from 0 mm to
 * the scale's top, the 98th percentile (a few outliers must not wash out the rest), ≥ 1 mm.
 */
export function distanceHeat(distancesMetres: Float32Array): { colours: Float32Array; maxMm: number } {
  const mm = Float32Array.from(distancesMetres, (d) => d * 1e3);
  const sorted = Float32Array.from(mm).sort();
  const maxMm = Math.max(1, Math.ceil(sorted[Math.floor(0.98 * (sorted.length - 1))] ?? 1));
  return { colours: heatColours(mm, 0, maxMm), maxMm };
}
