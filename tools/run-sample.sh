#!/usr/bin/env bash
# Builds cargo-openr, its SDK root and one program of testdata/programs with its own
# unmodified Makefile, then runs its Memory Stick tree (the README's first command).
#   tools/run-sample.sh [PROGRAM] [cargo openr run options...]   (default: movelegs --for 6s)
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
sample=${1:-movelegs}; shift || true
[ -d "testdata/programs/$sample" ] || { echo "no program testdata/programs/$sample; try one of: $(ls testdata/programs | tr '\n' ' ')" >&2; exit 2; }
cargo build -q -p cargo-openr
exe=$PWD/target/debug/cargo-openr
root=$("$exe" sdk install --prefix "$PWD/target/openr-sdk")
work=$PWD/target/samples/$sample
rm -rf "$work" && mkdir -p "$(dirname "$work")" && cp -r "testdata/programs/$sample" "$work"
echo "building $sample with its Makefile (log: $work.log)" >&2
make -C "$work" OPENRSDK_ROOT="$root" install >"$work.log" 2>&1 || { cat "$work.log" >&2; exit 1; }
[ $# -gt 0 ] || set -- --for 6s
exec "$exe" run --sdk "$root" "$work/MS" "$@"
