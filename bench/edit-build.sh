#!/usr/bin/env bash
# The edit-build cycle of `cargo openr build` on a multi-object program of the corpus
# (testdata/programs/blinkleds, 4 objects): clean build, no-op build and a one-file change,
# for the dev (-O0 -g) and release (-O2 -g) profiles, with -j 1 beside the default -j
# (the cores). Each figure is the min / median / max of RUNS runs (default 3).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
cargo build -q --release -p cargo-openr
exe=$PWD/target/release/cargo-openr
root=$("$exe" sdk install --prefix "$PWD/target/bench/sdk" | tail -1)
work=$PWD/target/bench/edit-build
src=testdata/programs/blinkleds
touch_file=BlinkingFaceLED/BlinkingFaceLED.cc

now() { date +%s.%N; }
diff() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
# stats NAME V1 V2 …: "NAME: min / median / max s"
stats() {
  local name=$1; shift
  printf '%s\n' "$@" | sort -n | awk -v n="$name" '{ v[NR] = $1 } END { m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%-44s %6.2f / %6.2f / %6.2f s\n", n ":", v[1], m, v[NR] }'
}
measure() { # profile-flag jobs
  local flag=$1 jobs=$2 clean=() noop=() touched=()
  for _ in $(seq "$runs"); do
    rm -rf "$work" && mkdir -p "$work" && cp -r "$src" "$work/p"
    local t0 t1 t2 t3 t4
    t0=$(now); "$exe" build --path "$work/p" --sdk "$root" $flag -j "$jobs" >/dev/null 2>&1
    t1=$(now); "$exe" build --path "$work/p" --sdk "$root" $flag -j "$jobs" >/dev/null 2>&1
    t2=$(now); sleep 0.01; touch "$work/p/$touch_file"
    t3=$(now); "$exe" build --path "$work/p" --sdk "$root" $flag -j "$jobs" >/dev/null 2>&1
    t4=$(now)
    clean+=("$(diff "$t0" "$t1")"); noop+=("$(diff "$t1" "$t2")"); touched+=("$(diff "$t3" "$t4")")
  done
  local label=${flag:---dev}
  stats "$label -j $jobs clean build" "${clean[@]}"
  stats "$label -j $jobs no-op build" "${noop[@]}"
  stats "$label -j $jobs one file changed" "${touched[@]}"
}
echo "blinkleds (4 objects), $runs runs each, $(nproc) cores"
for flag in "" --release; do
  measure "$flag" 1
  measure "$flag" "$(nproc)"
done
