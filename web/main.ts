import { CoreClient } from './client/core-client';

const app = document.getElementById('app')!;
const client = new CoreClient();
client.version().catch((e: Error) => e.message).then((v) => {
  app.textContent = `BodySpace core ${v}`;
  document.body.dataset.ready = 'true';
});
