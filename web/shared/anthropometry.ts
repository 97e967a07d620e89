// Bodies from measurements: the targets a person enters (in the panel's units), what the core
// found, and whether a value meets its target. No DOM here.
import type { PartName, Reading } from './shape-results';

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
  /** The model the coefficients are of: the whole body, or the segment in view. */
  part: PartName;
  /** Coefficients of `part`'s model in σ units. */
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

/** One measurement over one population (core `MeasureDistribution`); m, m³, m². */
export interface MeasureDistribution {
  name: string;
  kind: Reading['kind'];
  /** The values of the bodies where it could be taken, ascending. */
  values: number[];
  /** `null`: no values (NaN in the core). */
  mean: number | null;
  sd: number | null;
  /** The values at `PERCENTILE_LEVELS`. */
  percentiles: (number | null)[];
}

/** The percentile levels of `MeasureDistribution.percentiles` (core `PERCENTILE_LEVELS`), %. */
export const PERCENTILE_LEVELS = [5, 25, 50, 75, 95] as const;

/** Every measurement over one population (core `PopulationMeasurements`). */
export interface PopulationMeasurements {
  bodies: number;
  /** One per measurement, in the core's order. */
  measures: MeasureDistribution[];
  /** Pearson correlation, row-major, measurements × measurements; `null` where undefined. */
  correlation: (number | null)[];
}

/** A model's measurement distributions (core `MeasurementDistribution`) and their cost. */
export interface MeasurementDistribution {
  params: { samples: number; seed: number };
  training: PopulationMeasurements;
  samples: PopulationMeasurements;
  /** The core call in the worker, ms. */
  workerMs: number;
}

/**
 * The percentile (0–100) of `value` among `sorted` (ascending): 100·(below + ½·equal)/N, NaN for
 * an empty population — the core's `anthropometry::measurement_distribution::percentile_of`, done here so
 * that a slider move looks it up on the UI thread against the distribution computed once (held to
 * the core's by tests/e2e/percentile-parity.spec.ts).
 */
export function percentileOf(sorted: readonly number[], value: number): number {
  if (sorted.length === 0) return NaN;
  const first = (pred: (x: number) => boolean) => {
    let lo = 0;
    let hi = sorted.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (pred(sorted[mid]!)) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  };
  const below = first((x) => x < value);
  const notAbove = first((x) => x <= value);
  return (100 * (below + 0.5 * (notAbove - below))) / sorted.length;
}

/** One boundary manikin (core `Manikin`). */
export interface Manikin {
  /** `manikin_01`, … */
  name: string;
  /** Its unit direction in the principal axes of the chosen measurements. */
  direction: number[];
  /** The body: σ-unit whole-body coefficients and target vs achieved of each chosen measurement. */
  body: Omit<FoundBody, 'part' | 'tolerances' | 'workerMs'>;
  /** Mahalanobis distance of its chosen values from the population mean (the radius on the boundary). */
  distance: number;
  /** All its measurements `{name: value | null}` (m, m³, m²). */
  measurements: Record<string, number | null>;
}

/** The boundary manikins of a coverage region (core `BoundaryManikins`), with the core's CSV of them. */
export interface ManikinSet {
  manikins: {
    measures: string[];
    coverage: number;
    radius: number;
    mean: number[];
    covariance: number[];
    manikins: Manikin[];
  };
  csv: string;
  /** The core call in the worker, ms. */
  workerMs: number;
}

/** The core's defaults of boundary manikins (`ManikinParams`). */
export interface ManikinDefaults {
  /** Share of the population inside the boundary. */
  coverage: number;
  ellipse_points: number;
}
