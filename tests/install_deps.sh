#!/usr/bin/env bash
# Installs the Debian packages libmoa builds, tests and (when asked) binds with.
# Usage: bash tests/install_deps.sh [--bindings] [--robust]
#   --bindings  SWIG and the C#, Java and Lua toolchains
#   --robust    the robustness tools of tests/run_all.sh: clang-14 and libFuzzer (tests/fuzz),
#               llvm-14 (symbolized sanitizer reports), valgrind (the memcheck_* tests)
# Only missing packages are installed, so a second run costs nothing.
set -euo pipefail

packages=(build-essential cmake pkgconf libembree-dev libtbb-dev libnanoflann-dev
          libeigen3-dev libgmp-dev libcmocka-dev libpng-dev)
for flag in "$@"; do
  case "$flag" in
    --bindings) packages+=(swig mono-devel default-jdk-headless lua5.4 liblua5.4-dev) ;;
    # libclang-rt-14-dev holds the sanitizer and libFuzzer runtimes; clang-14 only recommends it.
    --robust) packages+=(clang-14 libclang-rt-14-dev libfuzzer-14-dev llvm-14 valgrind) ;;
    *) echo "unknown option '$flag' (expected --bindings or --robust)" >&2; exit 2 ;;
  esac
done

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
