// Sends dropped or picked files to the core worker, scans before landmarks, one at a time.
// Each file's bytes are transferred to the worker; a file that fails only adds its message.
import { CoreClient } from '../client/core-client';
import { classifyFile, unsupportedMessage } from '../shared/file-kind';
import type { ParsedLandmarks, ParsedScan } from '../shared/results';

/** A scan as read, with the round trip timed on this thread around the worker call, and its file. */
export interface ReadScan {
  scan: ParsedScan;
  roundTripMs: number;
  file: File;
}

/** A landmark file as read, and the file. */
export interface ReadLandmarks {
  landmarks: ParsedLandmarks;
  file: File;
}

export interface ReadOutcome {
  scans: ReadScan[];
  landmarks: ReadLandmarks[];
  /** One message per failed file, each naming the file. */
  errors: string[];
}

export async function readFiles(
  client: CoreClient<'core'>,
  files: File[],
  onStatus: (text: string) => void,
): Promise<ReadOutcome> {
  const outcome: ReadOutcome = { scans: [], landmarks: [], errors: [] };
  const scans = files.filter((f) => classifyFile(f.name) === 'scan');
  const landmarks = files.filter((f) => classifyFile(f.name) === 'landmarks');
  for (const f of files) if (classifyFile(f.name) === null) outcome.errors.push(unsupportedMessage(f.name));

  for (const file of scans) {
    onStatus(`Reading ${file.name}…`);
    try {
      const bytes = await file.arrayBuffer();
      const t0 = performance.now();
      const scan = await client.call(
        { type: 'parseScan', bytes, fileName: file.name },
        { transfer: [bytes], onProgress: (_fraction, label) => onStatus(`${label}…`) },
      );
      outcome.scans.push({ scan, roundTripMs: performance.now() - t0, file });
    } catch (error) {
      outcome.errors.push(messageFor(file.name, error, SCAN_ADVICE));
    }
  }
  for (const file of landmarks) {
    onStatus(`Reading ${file.name}…`);
    try {
      const bytes = await file.arrayBuffer();
      const parsed = await client.call({ type: 'parseLandmarks', bytes, fileName: file.name }, { transfer: [bytes] });
      outcome.landmarks.push({ landmarks: parsed, file });
    } catch (error) {
      outcome.errors.push(messageFor(file.name, error, LANDMARK_ADVICE));
    }
  }
  return outcome;
}

/** What a person can do about a scan the core refused, after its own message. */
const SCAN_ADVICE = 'Nothing else was changed. Export the scan again from the scanner software (PLY, OBJ or STL, complete and uncompressed if in doubt) and drop it again.';

/** What a person can do about a landmark file the core refused. */
const LANDMARK_ADVICE = 'Nothing else was changed. Fix the line named above, or export the landmarks as CSV (name,x,y,z), CAESAR .lnd or JSON, and drop the file again.';

/**
 * The core's message (which says what is wrong and starts with the file name; prefixed with it
 * when it does not), then what to do.
 */
function messageFor(fileName: string, error: unknown, advice: string): string {
  const message = error instanceof Error ? error.message : String(error);
  return `${message.startsWith(fileName) ? message : `${fileName}: ${message}`}. ${advice}`;
}
