#!/usr/bin/env bash
# The README's test command: every test of the workspace (unit, golden, property, doc).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --locked
