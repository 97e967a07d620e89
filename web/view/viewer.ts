// The 3D view: renderer, camera, orbit controls, lights, ground grid, and one BodyLayer per body.
// Renders on demand (after a change or a camera move), not in a loop: software WebGL is slow.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { BodyLayer, type BodyContent } from './body-layer';
import { MarkerEditing, type MarkerEditHandlers } from './marker-editing';
import { addLights, makeGrid } from './stage';
import { LandmarkTooltip } from './tooltip';

export type { BodyContent, BodyMesh } from './body-layer';
export type { LandmarkPoints } from './landmark-markers';
export type { MarkerEditHandlers, SurfacePoint } from './marker-editing';

/** Where a standing adult would be: what the camera frames before anything is loaded. */
const EMPTY_SCENE_BOX = new THREE.Box3(new THREE.Vector3(-0.3, 0, -0.15), new THREE.Vector3(0.3, 1.75, 0.15));

export class Viewer {
  private readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(40, 1, 0.01, 200);
  private readonly controls: OrbitControls;
  private readonly grid = makeGrid();
  private readonly layers = new Map<string, BodyLayer>();
  private frameRequested = false;
  /** What the camera was last aimed at, for `data-framed-ndc`. */
  private framed: THREE.Box3 | null = null;
  /** Back to the whole body after a close-up (`closeUp`); hidden otherwise. */
  private readonly whole = document.createElement('button');

  constructor(private readonly container: HTMLElement) {
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.outputColorSpace = THREE.SRGBColorSpace;
    this.renderer.setClearColor(0x15181d);
    this.renderer.domElement.dataset.testid = 'viewport-canvas';
    container.appendChild(this.renderer.domElement);

    addLights(this.scene);
    this.scene.add(this.grid);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());

    const tooltip = new LandmarkTooltip(this.renderer.domElement, this.camera, () =>
      [...this.layers.values()].flatMap((l) => (l.visible && l.landmarkMarkers ? [l.landmarkMarkers] : [])),
      () => [...this.layers.values()].flatMap((l) => (l.visible && l.surface ? [l.surface] : [])),
    );
    container.appendChild(tooltip.element);

    this.whole.type = 'button';
    this.whole.className = 'view-whole';
    this.whole.dataset.testid = 'view-whole';
    this.whole.textContent = 'Whole body';
    this.whole.hidden = true;
    this.whole.addEventListener('click', () => this.frame());
    container.appendChild(this.whole);

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.aimAt(EMPTY_SCENE_BOX);
  }

  /**
   * Shows a body (a mesh and/or its landmarks) under `key`, e.g. `'scan'` or `'template'`,
   * replacing what that key showed; frames the camera on it when `frame` is set.
   */
  showBody(key: string, content: BodyContent, frame = false): void {
    let layer = this.layers.get(key);
    if (!layer) {
      layer = new BodyLayer(key);
      this.layers.set(key, layer);
      this.scene.add(layer.group);
    }
    layer.update(content);
    this.container.dataset[`${key}Triangles`] = String(layer.triangleCount);
    this.container.dataset[`${key}Vertices`] = String(layer.vertexCount);
    this.container.dataset[`${key}Markers`] = String(layer.markerCount);
    this.container.dataset[`${key}Visible`] = String(layer.visible);
    this.container.dataset[`${key}Coloured`] = String(layer.coloured);
    this.placeGrid();
    if (frame) this.frame();
    this.requestRender();
  }

  /** Removes the body shown under `key`. */
  removeBody(key: string): void {
    const layer = this.layers.get(key);
    if (!layer) return;
    this.scene.remove(layer.group);
    layer.dispose();
    this.layers.delete(key);
    delete this.container.dataset[`${key}Triangles`];
    delete this.container.dataset[`${key}Vertices`];
    delete this.container.dataset[`${key}Markers`];
    delete this.container.dataset[`${key}Visible`];
    this.placeGrid();
    this.requestRender();
  }

  /** Lets the markers of the body under `key` be placed on and dragged along its surface. */
  editMarkers(key: string, handlers: MarkerEditHandlers): void {
    new MarkerEditing(this.container, this.renderer.domElement, this.camera, this.controls, () => this.layers.get(key), handlers);
  }

  /**
   * Where `point` (in the frame of the body under `key`, metres) is drawn on the canvas: CSS px
   * from its top-left corner, or null when that body is not shown.
   */
  canvasPoint(key: string, point: [number, number, number]): [number, number] | null {
    const layer = this.layers.get(key);
    if (!layer?.visible) return null;
    layer.group.updateMatrixWorld(true);
    this.camera.updateMatrixWorld();
    const p = layer.group.localToWorld(new THREE.Vector3(...point)).project(this.camera);
    const { clientWidth: w, clientHeight: h } = this.renderer.domElement;
    return [((p.x + 1) / 2) * w, ((1 - p.y) / 2) * h];
  }

  /** Points the camera at everything shown, from the front-right, the whole body in view. */
  frame(): void {
    const box = this.contentBounds();
    if (!box.isEmpty()) this.aimAt(box);
  }

  /**
   * Turns the camera to `point` (in the frame of the body under `key`, metres) up close, `radius`
   * metres around it in view, looking from the side of the body it lies on: away from the body's
   * long axis (a face from the front, an ear from its side). The axis runs through the median of
   * the surface's vertices, not the middle of its box: a piece beside the body (a stand, a
   * turntable's rim) widens the box, and an ear would be seen from the far side of the head.
   * "Whole body" then frames it all again.
   */
  closeUp(key: string, point: [number, number, number], radius = 0.15): void {
    const layer = this.layers.get(key);
    if (!layer?.visible) return;
    layer.group.updateMatrixWorld(true);
    const at = layer.group.localToWorld(new THREE.Vector3(...point));
    const box = new THREE.Box3().setFromObject(layer.group);
    const size = box.getSize(new THREE.Vector3());
    const long = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const out = at.clone().sub(medianOf(layer.surface) ?? box.getCenter(new THREE.Vector3())).setComponent(long, 0);
    // A point on the long axis (the crotch, the crown) is seen from where the camera is.
    if (out.length() < 0.02) out.copy(this.camera.position).sub(this.controls.target).setComponent(long, 0);
    out.normalize();
    const distance = radius / Math.sin(THREE.MathUtils.degToRad(this.camera.fov) / 2);
    this.place(at, at.clone().addScaledVector(out, distance));
    this.whole.hidden = false;
  }

  /** Camera position and orbit target (metres), for links. */
  cameraPose(): { position: [number, number, number]; target: [number, number, number] } {
    const p = this.camera.position;
    const t = this.controls.target;
    return { position: [p.x, p.y, p.z], target: [t.x, t.y, t.z] };
  }

  /** Puts the camera where `cameraPose` said it was. */
  setCameraPose(pose: { position: [number, number, number]; target: [number, number, number] }): void {
    this.place(new THREE.Vector3(...pose.target), new THREE.Vector3(...pose.position));
  }

  /** Puts the camera at `position` looking at `target`, its clipping planes set by their distance. */
  private place(target: THREE.Vector3, position: THREE.Vector3): void {
    this.controls.target.copy(target);
    this.camera.position.copy(position);
    const distance = position.distanceTo(target) || 1;
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.requestRender();
  }

  private aimAt(box: THREE.Box3): void {
    this.whole.hidden = true;
    this.framed = box.clone();
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const radius = Math.max(sphere.radius, 0.05);
    const fov = THREE.MathUtils.degToRad(this.camera.fov);
    const fitHeight = radius / Math.sin(fov / 2);
    const fitWidth = radius / Math.sin(Math.atan(Math.tan(fov / 2) * this.camera.aspect));
    // The bounding sphere is loose around a standing body; 0.92 fills the view without cropping.
    const distance = Math.max(fitHeight, fitWidth) * 0.92;
    const direction = new THREE.Vector3(0.45, 0.2, 1).normalize();
    this.place(sphere.center, sphere.center.clone().addScaledVector(direction, distance));
  }

  requestRender(): void {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      const t0 = performance.now();
      this.renderer.render(this.scene, this.camera);
      // The main thread's part of drawing (three.js's buffer uploads and draw calls), for the benchmarks.
      const renderMs = performance.now() - t0;
      this.container.dataset.lastRenderMs = renderMs.toFixed(1);
      this.container.dataset.maxRenderMs = Math.max(renderMs, Number(this.container.dataset.maxRenderMs ?? 0)).toFixed(1);
      this.container.dataset.totalRenderMs = (renderMs + Number(this.container.dataset.totalRenderMs ?? 0)).toFixed(1);
      const rendered = Number(this.container.dataset.frames ?? '0') + 1;
      this.container.dataset.frames = String(rendered);
      if (this.framed) this.container.dataset.framedNdc = projectedExtent(this.framed, this.camera);
      // Where everything shown lands (a body beside the framed one may reach past the canvas).
      const shown = this.contentBounds();
      if (!shown.isEmpty()) this.container.dataset.shownNdc = projectedExtent(shown, this.camera);
    });
  }

  private contentBounds(): THREE.Box3 {
    const box = new THREE.Box3();
    for (const layer of this.layers.values()) box.union(layer.bounds());
    return box;
  }

  /** The grid sits under the lowest point shown, so bodies stand on it. */
  private placeGrid(): void {
    const box = this.contentBounds();
    this.grid.position.y = box.isEmpty() ? 0 : box.min.y;
  }

  private resize(): void {
    const { clientWidth: w, clientHeight: h } = this.container;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }
}

/**
 * `minX,maxX,minY,maxY` of `box`'s corners in normalised device coordinates (the canvas spans
 * −1…1 both ways): where what the camera was aimed at lands on the canvas, for tests.
 */
function projectedExtent(box: THREE.Box3, camera: THREE.Camera): string {
  const [lo, hi] = [box.min, box.max];
  const xs: number[] = [];
  const ys: number[] = [];
  for (let i = 0; i < 8; i++) {
    const p = new THREE.Vector3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z).project(camera);
    xs.push(p.x);
    ys.push(p.y);
  }
  return [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)].map((v) => v.toFixed(3)).join(',');
}

/** The per-axis median of `mesh`'s vertices in world space (of at most 20,000 spread over them), or null without any. */
function medianOf(mesh: THREE.Mesh | null): THREE.Vector3 | null {
  const position = mesh?.geometry.getAttribute('position');
  if (!mesh || !position || position.count === 0) return null;
  const step = Math.max(1, Math.floor(position.count / 20_000));
  const axes: number[][] = [[], [], []];
  const v = new THREE.Vector3();
  for (let i = 0; i < position.count; i += step) {
    v.fromBufferAttribute(position, i).applyMatrix4(mesh.matrixWorld);
    axes[0]!.push(v.x);
    axes[1]!.push(v.y);
    axes[2]!.push(v.z);
  }
  const [x, y, z] = axes.map((values) => values.sort((a, b) => a - b)[values.length >> 1]!);
  return new THREE.Vector3(x, y, z);
}
