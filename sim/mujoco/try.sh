#!/usr/bin/env bash
# Manual check of the MuJoCo peer (issue 8, not part of the test suite):
#   1. installs mujoco (pinned) into a venv ($MUJOCO_VENV, default ~/.cache/cargo-openr/mujoco-venv);
#   2. builds cargo-openr, installs an SDK root and builds testdata/programs/movelegs;
#   3. runs the program for $SECONDS_RUN s of virtual time (--speed max, --robot-wait) with
#      sim/mujoco/peer.py owning the clock, and prints the joint angles the program read
#      back (its "Sensors : frame N LF J1 .. J2 .. J3 .. deg" lines) and the peer's
#      real-time factor / render figures;
#      (PEER_ARGS adds peer options, e.g. PEER_ARGS="--gain-scale 2 --no-camera");
#   4. measures the physics real-time factor for one robot without a runtime, camera off
#      and on (peer.py --bench).
# Needs python3 with venv, and for headless rendering EGL (Debian: libegl1 libegl-mesa0
# libgl1-mesa-dri) or OSMesa (libosmesa6, then MUJOCO_GL=osmesa).
set -euo pipefail
cd "$(dirname "$0")/../.."
REPO=$PWD
MUJOCO_VERSION=4.0.0
VENV=${MUJOCO_VENV:-$HOME/.cache/cargo-openr/mujoco-venv}
SECONDS_RUN=${SECONDS_RUN:-6}
export MUJOCO_GL=${MUJOCO_GL:-egl}

if ! "$VENV/bin/python" -c "import mujoco, sys; sys.exit(mujoco.__version__ != '$MUJOCO_VERSION')" 2>/dev/null; then
    echo "== installing mujoco==$MUJOCO_VERSION into $VENV"
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q "mujoco==$MUJOCO_VERSION"
fi
PY="$VENV/bin/python"

echo "== building cargo-openr, the SDK root and movelegs"
if [ -z "${OPENR:-}" ]; then  # OPENR=path/to/cargo-openr skips the build
    cargo build -q -p cargo-openr
    OPENR="$REPO/target/debug/cargo-openr"
fi
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$OPENR" sdk install --prefix "$WORK/sdk-root" >/dev/null
cp -r testdata/programs/movelegs "$WORK/movelegs"
make -s -C "$WORK/movelegs" OPENRSDK_ROOT="$WORK/sdk-root" install >"$WORK/make.log" 2>&1 || { cat "$WORK/make.log"; exit 1; }

echo "== running movelegs for ${SECONDS_RUN}s with the MuJoCo peer owning the clock (MUJOCO_GL=$MUJOCO_GL)"
SOCK="$WORK/robot.sock"
OPENRSDK_ROOT="$WORK/sdk-root" "$OPENR" run "$WORK/movelegs/MS" --speed max --for "${SECONDS_RUN}s" \
    --robot-socket "$SOCK" --robot-wait >"$WORK/run.out" 2>"$WORK/run.err" &
RUN_PID=$!
"$PY" sim/mujoco/peer.py "$SOCK" ${PEER_ARGS:-} 2>"$WORK/peer.err" || { cat "$WORK/peer.err"; kill "$RUN_PID" 2>/dev/null; exit 1; }
wait "$RUN_PID" || { echo "runtime failed:"; cat "$WORK/run.err"; exit 1; }
echo "-- the program's output (joint angles it read back from the simulated robot):"
grep -E "MovingLegs|Sensors" "$WORK/run.out" || cat "$WORK/run.out"
echo "-- the peer:"
cat "$WORK/peer.err"
echo "-- the runtime's messages about peers (none = no protocol error):"
grep -i "peer" "$WORK/run.err" || true

echo "== physics real-time factor, 1 robot, 10 s standing, camera off / on (416x320 at 30 fps)"
"$PY" sim/mujoco/peer.py --bench 10 --no-camera 2>&1 | grep "real-time"
"$PY" sim/mujoco/peer.py --bench 10 2>&1 | grep "real-time"
