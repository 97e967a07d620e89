#!/usr/bin/env bash
# Runs the bindings' tests in a real headless Chromium through Debian's chromedriver.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
export CHROMEDRIVER="${CHROMEDRIVER:-/usr/bin/chromedriver}"
wasm-pack test --headless --chrome crate
