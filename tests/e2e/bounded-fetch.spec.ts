// Model downloads have a size limit, checked on the declared length and again while the bytes
// stream in (a server may declare nothing, or lie). Runs in Node against a local server.
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { expect, test } from '@playwright/test';
import { fetchBounded, foreignHost } from '../../web/shared/bounded-fetch';

let server: Server;
let base = '';

test.beforeAll(async () => {
  server = createServer((request, response) => {
    const chunk = Buffer.alloc(64 * 1024, 7);
    if (request.url === '/declared') {
      response.writeHead(200, { 'content-length': String(10 * 1024 * 1024) });
      response.end();
    } else if (request.url === '/streamed') {
      // 4 MB without a declared length.
      response.writeHead(200);
      for (let i = 0; i < 64; i++) response.write(chunk);
      response.end();
    } else if (request.url === '/small') {
      response.writeHead(200);
      response.end(chunk);
    } else {
      response.writeHead(404, 'Not Found');
      response.end();
    }
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
});

test.afterAll(() => new Promise<void>((resolve) => server.close(() => resolve())));

test('a download within the limit arrives whole', async () => {
  const bytes = await fetchBounded(`${base}/small`, 1024 * 1024);
  expect(bytes.byteLength).toBe(64 * 1024);
});

test('a declared length over the limit is refused before the body is read', async () => {
  await expect(fetchBounded(`${base}/declared`, 1024 * 1024)).rejects.toThrow(/10 MB is more than the 1 MB/);
});

test('an undeclared stream is cut off once it passes the limit', async () => {
  await expect(fetchBounded(`${base}/streamed`, 1024 * 1024)).rejects.toThrow(/more than the 1 MB a model download may be/);
});

test('a server error names the location and the status', async () => {
  await expect(fetchBounded(`${base}/missing`, 1024)).rejects.toThrow(/missing: the server answered 404/);
});

test('only https locations on another origin count as another host', () => {
  expect(foreignHost('https://models.example.org/a.bsm', 'http://127.0.0.1:4173')).toBe('models.example.org');
  expect(foreignHost('https://app.example.org/models/a.bsm', 'https://app.example.org')).toBeNull();
  expect(foreignHost('http://127.0.0.1:4173/models/demo.bsm', 'http://127.0.0.1:4173')).toBeNull();
});
