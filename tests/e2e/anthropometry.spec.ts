// Anthropometry in the shape panel as a designer uses it: targets entered beside the
// measurements give the most likely body with them (achieved vs target shown; in a segment view
// on that segment's model), bad entries say what is wrong and change nothing; the population
// shows the body's percentile; boundary manikins are listed, shown and exported.
import { readFileSync } from 'node:fs';
import zlib from 'node:zlib';
import { expect, test, type Download, type Page } from '@playwright/test';
import { shapeReady } from './steps';

/** A reading as the panel shows it (`168.9 cm`) in cm. */
async function cm(page: Page, name: string): Promise<number> {
  const text = await page.getByTestId(`measure-${name}`).innerText();
  expect(text).toMatch(/^\d+\.\d cm$/);
  return Number.parseFloat(text);
}

test('two targets give a body that meets them; a bad entry is refused with its reason', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const stature = await cm(page, 'stature');
  const waist = await cm(page, 'waist_girth');

  // Not a number: refused, nothing moves.
  const checksum = await page.locator('body').getAttribute('data-shape-checksum');
  await page.getByTestId('target-chest_girth').fill('abc');
  await page.getByTestId('find-body').click();
  await expect(page.getByTestId('find-body-status')).toHaveText('Chest girth: "abc" is not a number (enter cm)');
  await page.getByTestId('target-chest_girth').fill('-3');
  await page.getByTestId('find-body').click();
  await expect(page.getByTestId('find-body-status')).toContainText('a target must be a positive number of cm');
  await expect(page.locator('body')).toHaveAttribute('data-shape-checksum', checksum!);
  await page.getByTestId('target-chest_girth').fill('');

  // Taller and slimmer than the mean, inside the population.
  const targets = { stature: stature + 4, waist_girth: waist - 3 };
  await page.getByTestId('target-stature').fill(targets.stature.toFixed(1));
  await page.getByTestId('target-waist_girth').fill(targets.waist_girth.toFixed(1));
  await page.getByTestId('find-body').click();
  await expect(page.locator('body')).toHaveAttribute('data-find-body', 'done');
  await shapeReady(page);
  await expect(page.getByTestId('find-body-status')).toContainText('2 of 2 targets met');
  for (const [name, target, tolerance] of [
    ['stature', targets.stature, 0.2],
    ['waist_girth', targets.waist_girth, 0.5],
  ] as const) {
    const cell = page.getByTestId(`achieved-${name}`);
    await expect(cell).toHaveAttribute('data-met', 'true');
    await expect(cell).toContainText(': met');
    expect(Math.abs(Number(await cell.getAttribute('data-achieved')) * 100 - Number(target.toFixed(1)))).toBeLessThanOrEqual(tolerance);
    // The reading on screen is the body found.
    expect(Math.abs((await cm(page, name)) - target)).toBeLessThanOrEqual(tolerance + 0.06);
  }
  // The sliders moved to the body found.
  expect(Number(await page.getByTestId('shape-slider-0').inputValue())).not.toBe(0);
  // A row without a target shows no achieved line.
  await expect(page.getByTestId('achieved-hip_girth')).toBeHidden();
});

test('in a segment view, targets act on that segment: the torso meets a waist target, stature takes none', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  const waist = await cm(page, 'waist_girth');
  await page.getByTestId('shape-segment').selectOption('torso');
  await expect(page.getByTestId('target-stature')).toBeDisabled();
  await expect(page.getByTestId('target-waist_girth')).toBeEnabled();
  await expect(page.getByTestId('target-scope')).toContainText('targets act on the torso model');
  const target = waist + 3;
  await page.getByTestId('target-waist_girth').fill(target.toFixed(1));
  await page.getByTestId('find-body').click();
  await expect(page.locator('body')).toHaveAttribute('data-find-body', 'done');
  await shapeReady(page);
  await expect(page.getByTestId('achieved-waist_girth')).toHaveAttribute('data-met', 'true');
  expect(Math.abs((await cm(page, 'waist_girth')) - Number(target.toFixed(1)))).toBeLessThanOrEqual(0.56);
  await expect(page.getByTestId('shape-segment-state')).toContainText('has its own shape');
});

/** The files `act` downloads, once `done` holds and `count` downloads have started (the page may finish before the last download event arrives). */
async function downloads(page: Page, act: () => Promise<void>, done: () => Promise<void>, count: number): Promise<Map<string, Buffer>> {
  const files = new Map<string, Buffer>();
  const pending: Promise<void>[] = [];
  const listener = (d: Download) => {
    pending.push(d.path().then((path) => void files.set(d.suggestedFilename(), readFileSync(path))));
  };
  page.on('download', listener);
  await act();
  await done();
  await expect.poll(() => pending.length).toBe(count);
  await Promise.all(pending);
  page.off('download', listener);
  return files;
}

/** The files of a ZIP archive of stored (uncompressed) entries, each checked against its CRC-32. */
function unzipStored(archive: Buffer): Map<string, Buffer> {
  const files = new Map<string, Buffer>();
  let at = 0;
  while (archive.readUInt32LE(at) === 0x04034b50) {
    expect(archive.readUInt16LE(at + 8)).toBe(0);
    const crc = archive.readUInt32LE(at + 14);
    const size = archive.readUInt32LE(at + 18);
    const nameLength = archive.readUInt16LE(at + 26);
    const extra = archive.readUInt16LE(at + 28);
    const name = archive.toString('utf8', at + 30, at + 30 + nameLength);
    const data = archive.subarray(at + 30 + nameLength + extra, at + 30 + nameLength + extra + size);
    expect(zlib.crc32(data), name).toBe(crc);
    files.set(name, Buffer.from(data));
    at += 30 + nameLength + extra + size;
  }
  // The central directory follows, then its end record, which counts the entries.
  const end = archive.lastIndexOf(Buffer.from([0x50, 0x4b, 0x05, 0x06]));
  expect(archive.readUInt32LE(end + 16)).toBe(at);
  expect(archive.readUInt16LE(end + 10)).toBe(files.size);
  return files;
}

test('the population shows where the body sits; boundary manikins of two measurements are listed, shown and exported', async ({ page }) => {
  await page.goto('/');
  await shapeReady(page);
  await expect(page.locator('body')).toHaveAttribute('data-population-ready', 'true', { timeout: 90_000 });
  await expect(page.getByTestId('population-status')).toContainText('300 bodies sampled from the model');
  await expect(page.getByTestId('correlation-map')).toBeVisible();
  // The mean body sits near the middle of the population in stature.
  const percentile = async () => Number(await page.getByTestId('percentile-stature').getAttribute('data-percentile'));
  await expect(page.getByTestId('percentile-stature')).toHaveText(/^P\d+$/);
  const atMean = await percentile();
  expect(atMean).toBeGreaterThan(20);
  expect(atMean).toBeLessThan(80);
  // A taller body (targets, so the direction is known) sits higher; the lookup follows the body.
  const stature = await cm(page, 'stature');
  await page.getByTestId('target-stature').fill((stature + 8).toFixed(1));
  await page.getByTestId('find-body').click();
  await expect(page.locator('body')).toHaveAttribute('data-find-body', 'done');
  await shapeReady(page);
  await expect.poll(percentile).toBeGreaterThan(atMean + 10);

  // Fewer than two measurements: refused with the reason.
  await page.getByTestId('manikin-pick-stature').check();
  await page.getByTestId('manikin-compute').click();
  await expect(page.getByTestId('manikin-status')).toHaveText('Pick 2, 3 or 4 measurements (1 picked).');
  await page.getByTestId('manikin-pick-waist_girth').check();
  await expect(page.getByTestId('manikin-coverage')).toHaveValue('90');
  await page.getByTestId('manikin-compute').click();
  await expect(page.locator('body')).toHaveAttribute('data-manikins', '8', { timeout: 60_000 });
  await expect(page.getByTestId('manikin-list').locator('li')).toHaveCount(8);

  // Clicking a manikin shows it: the stature on screen is the one listed.
  const listed = (await page.getByTestId('manikin-2').innerText()).match(/Stature (\d+\.\d) cm/)![1]!;
  await page.getByTestId('manikin-2').click();
  await expect(page.getByTestId('measure-stature')).toHaveText(`${listed} cm`);

  // One download: an archive of them all.
  const archives = await downloads(
    page,
    () => page.getByTestId('manikin-export').click(),
    () => expect(page.locator('body')).toHaveAttribute('data-manikins-exported', '8'),
    1,
  );
  expect([...archives.keys()]).toEqual(['manikins.zip']);
  const files = unzipStored(archives.get('manikins.zip')!);
  const names = [...files.keys()].sort();
  expect(names).toEqual(['manikin_01.ply', 'manikin_02.ply', 'manikin_03.ply', 'manikin_04.ply', 'manikin_05.ply', 'manikin_06.ply', 'manikin_07.ply', 'manikin_08.ply', 'manikins.csv', 'manikins.glb']);
  const glb = files.get('manikins.glb')!;
  expect(glb.toString('latin1', 0, 4)).toBe('glTF');
  expect(glb.readUInt32LE(4)).toBe(2);
  expect(glb.readUInt32LE(8)).toBe(glb.length);
  const json = JSON.parse(glb.toString('utf8', 20, 20 + glb.readUInt32LE(12))) as { meshes: unknown[] };
  expect(json.meshes).toHaveLength(8);
  for (let i = 1; i <= 8; i++) {
    const ply = files.get(`manikin_0${i}.ply`)!;
    const header = ply.toString('latin1', 0, ply.indexOf('end_header') + 10);
    expect(header.startsWith('ply\n')).toBe(true);
    expect(header).toMatch(/element vertex 13380\n/);
    expect(header).toMatch(/element face 26756\n/);
  }
  const rows = files.get('manikins.csv')!.toString('utf8').trim().split('\n').map((l) => l.split(','));
  expect(rows).toHaveLength(9);
  const header = rows[0]!;
  expect(header[0]).toBe('name');
  const statureCol = header.indexOf('stature');
  expect(statureCol).toBeGreaterThan(0);
  for (const [i, row] of rows.slice(1).entries()) {
    expect(row).toHaveLength(header.length);
    expect(row[0]).toBe(`manikin_0${i + 1}`);
    expect(Number(row[statureCol])).toBeGreaterThan(1.2);
    expect(Number(row[statureCol])).toBeLessThan(2.2);
  }
});

test('measuring the population shows progress and can be cancelled, then computed again', async ({ page }) => {
  // Click Cancel as soon as the first progress shows it (in the page, so a fast run cannot finish first).
  await page.addInitScript(() => {
    new MutationObserver((_, observer) => {
      const cancel = document.querySelector<HTMLButtonElement>('[data-testid="population-cancel"]');
      if (!cancel || cancel.hidden) return;
      observer.disconnect();
      document.body.dataset.populationProgressSeen = document.querySelector('[data-testid="population-status"]')?.textContent ?? '';
      cancel.click();
    }).observe(document, { subtree: true, childList: true, attributes: true, attributeFilter: ['hidden'] });
  });
  await page.goto('/');
  await shapeReady(page);
  await expect(page.locator('body')).toHaveAttribute('data-population-ready', 'cancelled');
  await expect(page.locator('body')).toHaveAttribute('data-population-progress-seen', /Measuring the training subjects and sampled bodies… \d+ %/);
  await expect(page.getByTestId('population-status')).toHaveText('Cancelled: the population was not computed.');
  await expect(page.getByTestId('percentile-stature')).toHaveCount(0);
  // The body shown lives in another worker: it still answers.
  const before = await page.getByTestId('measure-stature').innerText();
  await page.getByTestId('shape-slider-0').fill('2');
  await expect(page.getByTestId('measure-stature')).not.toHaveText(before);
  await page.getByTestId('population-compute').click();
  await expect(page.locator('body')).toHaveAttribute('data-population-ready', 'true', { timeout: 90_000 });
  await expect(page.getByTestId('percentile-stature')).toHaveText(/^P\d+$/);
});
