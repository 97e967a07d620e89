// Downloads with a size limit: a response larger than the limit is refused before it fills memory,
// by its Content-Length when the server gives one, else while it streams. No DOM.

/** Largest model file the app downloads (the demo model is 4.4 MB; a 1,000-subject fine model with
 * 50 modes in f16 is ≈ 130 MB). */
export const MODEL_DOWNLOAD_LIMIT = 256 * 1024 * 1024;

/** The bytes at `location`, or an error naming the location, the size and the limit. */
export async function fetchBounded(location: string, limit: number): Promise<ArrayBuffer> {
  const response = await fetch(location);
  if (!response.ok) throw new Error(`${location}: the server answered ${response.status} ${response.statusText}`);
  const tooLarge = (size: string) =>
    new Error(`${location}: ${size} is more than the ${(limit / 2 ** 20).toFixed(0)} MB a model download may be; download it yourself and drop the file if you trust it`);
  const declared = Number(response.headers.get('content-length') ?? NaN);
  if (declared > limit) throw tooLarge(`${(declared / 2 ** 20).toFixed(0)} MB`);
  if (!response.body) return response.arrayBuffer();
  const reader = response.body.getReader();
  const parts: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.byteLength;
    if (total > limit) {
      await reader.cancel();
      throw tooLarge('the file');
    }
    parts.push(value);
  }
  const out = new Uint8Array(total);
  let offset = 0;
  for (const part of parts) {
    out.set(part, offset);
    offset += part.byteLength;
  }
  return out.buffer;
}

/** The host of `location` when it is on another origin than `origin` (an https URL), else null. */
export function foreignHost(location: string, origin: string): string | null {
  if (!/^https:\/\//.test(location)) return null;
  try {
    const url = new URL(location);
    return url.origin === origin ? null : url.host;
  } catch {
    return null;
  }
}
