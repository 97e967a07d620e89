// The RBF warp step: runs the warp in the worker, shows the warped template over the scan (the
// scan see-through, both shown upright by the warp's Procrustes rotation), fills the panel.
import type { CoreClient } from '../client/core-client';
import { rbfParams, type RbfSettings, type WarpResult } from '../shared/align-types';
import { RbfPanel } from '../ui/rbf-panel';
import type { Viewer } from '../view/viewer';
import { describeFrame, uprightTransform } from './display-frame';
import { scanInput, scanTransfer } from './scan-input';
import type { Session } from './session';
import type { TemplateView } from './template-view';

/** Opacity of the scan under a warped or fitted template. */
export const SCAN_OPACITY = 0.4;

export class WarpStep {
  readonly panel: RbfPanel;
  /** The display transform of the scan frame (column-major), once a warp has found it. */
  transform: number[] | null = null;
  last: WarpResult | null = null;
  private readonly listeners: ((transform: number[] | null) => void)[] = [];

  constructor(
    private readonly client: CoreClient<'align'>,
    private readonly viewer: Viewer,
    private readonly session: Session,
    private readonly template: TemplateView,
    private readonly onError: (message: string) => void,
  ) {
    this.panel = new RbfPanel({
      onRun: (settings) => void this.run(settings),
      onShow: (what, on) => this.show(what, on),
    });
    template.onShown((on) => this.panel.setShown('template', on));
  }

  /** Called when the display transform changes (the align step shows its layer with it). */
  onTransform(listener: (transform: number[] | null) => void): void {
    this.listeners.push(listener);
  }

  get ready(): boolean {
    return Boolean(this.session.scan && this.session.edits?.placed().names.length);
  }

  /**
   * A new scan or landmark file: forget the old warp, and warp again with the current settings.
   * `keepView` (an edited landmark of the same scan): the scan stays where it is drawn and the
   * camera where the person put it.
   */
  reset(keepView = false): void {
    this.last = null;
    this.viewer.removeBody('warped');
    this.panel.setShown('warped', true);
    if (!keepView) {
      this.transform = null;
      if (this.session.scan) this.viewer.showBody('scan', { transform: null, opacity: 1, visible: true });
      this.panel.setShown('scan', true);
      // The loaded data takes the stage; the template's toggle brings it back.
      this.template.setShown(false);
    } else this.show('scan', true);
    this.panel.render(this.ready, null, null);
    const settings = this.panel.current;
    if (this.ready && settings) void this.run(settings, !keepView);
  }

  /** Warps; `frame` aims the camera at the result. */
  async run(settings: RbfSettings, frame = true): Promise<void> {
    const input = scanInput(this.session, this.template.resolution);
    if (!input) return;
    const body = document.body.dataset;
    body.rbfState = 'running';
    this.panel.render(true, this.outcome(), null, true);
    try {
      const warp = await this.client.call({ type: 'rbfWarp', scan: input, params: { rbf: rbfParams(settings) } }, { transfer: scanTransfer(input) });
      this.last = warp;
      this.transform = uprightTransform(warp.report.similarity);
      this.viewer.showBody('scan', { transform: this.transform, opacity: SCAN_OPACITY });
      const triangles = this.template.data?.triangles;
      if (!triangles) return;
      this.viewer.showBody('warped', { mesh: { positions: warp.positions, normals: warp.normals, triangles }, colour: 0x7fb8e6, transform: this.transform });
      this.show('warped', true);
      this.template.setShown(false);
      if (frame) this.viewer.frame();
      for (const listener of this.listeners) listener(this.transform);
      this.panel.render(true, this.outcome(), null);
      body.rbfState = 'done';
    } catch (error) {
      if (!(error instanceof Error) || error.name === 'CancelledError') {
        body.rbfState = 'idle';
        this.panel.render(true, this.outcome(), null);
        return;
      }
      this.panel.render(true, this.outcome(), error.message);
      this.onError(error.message);
      body.rbfState = 'error';
    }
  }

  private outcome() {
    const warp = this.last;
    if (!warp) return null;
    const r = warp.report;
    const scale = r.similarity.scale;
    const note =
      `Assumed: the scan's frame and units are unknown, so a similarity (Procrustes on ${r.used.length} landmark pairs) ` +
      `maps the template onto it; ${describeFrame(r.similarity)}, scale ×${scale.toFixed(3)}. ` +
      'The scan is drawn rotated upright by that fit (display only).';
    return { report: r, frameNote: note, workerMs: warp.workerMs };
  }

  /** Shows or hides one of the bodies the toggles name, keeping the toggle in step. */
  show(what: 'scan' | 'template' | 'warped', on: boolean): void {
    if (what === 'template') this.template.setShown(on);
    else this.viewer.showBody(what, { visible: on });
    this.panel.setShown(what, on);
  }
}
