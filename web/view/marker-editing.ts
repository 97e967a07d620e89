// Placing and dragging landmark markers on a body's surface. A click (press and release without
// moving) on the surface places the selected landmark at the point under the cursor; a press on a
// marker drags it along the surface (the orbit controls rest meanwhile). Only the body's own mesh
// is raycast; points come out in the body's frame (metres, before its display transform), where
// its markers live.
import * as THREE from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { BodyLayer } from './body-layer';

export type SurfacePoint = [number, number, number];

export interface MarkerEditHandlers {
  /** The landmark a click on the surface places, or null (clicks then only orbit). */
  selected(): string | null;
  /** Whether the markers may be edited at all (e.g. not while an estimate runs). */
  enabled(): boolean;
  /** `name` moves to `point`; `transient` while a drag is under way, false when it ends. */
  onPlace(name: string, point: SurfacePoint, transient: boolean): void;
  /** A press on marker `name`: whether it may be dragged (it then becomes the selected one). */
  onGrab(name: string): boolean;
}

/** A press that moves less than this (CSS px) before release is a click, not an orbit. */
const CLICK_SLOP_PX = 5;

export class MarkerEditing {
  private readonly raycaster = new THREE.Raycaster();
  private press: { x: number; y: number } | null = null;
  private drag: { name: string; last: SurfacePoint | null; pending: { x: number; y: number } | null } | null = null;

  constructor(
    container: HTMLElement,
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: THREE.Camera,
    private readonly controls: OrbitControls,
    private readonly layer: () => BodyLayer | undefined,
    private readonly handlers: MarkerEditHandlers,
  ) {
    // Capture on the container runs before the orbit controls' own listener on the canvas, so a
    // press on a marker can switch them off before they start rotating.
    container.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
  }

  private down(event: PointerEvent): void {
    this.press = null;
    if (event.button !== 0 || event.target !== this.canvas || !this.handlers.enabled()) return;
    const layer = this.editable();
    if (!layer) return;
    const grabbed = this.markerAt(layer, event);
    if (grabbed && this.handlers.onGrab(grabbed)) {
      this.controls.enabled = false;
      this.canvas.setPointerCapture(event.pointerId);
      this.drag = { name: grabbed, last: null, pending: null };
      return;
    }
    this.press = { x: event.clientX, y: event.clientY };
  }

  private move(event: PointerEvent): void {
    const drag = this.drag;
    if (!drag) return;
    const first = drag.pending === null;
    drag.pending = { x: event.clientX, y: event.clientY };
    // One raycast per frame: a large scan takes milliseconds per ray.
    if (first)
      requestAnimationFrame(() => {
        if (this.drag !== drag || !drag.pending) return;
        const point = this.surfaceAt(drag.pending);
        drag.pending = null;
        if (!point) return;
        drag.last = point;
        this.handlers.onPlace(drag.name, point, true);
      });
  }

  private up(event: PointerEvent): void {
    const drag = this.drag;
    if (drag) {
      this.drag = null;
      this.controls.enabled = true;
      const point = this.surfaceAt({ x: event.clientX, y: event.clientY }) ?? drag.last;
      if (point) this.handlers.onPlace(drag.name, point, false);
      return;
    }
    const press = this.press;
    this.press = null;
    const name = this.handlers.selected();
    if (!press || !name || Math.hypot(event.clientX - press.x, event.clientY - press.y) > CLICK_SLOP_PX) return;
    const point = this.surfaceAt({ x: event.clientX, y: event.clientY });
    if (point) this.handlers.onPlace(name, point, false);
  }

  /** The layer when it is shown with a surface, else undefined. */
  private editable(): BodyLayer | undefined {
    const layer = this.layer();
    return layer?.visible && layer.surface ? layer : undefined;
  }

  private aim(at: { x: number; y: number }): void {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((at.x - rect.left) / rect.width) * 2 - 1, -((at.y - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
  }

  /** The marker under the pointer, unless the surface lies clearly in front of it. */
  private markerAt(layer: BodyLayer, at: { clientX: number; clientY: number }): string | null {
    const markers = layer.landmarkMarkers;
    if (!markers) return null;
    this.aim({ x: at.clientX, y: at.clientY });
    const hit = markers.pick(this.raycaster);
    if (!hit) return null;
    const surface = this.raycaster.intersectObject(layer.surface!, false)[0];
    // A marker sits on the surface: its sphere pokes out in front by up to its radius.
    const slack = layer.bounds().getSize(new THREE.Vector3()).length() * 0.01;
    return surface && surface.distance + slack < hit.distance ? null : hit.name;
  }

  /** The point of the layer's surface under `at` (client px), in the layer's frame. */
  private surfaceAt(at: { x: number; y: number }): SurfacePoint | null {
    const layer = this.editable();
    if (!layer) return null;
    this.aim(at);
    const hit = this.raycaster.intersectObject(layer.surface!, false)[0];
    if (!hit) return null;
    layer.group.updateMatrixWorld(true);
    const p = layer.group.worldToLocal(hit.point.clone());
    return [p.x, p.y, p.z];
  }
}
