// One subject of the batch in one pool worker: its files go to the core's one path from a subject
// to a checked fit (`fitSubjectFiles`: the units rule, the landmark policy — a scan dropped without
// a landmark file gets the core's estimate — warp, fine alignment, quality check, frame), the path
// `bodyspace align` and `bodyspace batch` take, with the page's settings.
import { CancelledError, type CoreClient } from '../client/core-client';
import type { AlignResult, SubjectOptions } from '../shared/align-types';
import type { TemplateResolution } from '../shared/template-data';

/** The files of one subject; `landmarks` null when none was dropped with the scan. */
export interface SubjectInput {
  scan: File;
  landmarks: File | null;
}

/**
 * Aligns one subject in `client`; `onProgress(fraction, label)` after each iteration. Cancelling
 * terminates the client's worker, which rejects the call under way; `cancelled` stops the job
 * before the call too (a cancel that came while the files were being read).
 */
export async function alignSubject(
  client: CoreClient<'batch'>,
  input: SubjectInput,
  resolution: TemplateResolution,
  options: SubjectOptions,
  onProgress: (fraction: number, label: string) => void,
  cancelled: AbortSignal,
): Promise<AlignResult> {
  const scan = { bytes: await input.scan.arrayBuffer(), name: input.scan.name };
  const landmarks = input.landmarks ? { bytes: await input.landmarks.arrayBuffer(), name: input.landmarks.name } : null;
  if (cancelled.aborted) throw new CancelledError();
  const transfer = landmarks ? [scan.bytes, landmarks.bytes] : [scan.bytes];
  return client.call(
    { type: 'alignFiles', scan, landmarks, resolution, options },
    {
      transfer,
      onEvent: (event) => {
        if (event.kind !== 'alignProgress') return;
        if (event.stage === 'estimate') {
          onProgress(0, `estimating the landmarks, iteration ${event.iteration}`);
          return;
        }
        const fraction = event.max_iterations > 0 ? Math.min(1, event.iteration / event.max_iterations) : 0;
        onProgress(fraction, `${event.stage}, iteration ${event.iteration}`);
      },
    },
  );
}
