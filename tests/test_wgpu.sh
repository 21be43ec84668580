#!/usr/bin/env bash
# test_wgpu.sh: runs generated 1x1 WGSL kernels through tests/host_wgpu.c on wgpu-native (lavapipe
# through Vulkan) against the double reference: the host's own checks (chunks, 2-D dispatches),
# mutants that must fail, NaN control points, and whether this device contracts products.
# Needs BUILD (the folder with host_wgpu, ptpgen and libptptest.a) and WGPU_DIR (tests/deps.sh);
# PTPGEN (default $BUILD/ptpgen) writes the kernels.
set -u
B=${BUILD:?set BUILD}
P=${PTPGEN:-$B/ptpgen}
PY=${PTP_VENV:-build/venv}/bin/python
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export MESA_SHADER_CACHE_DIR=$PWD/build/cache/mesa
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
mkdir -p "$MESA_SHADER_CACHE_DIR"

. tests/host_lib.sh
if [ ! -x "$B/host_wgpu" ] || [ -z "${WGPU_DIR:-}" ]; then
    missing "$B/host_wgpu or wgpu-native" "WGSL kernels"
    exit 0
fi

# The table kernels (--kernel table): 1x1, world space, and clip space with --planes (4 threads
# per patch, 32 patches per workgroup of 128 invocations, 1 round).
"$P" --degree 1 --space world --kernel table --target wgsl -o "$tmp/world.wgsl" &&
    "$P" --degree 1 --planes --kernel table --target wgsl -o "$tmp/clip.wgsl" || notok "ptpgen writes 1x1 WGSL kernels" "it failed"
world="$tmp/world.wgsl --degree 1 1 --space world --rule strict --block-threads 128 --patches-per-block 32"
clip="$tmp/clip.wgsl --degree 1 1 --space clip --rule strict --block-threads 128 --patches-per-block 32 --planes"

# Exact zeros: every product of cross4 goes through mul_rn (no FMA contraction crosses it).
n=$(awk '/^fn ptp_1x1_cross4z/ { f = 1; next } f && /^}/ { f = 0 } f' "$tmp/clip.wgsl" | grep -o 'mul_rn(' | wc -l)
if [ "$n" -eq 9 ] && ! awk '/^fn ptp_1x1_cross4z/ { f = 1; next } f && /^}/ { f = 0 } f' "$tmp/clip.wgsl" | grep -q ' \* '; then
    ok "the 1x1 clip WGSL kernel's cross4z takes its 9 products through mul_rn"
else
    notok "the 1x1 clip WGSL kernel's cross4z takes its 9 products through mul_rn" "$n of them, or a plain product"
fi

# On random patches (a quarter with a collapsed edge: exact zeros) and exact data.
run_host "wgsl 1x1 world" "$B/host_wgpu" $world --random 3 10000 11 --exact 20 2000 12 --name "wgsl 1x1 world"
run_host "wgsl 1x1 clip" "$B/host_wgpu" $clip --random 3 10000 13 --exact 20 2000 14 --name "wgsl 1x1 clip --planes"

# Chunking and 2-D dispatches: a host whose storage bindings hold 64 KiB and whose dispatches
# have at most 7 groups along x runs a set of 20,000 patches in chunks of 1,024 (the last one
# partial), each 2-D (the partial last row exercises the check past patch_count).
for cc in gcc clang; do
    command -v $cc >/dev/null || continue
    if $cc -std=c11 -Wall -Wextra -Werror -pedantic -O2 -DHOST_MAX_BUFFER=65536 -DHOST_MAX_GROUPS_X=7 \
        -Igen -Itests -isystem "$WGPU_DIR" -o "$tmp/host_small" tests/host_wgpu.c tests/host_run.c build/$cc/libptptest.a \
        -L"$WGPU_DIR" -l:libwgpu_native-release.so -Wl,-rpath,"$WGPU_DIR" -lm 2>"$tmp/err"; then
        run_host "wgsl chunks ($cc)" "$tmp/host_small" $clip --random 1 20000 15 --name "wgsl 1x1 clip in 2-D chunks ($cc)"
    else
        notok "host_wgpu with small limits builds ($cc)" "$(grep -m1 error "$tmp/err")"
    fi
done

# must_fail NAME SED CHECK FILE ARGS...: the kernel FILE edited by SED must fail the check lines
# matching CHECK ("not ok - mutant CHECK") and exit non-zero.
must_fail() {
    local name=$1 script=$2 pat=$3 file=$4
    shift 4
    sed "$script" "$file" >"$tmp/m.wgsl"
    if cmp -s "$file" "$tmp/m.wgsl"; then
        notok "a WGSL kernel with $name fails" "the edit changed nothing"
    elif ! "$B/host_wgpu" "$tmp/m.wgsl" "$@" --name mutant >"$tmp/out" 2>&1 &&
        grep -q "^not ok - mutant$pat" "$tmp/out"; then
        ok "a WGSL kernel with $name fails ($(grep -m1 '^not ok' "$tmp/out" | cut -c1-90)...)"
    else
        notok "a WGSL kernel with $name fails" "it passed or did not fail by its exit status"
    fi
}
must_fail "front and back swapped" 's/select(select(2u, 0u, (f \& 2u) == 0u), 1u,/select(select(2u, 1u, (f \& 2u) == 0u), 0u,/' \
    ': .*classes' $world --random 1 2000 16
must_fail "one weight's sign flipped" 's/-1.0f, -1.0f, 1.0f, 1.0f/-1.0f, 1.0f, 1.0f, 1.0f/' \
    ': .*plane values' $clip --random 1 2000 17
must_fail "classes written past patch_count" 's/if (live \&\& t == 0u)/if (t == 0u)/' \
    ': nothing written past' $world --random 1 2001 18
must_fail "a workgroup size other than --block-threads" 's/@workgroup_size(128)/@workgroup_size(64)/' \
    ': .*workgroup size' $world --random 1 100 19
must_fail "a binding outside the contract" 's/@binding(3)/@binding(4)/' \
    ': .*pipeline' $world --random 1 100 20

# A NaN control point makes a patch silhouette, whatever the rule (WGSL compilers may assume there
# is no NaN: the kernels test the bits); a kernel whose NaN test is gone must fail.
nan_check() {
    local name=$1 file=$2
    shift 2
    run_host "$name" "$PY" tests/wgsl_nan.py "$file" "$@" "$name"
}
for cfg in "1x1 clip --rule strict" "1x1 world --rule degenerate" "2x3 world --certified" \
    "2x3 clip --rule degenerate --certified"; do
    set -- $cfg
    d=$1 space=$2
    shift 2
    "$P" --degree $d --space $space "$@" --target wgsl -o "$tmp/n.wgsl" &&
        nan_check "wgsl $d $space $*: NaN" "$tmp/n.wgsl" ${d%x*} ${d#*x} $space
done
"$P" --degree 1 --space world --rule degenerate --kernel table --target wgsl |
    sed 's/(bitcast<u32>(d) \& 0x7fffffffu) > 0x7f800000u/false/' >"$tmp/m.wgsl"
if grep -q 'bitcast<u32>(d)' "$tmp/m.wgsl" || "$PY" tests/wgsl_nan.py "$tmp/m.wgsl" 1 1 world mutant >"$tmp/out" 2>&1 ||
    ! grep -q '^not ok - mutant: .* NaN' "$tmp/out"; then
    notok "a WGSL kernel without its NaN test fails the NaN check" "it passed, or the test was not found"
else
    ok "a WGSL kernel without its NaN test fails the NaN check"
fi

# Exact zeros: whether a*b - c*d with a*b == c*d is exactly 0 here, plain and through the integer
# XOR that no contraction crosses (tests/README.md).
run_host "wgsl contraction probe" "${PTP_VENV:-build/venv}/bin/python" tests/wgsl_contract.py
