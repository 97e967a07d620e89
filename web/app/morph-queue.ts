// Keeps slider morphing fluid: at most one morph in flight; moves made meanwhile are coalesced
// and only the latest is sent when it returns (latest wins). The worker holds the body, so a
// slider move is a rank-1 update there; a full rebuild is asked for only when a coalesced
// request wanted one (reset, random body, link, new model or resolution).
import type { CoreClient } from '../client/core-client';
import type { ReconstructedBody, ShapeCoefficients } from '../shared/shape-results';

export class MorphQueue {
  private inFlight = false;
  private latest: ShapeCoefficients | null = null;
  private rebuild = false;

  constructor(
    private readonly client: CoreClient<'core'>,
    /** `sentAt`: `performance.now()` when the request was posted (for the round trip). */
    private readonly onBody: (body: ReconstructedBody, coefficients: ShapeCoefficients, sentAt: number) => void,
    private readonly onError: (message: string) => void,
  ) {}

  /** Asks for the body of `coefficients`; replaces any request not yet sent. */
  request(coefficients: ShapeCoefficients, rebuild = false): void {
    this.latest = structuredClone(coefficients);
    this.rebuild ||= rebuild;
    if (!this.inFlight) void this.pump();
  }

  /** Whether nothing is in flight or waiting. */
  get idle(): boolean {
    return !this.inFlight && this.latest === null;
  }

  private async pump(): Promise<void> {
    while (this.latest) {
      const next = this.latest;
      const rebuild = this.rebuild;
      this.latest = null;
      this.rebuild = false;
      this.inFlight = true;
      let body: ReconstructedBody | null = null;
      const sentAt = performance.now();
      try {
        body = await this.client.call({ type: 'morph', coefficients: next, rebuild });
      } catch (error) {
        // The worker may not hold the body it was asked to change: rebuild next time.
        this.rebuild = true;
        this.onError(error instanceof Error ? error.message : String(error));
      }
      // Not in flight any more while the body is shown, so `idle` tells whether it is the last.
      this.inFlight = false;
      if (body) this.onBody(body, next, sentAt);
    }
  }
}
