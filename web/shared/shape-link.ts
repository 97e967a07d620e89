// The shareable link of a body in a shape space: model location, every coefficient, the segment
// view, the camera and the resolution, in the URL hash. Format documented in docs/links.md. No DOM.
import { SEGMENTS, type SegmentName, type ShapeCoefficients } from './shape-results';

/** Slider values are held on this grid, so a link restores exactly the same body. */
const SIGMA_STEP = 0.001;
const LIMIT = 32767;

export interface CameraPose {
  position: [number, number, number];
  target: [number, number, number];
}

export interface ShapeLink {
  /** Same-origin path (`models/demo.bsm`) or an https URL. */
  model: string;
  coefficients: ShapeCoefficients;
  view: 'whole' | SegmentName;
  camera: CameraPose | null;
  /** Template resolution the body is shown at (a base model is mapped to fine in the worker). */
  resolution: 'base' | 'fine';
}

/** Rounds a σ value onto the link grid (and into the int16 range). */
export function quantiseSigma(t: number): number {
  const q = Math.max(-LIMIT, Math.min(LIMIT, Math.round(t / SIGMA_STEP)));
  return q * SIGMA_STEP;
}

function encodeValues(values: number[]): string {
  const bytes = new Uint8Array(values.length * 2);
  const view = new DataView(bytes.buffer);
  values.forEach((t, i) => view.setInt16(2 * i, Math.round(quantiseSigma(t) / SIGMA_STEP), true));
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function decodeValues(text: string): number[] | null {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) return null;
  let binary: string;
  try {
    binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  } catch {
    return null;
  }
  if (binary.length % 2 !== 0) return null;
  const values: number[] = [];
  for (let i = 0; i < binary.length; i += 2) {
    let q = binary.charCodeAt(i) | (binary.charCodeAt(i + 1) << 8);
    if (q >= 0x8000) q -= 0x10000;
    values.push(q * SIGMA_STEP);
  }
  return values;
}

/** Whether `model` is a location a link may carry: a same-origin relative path or https URL. */
export function isShareableModel(model: string): boolean {
  if (/^https:\/\/[^\s]+$/.test(model)) return true;
  return /^[A-Za-z0-9._~\-/]+$/.test(model) && !model.startsWith('/') && !model.includes('..') && !model.includes('//');
}

/** `#m=…&w=…&s=…&v=…&c=…&r=fine` (see docs/links.md). */
export function encodeShapeLink(link: ShapeLink): string {
  const parts = [`m=${encodeURIComponent(link.model)}`, `w=${encodeValues(link.coefficients.whole)}`];
  const segments = SEGMENTS.flatMap((name, i) => {
    const values = link.coefficients.segments[i];
    return values ? [`${name}.${encodeValues(values)}`] : [];
  });
  if (segments.length) parts.push(`s=${segments.join('~')}`);
  parts.push(`v=${link.view}`);
  if (link.camera) {
    const c = [...link.camera.position, ...link.camera.target].map((x) => x.toFixed(4));
    parts.push(`c=${c.join(',')}`);
  }
  if (link.resolution === 'fine') parts.push('r=fine');
  return `#${parts.join('&')}`;
}

export type DecodedLink = { link: ShapeLink; problems: [] } | { link: null; problems: string[] };

/**
 * Reads a hash made by `encodeShapeLink`. Any bad parameter voids the whole link (the app then
 * opens in its default state), and `problems` says what was ignored and why.
 */
export function decodeShapeLink(hash: string): DecodedLink | null {
  const text = hash.replace(/^#/, '');
  if (!text) return null;
  const problems: string[] = [];
  const params = new Map<string, string>();
  for (const pair of text.split('&')) {
    const eq = pair.indexOf('=');
    const key = eq < 0 ? pair : pair.slice(0, eq);
    if (!['m', 'w', 's', 'v', 'c', 'r'].includes(key)) problems.push(`unknown parameter "${key.slice(0, 20)}"`);
    else params.set(key, eq < 0 ? '' : pair.slice(eq + 1));
  }
  let model = '';
  try {
    model = decodeURIComponent(params.get('m') ?? '');
  } catch {
    problems.push('the model location (m) is not valid URL encoding');
  }
  if (!params.has('m')) problems.push('the model location (m) is missing');
  else if (model && !isShareableModel(model)) problems.push(`the model location "${model.slice(0, 60)}" is neither a same-origin path nor an https URL`);
  const whole = decodeValues(params.get('w') ?? '');
  if (whole === null) problems.push('the whole-body coefficients (w) are not base64url int16 values');
  const segments: (number[] | null)[] = SEGMENTS.map(() => null);
  for (const entry of (params.get('s') ?? '').split('~').filter(Boolean)) {
    const [name, data] = entry.split('.');
    const index = SEGMENTS.indexOf(name as SegmentName);
    const values = decodeValues(data ?? '');
    if (index < 0) problems.push(`unknown segment "${(name ?? '').slice(0, 20)}" in s`);
    else if (values === null) problems.push(`the ${name} coefficients are not base64url int16 values`);
    else segments[index] = values;
  }
  const view = params.get('v') ?? 'whole';
  if (view !== 'whole' && !SEGMENTS.includes(view as SegmentName)) problems.push(`unknown segment view "${view.slice(0, 20)}" (v)`);
  let camera: CameraPose | null = null;
  if (params.has('c')) {
    const c = (params.get('c') ?? '').split(',').map(Number);
    if (c.length !== 6 || c.some((x) => !Number.isFinite(x) || Math.abs(x) > 1000)) problems.push('the camera (c) is not six finite numbers');
    else camera = { position: [c[0]!, c[1]!, c[2]!], target: [c[3]!, c[4]!, c[5]!] };
  }
  const resolution = params.get('r') ?? 'base';
  if (resolution !== 'base' && resolution !== 'fine') problems.push(`unknown resolution "${resolution.slice(0, 20)}" (r: base or fine)`);
  if (problems.length) return { link: null, problems };
  return {
    link: { model, coefficients: { whole: whole!, segments }, view: view as ShapeLink['view'], camera, resolution: resolution as ShapeLink['resolution'] },
    problems: [],
  };
}
