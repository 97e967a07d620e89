// Placing and dragging landmark markers on a body's surface. A click (press and release without
// moving) on the surface places the selected landmark at the point under the cursor; a press on a
// marker drags it along the surface (the orbit controls rest meanwhile). Only the body's own mesh
// is raycast; points come out in the body's frame (metres, before its display transform), where
// its markers live. Where a body's triangles are known to face out of it (a scan's, per triangle
// from the core), a ray whose first hit is a triangle's back has gone through a hole in the surface
// onto the inside of the far side: nothing is placed there, and the handlers hear of it.
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
  /** A click meant to place `name` went through a hole onto the inside of the far side: nothing was placed. */
  onThroughHole(name: string): void;
}

/** The surface under the pointer: a point, nothing, or the inside of the far side through a hole. */
type Under = SurfacePoint | null | 'hole';

/** A press that moves less than this (CSS px) before release is a click, not an orbit. */
const CLICK_SLOP_PX = 5;

/** How far (m) behind a triangle's back a front may lie for the two to be a fold of the surface, not a hole. */
const FOLD_DEPTH = 0.01;

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
        if (!point || point === 'hole') return;
        drag.last = point;
        this.handlers.onPlace(drag.name, point, true);
      });
  }

  private up(event: PointerEvent): void {
    const drag = this.drag;
    if (drag) {
      this.drag = null;
      this.controls.enabled = true;
      const under = this.surfaceAt({ x: event.clientX, y: event.clientY });
      const point = under && under !== 'hole' ? under : drag.last;
      if (point) this.handlers.onPlace(drag.name, point, false);
      else if (under === 'hole') this.handlers.onThroughHole(drag.name);
      return;
    }
    const press = this.press;
    this.press = null;
    const name = this.handlers.selected();
    if (!press || !name || Math.hypot(event.clientX - press.x, event.clientY - press.y) > CLICK_SLOP_PX) return;
    const point = this.surfaceAt({ x: event.clientX, y: event.clientY });
    if (point === 'hole') this.handlers.onThroughHole(name);
    else if (point) this.handlers.onPlace(name, point, false);
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

  /**
   * The marker under the pointer, unless the surface lies clearly in front of it. Through a hole,
   * a marker on the far side of the body lies at the far side's inside, and is not taken; one in
   * front of the hole is.
   */
  private markerAt(layer: BodyLayer, at: { clientX: number; clientY: number }): string | null {
    const markers = layer.landmarkMarkers;
    if (!markers) return null;
    this.aim({ x: at.clientX, y: at.clientY });
    const hit = markers.pick(this.raycaster);
    if (!hit) return null;
    const surface = this.surfaceHit(layer);
    if (!surface) return hit.name;
    // A marker sits on the surface: its sphere pokes out in front by up to its radius.
    const slack = layer.bounds().getSize(new THREE.Vector3()).length() * 0.01;
    if (surface.throughHole) return hit.distance + slack < surface.hit.distance ? hit.name : null;
    return surface.hit.distance + slack < hit.distance ? null : hit.name;
  }

  /** The point of the layer's surface under `at` (client px), in the layer's frame. */
  private surfaceAt(at: { x: number; y: number }): Under {
    const layer = this.editable();
    if (!layer) return null;
    this.aim(at);
    const surface = this.surfaceHit(layer);
    if (!surface) return null;
    if (surface.throughHole) return 'hole';
    layer.group.updateMatrixWorld(true);
    const p = layer.group.worldToLocal(surface.hit.point.clone());
    return [p.x, p.y, p.z];
  }

  /**
   * The surface's first hit along the aimed ray, and whether it is seen through a hole: the back
   * of a triangle (one the core knows the way of) with no triangle's front within `FOLD_DEPTH`
   * behind it, the inside of the far side. A noisy scan's surface folds over in places, and there
   * a triangle's back lies just in front of the surface: that is a hit like any other.
   */
  private surfaceHit(layer: BodyLayer): { hit: THREE.Intersection; throughHole: boolean } | null {
    const hits = this.raycaster.intersectObject(layer.surface!, false);
    const hit = hits[0];
    if (!hit) return null;
    const throughHole = this.sideOf(layer, hit) === 'back' && !hits.some((h) => h.distance - hit.distance <= FOLD_DEPTH && this.sideOf(layer, h) === 'front');
    return { hit, throughHole };
  }

  /**
   * Which side of its triangle `hit` is on, where the core knows which way that triangle faces
   * (out of the body or into it): it says so per triangle, so a part wound one way tells it even
   * on a scan whose parts disagree, and a part whose triangles face both ways too; `null` where
   * it knows neither (a piece too small to judge, a sheet).
   * The triangle's side is taken from its corners in world space, so a display transform that
   * mirrors the body changes nothing.
   */
  private sideOf(layer: BodyLayer, hit: THREE.Intersection): 'front' | 'back' | null {
    const face = hit.face;
    const wound = face && hit.faceIndex != null ? (layer.triangleFacing?.[hit.faceIndex] ?? 0) : 0;
    if (!face || wound === 0) return null;
    const mesh = layer.surface!;
    const position = mesh.geometry.getAttribute('position');
    const [a, b, c] = [face.a, face.b, face.c].map((i) => new THREE.Vector3().fromBufferAttribute(position, i).applyMatrix4(mesh.matrixWorld));
    const normal = b!.sub(a!).cross(c!.sub(a!));
    const away = normal.dot(this.raycaster.ray.direction) > 0;
    return away === (wound > 0) ? 'back' : 'front';
  }
}
