// Dropped or picked fitted meshes (template vertex order) into the session's subject store.
import type { CoreClient } from '../client/core-client';
import type { SubjectStore } from './subjects';

/** Reads each file with the core; meshes with `vertexCount` vertices join the store as 'dropped'. */
export async function readFits(client: CoreClient<'core'>, store: SubjectStore, files: File[], vertexCount: number, resolution: string): Promise<string[]> {
  const errors: string[] = [];
  for (const file of files) {
    try {
      const bytes = await file.arrayBuffer();
      const scan = await client.call({ type: 'parseScan', bytes, fileName: file.name }, { transfer: [bytes] });
      const v = scan.positions.length / 3;
      if (v !== vertexCount) {
        errors.push(`${file.name}: ${v} vertices, but a fitted mesh in template order at ${resolution} resolution has ${vertexCount}`);
        continue;
      }
      store.add({ name: file.name, positions: scan.positions, resolution, source: 'dropped' });
    } catch (error) {
      errors.push(error instanceof Error ? error.message : String(error));
    }
  }
  return errors;
}
