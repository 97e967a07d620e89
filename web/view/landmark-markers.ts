// Landmarks as small spheres, one instanced mesh per set, that the tooltip can pick by name.
import * as THREE from 'three';

/** Named points in metres: `names[i]` sits at `positions[3i..3i+3]`. */
export interface LandmarkPoints {
  names: string[];
  positions: Float32Array;
  /** Names drawn in the warning colour (e.g. not CAESAR landmarks). */
  flagged?: ReadonlySet<string>;
  /** `#L·3` linear RGB per marker, instead of the two fixed colours. */
  colours?: Float32Array;
  /** A factor on each marker's radius (e.g. the selected one larger). */
  sizes?: Float32Array;
}

const KNOWN_COLOUR = new THREE.Color(0xff6a3d);
const FLAGGED_COLOUR = new THREE.Color(0xf2c14e);

export class LandmarkMarkers {
  readonly object: THREE.InstancedMesh;
  private readonly names: string[];

  /** Spheres of `radius` metres at each landmark. */
  constructor(points: LandmarkPoints, radius: number) {
    this.names = points.names;
    const geometry = new THREE.SphereGeometry(1, 16, 12);
    const material = new THREE.MeshStandardMaterial({
      roughness: 0.4,
      metalness: 0,
      emissive: 0x3a1004,
    });
    const count = points.names.length;
    this.object = new THREE.InstancedMesh(geometry, material, count);
    this.object.name = 'landmark-markers';
    const matrix = new THREE.Matrix4();
    const colour = new THREE.Color();
    const { colours, sizes } = points;
    for (let i = 0; i < count; i++) {
      const r = radius * (sizes?.[i] ?? 1);
      matrix.makeScale(r, r, r);
      matrix.setPosition(points.positions[3 * i]!, points.positions[3 * i + 1]!, points.positions[3 * i + 2]!);
      this.object.setMatrixAt(i, matrix);
      if (colours) colour.setRGB(colours[3 * i]!, colours[3 * i + 1]!, colours[3 * i + 2]!);
      else colour.copy(points.flagged?.has(points.names[i]!) ? FLAGGED_COLOUR : KNOWN_COLOUR);
      this.object.setColorAt(i, colour);
    }
    this.object.instanceMatrix.needsUpdate = true;
    this.object.computeBoundingSphere();
  }

  get count(): number {
    return this.names.length;
  }

  /** The nearest marker the ray hits: its name and distance along the ray, or null. */
  pick(raycaster: THREE.Raycaster): { name: string; distance: number } | null {
    const hit = raycaster.intersectObject(this.object, false)[0];
    const name = hit?.instanceId === undefined ? undefined : this.names[hit.instanceId];
    return hit && name !== undefined ? { name, distance: hit.distance } : null;
  }

  dispose(): void {
    this.object.geometry.dispose();
    (this.object.material as THREE.Material).dispose();
    this.object.dispose();
  }
}
