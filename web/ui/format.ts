// How numbers are written in the panels.

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
