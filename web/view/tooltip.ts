// Names the landmark under the pointer: raycasts the markers on pointer move (once per frame).
import * as THREE from 'three';
import type { LandmarkMarkers } from './landmark-markers';

export class LandmarkTooltip {
  readonly element = document.createElement('div');
  private readonly raycaster = new THREE.Raycaster();
  private readonly pointer = new THREE.Vector2();
  private pending: { x: number; y: number } | null = null;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: THREE.Camera,
    private readonly markers: () => LandmarkMarkers[],
    private readonly occluders: () => THREE.Object3D[],
  ) {
    this.element.className = 'tooltip';
    this.element.dataset.testid = 'landmark-tooltip';
    this.element.hidden = true;
    canvas.addEventListener('pointermove', (e) => this.schedule(e));
    canvas.addEventListener('pointerleave', () => this.hide());
  }

  private schedule(event: PointerEvent): void {
    const first = this.pending === null;
    this.pending = { x: event.clientX, y: event.clientY };
    if (first) requestAnimationFrame(() => this.update());
  }

  private update(): void {
    const at = this.pending;
    this.pending = null;
    if (!at) return;
    // Tests wait on this count rather than on time.
    this.element.dataset.updates = String(Number(this.element.dataset.updates ?? '0') + 1);
    const rect = this.canvas.getBoundingClientRect();
    this.pointer.set(((at.x - rect.left) / rect.width) * 2 - 1, -((at.y - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(this.pointer, this.camera);
    let nearest: { name: string; distance: number } | null = null;
    for (const set of this.markers()) {
      const hit = set.pick(this.raycaster);
      if (hit && (!nearest || hit.distance < nearest.distance)) nearest = hit;
    }
    if (!nearest || this.hidden(nearest.distance)) return this.hide();
    this.element.textContent = nearest.name;
    this.element.style.left = `${at.x - rect.left + 14}px`;
    this.element.style.top = `${at.y - rect.top + 14}px`;
    this.element.hidden = false;
  }

  /** Whether a surface lies in front of a marker hit at `distance` (only tested on a hit). */
  private hidden(distance: number): boolean {
    const surface = this.raycaster.intersectObjects(this.occluders(), false)[0];
    return surface !== undefined && surface.distance < distance;
  }

  private hide(): void {
    this.element.hidden = true;
  }
}
