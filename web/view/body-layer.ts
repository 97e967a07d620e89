// One body in the scene: a smooth-shaded triangle mesh (with the vertex normals the core sends;
// three.js computes them for meshes sent without, such as an alignment's per-round positions) and
// its landmark markers. Scans, the template, fits and shape-space bodies are all shown this way.
import * as THREE from 'three';
import type { Bounds } from '../shared/bounds';
import { LandmarkMarkers, type LandmarkPoints } from './landmark-markers';

/** Flat arrays as the core returns them: positions in metres, unit vertex normals. */
export interface BodyMesh {
  positions: Float32Array;
  triangles: Uint32Array;
  /** Computed from the triangles when absent. */
  normals?: Float32Array;
  /** `[minX, minY, minZ, maxX, maxY, maxZ]` of the positions, when known (else computed: a pass over them). */
  bounds?: Bounds;
}

/** What `Viewer.showBody` draws; `null` removes that part, `undefined` keeps it. */
export interface BodyContent {
  mesh?: BodyMesh | null;
  /** Uniform factor on the mesh positions (a units override), 1 by default. */
  meshScale?: number;
  landmarks?: LandmarkPoints | null;
  colour?: number;
  /** `#V·3` linear RGB per vertex (replaces `colour`); `null` goes back to the plain colour. */
  vertexColours?: Float32Array | null;
  /** 1 opaque (default); below 1 the surface is drawn see-through, markers stay opaque. */
  opacity?: number;
  /** Hidden bodies keep their geometry, so showing them again is instant. */
  visible?: boolean;
  /** Column-major 4×4 display transform of the whole body (e.g. a z-up scan shown upright). */
  transform?: number[] | null;
  /** `#F` per triangle, which way its front faces (a scan's, from the core): 1 out of the body, −1 into it, 0 not known; `null`: not known anywhere. */
  triangleFacing?: Int8Array | null;
}

/** Marker radius as a fraction of the body's height: 8 mm on a 1.75 m body. */
const MARKER_RADIUS_PER_HEIGHT = 0.008 / 1.75;

export class BodyLayer {
  readonly group = new THREE.Group();
  private mesh: THREE.Mesh | null = null;
  private source: BodyMesh | null = null;
  private markers: LandmarkMarkers | null = null;
  private landmarks: LandmarkPoints | null = null;
  /** The core's, per triangle of the mesh as sent. */
  private facing: Int8Array | null = null;
  private shownFacing: Int8Array | null = null;

  constructor(name: string) {
    this.group.name = name;
  }

  /**
   * Applies `content`. A new mesh object with the same triangles array and vertex count as the
   * one shown (a morphed body) only swaps the vertex buffers' arrays; any other new mesh
   * rebuilds the geometry.
   */
  update(content: BodyContent): void {
    const facing = content.triangleFacing !== undefined && content.triangleFacing !== this.facing;
    if (facing) {
      this.facing = content.triangleFacing!;
      this.shownFacing = this.facing && this.facing.map((f) => Math.abs(f));
    }
    let rebuilt = false;
    if (content.mesh !== undefined && content.mesh !== this.source) {
      if (content.mesh && this.sameTopology(content.mesh)) this.morphMesh(content.mesh);
      else {
        this.setMesh(content.mesh, content.colour);
        rebuilt = true;
      }
    }
    if (facing && !rebuilt && this.mesh) this.mesh.geometry.setIndex(new THREE.BufferAttribute(this.shownTriangles(this.source!.triangles), 1));
    if (this.mesh && content.meshScale !== undefined) this.mesh.scale.setScalar(content.meshScale);
    if (content.vertexColours !== undefined) this.setVertexColours(content.vertexColours);
    if (content.opacity !== undefined) this.setOpacity(content.opacity);
    if (content.visible !== undefined) this.group.visible = content.visible;
    if (content.transform !== undefined) {
      this.group.matrixAutoUpdate = false;
      if (content.transform) this.group.matrix.fromArray(content.transform);
      else this.group.matrix.identity();
      this.group.matrixWorldNeedsUpdate = true;
    }
    if (content.landmarks !== undefined) this.landmarks = content.landmarks;
    // Markers are sized by the body: rebuilt for new landmarks or a new body, not for a morph.
    if (content.landmarks !== undefined || rebuilt || content.meshScale !== undefined) this.rebuildMarkers();
  }

  get vertexCount(): number {
    return this.source ? this.source.positions.length / 3 : 0;
  }

  get triangleCount(): number {
    return this.source ? this.source.triangles.length / 3 : 0;
  }

  get markerCount(): number {
    return this.markers?.count ?? 0;
  }

  /**
   * Per triangle as shown, which way its front faces (1 out of the body, −1 into it, 0 not known),
   * when known. A triangle the core says faces into the body is shown turned (`shownTriangles`),
   * so as shown it faces out.
   */
  get triangleFacing(): Int8Array | null {
    return this.shownFacing;
  }

  /** The body's surface, which hides markers behind it from the tooltip. */
  get surface(): THREE.Mesh | null {
    return this.mesh;
  }

  get landmarkMarkers(): LandmarkMarkers | null {
    return this.markers;
  }

  /** Whether the surface is drawn with per-vertex colours. */
  get coloured(): boolean {
    return Boolean(this.mesh?.geometry.getAttribute('color'));
  }

  /** Whether the body is shown (hidden ones keep their geometry). */
  get visible(): boolean {
    return this.group.visible;
  }

  /** World-space bounds of everything in the layer (empty when nothing is shown). */
  bounds(): THREE.Box3 {
    if (!this.group.visible) return new THREE.Box3();
    this.group.updateMatrixWorld(true);
    return new THREE.Box3().setFromObject(this.group);
  }

  dispose(): void {
    this.setMesh(null);
    this.markers?.dispose();
    this.markers = null;
  }

  private colour = 0xc9c3bb;

  private setMesh(body: BodyMesh | null, colour = 0xc9c3bb): void {
    this.colour = colour;
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
    geometry.setIndex(new THREE.BufferAttribute(this.shownTriangles(body.triangles), 1));
    if (body.normals) geometry.setAttribute('normal', new THREE.BufferAttribute(body.normals, 3));
    else geometry.computeVertexNormals();
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

  /**
   * The triangles as drawn: each the core says faces into the body turned to face out, as the
   * core's normals of a scan are (`ParsedScan.normals`), so a scan whose triangles face both ways
   * is lit as one surface (three.js turns the normal of a triangle seen from behind). The same
   * array where none faces in.
   */
  private shownTriangles(triangles: Uint32Array): Uint32Array {
    const facing = this.facing;
    if (!facing || facing.length !== triangles.length / 3 || !facing.includes(-1)) return triangles;
    const shown = triangles.slice();
    for (let t = 0; t < facing.length; t++) {
      if (facing[t]! < 0) {
        shown[3 * t + 1] = triangles[3 * t + 2]!;
        shown[3 * t + 2] = triangles[3 * t + 1]!;
      }
    }
    return shown;
  }

  private sameTopology(body: BodyMesh): boolean {
    const old = this.source;
    return Boolean(
      this.mesh && old && body.triangles === old.triangles && body.positions.length === old.positions.length && Boolean(body.normals) === Boolean(old.normals),
    );
  }

  /** New positions (and normals) for the same mesh: the arrays are adopted, not copied. */
  private morphMesh(body: BodyMesh): void {
    const geometry = this.mesh!.geometry;
    const position = geometry.getAttribute('position') as THREE.BufferAttribute;
    position.array = body.positions;
    position.needsUpdate = true;
    if (body.normals) {
      const normal = geometry.getAttribute('normal') as THREE.BufferAttribute;
      normal.array = body.normals;
      normal.needsUpdate = true;
    } else geometry.computeVertexNormals();
    if (body.bounds) geometry.boundingBox = new THREE.Box3(new THREE.Vector3(...body.bounds.slice(0, 3)), new THREE.Vector3(...body.bounds.slice(3)));
    else geometry.computeBoundingBox();
    // The box's sphere is looser than computeBoundingSphere's but needs no second pass.
    geometry.boundingSphere = geometry.boundingBox!.getBoundingSphere(new THREE.Sphere());
    this.source = body;
  }

  private setVertexColours(colours: Float32Array | null): void {
    if (!this.mesh) return;
    const material = this.mesh.material as THREE.MeshStandardMaterial;
    if (colours && colours.length === this.mesh.geometry.getAttribute('position').count * 3) {
      this.mesh.geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
      material.vertexColors = true;
      material.color.set(0xffffff);
    } else {
      this.mesh.geometry.deleteAttribute('color');
      material.vertexColors = false;
      material.color.set(this.colour);
    }
    material.needsUpdate = true;
  }

  private setOpacity(opacity: number): void {
    if (!this.mesh) return;
    const material = this.mesh.material as THREE.MeshStandardMaterial;
    material.transparent = opacity < 1;
    material.opacity = opacity;
    // A see-through body must not hide what is inside it from the depth test.
    material.depthWrite = opacity >= 1;
    this.mesh.renderOrder = opacity < 1 ? 1 : 0;
    material.needsUpdate = true;
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
      // The largest side, not y: a z-up scan (CAESAR) is only ~0.4 m tall in y.
      const size = new THREE.Box3().setFromObject(this.mesh).getSize(new THREE.Vector3());
      height = Math.max(size.x, size.y, size.z);
    } else if (this.landmarks) {
      const p = this.landmarks.positions;
      const box = new THREE.Box3();
      for (let i = 0; i < p.length; i += 3) box.expandByPoint(new THREE.Vector3(p[i], p[i + 1], p[i + 2]));
      height = box.getSize(new THREE.Vector3()).length();
    }
    return Math.max(height, 1e-3) * MARKER_RADIUS_PER_HEIGHT;
  }
}
