// Synthetic subjects made by the core's own generator (`bodyspace synth`, the native CLI that
// the test command builds before the browser tests), read from disk as a person would drop them.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { TestFile } from './fixtures';

const TARGET = fileURLToPath(new URL('../../crate/target/', import.meta.url));

/** The native CLI: BODYSPACE_BIN, else the release build, else the debug build. */
export function bodyspaceBinary(): string {
  const candidates = [process.env.BODYSPACE_BIN, join(TARGET, 'release/bodyspace'), join(TARGET, 'debug/bodyspace')];
  const found = candidates.find((p): p is string => Boolean(p && existsSync(p)));
  if (!found) throw new Error('no bodyspace binary: run `cargo build --manifest-path crate/Cargo.toml` first');
  return found;
}

/**
 * `n` synthetic subjects of population `seed`, scanned every `stepMm` (20 mm: ≈ 3,500-vertex
 * scans, quick to align): `scan_00i.ply` and `landmarks_00i.lnd` for each. `extra`: more
 * `bodyspace synth` arguments (e.g. `--scanner-class stray`).
 */
export function synthSubjects(n: number, seed: number, stepMm = 20, extra: string[] = []): TestFile[] {
  return synthFolder(n, seed, stepMm, extra).filter((f) => /^(scan_\d+\.ply|landmarks_\d+\.lnd)$/.test(f.name));
}

/**
 * Every file `bodyspace synth` writes for `n` subjects, as "Open folder…" on its output reads them:
 * besides each scan and its landmarks (`.lnd` and `.csv`), the ground truths `surface_ID.ply`
 * and `truth_ID.ply`, and the population's own files.
 */
export function synthFolder(n: number, seed: number, stepMm = 20, extra: string[] = []): TestFile[] {
  const out = mkdtempSync(join(tmpdir(), 'bodyspace-synth-'));
  try {
    execFileSync(bodyspaceBinary(), ['synth', '--n', String(n), '--seed', String(seed), '--step', String(stepMm), ...extra, '--out', out], { stdio: 'ignore' });
    return readdirSync(out, { withFileTypes: true })
      .filter((entry) => entry.isFile())
      .map((entry) => entry.name)
      .sort()
      .map((name) => ({ name, bytes: readFileSync(join(out, name)) }));
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}
