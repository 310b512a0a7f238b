#!/usr/bin/env bash
# Installs the host packages cargo-openr needs on Debian/Ubuntu (idempotent, quiet when
# everything is already there). Used by the README commands and by CI:
#   * the build: g++ gcc make binutils gzip and gcc's plugin headers, python3 (tests and the robot protocol peers),
#     clangd (the compile database is checked with it), gdb and valgrind (`run --gdb`,
#     `run --valgrind` and the tests that debug a repaired header or check memcheck);
#   * the MuJoCo simulator (`cargo openr run --sim mujoco`): Mesa's headless GL (EGL and
#     OSMesa) and mujoco==$MUJOCO_VERSION from PyPI in a venv at $MUJOCO_VENV
#     (default ~/.cache/cargo-openr/mujoco-venv, where cargo-openr looks for it).
set -euo pipefail
MUJOCO_VERSION=4.0.0  # keep in step with cargo-openr/src/ops/sim.rs MUJOCO_VERSION
VENV=${MUJOCO_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/cargo-openr/mujoco-venv}

need=()
for pkg_cmd in g++:g++ gcc:gcc make:make binutils:ar gzip:gzip python3:python3 clangd:clangd gdb:gdb valgrind:valgrind; do
  pkg=${pkg_cmd%%:*}; cmd=${pkg_cmd##*:}
  command -v "$cmd" >/dev/null 2>&1 || need+=("$pkg")
done
# chromium: the browser tests of `run --view` (cargo-openr/tests/cli/view.rs).
for pkg in libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 chromium; do
  dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if command -v python3 >/dev/null 2>&1 && ! python3 -c "import ensurepip, venv" >/dev/null 2>&1; then
  need+=(python3-venv)
fi
if ((${#need[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${need[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi
# gcc's plugin headers, for the alignment trap's plugin (wrappers/src/align_plugin.rs;
# without them the trap falls back to gcc's own, slower check): the package of the very
# g++ installed above.
if ! [ -f "$(g++ -print-file-name=plugin)/include/gcc-plugin.h" ]; then
  pkg="gcc-$(g++ -dumpversion | cut -d. -f1)-plugin-dev"
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: $pkg" >&2
  ((${#need[@]})) || $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$pkg" >/dev/null
fi
command -v cargo >/dev/null 2>&1 || { echo "cargo not found: install Rust from your distribution or rustup" >&2; exit 1; }
# rustfmt: tools/test.sh checks the layout (rustfmt.toml).
if ! cargo fmt --version >/dev/null 2>&1 && command -v rustup >/dev/null 2>&1; then
  echo "installing: rustfmt (rustup component)" >&2
  rustup component add rustfmt >&2 || echo "warning: could not install rustfmt (offline?); tools/test.sh needs it" >&2
fi
# clippy: tools/test.sh checks that every unsafe block says why it is sound.
if ! cargo clippy --version >/dev/null 2>&1; then
  if command -v rustup >/dev/null 2>&1; then
    echo "installing: clippy (rustup component)" >&2
    rustup component add clippy >&2 || echo "warning: could not install clippy (offline?); tools/test.sh needs it: rustup component add clippy" >&2
  else
    echo "warning: cargo clippy not found and no rustup to add it; tools/test.sh needs it (Debian: apt-get install rust-clippy)" >&2
  fi
fi
# The declared MSRV (rust-version in Cargo.toml): tools/test.sh checks the workspace with it.
MSRV=$(sed -n 's/^rust-version = "\(.*\)"/\1/p' "$(dirname "$0")/../Cargo.toml")
if command -v rustup >/dev/null 2>&1 && ! rustup run "$MSRV" rustc --version >/dev/null 2>&1; then
  echo "installing: Rust $MSRV, the declared MSRV (rustup toolchain, minimal profile)" >&2
  rustup toolchain install "$MSRV" --profile minimal >&2 || echo "warning: could not install Rust $MSRV (offline?); tools/test.sh needs it" >&2
fi

if ! "$VENV/bin/python" -c "import mujoco, sys; sys.exit(mujoco.__version__ != '$MUJOCO_VERSION')" >/dev/null 2>&1; then
  echo "installing: mujoco==$MUJOCO_VERSION (pip, into $VENV)" >&2
  python3 -m venv "$VENV"
  "$VENV/bin/pip" install -q --disable-pip-version-check "mujoco==$MUJOCO_VERSION"
fi
