// The link to the body shown: the model's address, every slider value, the segment view, the
// camera and the resolution, kept up to date on the panel and copied on request. A model with no
// address (dropped, built here) has no link, and the panel says why.
import { encodeShapeLink, isShareableModel } from '../shared/shape-link';
import type { ShapePanel } from '../ui/shape-panel';
import type { Viewer } from '../view/viewer';
import type { ShapeModel } from './shape-model';
import type { ShapeSliders } from './shape-sliders';
import type { ShownBody } from './shown-body';

export class ShapeShare {
  private readonly page = document.body;

  constructor(
    private readonly model: ShapeModel,
    private readonly sliders: ShapeSliders,
    private readonly shown: ShownBody,
    private readonly panel: ShapePanel,
    private readonly viewer: Viewer,
  ) {}

  /** Shows the link to the body shown (published as `data-shape-link`). */
  update(): void {
    if (!this.model.loaded) return;
    const source = this.model.source;
    if (!source || !isShareableModel(source)) {
      this.panel.showLink('', 'This model was opened from a local file or built in this session: it has no address, so a link could not show it to anyone else. Put the model file on a web server (https) to share bodies of it.');
      this.page.dataset.shapeLink = '';
      return;
    }
    const hash = encodeShapeLink({
      model: source,
      coefficients: this.sliders.values,
      view: this.panel.currentView,
      camera: this.viewer.cameraPose(),
      resolution: this.shown.resolution,
    });
    const url = `${location.origin}${location.pathname}${hash}`;
    this.panel.showLink(url, 'The link holds the model location, every coefficient (0.001σ steps), the segment view, the camera and the resolution.');
    this.page.dataset.shapeLink = url;
  }

  /** Puts the link in the address bar and on the clipboard (when allowed). */
  async copy(): Promise<void> {
    // The body on screen may hold rank-1 updates (within 1e-7 m of a reconstruction); whoever
    // opens the link reconstructs from scratch, so rebuild here and both see the same bits.
    if (this.shown.body && !this.shown.body.rebuilt) this.shown.redraw(false, true);
    this.update();
    const url = this.page.dataset.shapeLink;
    if (!url) return;
    history.replaceState(null, '', url);
    try {
      await navigator.clipboard.writeText(url);
    } catch {
      // No clipboard permission (e.g. headless): the text field holds the link to copy by hand.
    }
  }
}
