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
# The declared MSRV builds every crate and test (dependencies included, as locked).
msrv=$(sed -n 's/^rust-version = "\(.*\)"/\1/p' Cargo.toml)
if command -v rustup >/dev/null 2>&1 && rustup run "$msrv" rustc --version >/dev/null 2>&1; then
  CARGO_TARGET_DIR=target/msrv cargo "+$msrv" check --workspace --all-targets --locked --quiet
elif [ -n "${CI:-}" ]; then
  echo "error: Rust $msrv (rust-version of Cargo.toml) is not installed: rustup toolchain install $msrv" >&2; exit 1
else
  echo "note: not checked with Rust $msrv, the declared MSRV (no rustup toolchain $msrv)" >&2
fi
exec cargo test --workspace
