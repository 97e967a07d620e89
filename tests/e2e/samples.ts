// The synthetic sample subjects of public/samples, read from disk as a person would drop them.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { TestFile } from './fixtures';

const SAMPLES = fileURLToPath(new URL('../../public/samples/', import.meta.url));

export function sampleFile(name: string): TestFile {
  return { name, bytes: readFileSync(join(SAMPLES, name)) };
}

/** Sample subject 001: its scan (mm, z-up, facing −y) and its 73 landmarks. */
export function sampleSubject(): TestFile[] {
  return [sampleFile('scan_001.ply.gz'), sampleFile('landmarks_001.csv')];
}

/** `landmarks_001.csv` without every landmark whose name is not in `keep`: a partial file. */
export function partialCsv(keep: (name: string, index: number) => boolean): TestFile {
  const [header, ...lines] = sampleFile('landmarks_001.csv').bytes.toString('utf8').trim().split('\n');
  const kept = lines.filter((line, i) => keep(line.replace(/^"([^"]*)".*$|^([^,]*),.*$/, '$1$2'), i));
  return { name: 'partial.csv', bytes: Buffer.from([header, ...kept].join('\n')) };
}
