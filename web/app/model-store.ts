// The last shape model built in the app, kept in the browser's IndexedDB: a reload opens the demo
// model (or a link's) as before, and the panel offers the one built here back. Its subjects'
// fits stay in the batch's storage; the model itself took the build to make.
import { IdbStore } from './idb-store';

/** A model built here: its `.bsm` file, its name, how many subjects built it and when. */
export interface KeptModel {
  bytes: ArrayBuffer;
  fileName: string;
  subjects: number;
  builtAt: string;
}

export class ModelStore {
  private readonly db = new IdbStore('bodyspace-model', 'models', 'key');

  /** Keeps `model` in place of the one kept before; false when the browser refused (private mode). */
  keep(model: KeptModel): Promise<boolean> {
    return this.db.run('readwrite', (store) => store.put({ key: 'built', ...model })).then(
      () => true,
      () => false,
    );
  }

  /** The model kept, or null. */
  load(): Promise<KeptModel | null> {
    return this.db.run('readonly', (store) => store.get('built') as IDBRequest<KeptModel | undefined>).then(
      (kept) => kept ?? null,
      () => null,
    );
  }
}
