// How numbers are written in the panels.

import type { MeasurementTrust, QualityFlag, QualityReport } from '../shared/align-types';
import type { Reorientation, ScanRemoval } from '../shared/landmark-entry';
import type { Reading } from '../shared/shape-results';

const integer = new Intl.NumberFormat('en-GB', { maximumFractionDigits: 0 });

/** 12,345 */
export function formatCount(n: number): string {
  return integer.format(n);
}

/** Millimetre precision without a minus sign on zero: `-0.0001` → `0.000`. */
function fixed3(v: number): string {
  return (Math.abs(v) < 0.0005 ? 0 : v).toFixed(3);
}

/** Metres with millimetre precision: `1.752 m`. */
export function formatMetres(m: number): string {
  return `${fixed3(m)} m`;
}

/** `(x, y, z)` in metres with millimetre precision. */
export function formatPoint(p: readonly number[]): string {
  return `(${p.map(fixed3).join(', ')})`;
}

/** A measurement in its usual unit: lengths and girths `84.8 cm`, volume `54.9 L`, area `1.613 m²`;
 * `—` when not taken. */
export function formatReading(kind: Reading['kind'], value: number | null): string {
  if (value == null) return '—';
  if (kind === 'volume') return `${(value * 1000).toFixed(1)} L`;
  if (kind === 'area') return `${value.toFixed(3)} m²`;
  return `${(value * 100).toFixed(1)} cm`;
}

/** What a fit's raised quality flags mean, with the measures behind them (`align/quality.rs`). */
export function qualityText(q: QualityReport): string {
  const t = q.thresholds;
  const parts: string[] = [];
  if (q.flags.includes('high_rms')) parts.push(`RMS ${q.rms_mm?.toFixed(2)} mm > ${t.max_rms_mm} mm`);
  if (q.flags.includes('unmatched')) parts.push(`${(q.unmatched_fraction * 100).toFixed(0)} % unmatched > ${t.max_unmatched_fraction * 100} %`);
  if (q.flags.includes('fold_overs')) parts.push(`${(q.folded_fraction * 100).toFixed(1)} % folded > ${t.max_folded_fraction * 100} %`);
  if (q.flags.includes('uncovered_scan'))
    parts.push(
      `${(q.uncovered_share * 1000).toFixed(1)} ‰ of the scan (${q.uncovered_scan_vertices} points) lies more than ${t.uncovered_mm} mm from the fit, ` +
        `most near the ${q.uncovered_near ?? 'template'}: the fit missed part of the body (limit ${t.max_uncovered_share * 1000} ‰)`,
    );
  if (q.flags.includes('uneven_limb'))
    for (const u of q.uneven_limbs) {
      const [side, worse, other] = u.left_rms_mm > u.right_rms_mm ? ['left', u.left_rms_mm, u.right_rms_mm] : ['right', u.right_rms_mm, u.left_rms_mm];
      parts.push(
        `the ${side} ${u.part} lies ${worse.toFixed(1)} mm RMS from the scan, the other side ${other.toFixed(1)} mm: ` +
          `the fit missed that limb, or the scan lacks part of it (limit ${t.uneven_limb_ratio} times and ${t.uneven_limb_mm} mm)`,
      );
    }
  if (q.flags.includes('suspicious_landmarks')) parts.push(`suspicious landmarks left out: ${q.suspicious_landmarks.join(', ')}`);
  if (q.flags.includes('landmark_estimate')) parts.push(`landmark estimate: ${q.landmark_estimate.join('; ')}`);
  return parts.join('; ');
}

/**
 * The measurements a fit cannot be trusted for, in words, one sentence after another (the Batch
 * table's hover): each doubtful one's reason from the core (`measure/trust.rs`) — its estimated
 * landmarks, the fit's own error or the scan missing under the fit; empty when there is none.
 */
export function doubtfulMeasurementsText(trust: readonly MeasurementTrust[]): string {
  return trust
    .filter((t) => t.doubtful)
    .map((t) => t.words)
    .join('; ');
}

/** A quality flag's short name, for a button or a list: `landmark_estimate` → "doubtful landmark estimate". */
export function flagName(flag: QualityFlag): string {
  const names: Record<QualityFlag, string> = {
    high_rms: 'high RMS',
    unmatched: 'unmatched template',
    fold_overs: 'fold-overs',
    uncovered_scan: 'scan not covered',
    uneven_limb: 'limb off the scan',
    suspicious_landmarks: 'suspicious landmarks',
    landmark_estimate: 'doubtful landmark estimate',
  };
  return names[flag];
}

/** The parts of the scan the core turned to face out before fitting it, in its words: empty when none. */
export function turnedWords(turned: Reorientation | undefined): string {
  return turned ? ` Turned: ${turned.words}.` : '';
}

/** What the core took off the scan before fitting it (stray pieces, a floor), in its words: empty when nothing. */
export function notFitted(removed: (ScanRemoval | undefined)[]): string {
  const words = removed.flatMap((r) => (r ? [r.words] : []));
  return words.length ? ` Not fitted: ${words.join('; ')}.` : '';
}

/**
 * What said the frame's up or facing (the core's `FrameBasis` word), as words after the axis:
 * " (as chosen)", " (from the given landmarks, not the chosen +y)", " (from the legs)", … An
 * axis the person chose and the core did not take is named, so a choice overruled is never shown as kept.
 */
export function basisWords(basis: string, chosen: string | null): string {
  if (basis === 'chosen') return ' (as chosen)';
  const overruled = chosen ? `, not the chosen ${chosen}` : '';
  if (basis === 'the fits') return ` (by the fits alone${overruled})`;
  return ` (from ${basis}${overruled})`;
}
