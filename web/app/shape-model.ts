// The shape model in view and where it came from: fetched (same origin, or another host the person
// agreed to), dropped, or built here from aligned subjects; a copy of its file is kept, so a
// replaced worker (its core trapped) and the population worker can be given it again.
import type { CoreClient } from '../client/core-client';
import { fetchBounded, foreignHost, MODEL_DOWNLOAD_LIMIT } from '../shared/bounded-fetch';
import type { LoadedModel } from '../shared/shape-results';
import type { TemplateResolution } from '../shared/template-data';
import { HostPrompt } from '../ui/host-prompt';
import type { ModelFile } from './population';
import { readFits } from './read-fits';
import { subjects, type AlignedSubject } from './subjects';

/** Vertices of the base template: fitted meshes dropped before any model are read at it. */
const BASE_VERTEX_COUNT = 13380;

export class ShapeModel {
  loaded: LoadedModel | null = null;
  /** Same-origin path or https URL of the model, `null` when dropped or built here. */
  source: string | null = null;
  /** A copy of the model file in view. */
  file: ModelFile | null = null;
  private readonly hostPrompt = new HostPrompt();
  private readonly page = document.body;

  constructor(private readonly client: CoreClient<'core'>) {}

  /**
   * The bytes at `location`, or null when it is on another host and the person declined (the
   * prompt names the host). Every download has a size limit; throws what the fetch threw.
   */
  async fetch(location: string): Promise<ArrayBuffer | null> {
    const host = foreignHost(new URL(location, document.baseURI).href, window.location.origin);
    if (host && !(await this.hostPrompt.ask(host, 'shape model'))) {
      this.page.dataset.shapeForeignDeclined = host;
      return null;
    }
    return fetchBounded(location, MODEL_DOWNLOAD_LIMIT);
  }

  /** Loads a model file (`bytes` are transferred) in the worker; on failure throws the core's error and the old model stays. */
  async load(bytes: ArrayBuffer, fileName: string, source: string | null): Promise<LoadedModel> {
    const copy = bytes.slice(0);
    const loaded = await this.client.call({ type: 'loadModel', bytes, fileName }, { transfer: [bytes] });
    this.file = { bytes: copy, fileName };
    this.loaded = loaded;
    this.source = source;
    return loaded;
  }

  /**
   * Builds a model of `all` keeping `variance` (%) in the worker; the model in view from then on
   * (its file is kept by `keepBuiltFile`). Throws the core's error.
   */
  async build(all: readonly AlignedSubject[], variance: number, onProgress: (fraction: number, label: string) => void): Promise<LoadedModel> {
    const v = all[0]!.positions.length;
    const positions = new Float32Array(v * all.length);
    all.forEach((s, i) => positions.set(s.positions, i * v));
    const built = await this.client.call(
      { type: 'buildModel', positions, names: all.map((s) => s.name), variance },
      { transfer: [positions.buffer], onProgress },
    );
    this.loaded = built;
    this.source = null;
    return built;
  }

  /** Keeps a copy of the file of the model just built, written by the worker. */
  async keepBuiltFile(fileName: string): Promise<ModelFile> {
    this.file = { bytes: (await this.client.call({ type: 'modelFile' })).slice().buffer, fileName };
    return this.file;
  }

  /** Gives a replaced worker the model in view again, mapped to `resolution`; throws the core's error. */
  async reload(resolution: TemplateResolution): Promise<void> {
    const file = this.file;
    if (!file) return;
    await this.client.call({ type: 'loadModel', bytes: file.bytes.slice(0), fileName: file.fileName });
    if (resolution === 'fine' && this.loaded?.info.template.resolution === 'base') {
      await this.client.call({ type: 'shapeResolution', resolution: 'fine' });
    }
  }

  /** Reads fitted meshes (at the model's resolution, else the base template's) into the training subjects; the problems, one line each. */
  addFits(files: File[]): Promise<string[]> {
    const model = this.loaded;
    const vertexCount = model?.info.template.vertex_count ?? BASE_VERTEX_COUNT;
    const resolution = model?.info.template.resolution ?? 'base';
    return readFits(this.client, subjects, files, vertexCount, resolution);
  }
}

/** Why `all` cannot make a model (fewer than 2, or of different resolutions), or null when it can. */
export function cannotBuild(all: readonly AlignedSubject[]): string | null {
  if (all.length < 2) return 'A model needs at least 2 aligned subjects; add fitted meshes or align scans first.';
  const v = all[0]!.positions.length;
  if (all.some((s) => s.positions.length !== v)) return 'The subjects are at different template resolutions; a model needs one.';
  return null;
}
