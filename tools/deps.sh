#!/usr/bin/env bash
# Installs the host packages cargo-openr needs on Debian/Ubuntu (idempotent, quiet when
# everything is already there). Used by the README commands and by CI.
set -euo pipefail
need=()
for pkg_cmd in g++:g++ gcc:gcc make:make binutils:ar gzip:gzip python3:python3; do
  pkg=${pkg_cmd%%:*}; cmd=${pkg_cmd##*:}
  command -v "$cmd" >/dev/null 2>&1 || need+=("$pkg")
done
if ((${#need[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${need[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi
command -v cargo >/dev/null 2>&1 || { echo "cargo not found: install Rust from your distribution or rustup" >&2; exit 1; }
