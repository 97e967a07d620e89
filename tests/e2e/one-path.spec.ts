// One path for a subject (docs/subject.md): the same scan and CAESAR landmark file give the same
// fit through `bodyspace align` (the native program), the app's single scan and the app's batch —
// the RMS the page shows equals the command line's to the digits shown. The scans are what
// `bodyspace synth` writes: z up, millimetres, `.lnd` in millimetres.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads, type TestFile } from './fixtures';
import { shapeReady } from './steps';
import { bodyspaceBinary, synthFolder, synthSubjects } from './synth';

/** `bodyspace align` on the files, with the core's defaults: its report. */
function alignNatively(
  scan: { name: string; bytes: Buffer },
  landmarks: { name: string; bytes: Buffer },
): {
  quality: { rms_mm: number; flags: string[]; uneven_limbs: { part: string; left_rms_mm: number; right_rms_mm: number }[] };
  landmarks: { source: string; used: number };
  strays?: { words: string };
  floor?: { words: string };
} {
  const dir = mkdtempSync(join(tmpdir(), 'bodyspace-one-path-'));
  try {
    writeFileSync(join(dir, scan.name), scan.bytes);
    writeFileSync(join(dir, landmarks.name), landmarks.bytes);
    const out = execFileSync(bodyspaceBinary(), ['align', '--scan', join(dir, scan.name), '--landmarks', join(dir, landmarks.name), '--out', join(dir, 'fit.ply')], {
      encoding: 'utf8',
      maxBuffer: 64 << 20,
    });
    return JSON.parse(out);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** Drops a scan and its landmark file on the open page and aligns it with the panel's defaults: the RMS (mm) the page shows. */
async function alignSingle(page: Page, files: TestFile[]): Promise<number> {
  await dropFiles(page, files);
  await waitForLoads(page, 1);
  await expect(page.locator('body')).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await page.getByTestId('align-run').click();
  await expect(page.locator('body')).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
  return Number(await page.getByTestId('align-rms').getAttribute('data-rms-mm'));
}

test('the command line, the single scan and the batch give the same fit of the same files', async ({ page }) => {
  test.setTimeout(420_000);
  const files = synthSubjects(2, 31);
  const scan = files.find((f) => f.name === 'scan_001.ply')!;
  const lnd = files.find((f) => f.name === 'landmarks_001.lnd')!;
  const native = alignNatively(scan, lnd);
  expect(native.landmarks.source).toBe('checked');
  const expected = native.quality.rms_mm.toFixed(2);

  await page.goto('./?debug');
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await shapeReady(page);

  // The single scan: dropped with its landmark file, aligned with the panel's defaults.
  const single = await alignSingle(page, [scan, lnd]);
  expect(single.toFixed(2), `single scan ${single} mm, command line ${native.quality.rms_mm} mm`).toBe(expected);

  // The batch: both subjects dropped at once, each aligned in a pool worker.
  await dropFiles(page, files);
  await expect(page.locator('body')).toHaveAttribute('data-batch-total', '2');
  await expect(page.locator('body')).toHaveAttribute('data-batch-finished', '2', { timeout: 300_000 });
  const row = page.locator('[data-testid="batch-row"][data-subject="scan_001"]');
  await expect(row.getByTestId('batch-rms')).toHaveText(expected);
});

// What a scanner leaves beside the body (the scanner zoo's classes): the core takes it off the
// scan on the one path, so the command line and the app fit the same and the page says what.
for (const [scannerClass, field] of [
  ['stray', 'strays'],
  ['floor', 'floor'],
] as const) {
  test(`a ${scannerClass} scan: what is not the body is left out alike by the command line and the app, which says so`, async ({ page }) => {
    test.setTimeout(300_000);
    const files = synthSubjects(1, 31, 20, ['--scanner-class', scannerClass]);
    const scan = files.find((f) => f.name === 'scan_001.ply')!;
    const lnd = files.find((f) => f.name === 'landmarks_001.lnd')!;
    const native = alignNatively(scan, lnd);
    const removed = native[field];
    expect(removed, `bodyspace align's report has no ${field}`).toBeTruthy();
    expect(native.quality.flags).not.toContain('high_rms');

    await page.goto('./?debug');
    await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
    const single = await alignSingle(page, [scan, lnd]);
    expect(single.toFixed(2)).toBe(native.quality.rms_mm.toFixed(2));
    await expect(page.getByTestId('align-check')).toContainText(removed!.words);
    await expect(page.getByTestId('align-check')).not.toHaveAttribute('data-flags', /high_rms/);
  });
}

/**
 * `ply` (a binary little-endian PLY of float x y z and uchar/int triangles, as `bodyspace synth`
 * writes) without the triangles that touch a vertex within `radius` mm of the segment `a`–`b`:
 * that part of the body cut away, its points left unconnected.
 */
function withoutTrianglesNear(ply: Buffer, a: number[], b: number[], radius: number): Buffer {
  const end = ply.indexOf('end_header\n') + 'end_header\n'.length;
  const header = ply.subarray(0, end).toString('latin1');
  const vertices = Number(/element vertex (\d+)/.exec(header)![1]);
  const faces = Number(/element face (\d+)/.exec(header)![1]);
  const axis = [b[0]! - a[0]!, b[1]! - a[1]!, b[2]! - a[2]!];
  const length = Math.hypot(...axis);
  const cut = Array.from({ length: vertices }, (_, v) => {
    const p = [0, 1, 2].map((i) => ply.readFloatLE(end + 12 * v + 4 * i) - a[i]!);
    const t = Math.min(length, Math.max(0, (p[0]! * axis[0]! + p[1]! * axis[1]! + p[2]! * axis[2]!) / length));
    return Math.hypot(...p.map((x, i) => x - (axis[i]! * t) / length)) < radius;
  });
  const kept: Buffer[] = [];
  for (let f = 0, at = end + 12 * vertices; f < faces; f++, at += 13) {
    const corners = [0, 1, 2].map((i) => ply.readInt32LE(at + 1 + 4 * i));
    if (!corners.some((v) => cut[v])) kept.push(ply.subarray(at, at + 13));
  }
  const newHeader = header.replace(`element face ${faces}`, `element face ${kept.length}`);
  return Buffer.concat([Buffer.from(newHeader, 'latin1'), ply.subarray(end, end + 12 * vertices), ...kept]);
}

test('a scan missing a foot: the command line and the app flag the same limb, in words', async ({ page }) => {
  test.setTimeout(300_000);
  const files = synthFolder(1, 2929, 20);
  const scan = files.find((f) => f.name === 'scan_001.ply')!;
  const lnd = files.find((f) => f.name === 'landmarks_001.lnd')!;
  const at = (name: string) => {
    const line = files.find((f) => f.name === 'landmarks_001.csv')!.bytes.toString('utf8').split('\n').find((l) => l.startsWith(`"${name}",`) || l.startsWith(`${name},`))!;
    return line.split(',').slice(-3).map(Number);
  };
  // Every point within 60 mm of the left heel–toe line cut away.
  const footless = { name: 'footless.ply', bytes: withoutTrianglesNear(scan.bytes, at('Lt. Calcaneous, Post.'), at('Lt. Digit II'), 60) };
  expect(footless.bytes.length).toBeLessThan(scan.bytes.length - 13 * 30);
  const native = alignNatively(footless, lnd);
  expect(native.quality.flags).toContain('uneven_limb');
  const limb = native.quality.uneven_limbs.find((u) => u.part === 'lower leg')!;
  expect(limb.left_rms_mm).toBeGreaterThan(2.5 * limb.right_rms_mm);
  expect(alignNatively(scan, lnd).quality.flags).not.toContain('uneven_limb');

  await page.goto('./?debug');
  await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  const single = await alignSingle(page, [footless, lnd]);
  expect(single.toFixed(2)).toBe(native.quality.rms_mm.toFixed(2));
  const check = page.getByTestId('align-check');
  await expect(check).toHaveAttribute('data-flags', native.quality.flags.join(' '));
  await expect(check).toContainText(`the left lower leg lies ${limb.left_rms_mm.toFixed(1)} mm RMS from the scan, the other side ${limb.right_rms_mm.toFixed(1)} mm`);
  await expect(check).toContainText('the fit missed that limb, or the scan lacks part of it');
  await expect(page.getByTestId('align-keep')).toContainText('limb off the scan');
});
