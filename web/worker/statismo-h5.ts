// Statismo HDF5 files in the worker, with h5wasm (the HDF5 C library compiled to WebAssembly).
// h5wasm is imported only when a .h5 is opened or saved (its 4 MB stay out of the first load).
// This file only moves datasets between the file and the core's StatismoArrays; the layout's
// meaning and every check are the core's (crate/src/model_file/statismo.rs, docs/shape-model.md).
import { maxModelBytes, StatismoArrays } from '../pkg/bodyspace.js';

type H5Module = typeof import('h5wasm');
type H5Group = InstanceType<H5Module['Group']>;

/** The 8 bytes every HDF5 file starts with (where both our writers put the superblock). */
const HDF5_SIGNATURE = [0x89, 0x48, 0x44, 0x46, 0x0d, 0x0a, 0x1a, 0x0a];

export function isHdf5(bytes: Uint8Array): boolean {
  return bytes.length >= 8 && HDF5_SIGNATURE.every((b, i) => bytes[i] === b);
}

let module: Promise<H5Module> | null = null;

function h5wasm(): Promise<H5Module> {
  module ??= import('h5wasm').then(async (m) => {
    await m.ready;
    return m;
  });
  return module;
}

let files = 0;

/** A fresh path in h5wasm's in-memory file system. */
function scratchPath(): string {
  files += 1;
  return `/statismo-${files}.h5`;
}

interface Read {
  shape: number[];
  values: ArrayLike<number | bigint>;
}

function dataset(file: H5Group, path: string, fileName: string): Read {
  const entity = file.get(path);
  if (!entity || !('shape' in entity) || !('value' in entity)) throw new Error(`${fileName}: not a statismo model: /${path} is missing or unreadable (is the file complete?)`);
  const value = entity.value;
  const shape = entity.shape ?? [];
  if (typeof value === 'number' || typeof value === 'bigint') return { shape, values: [value] };
  if (!ArrayBuffer.isView(value) && !Array.isArray(value)) throw new Error(`${fileName}: ${path} is not numeric`);
  return { shape, values: value as ArrayLike<number | bigint> };
}

function floats(r: Read): Float32Array {
  return Float32Array.from(r.values as ArrayLike<number>, Number);
}

/** Rows × columns of a dataset of one or two dimensions (a vector is n × 1, a scalar 1 × 1). */
function dims(r: Read, path: string, fileName: string): [number, number] {
  if (r.shape.length === 0) return [1, 1];
  if (r.shape.length === 1) return [r.shape[0]!, 1];
  if (r.shape.length === 2) return [r.shape[0]!, r.shape[1]!];
  throw new Error(`${fileName}: ${path} has ${r.shape.length} dimensions, not 1 or 2`);
}

/** Reads the datasets of a statismo model; the core judges them (`loadStatismoModel`). */
export async function readStatismoH5(bytes: Uint8Array, fileName: string): Promise<StatismoArrays> {
  const limit = maxModelBytes();
  if (bytes.length > limit) throw new Error(`${fileName}: model file is ${bytes.length} bytes, more than the ${limit} bytes of the largest model accepted (see Limits in the README)`);
  const h5 = await h5wasm();
  const path = scratchPath();
  h5.FS!.writeFile(path, bytes);
  let file: InstanceType<H5Module['File']> | null = null;
  try {
    try {
      file = new h5.File(path, 'r');
    } catch (error) {
      throw new Error(`${fileName}: not a readable HDF5 file (${error instanceof Error ? error.message : String(error)})`);
    }
    const arrays = new StatismoArrays();
    if (file.get('version')) {
      const major = Number(dataset(file, 'version/majorVersion', fileName).values[0]);
      const minor = Number(dataset(file, 'version/minorVersion', fileName).values[0]);
      arrays.setVersion(major, minor);
    }
    const points = dataset(file, 'representer/points', fileName);
    arrays.setPoints(...dims(points, '/representer/points', fileName), floats(points));
    const cells = dataset(file, 'representer/cells', fileName);
    // Cells may be stored signed or 64-bit; a negative index becomes a huge one the core refuses.
    arrays.setCells(...dims(cells, '/representer/cells', fileName), Uint32Array.from(cells.values as ArrayLike<number>, (v) => Math.min(Number(v) >>> 0, 0xffffffff)));
    arrays.setMean(floats(dataset(file, 'model/mean', fileName)));
    const basis = dataset(file, 'model/pcaBasis', fileName);
    arrays.setPcaBasis(...dims(basis, '/model/pcaBasis', fileName), floats(basis));
    arrays.setPcaVariance(floats(dataset(file, 'model/pcaVariance', fileName)));
    if (file.get('modelinfo/scores')) {
      const scores = dataset(file, 'modelinfo/scores', fileName);
      const [rows, cols] = dims(scores, '/modelinfo/scores', fileName);
      // statismo's "no scores" is a 1 × 1 zero.
      if (!(rows * cols === 1 && Number(scores.values[0]) === 0)) arrays.setScores(rows, cols, floats(scores));
    }
    return arrays;
  } finally {
    file?.close();
    h5.FS!.unlink(path);
  }
}

interface ArraysInfo {
  dataInfo: [string, string][];
  parameters: [string, string][];
  builderName: string;
  representer: { name: string; version: string; datasetType: string };
}

/** Writes `arrays` as a statismo 0.9 file (the layout of crate/src/io/statismo_h5.rs) and returns its bytes. */
export async function writeStatismoH5(arrays: StatismoArrays): Promise<Uint8Array> {
  const h5 = await h5wasm();
  const path = scratchPath();
  const info = JSON.parse(arrays.infoJson()) as ArraysInfo;
  const now = new Date().toISOString().replace('T', ' ').replace(/\.\d+Z$/, ' UTC');
  const n = arrays.pointCount;
  const k = arrays.modeCount;
  const file = new h5.File(path, 'w');
  try {
    const version = file.create_group('version');
    version.create_dataset({ name: 'majorVersion', data: new Int32Array([arrays.majorVersion]), shape: [], dtype: '<i' });
    version.create_dataset({ name: 'minorVersion', data: new Int32Array([arrays.minorVersion]), shape: [], dtype: '<i' });

    const representer = file.create_group('representer');
    representer.create_attribute('name', info.representer.name);
    representer.create_attribute('version', info.representer.version);
    representer.create_attribute('datasetType', info.representer.datasetType);
    representer.create_dataset({ name: 'points', data: arrays.points(), shape: [3, n], dtype: '<f' });
    representer.create_dataset({ name: 'cells', data: arrays.cells(), shape: [3, arrays.cellCount], dtype: '<I' });
    representer.create_group('pointData');
    representer.create_group('cellData');

    const model = file.create_group('model');
    model.create_dataset({ name: 'mean', data: arrays.mean(), shape: [3 * n], dtype: '<f' });
    model.create_dataset({ name: 'pcaBasis', data: arrays.pcaBasis(), shape: [3 * n, k], dtype: '<f' });
    model.create_dataset({ name: 'pcaVariance', data: arrays.pcaVariance(), shape: [k], dtype: '<f' });
    model.create_dataset({ name: 'noiseVariance', data: new Float32Array([0]), shape: [], dtype: '<f' });

    const modelinfo = file.create_group('modelinfo');
    modelinfo.create_dataset({ name: 'build-time', data: now });
    const subjects = arrays.subjectCount;
    if (subjects > 0) modelinfo.create_dataset({ name: 'scores', data: arrays.scores(), shape: [k, subjects], dtype: '<f' });
    else modelinfo.create_dataset({ name: 'scores', data: new Float32Array([0]), shape: [1, 1], dtype: '<f' });
    const builder = modelinfo.create_group('modelBuilder-0');
    builder.create_dataset({ name: 'builderName', data: info.builderName });
    builder.create_dataset({ name: 'buildTime', data: now });
    for (const [group, entries] of [['dataInfo', info.dataInfo], ['parameters', info.parameters]] as const) {
      const g = builder.create_group(group);
      for (const [key, value] of entries) g.create_dataset({ name: key, data: value });
    }
  } finally {
    file.close();
  }
  try {
    return h5.FS!.readFile(path);
  } finally {
    h5.FS!.unlink(path);
  }
}
