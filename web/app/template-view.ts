// The template on screen: loads it from the worker, shows it with its landmarks, colours it by
// segment on request. The page opens on the base template.
import type { CoreClient } from '../client/core-client';
import type { TemplateData, TemplateResolution } from '../shared/template-data';
import { TemplatePanel } from '../ui/template-panel';
import { segmentColours } from '../view/segment-colours';
import type { Viewer } from '../view/viewer';

export class TemplateView {
  readonly panel: TemplatePanel;
  data: TemplateData | null = null;
  private colourBySegment = false;
  private shown = true;
  private readonly listeners: ((data: TemplateData) => void)[] = [];
  private readonly shownListeners: ((on: boolean) => void)[] = [];

  constructor(
    private readonly client: CoreClient<'core'>,
    private readonly viewer: Viewer,
    private readonly onError: (message: string) => void,
  ) {
    this.panel = new TemplatePanel({
      onResolution: (r) => void this.load(r),
      onSegmentColours: (on) => this.setSegmentColours(on),
      onShow: (on) => this.setShown(on),
    });
  }

  /** Called with the template each time one is loaded. */
  onLoaded(listener: (data: TemplateData) => void): void {
    this.listeners.push(listener);
  }

  get resolution(): TemplateResolution {
    return this.data?.resolution ?? 'base';
  }

  async load(resolution: TemplateResolution, frame = false): Promise<void> {
    document.body.dataset.templateReady = 'false';
    this.panel.render(this.data ? this.facts(this.data) : null, true);
    try {
      const data = await this.client.call({ type: 'loadTemplate', resolution });
      this.data = data;
      const virtual = new Set(data.landmarkNames.slice(data.landmarkNames.length - data.virtualLandmarkCount));
      this.viewer.showBody(
        'template',
        {
          mesh: data,
          colour: 0x9fb4c7,
          landmarks: { names: data.landmarkNames, positions: data.landmarkPositions, flagged: virtual },
          vertexColours: this.colourBySegment ? segmentColours(data.segmentWeights) : null,
          visible: this.shown,
        },
        frame,
      );
      this.panel.render(this.facts(data));
      document.body.dataset.templateResolution = resolution;
      document.body.dataset.templateReady = 'true';
      for (const listener of this.listeners) listener(data);
    } catch (error) {
      this.panel.render(this.data ? this.facts(this.data) : null);
      if (error instanceof Error && error.name !== 'CancelledError') this.onError(`Template: ${error.message}`);
    }
  }

  setSegmentColours(on: boolean): void {
    this.colourBySegment = on;
    if (this.data) this.viewer.showBody('template', { vertexColours: on ? segmentColours(this.data.segmentWeights) : null });
    document.body.dataset.templateSegmentColours = String(on);
  }

  /** Shows or hides the template and keeps every toggle of it in step. */
  setShown(on: boolean): void {
    this.shown = on;
    this.viewer.showBody('template', { visible: on });
    this.panel.setShown(on);
    for (const listener of this.shownListeners) listener(on);
  }

  /** Called whenever the template is shown or hidden. */
  onShown(listener: (on: boolean) => void): void {
    this.shownListeners.push(listener);
  }

  private facts(data: TemplateData) {
    return {
      resolution: data.resolution,
      vertices: data.positions.length / 3,
      triangles: data.triangles.length / 3,
      landmarks: data.landmarkNames.length,
      virtualLandmarks: data.virtualLandmarkCount,
    };
  }
}
