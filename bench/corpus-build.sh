#!/usr/bin/env bash
# Times clean builds of every program of testdata/programs with an SDK root (each with its
# own unmodified Makefile, `make install`), then a no-op rebuild.
#
#   bench/corpus-build.sh [--sdk ROOT] [--runs N] [--skip NAME]...
#
# Without --sdk the root is installed from this checkout (target/bench/sdk); --sdk times
# another root, e.g. one installed by an older build, to compare compiler wrappers on the
# same corpus. --skip leaves a program out (e.g. one the other root cannot build).
# Prints each clean build's wall-clock and CPU seconds (user + system of make and the
# compilers: steadier on a shared machine), then min / median / max of each.
set -euo pipefail
cd "$(dirname "$0")/.."
root="" runs=1 skip=()
while (($#)); do
  case $1 in
    --sdk) root=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --skip) skip+=("$2"); shift 2 ;;
    *) echo "usage: $0 [--sdk ROOT] [--runs N] [--skip NAME]..." >&2; exit 2 ;;
  esac
done
if [ -z "$root" ]; then
  cargo build -q -p cargo-openr
  root=$(target/debug/cargo-openr sdk install --prefix "$PWD/target/bench/sdk")
fi
work=$PWD/target/bench/corpus
fresh_copy() {
  rm -rf "$work" && mkdir -p "$work" && cp -r testdata/programs/. "$work/"
  for s in "${skip[@]}"; do rm -rf "${work:?}/$s"; done
}
build_all() {
  local failed=0
  for p in "$work"/*/; do
    make -s -C "$p" OPENRSDK_ROOT="$root" install >/dev/null 2>&1 || { echo "FAILED: $p" >&2; failed=1; }
  done
  return $failed
}
# CPU seconds (user + system) of this shell's finished children: bash's `times`, run in
# this shell (in a $(…) subshell it would count the subshell's children only).
cpu_file=$(mktemp); trap 'rm -f "$cpu_file"' EXIT
child_cpu() {
  times >"$cpu_file"
  awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%.2f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$cpu_file"
}
times=() cpus=()
for ((r = 1; r <= runs; r++)); do
  fresh_copy
  child_cpu >"$cpu_file.0"; t0=$(date +%s.%N); build_all || true; t1=$(date +%s.%N); child_cpu >"$cpu_file.1"
  c0=$(cat "$cpu_file.0") c1=$(cat "$cpu_file.1"); rm -f "$cpu_file".[01]
  times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')")
  cpus+=("$(awk -v a="$c0" -v b="$c1" 'BEGIN { printf "%.2f", b - a }')")
  echo "clean build $r: ${times[-1]} s (CPU ${cpus[-1]} s)"
done
t1=$(date +%s.%N); build_all || true; t2=$(date +%s.%N)
objs=$(find "$work" -path '*/MW/OBJS/*' -iname '*.bin' | wc -l)
printf 'root: %s\nprograms: %d, installed .BIN files: %d\n' "$root" "$(ls -d "$work"/*/ | wc -l)" "$objs"
stats() { sort -n | awk -v what="$1" '{ v[NR] = $1 } END {
  printf "%s (%d runs): min %.2f s, median %.2f s, max %.2f s\n", what, NR, v[1], v[int((NR + 1) / 2)], v[NR] }'; }
printf '%s\n' "${times[@]}" | stats "clean build"
printf '%s\n' "${cpus[@]}" | stats "clean build, CPU"
awk -v a="$t1" -v b="$t2" 'BEGIN { printf "no-op rebuild: %.2f s\n", b - a }'
