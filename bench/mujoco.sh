#!/usr/bin/env bash
# MuJoCo simulation speed (issue 8): real-time factor of whole runs -- runtimes, the
# lockstep protocol, physics and head cameras at 30 fps -- for 1, 4 and 8 ERS-7s, each
# running movelegs (walking swing) plus camwatch (an object reading every camera image),
# then the peer alone (physics and rendering without runtimes). Release build.
# Each run gives two figures: the wall time of the whole command (process start,
# loading, MuJoCo import and model compile included) and the simulation's own speed
# from the moment every robot is attached to the end (the peer's "whole run").
# Needs what tools/deps.sh installs. SECONDS_RUN (default 30) of virtual time per run.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_RUN=${SECONDS_RUN:-30}
cargo build -q --release -p cargo-openr
exe=$PWD/target/release/cargo-openr
root=$("$exe" sdk install --prefix "$PWD/target/bench/sdk")
work=$PWD/target/bench/mujoco
rm -rf "$work" && mkdir -p "$work"
cp -r testdata/programs/movelegs bench/programs/camwatch bench/programs/common.mk "$work/"
make -s -C "$work/movelegs" OPENRSDK_ROOT="$root" install >/dev/null
make -s -C "$work/camwatch" OPENRSDK_ROOT="$root" install >/dev/null
ms=$work/movelegs/MS
cp "$work/camwatch/MS/OPEN-R/MW/OBJS/WATCH.BIN" "$ms/OPEN-R/MW/OBJS/"
echo /MS/OPEN-R/MW/OBJS/WATCH.BIN >>"$ms/OPEN-R/MW/CONF/OBJECT.CFG"
cat "$work/camwatch/MS/OPEN-R/MW/CONF/CONNECT.CFG" >>"$ms/OPEN-R/MW/CONF/CONNECT.CFG"
py=$("$exe" doctor --format json 2>/dev/null | python3 -c 'import json,sys; f=[f for f in json.load(sys.stdin)["findings"] if f["name"]=="MuJoCo + GL"][0]; print(f["detail"].split(" via ")[-1])')

echo "== whole runs: ${SECONDS_RUN} s of robot time at --speed max"
# Each size plain, then with the peer's --pipeline (the physics steps while the runtime
# works; a command shows in the readings one frame later), one right after the other.
for n in 1 4 8; do
  for pipeline in "" --sim-arg=--pipeline; do
    t0=$(date +%s.%N)
    OPENRSDK_ROOT=$root "$exe" run "$ms" --sim mujoco --robots "$n" --for "${SECONDS_RUN}s" --speed max $pipeline \
      >"$work/out.txt" 2>"$work/err.txt" || { cat "$work/err.txt"; exit 1; }
    t1=$(date +%s.%N)
    rtf=$(grep -o 'whole run [0-9.]* s wall -> [0-9.]* x' "$work/err.txt" | awk '{ print $7 }')
    awk -v a="$t0" -v b="$t1" -v s="$SECONDS_RUN" -v n="$n" -v r="$rtf" -v p="${pipeline:+ (--pipeline)}" \
      'BEGIN { printf "%d robot(s)%s: %.1f x real time attached (the simulation); %.2f s wall with process start -> %.1f x\n", n, p, r, b - a, s / (b - a) }'
    grep "mujoco peer:.*frames" "$work/err.txt" | sed 's/^/    /'
  done
done

echo "== the peer alone (no runtimes): robots standing, every head camera at 30 fps"
for n in 1 4 8; do
  MUJOCO_GL=${MUJOCO_GL:-egl} "$py" "$root/sim/mujoco/peer.py" --bench "$SECONDS_RUN" --robots "$n" 2>&1 | grep "real-time" | sed 's/^/    /'
done
MUJOCO_GL=${MUJOCO_GL:-egl} "$py" "$root/sim/mujoco/peer.py" --bench "$SECONDS_RUN" --robots 1 --no-camera 2>&1 | grep "real-time" | sed 's/^/    /'
