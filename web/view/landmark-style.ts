// How the landmarks being edited look on the scan: given ones in the landmark colour, edited ones
// in blue, estimated ones from red (low confidence) through yellow to green (high), the file's
// non-CAESAR names in the warning colour; the picked one and the suspicious ones drawn larger,
// suspicious ones in magenta.
import * as THREE from 'three';
import type { LandmarkEntry, Point } from '../shared/landmark-entry';
import type { LandmarkPoints } from './landmark-markers';

const GIVEN = new THREE.Color(0xff6a3d);
const EDITED = new THREE.Color(0x4fb3ff);
const UNKNOWN = new THREE.Color(0xf2c14e);
const SUSPICIOUS = new THREE.Color(0xff3df2);
/** Confidence 0, ½ and 1: the page's bad, warning and ok colours. */
const CONFIDENCE = [new THREE.Color(0xe5646a), new THREE.Color(0xf2c14e), new THREE.Color(0x5ccf8a)] as const;

const SELECTED_SIZE = 1.8;
const SUSPICIOUS_SIZE = 1.5;

/** The markers of `placed` (entries with a position) and of `unknown` named points. */
export function landmarkStyle(
  placed: readonly LandmarkEntry[],
  unknown: readonly { name: string; position: Point }[],
  selected: string | null,
  suspicious: ReadonlySet<string>,
): LandmarkPoints {
  const all = [...placed.map((e) => ({ name: e.name, position: e.position!, colour: colourOf(e, suspicious) })), ...unknown.map((u) => ({ ...u, colour: UNKNOWN }))];
  const colours = new Float32Array(all.length * 3);
  const sizes = new Float32Array(all.length);
  all.forEach((m, i) => {
    m.colour.toArray(colours, 3 * i);
    sizes[i] = m.name === selected ? SELECTED_SIZE : suspicious.has(m.name) ? SUSPICIOUS_SIZE : 1;
  });
  return { names: all.map((m) => m.name), positions: Float32Array.from(all.flatMap((m) => m.position)), colours, sizes };
}

function colourOf(entry: LandmarkEntry, suspicious: ReadonlySet<string>): THREE.Color {
  if (suspicious.has(entry.name)) return SUSPICIOUS;
  if (entry.state === 'edited') return EDITED;
  if (entry.state === 'estimated' && entry.confidence !== null) {
    const t = Math.min(Math.max(entry.confidence, 0), 1) * 2;
    const i = Math.min(Math.floor(t), 1);
    return CONFIDENCE[i]!.clone().lerp(CONFIDENCE[i + 1]!, t - i);
  }
  return GIVEN;
}
