#!/usr/bin/env bash
# Installs a libmoa build tree into a scratch prefix and checks what a user gets there: the
# files and SONAME links, moa.pc, and the CMake package, each used to build and run a program
# (consumer.c) that reconstructs a sphere. Called by CTest; see CMakeLists.txt for arguments.
set -euo pipefail

sanitize=0
config=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) build_dir=$2 ;;
    --work-dir) work_dir=$2 ;;
    --source-dir) source_dir=$2 ;;
    --libdir) libdir=$2 ;;
    --cmake) cmake=$2 ;;
    --cc) cc=$2 ;;
    --version) version=$2 ;;
    --soversion) soversion=$2 ;;
    --config) config=$2 ;;
    --sanitize) sanitize=$2 ;;
    *) echo "run_install_test.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift 2
done

fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "--- $*"; }

rm -rf "$work_dir"
mkdir -p "$work_dir"
prefix=$work_dir/prefix
case "$libdir" in
  /*) fail "CMAKE_INSTALL_LIBDIR is absolute ($libdir); this test needs a relative one" ;;
esac

# A sanitized libmoa needs the sanitizer runtime loaded first, so the consumers get it too.
extra_flags=()
if [[ "$sanitize" == 1 ]]; then
  extra_flags=(-fsanitize=address,undefined -fno-omit-frame-pointer)
fi

step "cmake --install into $prefix"
install_args=(--install "$build_dir" --prefix "$prefix")
[[ -n "$config" ]] && install_args+=(--config "$config")
"$cmake" "${install_args[@]}"

step "installed files"
lib=$prefix/$libdir
[[ -f "$prefix/include/moa/moa.h" ]] || fail "include/moa/moa.h not installed"
[[ -f "$prefix/include/moa/version.h" ]] || fail "include/moa/version.h not installed"
[[ -f "$lib/libmoa.so.$version" ]] || fail "$libdir/libmoa.so.$version not installed"
[[ "$(readlink "$lib/libmoa.so.$soversion")" == "libmoa.so.$version" ]] ||
  fail "libmoa.so.$soversion does not link to libmoa.so.$version"
[[ "$(readlink "$lib/libmoa.so")" == "libmoa.so.$soversion" ]] ||
  fail "libmoa.so does not link to libmoa.so.$soversion"
if command -v objdump >/dev/null; then
  objdump -p "$lib/libmoa.so.$version" | grep -q "SONAME *libmoa.so.$soversion\$" ||
    fail "the SONAME of libmoa is not libmoa.so.$soversion"
fi
if find "$prefix" -name '*moa_core*' | grep -q .; then fail "moa_core was installed"; fi
for f in moaConfig.cmake moaConfigVersion.cmake moaTargets.cmake; do
  [[ -f "$lib/cmake/moa/$f" ]] || fail "$libdir/cmake/moa/$f not installed"
done
if grep -q moa_core "$lib"/cmake/moa/*.cmake; then fail "the CMake package refers to moa_core"; fi

export LD_LIBRARY_PATH=$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}

step "pkg-config consumer"
export PKG_CONFIG_PATH=$lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}
[[ -f "$lib/pkgconfig/moa.pc" ]] || fail "$libdir/pkgconfig/moa.pc not installed"
[[ "$(pkg-config --modversion moa)" == "$version" ]] || fail "pkg-config --modversion moa"
[[ "$(pkg-config --variable=prefix moa)" == "$prefix" ]] ||
  fail "moa.pc has prefix $(pkg-config --variable=prefix moa), not $prefix"
pc_flags=$(pkg-config --cflags --libs moa)
echo "pkg-config --cflags --libs moa: $pc_flags"
# shellcheck disable=SC2086 # the flags are meant to split
"$cc" "${extra_flags[@]}" -o "$work_dir/consumer_pc" "$source_dir/consumer.c" $pc_flags -lm
"$work_dir/consumer_pc"

step "CMake consumer (find_package(moa))"
cmake_flags=()
if [[ "$sanitize" == 1 ]]; then
  cmake_flags=("-DCMAKE_C_FLAGS=${extra_flags[*]}" "-DCMAKE_EXE_LINKER_FLAGS=${extra_flags[*]}")
fi
"$cmake" -S "$source_dir/cmake_consumer" -B "$work_dir/cmake_consumer" \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DMOA_EXPECTED_PREFIX="$prefix" \
  -DMOA_CONSUMER_SOURCE="$source_dir/consumer.c" "${cmake_flags[@]}"
"$cmake" --build "$work_dir/cmake_consumer"
"$work_dir/cmake_consumer/consumer"

echo "install test passed"
