// Which reader a file goes to, told from its name alone. No DOM here.

export type FileKind = 'scan' | 'landmarks';

const SCAN_EXTENSIONS = ['ply', 'obj', 'stl'];
const LANDMARK_EXTENSIONS = ['csv', 'lnd', 'json'];

/** What the app accepts, for the file picker and for messages. */
export const ACCEPTED_EXTENSIONS = [...SCAN_EXTENSIONS, ...LANDMARK_EXTENSIONS].flatMap((e) => [
  `.${e}`,
  `.${e}.gz`,
]);

/** The kind of file by its extension after stripping a trailing `.gz`; null when unsupported. */
export function classifyFile(fileName: string): FileKind | null {
  const lower = fileName.toLowerCase().replace(/\.gz$/, '');
  const dot = lower.lastIndexOf('.');
  if (dot < 0) return null;
  const ext = lower.slice(dot + 1);
  if (SCAN_EXTENSIONS.includes(ext)) return 'scan';
  if (LANDMARK_EXTENSIONS.includes(ext)) return 'landmarks';
  return null;
}

/** The message shown for a file the app does not read. */
export function unsupportedMessage(fileName: string): string {
  return `${fileName}: unsupported file type; scans are .ply, .obj or .stl and landmarks .csv, .lnd or .json (each optionally .gz)`;
}

/** The name without its directory-free extension(s): `scan_001.ply.gz` → `scan_001`. */
export function baseName(fileName: string): string {
  return fileName.replace(/\.gz$/i, '').replace(/\.[^.]+$/, '');
}
