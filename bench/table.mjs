// Median / min / max rows of the browser benchmarks' Markdown tables.

/** Median, min and max of `xs`. */
export function stats(xs) {
  const s = [...xs].sort((a, b) => a - b);
  const m = Math.floor(s.length / 2);
  return { median: s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2, min: s[0], max: s.at(-1) };
}

/** `| label | median | min | max |`, the label padded to `width`, values with 2 decimals. */
export function row(label, xs, width) {
  const { median, min, max } = stats(xs);
  return `| ${label.padEnd(width)} | ${median.toFixed(2).padStart(8)} | ${min.toFixed(2).padStart(8)} | ${max.toFixed(2).padStart(8)} |`;
}
