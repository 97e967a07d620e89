// What every view shares: lights and a ground grid in metres (y up).
import * as THREE from 'three';

/** Sky/ground hemisphere light plus a key and a rim directional light. */
export function addLights(scene: THREE.Scene): void {
  scene.add(new THREE.HemisphereLight(0xdde6f5, 0x2a2622, 1.6));
  const key = new THREE.DirectionalLight(0xffffff, 2.2);
  key.position.set(1.5, 3, 2.5);
  scene.add(key);
  const rim = new THREE.DirectionalLight(0x9fb8ff, 0.9);
  rim.position.set(-2, 2, -3);
  scene.add(rim);
}

/** A 6 m × 6 m ground grid: 1 m major lines over 10 cm minor lines. */
export function makeGrid(): THREE.Group {
  const grid = new THREE.Group();
  grid.name = 'ground-grid';
  const minor = new THREE.GridHelper(6, 60, 0x2b313b, 0x2b313b);
  const major = new THREE.GridHelper(6, 6, 0x4a5466, 0x4a5466);
  for (const g of [minor, major]) {
    const material = g.material as THREE.Material;
    material.transparent = true;
    material.opacity = g === minor ? 0.55 : 0.9;
    material.depthWrite = false;
    grid.add(g);
  }
  major.position.y = 0.0005;
  return grid;
}
