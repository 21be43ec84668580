#!/usr/bin/env bash
# test_cmake.sh: builds tests/examples/cmake_consumer with CMake, through add_subdirectory and
# through find_package after cmake --install; runs it; checks a changed option remakes a kernel.
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
src=$PWD
ex=$src/tests/examples/cmake_consumer

ok() { echo "ok - $1"; }
notok() { echo "not ok - $1: $2"; }

if ! command -v cmake >/dev/null 2>&1; then
    notok "cmake" "not installed (Debian package cmake)"
    exit 1
fi

# check NAME BUILD: the consumer ran, and its GLSL kernel opens with ptpgen's banner.
check() {
    local name=$1 b=$2
    if "$b/consumer" >"$tmp/run.out" 2>&1 && head -1 "$b/tri3.comp" | grep -q '^/\* ptp_tri3.comp: ' &&
        head -2 "$b/tri3.comp" | grep -q 'ptpgen --domain triangle --degree 3 --target glsl'; then
        ok "$name: the consumer builds, classifies ($(head -1 "$tmp/run.out")) and has its GLSL kernel"
    else
        notok "$name" "$(tail -3 "$tmp/run.out" "$b/build.log" 2>/dev/null | tr '\n' ' ')"
    fi
}

# rebuild NAME BUILD: a new option (--rule degenerate) in the cache remakes the kernel.
rebuild() {
    local name=$1 b=$2
    if cmake -S "$ex" -B "$b" -DCONSUMER_GLSL_OPTIONS="--rule;degenerate" >>"$b/build.log" 2>&1 &&
        cmake --build "$b" -j2 >>"$b/build.log" 2>&1 &&
        head -2 "$b/tri3.comp" | grep -q -- '--rule degenerate'; then
        ok "$name: a changed option remakes the kernel at build time"
    else
        notok "$name: a changed option remakes the kernel" "$(head -2 "$b/tri3.comp" | tail -1)"
    fi
}

# add_subdirectory(ptpgen).
b=$tmp/sub
mkdir -p "$b"
cmake -S "$ex" -B "$b" -DCMAKE_BUILD_TYPE=Release -DPTPGEN_SOURCE_DIR="$src" >"$b/build.log" 2>&1 &&
    cmake --build "$b" -j2 >>"$b/build.log" 2>&1
check "add_subdirectory(ptpgen)" "$b"
rebuild "add_subdirectory(ptpgen)" "$b"

# cmake --install, then find_package(ptpgen) with CMAKE_PREFIX_PATH.
pb=$tmp/ptpgen-build pre=$tmp/prefix
if cmake -S "$src" -B "$pb" -DCMAKE_BUILD_TYPE=Release >"$tmp/install.log" 2>&1 &&
    cmake --build "$pb" -j2 >>"$tmp/install.log" 2>&1 &&
    cmake --install "$pb" --prefix "$pre" >>"$tmp/install.log" 2>&1 &&
    [ -x "$pre/bin/ptpgen" ] && [ -f "$pre/share/man/man1/ptpgen.1" ] &&
    ls "$pre"/lib*/cmake/ptpgen/ptpgenConfig.cmake "$pre"/lib*/cmake/ptpgen/ptpgenConfigVersion.cmake >/dev/null 2>&1; then
    ok "cmake --install: bin/ptpgen, the man page and ptpgenConfig.cmake with its version file"
else
    notok "cmake --install" "$(tail -3 "$tmp/install.log" | tr '\n' ' ')"
fi
b=$tmp/pkg
mkdir -p "$b"
cmake -S "$ex" -B "$b" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$pre" >"$b/build.log" 2>&1 &&
    cmake --build "$b" -j2 >>"$b/build.log" 2>&1
check "find_package(ptpgen)" "$b"
grep -q "$pre/bin/ptpgen" "$b/build.log" 2>/dev/null || grep -rqs "$pre/bin/ptpgen" "$b/CMakeFiles" &&
    ok "find_package(ptpgen): the kernels come from the installed ptpgen" ||
    notok "find_package(ptpgen)" "the installed ptpgen is not the one run"
rebuild "find_package(ptpgen)" "$b"
