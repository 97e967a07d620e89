// One object store of the browser's IndexedDB, opened once: what the batch and the single scan's
// work are kept in, so a reload loses nothing. Every call resolves once its transaction is done.

function request<T>(r: IDBRequest<T>): Promise<T> {
  return new Promise((resolve, reject) => {
    r.onsuccess = () => resolve(r.result);
    r.onerror = () => reject(r.error ?? new Error('IndexedDB request failed'));
  });
}

export class IdbStore {
  private db: Promise<IDBDatabase> | null = null;

  /** The store `store` (records keyed by their `keyPath` field) of database `name`. */
  constructor(
    private readonly name: string,
    private readonly store: string,
    private readonly keyPath: string,
  ) {}

  private open(): Promise<IDBDatabase> {
    this.db ??= new Promise((resolve, reject) => {
      const r = indexedDB.open(this.name, 1);
      r.onupgradeneeded = () => r.result.createObjectStore(this.store, { keyPath: this.keyPath });
      r.onsuccess = () => resolve(r.result);
      r.onerror = () => reject(r.error ?? new Error('the browser refused its database (private mode?)'));
    });
    return this.db;
  }

  /** Runs `f` on the store in one transaction of `mode`. */
  async run<T>(mode: IDBTransactionMode, f: (store: IDBObjectStore) => IDBRequest<T>): Promise<T> {
    const db = await this.open();
    const tx = db.transaction(this.store, mode);
    const result = request(f(tx.objectStore(this.store)));
    await new Promise<void>((resolve, reject) => {
      tx.oncomplete = () => resolve();
      tx.onerror = tx.onabort = () => reject(tx.error ?? new Error('IndexedDB transaction failed'));
    });
    return result;
  }
}
