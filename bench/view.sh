#!/usr/bin/env bash
# The view's cost to the robot (issue 16): wall time per 8 ms frame at --speed max of
# movelegs plus camwatch (an object reading every camera image, 30 a second), run
#   plain      no view
#   view       --view, no browser
#   browser    --view with one headless Chromium showing the page (polls /state at its
#              frame rate, the camera picture at up to 30 a second)
#   record     --record DIR (PNG of every picture, the trace)
# interleaved round by round, so each ratio is against the plain run of the same
# moments. Each run starts at --speed 0.01, waits 3 s (the browser loads the page), then
# gets `speed max` on its --control socket; the clock runs from that answer to the exit.
# Then real time, without and with the browser: frames that started late.
# Release build; needs chromium (tools/deps.sh). RUNS (default 3), SECONDS_RUN (default 30).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
secs=${SECONDS_RUN:-30}
cargo build -q --release -p cargo-openr
exe=$PWD/target/release/cargo-openr
root=$("$exe" sdk install --prefix "$PWD/target/bench/sdk" | tail -1)
work=$PWD/target/bench/view
rm -rf "$work" && mkdir -p "$work"
cp -r testdata/programs/movelegs bench/programs/camwatch bench/programs/common.mk "$work/"
make -s -C "$work/movelegs" OPENRSDK_ROOT="$root" install >/dev/null
make -s -C "$work/camwatch" OPENRSDK_ROOT="$root" install >/dev/null
ms=$work/movelegs/MS
cp "$work/camwatch/MS/OPEN-R/MW/OBJS/WATCH.BIN" "$ms/OPEN-R/MW/OBJS/"
echo /MS/OPEN-R/MW/OBJS/WATCH.BIN >>"$ms/OPEN-R/MW/CONF/OBJECT.CFG"
cat "$work/camwatch/MS/OPEN-R/MW/CONF/CONNECT.CFG" >>"$ms/OPEN-R/MW/CONF/CONNECT.CFG"

now() { date +%s.%N; }
control() { python3 -c 'import socket,sys; s=socket.socket(socket.AF_UNIX); s.connect(sys.argv[1]); s.sendall(sys.argv[2].encode()+b"\n"); print(s.recv(200).decode().strip())' "$1" "$2"; }
# addr_of ERRFILE: the `Viewing http://ADDR/` address once printed.
addr_of() { for _ in $(seq 200); do a=$(grep -o 'Viewing http://[^/]*' "$1" | sed 's|Viewing http://||') && [ -n "$a" ] && { echo "$a"; return; }; sleep 0.05; done; echo "no Viewing line" >&2; cat "$1" >&2; exit 1; }

# run MODE: seconds of wall time from `speed max` to the end of the run.
run() {
  local mode=$1 sock=$work/ctl.sock err=$work/err.txt extra=() browser=
  rm -f "$sock"
  case $mode in
    view | browser) extra=(--view) ;;
    record) rm -rf "$work/rec"; extra=(--record "$work/rec") ;;
  esac
  OPENRSDK_ROOT=$root "$exe" run "$ms" -q --speed 0.01 --for "${secs}s" --control "$sock" "${extra[@]}" >/dev/null 2>"$err" &
  local pid=$!
  for _ in $(seq 200); do [ -S "$sock" ] && break; sleep 0.05; done
  if [ "$mode" = browser ]; then
    local addr; addr=$(addr_of "$err")
    chromium --headless --disable-gpu --no-sandbox --no-first-run --disable-background-networking --disable-component-update --disable-sync --disable-quic --user-data-dir="$work/profile" --remote-debugging-port=0 "http://$addr/" >/dev/null 2>&1 &
    browser=$!
  fi
  sleep 3
  control "$sock" "speed max" >/dev/null
  local t0; t0=$(now)
  wait "$pid" || { cat "$err"; exit 1; }
  local t1; t1=$(now)
  [ -n "$browser" ] && { kill "$browser"; wait "$browser" 2>/dev/null || true; }
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}

declare -A times
modes="plain view browser record"
for r in $(seq "$runs"); do
  for m in $modes; do
    t=$(run "$m")
    times[$m]="${times[$m]:-} $t"
    echo "round $r $m: $t s" >&2
  done
done
frames=$((secs * 125))
echo "== wall time per frame at --speed max, ${secs} s of robot time (${frames} frames), ${runs} round(s): min / median / max, and the median's ratio to plain"
median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { printf "%s %s %s", v[1], v[int((NR + 1) / 2)], v[NR] }'; }
read -r _ pmed _ <<<"$(echo "${times[plain]}" | median)"
for m in $modes; do
  read -r lo med hi <<<"$(echo "${times[$m]}" | median)"
  awk -v m="$m" -v lo="$lo" -v med="$med" -v hi="$hi" -v f="$frames" -v p="$pmed" \
    'BEGIN { printf "%-8s %.1f / %.1f / %.1f us per frame  (x %.2f)\n", m, lo / f * 1e6, med / f * 1e6, hi / f * 1e6, med / p }'
done
if [ -n "$(ls "$work/rec/camera" 2>/dev/null)" ]; then
  echo "record: $(ls "$work/rec/camera" | wc -l) pictures, $(du -sk "$work/rec" | cut -f1) KiB for ${secs} s"
fi

echo "== real time (--speed 1, 10 s): frames that started late, without and with the browser"
for with in no yes; do
  OPENRSDK_ROOT=$root "$exe" run "$ms" --for 10s --view >/dev/null 2>"$work/err.txt" &
  pid=$!
  addr=$(addr_of "$work/err.txt")
  browser=
  if [ $with = yes ]; then
    chromium --headless --disable-gpu --no-sandbox --no-first-run --disable-background-networking --disable-component-update --disable-sync --disable-quic --user-data-dir="$work/profile" --remote-debugging-port=0 "http://$addr/" >/dev/null 2>&1 &
    browser=$!
    sleep 2  # the camera's first picture (a 404 text before it)
    page=$(curl -s "http://$addr/" | wc -c)
    state=$(curl -s "http://$addr/state" | wc -c)
    picture=$(curl -s "http://$addr/camera.png" | wc -c)
  fi
  wait "$pid"
  [ -n "$browser" ] && { kill "$browser"; wait "$browser" 2>/dev/null || true; }
  echo "browser $with: $(grep -o '[0-9]* frames, [0-9]* late' "$work/err.txt")"
done
echo "page $page bytes (snapshot inlined), /state $state bytes, /camera.png $picture bytes"
