// Bodies from measurements: the targets a person enters (in the panel's units), what the core
// found, and whether a value meets its target. No DOM here.
import type { Reading } from './shape-results';

/** Targets by measurement name, in the core's units: m, m³, m². */
export type Targets = Record<string, number>;

/** How close "met" is per kind (core `FromMeasurementsParams` defaults), m / m³ / m². */
export type TargetTolerances = Record<Reading['kind'], number>;

/** One target and what the body found by the core achieved (core `Achieved`). */
export interface AchievedTarget {
  name: string;
  target: number;
  achieved: number;
  met: boolean;
}

/** The body the core found for a set of targets (core `BodyFromMeasurements`) and its cost. */
export interface FoundBody {
  /** Whole-body coefficients in σ units. */
  sigma: number[];
  achieved: AchievedTarget[];
  iterations: number;
  /** ‖z‖, the body's Mahalanobis distance from the mean. */
  mahalanobis: number;
  tolerances: TargetTolerances;
  /** The core call in the worker, ms. */
  workerMs: number;
}

/** The unit a target of `kind` is entered in (the unit the panel shows the reading in). */
export function targetUnit(kind: Reading['kind']): string {
  if (kind === 'volume') return 'L';
  if (kind === 'area') return 'm²';
  return 'cm';
}

/** A value entered in `targetUnit(kind)` in the core's unit (m, m³, m²). */
function toCoreUnit(kind: Reading['kind'], value: number): number {
  if (kind === 'volume') return value / 1000;
  if (kind === 'area') return value;
  return value / 100;
}

/** One entry: an empty text is no target; anything else must be a positive number in the row's unit. */
export function parseTarget(reading: Pick<Reading, 'label' | 'kind'>, text: string): { value: number | null; error?: string } {
  const trimmed = text.trim().replace(',', '.');
  if (trimmed === '') return { value: null };
  const unit = targetUnit(reading.kind);
  const value = Number(trimmed);
  if (!Number.isFinite(value)) return { value: null, error: `${reading.label}: "${text.trim()}" is not a number (enter ${unit})` };
  if (value <= 0) return { value: null, error: `${reading.label}: ${trimmed} ${unit} — a target must be a positive number of ${unit}` };
  return { value: toCoreUnit(reading.kind, value) };
}

/** Whether `value` meets `target` within the tolerance of `kind`. */
export function meets(kind: Reading['kind'], value: number | null, target: number, tolerances: TargetTolerances): boolean {
  return value != null && Math.abs(value - target) <= tolerances[kind] + 1e-9;
}
