// The batch on the page: the Batch panel wired to the batch, its table drawn at once on a change
// of state and at most once a frame for progress, and a batch fit shown on the template view
// with its distance heat map.
import type { CoreClient } from '../client/core-client';
import { rbfParams } from '../shared/align-types';
import { orientationText } from '../shared/orientation';
import { BatchPanel } from '../ui/batch-panel';
import type { ErrorBanner } from '../ui/error-banner';
import { distanceHeat } from '../view/heat-colours';
import type { Viewer } from '../view/viewer';
import { FITTED_COLOUR } from './align-step';
import { Batch, type BatchSettings } from './batch';
import { uprightTransform } from './display-frame';
import type { Session } from './session';
import type { ShapeSpace } from './shape-space';
import type { TemplateView } from './template-view';
import type { WarpStep } from './warp-step';

export interface BatchPage {
  /** The main core worker (pairing); the batch's own workers are its pool's. */
  client: CoreClient<'core'>;
  viewer: Viewer;
  session: Session;
  templateView: TemplateView;
  warpStep: WarpStep;
  shapeSpace: ShapeSpace;
  banner: ErrorBanner;
}

/** Makes the page's batch, with the Template panel's resolution and the RBF panel's settings. */
export function startBatch(page: BatchPage): Batch {
  const { viewer, templateView, banner } = page;
  let drawScheduled = false;
  const draw = () => panel.render(batch.all, batch.summary(), { orientation: batch.orientation, alignableAgain: batch.alignableAgain().length });
  const batch: Batch = new Batch(
    page.client,
    (): BatchSettings | null => {
      const resolution = templateView.data?.resolution;
      const rbf = page.warpStep.panel.current;
      return resolution ? { resolution, options: { params: rbf ? { rbf: rbfParams(rbf) } : {}, orientation: batch.orientation } } : null;
    },
    (progress) => {
      if (!progress) return draw();
      if (drawScheduled) return;
      drawScheduled = true;
      requestAnimationFrame(() => {
        drawScheduled = false;
        draw();
      });
    },
    (messages) => banner.show(messages),
  );
  const panel = new BatchPanel({
    onSelect: (subject) => showFit(subject),
    onCancel: (subject) => batch.cancel(subject),
    onRetry: (subject) => batch.retry(subject),
    onExclude: (subject, excluded) => batch.setExcluded(subject, excluded),
    onOrientation: (orientation) => batch.setOrientation(orientation),
    onAlignAgain: () => {
      const again = batch.alignableAgain();
      const question = `Align ${again.length} subject${again.length === 1 ? '' : 's'} again with ${orientationText(batch.orientation)}? ${again.length === 1 ? 'Its fit is' : 'Their fits are'} replaced by the new ones.`;
      if (again.length && window.confirm(question)) batch.alignAgain();
    },
    onCancelAll: () => batch.cancelAll(),
    onRetryAll: () => batch.retryAll(),
    onBuild: () => void page.shapeSpace.buildFrom(batch.kept(), (text) => panel.showBuildStatus(text)),
    onClear: () => {
      const fits = batch.all.filter((r) => r.fit).length;
      const question = `Clear the batch? Its ${batch.all.length} subject${batch.all.length === 1 ? '' : 's'} and ${fits} fit${fits === 1 ? '' : 's'} are forgotten here and in this browser's storage; this cannot be undone.`;
      if (!window.confirm(question)) return;
      panel.select(null);
      void batch.clear();
    },
  });

  /** Shows a subject's fit alone, upright, coloured by its distance to its scan. */
  function showFit(subject: string): void {
    const fit = batch.row(subject)?.fit;
    const template = templateView.data;
    if (!fit || !template || fit.positions.length !== template.positions.length) {
      banner.show([`${subject}: its fit is at another template resolution than the one loaded; choose that resolution in the Template panel to see it.`]);
      return;
    }
    const heat = distanceHeat(fit.distances);
    page.shapeSpace.hide();
    page.session.changed('batchFit');
    templateView.setShown(false);
    // The next scan opened shows itself again (the warp step's reset).
    for (const key of ['scan', 'warped']) viewer.showBody(key, { visible: false });
    viewer.showBody(
      'fitted',
      { mesh: { positions: fit.positions, triangles: template.triangles }, colour: FITTED_COLOUR, vertexColours: heat.colours, transform: uprightTransform(fit.report.warp.similarity), visible: true },
      true,
    );
    document.getElementById('empty-hint')!.hidden = true;
    panel.select(subject, heat.maxMm);
    document.body.dataset.batchShown = subject;
  }

  void batch.restore();
  // Subjects dropped before the template was ready start when it is.
  templateView.onLoaded(() => batch.pump());
  return batch;
}
