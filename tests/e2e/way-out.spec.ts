// A way out of a wrong estimate in the app (issue 31): the sample scan (z up, facing −y,
// millimetres) estimated with Up = −z chosen — a body standing on its head — says its estimate
// failed and why, its confidences say so, the fit made from it is flagged and Keep asks first
// (kept only when confirmed); the person picks Up = +z and Facing = −y, estimates again (a
// landmark moved by hand stays where it was put) and aligns: the fit is as good as the sample's
// (≤ 2 mm RMS) and nothing is flagged about the estimate.
// An estimate cancelled after a failed one keeps the failed one's landmarks, and its verdict on
// them stays on screen. An estimate back to front (the facing chosen wrong) is re-anchored by
// five given landmarks, and the page says the landmarks, not the choice, set the facing. A face
// placed on the throat is named with the landmarks to check first, and three clicked on the face,
// each from its close-up, re-pose the head; a click through a hole places nothing, on a scan
// whose parts face different ways and whose triangles face both ways too. A scan wound inwards, or with its triangles facing both
// ways, is turned before it is fitted, and fits as the sample does; one facing both ways is drawn as the sample is.
import { gunzipSync } from 'node:zlib';
import { expect, test, type Page } from '@playwright/test';
import { dropFiles } from './fixtures';
import { partialCsv, sampleFile } from './samples';
import { cancelEstimateWhenItRuns, openWithSample } from './steps';
import { facingBothWays, synthFolder, turnedInsideOut, withInsideOutBox } from './synth';

const body = (page: Page) => page.locator('body');
const row = (page: Page, name: string) => page.getByTestId('landmark-list').locator(`li[data-name="${name}"]`);

/** Clicks the estimate button (its label is checked) and waits for estimate number `n` of the page. */
async function estimate(page: Page, label: string, n: number): Promise<void> {
  await expect(page.getByTestId('landmarks-estimate')).toHaveText(label);
  await page.getByTestId('landmarks-estimate').click();
  await expect(body(page)).toHaveAttribute('data-estimates', String(n), { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-state', 'done');
}

/** Aligns once the warp of the current set is done; returns the fit's RMS (mm) and quality flags. */
async function align(page: Page): Promise<{ rms: number; flags: string }> {
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await page.getByTestId('align-run').click();
  await expect(body(page)).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
  const rms = Number(await page.getByTestId('align-rms').getAttribute('data-rms-mm'));
  return { rms, flags: (await page.getByTestId('align-check').getAttribute('data-flags')) ?? '' };
}

/**
 * Of the body's pixels in `a` (a PNG of the viewport: those brighter than the dark background and
 * its grid), the share whose colour in `b` (as large) differs by at least `by` (of 255) in some
 * channel. Both are decoded in the page.
 */
async function pixelsApart(page: Page, a: Buffer, b: Buffer, by: number): Promise<number> {
  return page.evaluate(
    async ({ images, by }) => {
      const pixels = await Promise.all(
        images.map(async (base64) => {
          const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
          const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
          const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
          const context = canvas.getContext('2d')!;
          context.drawImage(bitmap, 0, 0);
          return context.getImageData(0, 0, bitmap.width, bitmap.height).data;
        }),
      );
      const [p, q] = pixels as [Uint8ClampedArray, Uint8ClampedArray];
      if (p.length !== q.length) return 1;
      let [apart, body] = [0, 0];
      for (let i = 0; i < p.length; i += 4) {
        if (Math.max(p[i]!, p[i + 1]!, p[i + 2]!) < 120) continue;
        body++;
        if (Math.max(Math.abs(p[i]! - q[i]!), Math.abs(p[i + 1]! - q[i + 1]!), Math.abs(p[i + 2]! - q[i + 2]!)) >= by) apart++;
      }
      return body > 0 ? apart / body : 1;
    },
    { images: [a.toString('base64'), b.toString('base64')], by },
  );
}

/** The confidences (%) the list shows for the estimated landmarks. */
async function confidences(page: Page): Promise<number[]> {
  const texts = await page.getByTestId('landmark-list').locator('li[data-state="estimated"] .confidence').allTextContents();
  return texts.map((t) => parseInt(t, 10));
}

test('an estimate in a wrong frame says it failed; choosing up and estimating again gives a good fit', async ({ page }) => {
  test.setTimeout(600_000);
  await openWithSample(page, [sampleFile('scan_001.ply.gz')]);
  // The frame found by itself: a good estimate stays quiet, and Estimate stays on offer.
  await expect(body(page)).toHaveAttribute('data-estimates', '1', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'good');
  await expect(page.getByTestId('estimate-check')).toHaveCount(0);
  await expect(page.getByTestId('estimate-up')).toHaveValue('auto');
  await expect(page.getByTestId('estimate-facing')).toBeDisabled();

  // The body stood on its head: Up = −z.
  await page.getByTestId('estimate-up').selectOption('-z');
  await expect(body(page)).toHaveAttribute('data-orientation', '-z auto');
  await expect(page.getByTestId('estimate-facing')).toBeEnabled();
  // Only the axes across −z can be the facing.
  expect(await page.getByTestId('estimate-facing').locator('option').allTextContents()).toEqual(['auto', '+x', '−x', '+y', '−y']);
  await estimate(page, 'Estimate again, keeping my edits', 2);
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'failed');
  await expect(page.getByTestId('estimate-assumed')).toContainText("up is the scan's -z axis (as chosen)");
  const check = page.getByTestId('estimate-check');
  await expect(check).toHaveAttribute('data-verdict', 'failed');
  await expect(check).toContainText('The estimate failed its own check');
  await expect(check).toContainText('choose which way is up');
  expect(await check.locator('li').count()).toBeGreaterThan(0);
  // Nothing says all is well, and no estimated landmark keeps a confidence above 10 %.
  await expect(page.getByTestId('landmarks-suspicious-none')).toHaveCount(0);
  const failedConfidences = await confidences(page);
  expect(failedConfidences).toHaveLength(73);
  expect(Math.max(...failedConfidences)).toBeLessThanOrEqual(10);

  // Aligned from the failed estimate: flagged in words, and Keep asks first.
  const wrong = await align(page);
  expect(wrong.flags.split(' ')).toContain('landmark_estimate');
  await expect(page.getByTestId('align-check')).toContainText('landmark estimate: ');
  await expect(page.getByTestId('align-keep')).toContainText('flagged: ');
  await expect(page.getByTestId('align-keep')).toContainText('doubtful landmark estimate');
  await page.getByTestId('align-keep').click();
  const question = page.getByTestId('align-keep-question');
  await expect(question).toContainText('This fit is flagged: ');
  await expect(question).toContainText('landmark estimate: the landmark estimate failed');
  await expect(question).toContainText('Keep it all the same?');
  await page.getByTestId('align-keep-cancel').click();
  await expect(question).toHaveCount(0);
  await expect(body(page)).not.toHaveAttribute('data-subjects', /./);
  // Asked again and confirmed, it is kept.
  await page.getByTestId('align-keep').click();
  await page.getByTestId('align-keep-confirm').click();
  await expect(body(page)).toHaveAttribute('data-subjects', '1');
  await expect(page.getByTestId('align-keep')).toHaveText('Kept ✓');

  // The right way up, a landmark moved by hand, and the estimate again: the move is kept as placed.
  await page.getByTestId('estimate-up').selectOption('+z');
  await expect(body(page)).toHaveAttribute('data-orientation', '+z auto');
  await page.getByTestId('estimate-facing').selectOption('-y');
  await expect(body(page)).toHaveAttribute('data-orientation', '+z -y');
  await estimate(page, 'Estimate again, keeping my edits', 3);
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'good');
  await expect(page.getByTestId('estimate-check')).toHaveCount(0);
  await expect(page.getByTestId('estimate-assumed')).toContainText("up is the scan's +z axis (as chosen) and it faces -y (as chosen)");
  expect(Math.max(...(await confidences(page)))).toBeGreaterThan(10);

  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
  await row(page, 'Substernale').click();
  const [x, y] = (await body(page).getAttribute('data-selected-marker-px'))!.split(',').map(Number);
  const canvas = (await page.getByTestId('viewport-canvas').boundingBox())!;
  await page.mouse.click(canvas.x + x! + 9, canvas.y + y! + 7);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  const placed = await row(page, 'Substernale').getAttribute('data-position-mm');
  await estimate(page, 'Estimate again, keeping my edits', 4);
  await expect(row(page, 'Substernale')).toHaveAttribute('data-state', 'edited');
  await expect(row(page, 'Substernale')).toHaveAttribute('data-position-mm', placed!);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="estimated"]')).toHaveCount(72);
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'good');

  // Aligned: as good as the sample fits (0.92 mm with its true landmarks), nothing about the estimate.
  const right = await align(page);
  expect(right.rms).toBeLessThanOrEqual(2);
  expect(right.flags.split(' ')).not.toContain('landmark_estimate');
  await expect(page.getByTestId('align-check')).not.toContainText('landmark estimate');
});

test('an estimate cancelled after a failed one leaves the failed verdict on the landmarks it kept', async ({ page }) => {
  test.setTimeout(300_000);
  await openWithSample(page, [sampleFile('scan_001.ply.gz')]);
  await expect(body(page)).toHaveAttribute('data-estimates', '1', { timeout: 120_000 });
  await page.getByTestId('estimate-up').selectOption('-z');
  await estimate(page, 'Estimate again, keeping my edits', 2);
  await expect(page.getByTestId('estimate-check')).toHaveAttribute('data-verdict', 'failed');
  // Estimate again, cancelled as soon as it runs.
  await cancelEstimateWhenItRuns(page);
  await page.getByTestId('landmarks-estimate').click();
  await expect(page.getByTestId('estimate-cancelled')).toBeVisible({ timeout: 60_000 });
  await expect(body(page)).toHaveAttribute('data-estimates', '2');
  // The landmarks kept are the failed estimate's: it still says so, and nothing says all is well.
  await expect(page.getByTestId('estimate-check')).toHaveAttribute('data-verdict', 'failed');
  await expect(page.getByTestId('estimate-check')).toContainText('choose which way is up');
  await expect(page.getByTestId('landmarks-suspicious-none')).toHaveCount(0);
  expect(Math.max(...(await confidences(page)))).toBeLessThanOrEqual(10);
});

test('five given landmarks overrule a facing chosen wrong, and the page says what set the frame', async ({ page }) => {
  test.setTimeout(600_000);
  // Without landmarks, the scan's shape says which end is up and the feet which way it faces.
  await openWithSample(page, [sampleFile('scan_001.ply.gz')]);
  await expect(body(page)).toHaveAttribute('data-estimates', '1', { timeout: 120_000 });
  await expect(page.getByTestId('estimate-assumed')).toContainText("up is the scan's +z axis (from the scan's shape) and it faces -y (from the feet)");

  // Facing chosen wrong: the estimate goes back to front and does not call itself good.
  await page.getByTestId('estimate-up').selectOption('+z');
  await page.getByTestId('estimate-facing').selectOption('+y');
  await estimate(page, 'Estimate again, keeping my edits', 2);
  await expect(page.getByTestId('estimate-assumed')).toContainText("up is the scan's +z axis (as chosen) and it faces +y (as chosen)");
  await expect(body(page)).not.toHaveAttribute('data-estimate-verdict', 'good');

  // Five landmarks on the face, the neck and the shoulders and a hip bone (a partial file, as a
  // person clicks them): they re-anchor the estimate the right way round, over the choice, and
  // the page says the landmarks set the facing — not "as chosen".
  const CLICKED = ['Sellion', 'Suprasternale', 'Rt. Acromion', 'Lt. Acromion', 'Rt. ASIS'];
  await dropFiles(page, [partialCsv((name) => CLICKED.includes(name))]);
  await expect(page.getByTestId('landmark-list').locator('li[data-state="given"]')).toHaveCount(5, { timeout: 60_000 });
  await estimate(page, 'Estimate again, keeping my edits', 4);
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'good');
  await expect(page.getByTestId('estimate-assumed')).toContainText("up is the scan's +z axis (as chosen) and it faces -y (from given landmarks, not the chosen +y)");
  await expect(page.getByTestId('landmark-list').locator('li[data-state="estimated"]')).toHaveCount(68);

  // Aligned: as good as the sample fits (0.92 mm with its true landmarks), nothing about the estimate.
  const right = await align(page);
  expect(right.rms).toBeLessThanOrEqual(2);
  expect(right.flags.split(' ')).not.toContain('landmark_estimate');
});

test('a scan wound inwards is turned to face out, estimated and aligned as the sample is, and the page says so', async ({ page }) => {
  test.setTimeout(300_000);
  // The sample scan with every triangle's corners in the other order, as some exporters write:
  // left so, its normals pointed into the body and nothing matched the template's.
  const inwards = { name: 'inwards.ply', bytes: turnedInsideOut(gunzipSync(sampleFile('scan_001.ply.gz').bytes)) };
  await page.goto('./');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  await dropFiles(page, [inwards]);
  await expect(page.getByTestId('scan-winding')).toHaveText('inwards');
  await expect(body(page)).toHaveAttribute('data-estimates', '1', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'good');
  await expect(page.getByTestId('estimate-assumed')).toContainText("Turned: the scan's triangles faced into the body");
  const fit = await align(page);
  expect(fit.rms).toBeLessThanOrEqual(2);
  expect(fit.flags).toBe('');
  await expect(page.getByTestId('align-check')).toContainText("Turned: the scan's triangles faced into the body");
});

test('a scan whose triangles face both ways is drawn as the sample is, turned to agree and aligned as the sample is, and the page says so', async ({ page }) => {
  test.setTimeout(300_000);
  // The sample scan with about half its triangles' corners in the other order: left so, its
  // normals said nothing and the fit from the sample's own landmarks folded and left the scan
  // uncovered (the end-to-end test in crate/tests/subject_paths.rs).
  const oneWay = gunzipSync(sampleFile('scan_001.ply.gz').bytes);
  await openWithSample(page, [{ name: 'one-way.ply', bytes: oneWay }, sampleFile('landmarks_001.csv')]);
  const drawnOneWay = await page.getByTestId('viewport-canvas').screenshot();
  const bothWays = { name: 'both-ways.ply', bytes: facingBothWays(oneWay) };
  await openWithSample(page, [bothWays, sampleFile('landmarks_001.csv')]);
  await expect(page.getByTestId('scan-winding')).toHaveText('mixed');
  // It is drawn as the sample is: each triangle facing in is shown turned, and lit as one surface
  // (0.09 % of the body's pixels 16 or more apart). Drawn in the file's own order its shading was
  // speckled: 14 % apart, and 10 % with the normals turned but not the triangles shown.
  const apart = await pixelsApart(page, drawnOneWay, await page.getByTestId('viewport-canvas').screenshot(), 16);
  expect(apart).toBeLessThan(0.01);
  // Its holes are counted on its triangles turned to agree: within a tenth of the sample's 107
  // (112 here; the rims traced on the file's own order had made thousands of them).
  const holes = Number((await page.getByTestId('scan-holes').textContent())!.replace(/,/g, ''));
  expect(Math.abs(holes - 107)).toBeLessThanOrEqual(11);
  const fit = await align(page);
  expect(fit.rms).toBeLessThanOrEqual(2);
  expect(fit.flags).toBe('');
  await expect(page.getByTestId('align-check')).toContainText('faced the other way from their neighbours');
});

test("a face placed on the throat names the face's landmarks to check first; Sellion and the Tragions clicked re-pose the head", async ({ page }) => {
  test.setTimeout(600_000);
  // Raw scanner output of the held-out population (parts, crown cut, floor, slices; ≈ 100K
  // vertices): the estimate puts its twelfth subject's face on the throat (the blind zoo 8461's
  // `raw` scan, as `crate/tests/zoo_estimate.rs` has it).
  const files = synthFolder(12, 8461, 4, ['--profile', 'held-out', '--scanner-class', 'raw']);
  const file = (name: string) => files.find((f) => f.name === name)!;
  const truth = new Map(
    file('landmarks_012.csv').bytes.toString('utf8').trim().split('\n').slice(1).map((line) => {
      const [name, ...xyz] = line.split(',');
      return [name!, xyz.map(Number)] as const;
    }),
  );
  const off = async (name: string) => {
    const at = (await row(page, name).getAttribute('data-position-mm'))!.split(',').map(Number);
    return Math.hypot(...at.map((v, i) => v - truth.get(name)![i]!));
  };
  await page.goto('./?debug');
  await expect(body(page)).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
  // With a box turned inside out beside its feet, the scan's parts disagree on which way they
  // face; and with about half its triangles in the other order, as a mesh never oriented may
  // be, no part is wound one way. The core still says which way each triangle faces, once its
  // triangles are brought to agree.
  await dropFiles(page, [{ name: 'scan_012.ply', bytes: facingBothWays(withInsideOutBox(file('scan_012.ply').bytes)) }]);
  await expect(page.getByTestId('scan-winding')).toHaveText('mixed');
  await expect(body(page)).toHaveAttribute('data-estimates', '1', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'doubtful');
  expect(await off('Rt. Infraorbitale')).toBeGreaterThan(50);
  await expect(page.getByTestId('estimate-check')).toContainText('The face is turned');
  await expect(page.getByTestId('estimate-way-out')).toContainText('Pick each landmark named above');
  // The face's landmarks are named first, each a button that picks it and shows it up close.
  const first = page.getByTestId('estimate-check-first');
  await expect(first.locator('button').first()).toHaveText('Sellion');
  await expect(body(page)).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });

  // Sellion and the Tragions clicked where they truly are on the scan, each from its close-up.
  const canvas = (await page.getByTestId('viewport-canvas').boundingBox())!;
  let throughHoles = 0;
  for (const name of ['Sellion', 'Rt. Tragion', 'Lt. Tragion']) {
    await first.locator(`button[data-name="${name}"]`).click();
    await expect(body(page)).toHaveAttribute('data-selected-landmark', name);
    await expect(page.getByTestId('view-whole')).toBeVisible();
    const metres = truth.get(name)!.map((v) => v / 1000);
    const px = await page.evaluate(
      (p) => (window as unknown as { bodyspaceDebug: { canvasPoint: (p: number[]) => [number, number] | null } }).bodyspaceDebug.canvasPoint(p),
      metres,
    );
    // The scan has holes (a raw scanner's slices, shadowed ears): a click that falls through one
    // would land on the inside of the far side of the head; it places nothing and says so, and a
    // person clicks again beside it.
    const beside = [[0, 0], ...[2, 4, 6, 8].flatMap((r) => [0, 1, 2, 3, 4, 5, 6, 7].map((k) => [r * Math.cos((k * Math.PI) / 4), r * Math.sin((k * Math.PI) / 4)]))];
    for (const [dx, dy] of beside as [number, number][]) {
      await page.mouse.click(canvas.x + px![0] + dx, canvas.y + px![1] + dy);
      const placed = await expect(row(page, name))
        .toHaveAttribute('data-state', 'edited', { timeout: 2_000 })
        .then(() => true, () => false);
      if (!placed && (await page.getByTestId('landmark-through-hole').isVisible())) {
        await expect(page.getByTestId('landmark-through-hole')).toContainText(`${name} was not placed: that click went through a hole`);
        throughHoles++;
      }
      if (placed && (await off(name)) < 8) break;
    }
    expect(await off(name)).toBeLessThan(8);
  }
  // The truth's Lt. Tragion lies over a hole in this scan (measured: the click there had put it
  // on the right side of the head, 141 mm off).
  expect(throughHoles).toBeGreaterThan(0);
  await expect(page.getByTestId('landmark-through-hole')).toHaveCount(0);
  await page.getByTestId('view-whole').click();
  await expect(page.getByTestId('view-whole')).toBeHidden();

  // Estimated again keeping them: they re-pose the head, and the estimate is good.
  await page.getByTestId('landmarks-estimate').click();
  await expect(body(page)).toHaveAttribute('data-estimates', '2', { timeout: 120_000 });
  await expect(body(page)).toHaveAttribute('data-estimate-verdict', 'good');
  await expect(page.getByTestId('landmark-list').locator('li[data-state="edited"]')).toHaveCount(3);
  expect(await off('Rt. Infraorbitale')).toBeLessThan(25);
  expect(await off('Supramenton')).toBeLessThan(25);
});
