// One subject of the batch in one pool worker: read its scan and landmarks with the core, then the
// core's one pipeline (`align`: RBF warp + fine alignment) with the page's settings. The units
// rules are the single alignment's (Session, scanInput).
import { CancelledError, type CoreClient } from '../client/core-client';
import type { AlignParams, AlignResult } from '../shared/align-types';
import type { ParsedLandmarks, ParsedScan } from '../shared/results';
import type { TemplateResolution } from '../shared/template-data';
import { scanInput, scanTransfer } from './scan-input';
import { Session } from './session';

/** The files of one subject; `landmarks` null when none was dropped with the scan. */
export interface SubjectInput {
  scan: File;
  landmarks: File | null;
}

/**
 * Aligns one subject in `client`; `onProgress(fraction, label)` after each iteration. Cancelling
 * terminates the client's worker, which rejects the call under way; `cancelled` stops the job
 * between calls too (a cancel that came when no call was under way).
 */
export async function alignSubject(
  client: CoreClient,
  input: SubjectInput,
  resolution: TemplateResolution,
  params: AlignParams,
  onProgress: (fraction: number, label: string) => void,
  cancelled: AbortSignal,
): Promise<AlignResult> {
  const go = () => {
    if (cancelled.aborted) throw new CancelledError();
  };
  const bytes = await input.scan.arrayBuffer();
  go();
  const scan = await client.call({ type: 'parseScan', bytes, fileName: input.scan.name }, { transfer: [bytes] });
  const session = new Session();
  session.setScan(scan);
  go();
  session.setLandmarks(await landmarksOf(client, input, scan));
  go();
  const aligned = scanInput(session, resolution);
  if (!aligned) throw new Error('the scan or its landmarks could not be read');
  return client.call(
    { type: 'align', scan: aligned, params },
    {
      transfer: scanTransfer(aligned),
      onEvent: (event) => {
        if (event.kind !== 'alignProgress') return;
        const fraction = event.max_iterations > 0 ? Math.min(1, event.iteration / event.max_iterations) : 0;
        onProgress(fraction, `${event.stage}, iteration ${event.iteration}`);
      },
    },
  );
}

/**
 * The subject's landmarks: its landmark file read by the core. A scan without one is where
 * estimated landmarks will come from once the core can estimate them (the landmark-free issue):
 * the one place to call the estimate. Until then it fails with that reason.
 */
async function landmarksOf(client: CoreClient, input: SubjectInput, _scan: ParsedScan): Promise<ParsedLandmarks> {
  if (!input.landmarks) {
    throw new Error('no landmark file with the same base name was dropped (landmark estimation is not available yet); drop its .lnd, .csv or .json and retry');
  }
  const bytes = await input.landmarks.arrayBuffer();
  return client.call({ type: 'parseLandmarks', bytes, fileName: input.landmarks.name }, { transfer: [bytes] });
}
