// The only code that imports the WASM core. Runs every core call off the UI thread.
import init, { coreVersion } from '../pkg/bodyspace.js';
import type { CoreReply, CoreRequest } from '../shared/messages';

const ready = init();

function post(reply: CoreReply): void {
  (self as unknown as Worker).postMessage(reply);
}

self.onmessage = async (event: MessageEvent<CoreRequest>) => {
  const request = event.data;
  try {
    await ready;
    switch (request.type) {
      case 'version':
        post({ id: request.id, type: 'result', result: coreVersion() });
        break;
    }
  } catch (error) {
    post({ id: request.id, type: 'error', message: error instanceof Error ? error.message : String(error) });
  }
};
