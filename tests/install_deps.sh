#!/usr/bin/env bash
# Installs the Debian packages libmoa builds, tests and (when asked) binds with.
# Usage: bash tests/install_deps.sh [--bindings]
# Only missing packages are installed, so a second run costs nothing.
set -euo pipefail

packages=(build-essential cmake pkgconf libembree-dev libtbb-dev libnanoflann-dev
          libeigen3-dev libgmp-dev libcmocka-dev libpng-dev)
if [[ "${1:-}" == "--bindings" ]]; then
  packages+=(swig mono-devel default-jdk-headless lua5.4 liblua5.4-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
