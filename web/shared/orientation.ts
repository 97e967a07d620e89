// Which way is up on a scan, as a person states it: the core's `Orientation`
// (crate/src/estimate/orientation.rs). The landmark estimate then tries only the frames that
// agree with it. No DOM here: shared by the page and the workers.

/** A scan direction named by its coordinate axis, as the core writes it. */
export type Axis = '+x' | '-x' | '+y' | '-y' | '+z' | '-z';

/** The six axes, in the order the app lists them (the core's `Axis::ALL`). */
export const AXES: readonly Axis[] = ['+x', '-x', '+y', '-y', '+z', '-z'];

/**
 * Which scan axis points from the feet to the head and, when known, which way the body faces
 * (across `up`; null: the estimate tries both facings across the body's width).
 */
export interface Orientation {
  up: Axis;
  facing: Axis | null;
}

/** The axes across `up`: the facings the core accepts with it. */
export function axesAcross(up: Axis): Axis[] {
  return AXES.filter((a) => a[1] !== up[1]);
}

/** What the core's `estimateLandmarks` takes: the orientation's JSON, or '' for "find the frame". */
export function orientationArgument(orientation: Orientation | null): string {
  return orientation ? JSON.stringify({ up: orientation.up, facing: orientation.facing }) : '';
}

/** `+x` as a person reads it: `+x`, `−x` (a true minus sign). */
export function axisLabel(axis: Axis): string {
  return axis.replace('-', '−');
}

/** The orientation as the app writes it for a person: `up +z, facing auto`, or `auto`. */
export function orientationText(orientation: Orientation | null): string {
  if (!orientation) return 'auto';
  return `up ${axisLabel(orientation.up)}, facing ${orientation.facing ? axisLabel(orientation.facing) : 'auto'}`;
}

/** Whether two orientations are the same statement (null: auto). */
export function sameOrientation(a: Orientation | null, b: Orientation | null): boolean {
  return (a?.up ?? null) === (b?.up ?? null) && (a?.facing ?? null) === (b?.facing ?? null);
}
