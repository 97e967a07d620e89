// One subject of the batch in one pool worker: read its scan and landmarks with the core (a scan
// dropped without a landmark file gets the core's estimate of them, as a single scan does), then
// the core's one pipeline (`align`: RBF warp + fine alignment) with the page's settings. The
// units rules are the single alignment's (Session, scanInput).
import { CancelledError, type CoreClient } from '../client/core-client';
import type { AlignParams, AlignResult } from '../shared/align-types';
import type { ParsedLandmarks } from '../shared/results';
import type { TemplateResolution } from '../shared/template-data';
import { estimateInput, scanInput, scanTransfer } from './scan-input';
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
  const names = await client.call({ type: 'caesarNames' });
  const session = new Session(() => names);
  session.setScan(scan);
  go();
  if (input.landmarks) session.setLandmarks(await readLandmarks(client, input.landmarks));
  else await estimateLandmarks(client, session, onProgress);
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

async function readLandmarks(client: CoreClient, file: File): Promise<ParsedLandmarks> {
  const bytes = await file.arrayBuffer();
  return client.call({ type: 'parseLandmarks', bytes, fileName: file.name }, { transfer: [bytes] });
}

/** A scan dropped without a landmark file: the core's estimate of all 73 (as the single scan gets). */
async function estimateLandmarks(client: CoreClient, session: Session, onProgress: (fraction: number, label: string) => void): Promise<void> {
  const input = estimateInput(session);
  if (!input || !session.edits) throw new Error('the scan could not be read');
  const estimate = await client.call(
    { type: 'estimateLandmarks', scan: input },
    { transfer: scanTransfer(input), onProgress: (fraction, label) => onProgress(0, `${label} (${Math.round(100 * fraction)} %)`) },
  );
  session.edits.fillEstimate(estimate.names, estimate.positions, estimate.confidence, estimate.given);
}
