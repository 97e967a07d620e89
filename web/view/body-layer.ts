// One body in the scene: a smooth-shaded triangle mesh and its landmark markers. Scans and the
// template are both shown through this.
import * as THREE from 'three';
import { LandmarkMarkers, type LandmarkPoints } from './landmark-markers';

/** Flat arrays as the core returns them: positions in metres, unit vertex normals. */
export interface BodyMesh {
  positions: Float32Array;
  triangles: Uint32Array;
  normals: Float32Array;
}

/** What `Viewer.showBody` draws; `null` removes that part, `undefined` keeps it. */
export interface BodyContent {
  mesh?: BodyMesh | null;
  /** Uniform factor on the mesh positions (a units override), 1 by default. */
  meshScale?: number;
  landmarks?: LandmarkPoints | null;
  colour?: number;
}

/** Marker radius as a fraction of the body's height: 8 mm on a 1.75 m body. */
const MARKER_RADIUS_PER_HEIGHT = 0.008 / 1.75;

export class BodyLayer {
  readonly group = new THREE.Group();
  private mesh: THREE.Mesh | null = null;
  private source: BodyMesh | null = null;
  private markers: LandmarkMarkers | null = null;
  private landmarks: LandmarkPoints | null = null;

  constructor(name: string) {
    this.group.name = name;
  }

  /** Applies `content`; geometry is rebuilt only when a new mesh object is given. */
  update(content: BodyContent): void {
    if (content.mesh !== undefined && content.mesh !== this.source) this.setMesh(content.mesh, content.colour);
    if (this.mesh && content.meshScale !== undefined) this.mesh.scale.setScalar(content.meshScale);
    if (content.landmarks !== undefined) this.landmarks = content.landmarks;
    this.rebuildMarkers();
  }

  get triangleCount(): number {
    return this.source ? this.source.triangles.length / 3 : 0;
  }

  get markerCount(): number {
    return this.markers?.count ?? 0;
  }

  /** The body's surface, which hides markers behind it from the tooltip. */
  get surface(): THREE.Mesh | null {
    return this.mesh;
  }

  get landmarkMarkers(): LandmarkMarkers | null {
    return this.markers;
  }

  /** World-space bounds of everything in the layer (empty when nothing is shown). */
  bounds(): THREE.Box3 {
    this.group.updateMatrixWorld(true);
    return new THREE.Box3().setFromObject(this.group);
  }

  dispose(): void {
    this.setMesh(null);
    this.markers?.dispose();
    this.markers = null;
  }

  private setMesh(body: BodyMesh | null, colour = 0xc9c3bb): void {
    if (this.mesh) {
      this.group.remove(this.mesh);
      this.mesh.geometry.dispose();
      (this.mesh.material as THREE.Material).dispose();
      this.mesh = null;
    }
    this.source = body;
    if (!body) return;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(body.positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(body.normals, 3));
    geometry.setIndex(new THREE.BufferAttribute(body.triangles, 1));
    geometry.computeBoundingBox();
    geometry.computeBoundingSphere();
    // Scans have holes and open borders: show both faces so the inside of a hole is not see-through.
    const material = new THREE.MeshStandardMaterial({
      color: colour,
      roughness: 0.75,
      metalness: 0,
      side: THREE.DoubleSide,
    });
    this.mesh = new THREE.Mesh(geometry, material);
    this.mesh.name = 'body-mesh';
    this.group.add(this.mesh);
  }

  private rebuildMarkers(): void {
    if (this.markers) {
      this.group.remove(this.markers.object);
      this.markers.dispose();
      this.markers = null;
    }
    if (!this.landmarks || this.landmarks.names.length === 0) return;
    this.markers = new LandmarkMarkers(this.landmarks, this.markerRadius());
    this.group.add(this.markers.object);
  }

  /** Relative to the body's height (the mesh's, else the landmarks' extent). */
  private markerRadius(): number {
    let height = 0;
    if (this.mesh) {
      this.mesh.updateMatrixWorld(true);
      const box = new THREE.Box3().setFromObject(this.mesh);
      height = box.getSize(new THREE.Vector3()).y;
    } else if (this.landmarks) {
      const p = this.landmarks.positions;
      const box = new THREE.Box3();
      for (let i = 0; i < p.length; i += 3) box.expandByPoint(new THREE.Vector3(p[i], p[i + 1], p[i + 2]));
      height = box.getSize(new THREE.Vector3()).length();
    }
    return Math.max(height, 1e-3) * MARKER_RADIUS_PER_HEIGHT;
  }
}
