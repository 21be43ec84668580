#!/usr/bin/env bash
# run.sh: what `make test` runs: installs missing tools, builds with gcc and clang, runs every test.
# Each test prints "ok - ..." / "not ok - ..." lines; the last line is "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
. tests/deps.sh

log=build/test.log
mkdir -p build
: > "$log"

# Runs a command, streams its output to the terminal and the log, and turns a non-zero exit
# with no "not ok" line into one.
run() {
    local name=$1 rc
    shift
    "$@" 2>&1 | tee build/run.out | tee -a "$log"
    rc=${PIPESTATUS[0]}
    if [ "$rc" -ne 0 ] && ! grep -q '^not ok - ' build/run.out; then
        echo "not ok - $name exited with status $rc" | tee -a "$log"
    fi
}

ptp_ensure_deps | tee -a "$log"
# Not in a pipe: it exports WGPU_DIR (wgpu-native) for the Makefile and test_wgpu.sh.
ptp_ensure_wgpu >build/wgpu.out
tee -a "$log" <build/wgpu.out

compilers=""
for cc in gcc clang; do
    command -v $cc >/dev/null 2>&1 || continue
    compilers="$compilers $cc"
    if make -s CC=$cc build-tests >build/make-$cc.log 2>&1; then
        echo "ok - builds with $cc -std=c11 -Wall -Wextra -Werror -pedantic" | tee -a "$log"
    else
        echo "not ok - build with $cc failed: see build/make-$cc.log" | tee -a "$log"
        cat build/make-$cc.log
    fi
done

for cc in $compilers; do
    for t in build/$cc/test_*; do
        [ -x "$t" ] && run "$t" "$t"
    done
done

# verify's fuzz seeds and every input that once failed, replayed under ASan and UBSan.
for cc in $compilers; do
    n=$(ls tests/fuzz/verify tests/fuzz/regressions | grep -vc ':$')
    if make -s CC=$cc build/$cc/replay_verify >build/make-$cc-replay.log 2>&1 &&
        build/$cc/replay_verify tests/fuzz/verify/* tests/fuzz/regressions/* >build/replay-$cc.log 2>&1; then
        echo "ok - verify replays its fuzz corpus and regressions ($n inputs) cleanly under ASan and UBSan ($cc)" | tee -a "$log"
    else
        echo "not ok - verify's fuzz corpus under ASan and UBSan ($cc): $(tail -3 build/replay-$cc.log build/make-$cc-replay.log 2>/dev/null | tr '\n' ' ')" | tee -a "$log"
    fi
done

run tests/test_layers.sh bash tests/test_layers.sh

if [ -x build/gcc/ptpgen ]; then
    run tests/test_cli.sh env PTPGEN=build/gcc/ptpgen PTPGEN_OTHER=build/clang/ptpgen bash tests/test_cli.sh
    run tests/test_examples.sh env PTPGEN=build/gcc/ptpgen bash tests/test_examples.sh
fi

# bench/cullrate (make cullrate) on small models (bicubic and PN triangles), its errors on bad
# input, and pn_check (PN triangles, the tessellator, triangular cones and the exact arbiter).
if make -s CC=gcc build/gcc/cullrate/cullrate build/gcc/cullrate/pn_check >build/make-cullrate.log 2>&1; then
    run tests/test_cullrate.sh env CULLRATE=build/gcc/cullrate/cullrate bash tests/test_cullrate.sh
else
    echo "not ok - build of build/gcc/cullrate/cullrate failed: see build/make-cullrate.log" | tee -a "$log"
fi

# The hosts that execute emitted kernels (they need the OpenCL and Vulkan development files, and
# wgpu-native for the WGSL host).
hosts="libptptest.a host_opencl host_vulkan"
[ -n "${WGPU_DIR:-}" ] && hosts="$hosts host_wgpu"
for cc in $compilers; do
    for h in $hosts; do
        if make -s CC=$cc build/$cc/$h >build/make-$cc-$h.log 2>&1; then
            echo "ok - builds build/$cc/$h" | tee -a "$log"
        else
            echo "not ok - build of build/$cc/$h failed: $(grep -m1 -i error build/make-$cc-$h.log)" | tee -a "$log"
        fi
    done
done
if [ -x build/gcc/ptpgen ]; then
    run tests/test_refine.sh env PTPGEN=build/gcc/ptpgen bash tests/test_refine.sh
    run tests/test_kernels.sh env PTPGEN=build/gcc/ptpgen BUILD=build/gcc bash tests/test_kernels.sh
fi
run tests/test_wgpu.sh env BUILD=build/gcc bash tests/test_wgpu.sh

# build/render: the GLSL kernels culling patches before a tessellation pipeline on lavapipe.
run tests/test_render.sh env CC=gcc bash tests/test_render.sh

passed=$(grep -c '^ok - ' "$log")
failed=$(grep -c '^not ok - ' "$log")
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
