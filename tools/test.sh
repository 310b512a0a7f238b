#!/usr/bin/env bash
# Runs every test of the workspace (the README's second command; CI runs exactly this).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
# Every unsafe block and unsafe impl says why it is sound (a `// SAFETY:` comment).
cargo clippy --version >/dev/null 2>&1 || { echo "error: cargo clippy not found (tools/deps.sh could not install it): rustup component add clippy" >&2; exit 1; }
cargo clippy --workspace --all-targets --quiet -- -A clippy::all -D clippy::undocumented_unsafe_blocks
# One layout (rustfmt.toml).
cargo fmt --version >/dev/null 2>&1 || { echo "error: cargo fmt not found (tools/deps.sh could not install it): rustup component add rustfmt" >&2; exit 1; }
cargo fmt --all --check >/dev/null || { echo "error: the code is not formatted: run \`cargo fmt --all\`" >&2; exit 1; }
exec cargo test --workspace
