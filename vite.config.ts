import { defineConfig, type Plugin } from 'vite';

/**
 * The built site's Content-Security-Policy, as a meta tag (so it holds on any static server):
 * scripts, WebAssembly and workers from the page's own origin only (`'wasm-unsafe-eval'` is what
 * compiling WebAssembly needs; no other eval, no inline script); models from the own origin or,
 * after the person agrees to the host, https. Not applied to `vite dev`, whose live reload injects
 * inline scripts.
 */
export const CONTENT_SECURITY_POLICY = [
  "default-src 'self'",
  "script-src 'self' 'wasm-unsafe-eval'",
  "worker-src 'self'",
  "connect-src 'self' https:",
  "img-src 'self' data: blob:",
  "style-src 'self'",
  "object-src 'none'",
  "base-uri 'self'",
  "form-action 'none'",
].join('; ');

function contentSecurityPolicy(): Plugin {
  return {
    name: 'bodyspace-csp',
    apply: 'build',
    transformIndexHtml: (html) => ({
      html,
      tags: [{ tag: 'meta', attrs: { 'http-equiv': 'Content-Security-Policy', content: CONTENT_SECURITY_POLICY }, injectTo: 'head-prepend' }],
    }),
  };
}

// The app is a static site: `dist/` works from any static file server under any path (base './'),
// and makes no request to any other origin.
export default defineConfig({
  plugins: [contentSecurityPolicy()],
  root: 'web',
  base: './',
  publicDir: '../public',
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 2000,
  },
  worker: {
    format: 'es',
  },
  server: {
    host: '127.0.0.1',
    port: 5173,
  },
  preview: {
    host: '127.0.0.1',
    port: 4173,
    strictPort: true,
  },
});
