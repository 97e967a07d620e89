// The page at the window widths people use (1280–1920 × 900): with the sample subject open,
// warped and aligned, no value in a panel is cut off, no panel scrolls sideways, and the 3D
// view sits between the columns, so the bodies are never drawn under a panel; the shape body
// brought back beside a scan is in view; the batch table's headers and statuses are whole.
import { expect, test, type Page } from '@playwright/test';
import { dropFiles, waitForLoads } from './fixtures';
import { sampleSubject } from './samples';
import { shapeReady, slide } from './steps';
import { synthSubjects } from './synth';

const WIDTHS = [1280, 1400, 1600, 1920];
const HEIGHT = 900;

/** Elements of the panels that hold a value a person reads (or picks). */
const VALUE_CELLS = [
  'dd',
  'td',
  'th',
  'output',
  'select',
  'input[type=number]',
  'input.small-input',
  '.file-name',
  '.counts > span',
  '.slider-value',
  '.slider-explained',
  '.slider-label',
  '.heat-ticks > *',
  'ul.landmark-list li .name',
  'ul.swatches li',
  '.toggle',
]
  .map((s) => `.workspace .panel ${s}`)
  .join(', ');

interface Clipped {
  what: string;
  text: string;
  need: number;
  have: number;
}

/**
 * Every visible value cell whose content is wider than its box (1 px allowed), and every panel
 * that scrolls sideways. A `select` clips its chosen option without growing its scrollWidth, so
 * a copy holding only that option, at its natural width beside it, says how wide it needs to be.
 */
async function clippedText(page: Page): Promise<Clipped[]> {
  return page.evaluate((selector) => {
    const out: { what: string; text: string; need: number; have: number }[] = [];
    const describe = (e: Element) =>
      `${e.tagName.toLowerCase()}${e.getAttribute('data-testid') ? `[data-testid=${e.getAttribute('data-testid')}]` : ''}${
        e.className && typeof e.className === 'string' ? `.${e.className.split(' ').join('.')}` : ''
      } in #${e.closest('section[id], aside[id]')?.id ?? '?'}`;
    for (const e of document.querySelectorAll<HTMLElement>(selector)) {
      if (e.offsetParent === null || e.closest('[hidden]')) continue;
      if (e instanceof HTMLSelectElement) {
        const text = e.selectedOptions[0]?.textContent ?? '';
        const copy = document.createElement('select');
        copy.className = e.className;
        copy.append(new Option(text));
        copy.style.cssText = 'position:absolute;visibility:hidden;width:auto;max-width:none;min-width:0';
        e.parentElement!.append(copy);
        const need = copy.getBoundingClientRect().width;
        const have = e.getBoundingClientRect().width;
        copy.remove();
        if (need > have + 1) out.push({ what: describe(e), text, need, have });
      } else if (e.scrollWidth > e.clientWidth + 1) {
        const text = e instanceof HTMLInputElement ? e.value : (e.textContent ?? '');
        out.push({ what: describe(e), text, need: e.scrollWidth, have: e.clientWidth });
      }
    }
    for (const panel of document.querySelectorAll<HTMLElement>('.workspace .panel')) {
      if (panel.scrollWidth > panel.clientWidth + 1) {
        out.push({ what: `panel #${panel.id || panel.className} scrolls sideways`, text: '', need: panel.scrollWidth, have: panel.clientWidth });
      }
    }
    return out;
  }, VALUE_CELLS);
}

/**
 * The 3D canvas lies between the left column and the right-hand panels, and what the camera was
 * last aimed at lands on it: `data-framed-ndc` is that box's extent in normalised device
 * coordinates (the canvas is −1…1). The box's corners stand out of the bodies, so a little past
 * ±1 is still a whole body in view; a body beside the view would be far past it.
 */
async function canvasBetweenPanels(page: Page): Promise<void> {
  const box = async (selector: string) => (await page.locator(selector).boundingBox())!;
  const canvas = await box('[data-testid=viewport-canvas]');
  const left = await box('.left-column');
  const landmarks = await box('#landmarks-panel');
  const shape = await box('#shape-panel');
  expect(canvas.x).toBeGreaterThanOrEqual(left.x + left.width - 1);
  expect(canvas.x + canvas.width).toBeLessThanOrEqual(Math.min(landmarks.x, shape.x) + 1);
  expect(canvas.width).toBeGreaterThan(300);
  // Polled: the attribute follows the next frame, which may not have run yet.
  await expect
    .poll(async () => {
      const ndc = (await page.locator('#viewport').getAttribute('data-framed-ndc'))?.split(',').map(Number) ?? [];
      return ndc.length === 4 ? Math.max(...ndc.map(Math.abs)) : Infinity;
    })
    .toBeLessThan(1.05);
}

for (const width of WIDTHS) {
  test(`at ${width} × ${HEIGHT} every panel value is readable and the view sits between the panels`, async ({ page }, info) => {
    test.setTimeout(300_000);
    await page.setViewportSize({ width, height: HEIGHT });
    await page.goto('./');
    await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
    await expect(page.locator('body')).toHaveAttribute('data-shape-settled', 'true');
    // The template and the shape body beside it, framed together.
    await canvasBetweenPanels(page);
    await page.screenshot({ path: info.outputPath(`layout-${width}-start.png`) });

    await dropFiles(page, sampleSubject());
    await waitForLoads(page, 1);
    await expect(page.locator('body')).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
    await expect(page.getByTestId('scan-vertices')).toBeVisible();
    await expect(page.getByTestId('rbf-residuals')).toBeVisible();
    await canvasBetweenPanels(page);
    await page.screenshot({ path: info.outputPath(`layout-${width}.png`) });
    await page.getByTestId('rbf-residuals').scrollIntoViewIfNeeded();
    await page.screenshot({ path: info.outputPath(`layout-${width}-warp.png`) });
    expect(await clippedText(page)).toEqual([]);

    // The Align panel's results (Table 1 numbers, iterations, legend) as well.
    await page.getByTestId('align-run').click();
    await expect(page.locator('body')).toHaveAttribute('data-align-state', 'done', { timeout: 240_000 });
    await page.getByTestId('align-rms').scrollIntoViewIfNeeded();
    await page.screenshot({ path: info.outputPath(`layout-${width}-align.png`) });
    expect(await clippedText(page)).toEqual([]);
  });
}

/** The largest |NDC| of everything shown (`data-shown-ndc`): past ≈ 1.05 a body is cut off by the canvas's edge. */
async function shownExtent(page: Page): Promise<number> {
  const ndc = (await page.locator('#viewport').getAttribute('data-shown-ndc'))?.split(',').map(Number) ?? [];
  return ndc.length === 4 ? Math.max(...ndc.map(Math.abs)) : Infinity;
}

for (const width of [1280, 1920]) {
  test(`at ${width} × ${HEIGHT} the shape body brought back beside a scan is in view, and the batch table is not cramped`, async ({ page }, info) => {
    test.setTimeout(300_000);
    await page.setViewportSize({ width, height: HEIGHT });
    await page.goto('./');
    await expect(page.locator('body')).toHaveAttribute('data-template-ready', 'true', { timeout: 60_000 });
    await shapeReady(page);
    const [landmarks, scan] = synthSubjects(1, 41);
    await dropFiles(page, [scan!, landmarks!]);
    await waitForLoads(page, 1);
    await expect(page.locator('body')).toHaveAttribute('data-rbf-state', 'done', { timeout: 60_000 });
    await expect(page.locator('body')).toHaveAttribute('data-shape-shown', 'false');
    // A slider brings the shape body back beside the scan: the view takes both in.
    await slide(page, 0, 1.5);
    await expect(page.locator('body')).toHaveAttribute('data-shape-shown', 'true');
    await expect.poll(() => shownExtent(page)).toBeLessThan(1.05);
    await page.screenshot({ path: info.outputPath(`scan-and-shape-${width}.png`) });

    // A batch: headers and values whole, each status on one line.
    await dropFiles(page, synthSubjects(3, 42));
    await waitForLoads(page, 2);
    await expect(page.locator('body')).toHaveAttribute('data-batch-finished', '3', { timeout: 240_000 });
    await page.getByTestId('batch-table').scrollIntoViewIfNeeded();
    await page.screenshot({ path: info.outputPath(`batch-${width}.png`) });
    expect(await clippedText(page)).toEqual([]);
    // One line box per line of text: a wrapped status has two.
    const lines = await page.getByTestId('batch-status').evaluateAll((cells) =>
      cells.map((c) => {
        const range = document.createRange();
        range.selectNodeContents(c);
        return new Set([...range.getClientRects()].map((r) => Math.round(r.top))).size;
      }),
    );
    expect(lines).toEqual([1, 1, 1]);
  });
}
