#!/usr/bin/env bash
# MuJoCo simulation speed (issues 8, 21): real-time factor of whole runs -- runtimes, the
# lockstep protocol, physics and head cameras at 30 fps -- each ERS-7 running movelegs
# (walking swing) plus camwatch (an object reading every camera image), plain and with
# the peer's --pipeline, then the peer alone (physics and rendering without runtimes,
# every robot standing, every head camera at 30 fps). Release build.
#
# Each figure is the simulation's own speed once every robot is attached (the peer's
# "whole run"), and the CPU time of the whole command (runtimes + peer) per simulated
# second, less that of a run of STARTUP_RUN (process start, MuJoCo import, model
# compile, GL contexts): with C cores nothing can run faster than C / that.
#
#   SECONDS_RUN  virtual time per run (default 10)
#   ROUNDS       runs of each kind (default 3); min / median / max are printed
#   SIZES        robot counts (default "1 8")
#   BEFORE       a git rev or a directory (holding peer.py, or sim/mujoco/peer.py) to
#                compare the peer with: its runs alternate with this tree's, so a load
#                that comes and goes falls on both alike
# Goals (issue 21): attached >= 0.9 x the peer alone; >= 15 x real time for 1 robot and
# >= 4 x for 8 (with cameras), each printed as PASS/FAIL with the reason.
# Needs what tools/deps.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_RUN=${SECONDS_RUN:-10}
STARTUP_RUN=0.08  # one frame of camera (10 frames): what every run costs before it simulates
ROUNDS=${ROUNDS:-3}
SIZES=${SIZES:-1 8}
BEFORE=${BEFORE:-}
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
export MUJOCO_GL=${MUJOCO_GL:-egl}

# The peers compared: "after" is this tree's (as `sdk install` put it), "before" BEFORE's.
declare -A peer=([after]="$root/sim/mujoco")
sides=(after)
if [ -n "$BEFORE" ]; then
  if [ -f "$BEFORE/sim/mujoco/peer.py" ]; then peer[before]=$(cd "$BEFORE/sim/mujoco" && pwd)
  elif [ -f "$BEFORE/peer.py" ]; then peer[before]=$(cd "$BEFORE" && pwd)
  else
    mkdir -p "$work/before"
    git archive "$BEFORE" sim/mujoco tools/robot_peer.py | tar -x -C "$work/before"
    peer[before]=$work/before/sim/mujoco
  fi
  sides=(before after)
fi
# cargo openr run starts $OPENR_PYTHON .../peer.py: this one runs $PEER/peer.py instead.
cat >"$work/python" <<EOF
#!/usr/bin/env bash
if [[ "\${1:-}" == */peer.py ]]; then shift; exec "$py" "\$PEER/peer.py" "\$@"; fi
exec "$py" "\$@"
EOF
chmod +x "$work/python"

# timed OUT CMD...: runs CMD, appends "wall cpu" (s; CPU of it and all its children) to OUT
timed() {
  python3 - "$@" <<'EOF'
import os, resource, subprocess, sys, time
t = time.perf_counter()
code = subprocess.call(sys.argv[2:], stdout=subprocess.DEVNULL, stderr=open(sys.argv[1] + ".err", "w"))
r = resource.getrusage(resource.RUSAGE_CHILDREN)
with open(sys.argv[1], "a") as f:
    f.write(f"{time.perf_counter() - t:.3f} {r.ru_utime + r.ru_stime:.3f}\n")
sys.exit(code)
EOF
}

# run SIDE N MODE SECONDS: one run; prints "x_real_time cpu_s"
run() {
  local side=$1 n=$2 mode=$3 secs=$4 out=$work/run
  rm -f "$out"
  case $mode in
    alone) timed "$out" "$py" "${peer[$side]}/peer.py" --bench "$secs" --robots "$n" ;;
    *) PEER=${peer[$side]} OPENR_PYTHON=$work/python OPENRSDK_ROOT=$root timed "$out" "$exe" run "$ms" --sim mujoco \
         --robots "$n" --for "${secs}s" --speed max ${mode/plain/} ;;
  esac || { cat "$out.err" >&2; exit 1; }
  local cpu
  read -r _ cpu <"$out"
  echo "$(grep -o 'whole run [0-9.]* s wall -> [0-9.]* x' "$out.err" | awk '{ print $7 }') $cpu"
}

# one SIDE N MODE: one measured run; appends "side n mode rtf cpu_per_sim_s" to $work/results
declare -A startup
one() {
  local key="$1 $2 $3" got rtf cpu
  [ -n "${startup[$key]:-}" ] || startup[$key]=$(run "$@" "$STARTUP_RUN" | awk '{ print $2 }')
  got=$(run "$@" "$SECONDS_RUN")
  read -r rtf cpu <<<"$got"
  echo "$1 $2 ${3#--sim-arg=--} $rtf $(awk -v c="$cpu" -v c0="${startup[$key]}" -v s="$SECONDS_RUN" -v s0="$STARTUP_RUN" 'BEGIN { printf "%.3f", (c - c0) / (s - s0) }')" >>"$work/results"
}

echo "== ${ROUNDS} round(s) of ${SECONDS_RUN} s of robot time, robots: ${SIZES}; peers: ${sides[*]}${BEFORE:+ (before = $BEFORE)}; $(nproc) cores; $(uptime | sed 's/.*load/load/')"
: >"$work/results"
: >"$work/load"
for ((round = 1; round <= ROUNDS; round++)); do
  # before/after in turn, the order swapped every round
  order=("${sides[@]}")
  if ((round % 2 == 0)) && ((${#sides[@]} == 2)); then order=(after before); fi
  for n in $SIZES; do
    for mode in plain --sim-arg=--pipeline alone; do
      for side in "${order[@]}"; do one "$side" "$n" "$mode"; done
    done
  done
  echo "   round $round done; $(uptime | sed 's/.*load/load/')"
  cut -d' ' -f1 /proc/loadavg >>"$work/load"
done

python3 - "$work/results" "$SIZES" "$work/load" <<'EOF'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
sizes = [int(n) for n in sys.argv[2].split()]
res = {}
for side, n, mode, rtf, cpu in rows:
    res.setdefault((side, int(n), mode), []).append((float(rtf), float(cpu)))
cores = __import__("os").cpu_count()
load = statistics.mean(float(l) for l in open(sys.argv[3]))  # 1-minute load average after each round
med = lambda side, n, mode, i=0: statistics.median(v[i] for v in res[(side, n, mode)])  # noqa: E731
sides = [s for s in ("before", "after") if any(k[0] == s for k in res)]
print("== x real time (min / median / max) and CPU-s per simulated second (median)")
for n in sizes:
    for mode in ("plain", "pipeline", "alone"):
        parts = []
        for side in sides:
            v = res[(side, n, mode)]
            r = sorted(x for x, _ in v)
            parts.append(f"{side} {r[0]:5.2f} / {statistics.median(r):5.2f} / {r[-1]:5.2f} x, {med(side, n, mode, 1):.3f} CPU-s/s")
        change = ""
        if len(sides) == 2:
            change = f"  -> {med('after', n, mode) / med('before', n, mode) - 1:+.0%} speed, {med('after', n, mode, 1) / med('before', n, mode, 1) - 1:+.0%} CPU"
        print(f"{n} robot(s) {mode:8s}: " + "; ".join(parts) + change)
print("== goals (this tree's medians)")
def limit(n, mode):
    """The most the CPU allows: every core busy with this run's work."""
    return cores / med("after", n, mode, 1)
for n in sizes:
    alone = med("after", n, "alone")
    for mode in ("plain", "pipeline"):
        a = med("after", n, mode)
        ok = a >= 0.9 * alone
        why = "" if ok else (f": attached needs {med('after', n, mode, 1):.3f} CPU-s per simulated s, the peer alone "
                             f"{med('after', n, 'alone', 1):.3f} (the runtimes' share and the hand-offs)")
        print(f"{'PASS' if ok else 'FAIL'} {n} robot(s) {mode} attached {a:.2f} x = {a / alone:.2f} of the peer alone "
              f"{alone:.2f} x (goal >= 0.9){why}")
for n, goal in ((1, 15), (8, 4)):
    if n not in sizes:
        continue
    mode = max(("plain", "pipeline"), key=lambda m: med("after", n, m))
    a, cpu, most = med("after", n, mode), med("after", n, mode, 1), limit(n, mode)
    busy = f"the runs kept {cpu * a:.2f} of {cores} cores busy (load average {load:.1f} with whatever else runs here)"
    if a >= goal:
        why = ""
    elif most < 1.1 * goal:
        why = f": CPU-bound, {cpu:.3f} CPU-s per simulated s allow at most {most:.1f} x on {cores} free cores; {busy}"
    else:
        why = (f": not CPU-bound ({cpu:.3f} CPU-s per simulated s would allow {most:.1f} x on {cores} free cores), "
               f"latency-bound: the lockstep's hand-offs between peer, runtimes and camera threads; {busy}")
    print(f"{'PASS' if a >= goal else 'FAIL'} {n} robot(s) {a:.2f} x real time attached ({mode}; goal >= {goal}){why}")
EOF
