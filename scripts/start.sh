#!/usr/bin/env bash
# Quick start: install what is missing, build the core and the app, and serve it on localhost.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-wasm.sh
if [ ! -f dist/index.html ] || [ -n "$(find web public vite.config.ts -newer dist/index.html -print -quit)" ]; then
  npx vite build --logLevel warn
fi
echo
echo "Serving BodySpace; open the Local URL below (Ctrl+C stops it)."
# Vite takes the next free port when 4173 is busy and prints the URL it serves.
exec npx vite preview --host 127.0.0.1 --port 4173
