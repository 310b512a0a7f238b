#!/usr/bin/env bash
# Times a full clean build of every program of testdata/programs with the SDK root
# (each with its own unmodified Makefile, `make install`), then a no-op rebuild.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build -q -p cargo-openr
exe=$PWD/target/debug/cargo-openr
root=$("$exe" sdk install --prefix "$PWD/target/bench/sdk")
work=$PWD/target/bench/corpus
rm -rf "$work" && mkdir -p "$work" && cp -r testdata/programs/. "$work/"
build_all() {
  for p in "$work"/*/; do make -s -C "$p" OPENRSDK_ROOT="$root" install >/dev/null 2>&1 || echo "FAILED: $p" >&2; done
}
t0=$(date +%s.%N); build_all; t1=$(date +%s.%N); build_all; t2=$(date +%s.%N)
objs=$(find "$work" -path '*/MW/OBJS/*' -iname '*.bin' | wc -l)
printf 'programs: %d, installed .BIN files: %d\n' "$(ls -d "$work"/*/ | wc -l)" "$objs"
awk -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN { printf "clean build: %.1f s\nno-op rebuild: %.2f s\n", b - a, c - b }'
