// Keeps slider morphing fluid: at most one reconstruction in flight; moves made meanwhile are
// coalesced and only the latest is sent when it returns (latest wins).
import type { CoreClient } from '../client/core-client';
import type { ReconstructedBody, ShapeCoefficients } from '../shared/shape-results';

export class MorphQueue {
  private inFlight = false;
  private latest: ShapeCoefficients | null = null;

  constructor(
    private readonly client: CoreClient,
    private readonly onBody: (body: ReconstructedBody, coefficients: ShapeCoefficients) => void,
    private readonly onError: (message: string) => void,
  ) {}

  /** Asks for the body of `coefficients`; replaces any request not yet sent. */
  request(coefficients: ShapeCoefficients): void {
    this.latest = structuredClone(coefficients);
    if (!this.inFlight) void this.pump();
  }

  /** Whether nothing is in flight or waiting. */
  get idle(): boolean {
    return !this.inFlight && this.latest === null;
  }

  private async pump(): Promise<void> {
    while (this.latest) {
      const next = this.latest;
      this.latest = null;
      this.inFlight = true;
      let body: ReconstructedBody | null = null;
      try {
        body = await this.client.call({ type: 'reconstruct', coefficients: next });
      } catch (error) {
        this.onError(error instanceof Error ? error.message : String(error));
      }
      // Not in flight any more while the body is shown, so `idle` tells whether it is the last.
      this.inFlight = false;
      if (body) this.onBody(body, next);
    }
  }
}
