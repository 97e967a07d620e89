// glTF (binary) of bodies through three.js GLTFExporter: one mesh node per body.
import * as THREE from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';

export interface NamedBody {
  name: string;
  positions: Float32Array;
  normals: Float32Array;
  triangles: Uint32Array;
}

/** A GLB holding every body as its own mesh, side by side along x when `spread` > 0 (metres). */
export async function bodiesGlb(bodies: NamedBody[], spread = 0): Promise<Uint8Array> {
  const scene = new THREE.Scene();
  const material = new THREE.MeshStandardMaterial({ color: 0xc8b4a0, roughness: 0.8 });
  bodies.forEach((body, i) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(body.positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(body.normals, 3));
    geometry.setIndex(new THREE.BufferAttribute(body.triangles, 1));
    const mesh = new THREE.Mesh(geometry, material);
    mesh.name = body.name;
    mesh.position.x = i * spread;
    scene.add(mesh);
  });
  const result = await new GLTFExporter().parseAsync(scene, { binary: true });
  return new Uint8Array(result as ArrayBuffer);
}
