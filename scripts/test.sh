#!/usr/bin/env bash
# The one test command (README, .ci/run): installs what is missing, lints, then runs the three
# depths of tests: Rust unit + algorithm end-to-end, the WASM bindings in a real browser, and
# Playwright against the built app.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
# One build from scratch: incremental caches would only take disk (1.3 GB) for no later build.
export CARGO_INCREMENTAL="${CARGO_INCREMENTAL:-0}"

bash scripts/setup.sh

echo "== build the core for the browser (the TypeScript check reads its types)"
bash scripts/build-wasm.sh

echo "== lint (package.json's lint: rustfmt, clippy native and wasm32, tsc)"
npm run --silent lint

echo "== rust tests"
cargo test --manifest-path crate/Cargo.toml

echo "== wasm tests (headless chromium)"
bash scripts/test-wasm.sh

echo "== build the app"
npx vite build --logLevel warn

echo "== browser tests (playwright)"
npx playwright test
