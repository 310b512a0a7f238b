#!/usr/bin/env bash
# Runs every test of the workspace (the README's second command; CI runs exactly this).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
exec cargo test --workspace
