#!/usr/bin/env bash
# test_certified.sh: the certified kernels (--certified) of every target on exact, far and random
# data, and the mutants that show these checks can fail. Needs PTPGEN, BUILD (the folder with the
# OpenCL and Vulkan hosts) and build/<cc>/libptptest.a for each C compiler.
set -u
. tests/kernels_lib.sh

# Certified kernels (--certified) against exact classes. kref's --exact data are integer patches
# built to sit on the edge between the classes (planar through the eye, the eye on a corner's
# tangent plane, collapsed edges, +-1 noise), classified exactly in 128-bit integers. A
# certified kernel must never call a patch back or front that is not exactly back or front
# under the strict rule ("unsafe"); the plain float kernel, on the first fifth of the same data,
# must be unsafe somewhere, which shows that the data reach the rounding. Each certified kernel
# also runs on random data, where its classes must be the double reference's or silhouette, and
# on the knot and the teapot, where it gives up at most 1% of the back or front patches.
# The GPU kernels are each target's default form: the straight-line kernel (OpenCL and CUDA with
# a second look in double-float for the planes whose float bounds do not clear, GLSL and HLSL
# giving such a patch up), WGSL's the table kernel; the paper's table kernel of every target
# follows below. Every runtime's certified kernel sees 10^6 exact patches, and 4,000 far tangent
# corners (--exact-far: points 2^22 to 2^23 from the eye, 2^13 to 2^15 times their extent), where
# a second look bounded by the differences' magnitudes fails.
cert_far="--exact-far 4 1000 41"
cert_data="--exact 100 10000 41 $cert_far" cert_short="--exact 20 10000 41 $cert_far"
# exact_run NAME KIND CMD...: runs a host like run_host; KIND plain also requires the first
# "kernel unsafe N" the host prints to be at least 1 (a host with no GPU prints none: skipped).
exact_run() {
    local name=$1 kind=$2 out n
    shift 2
    out=$(run_host "$name" "$@")
    printf '%s\n' "$out"
    [ "$kind" = plain ] || return 0
    printf '%s\n' "$out" | grep -q 'no CUDA device here' && return 0
    n=$(printf '%s\n' "$out" | grep -m1 -o 'kernel unsafe [0-9]*' | grep -o '[0-9]*$')
    if [ "${n:-0}" -ge 1 ]; then
        ok "$name: plain float is unsafe on $n exact patches, so the data reach the rounding"
    else
        notok "$name: plain float is unsafe on some exact patch" "${n:-no} unsafe classes reported"
    fi
}
# looks_again NAME OUT: on the exact data (clip strict) a straight-line OpenCL or CUDA kernel gives
# up at most half of the exactly back or front patches: its float bounds alone give up 77% (GLSL's
# and HLSL's, with their larger u, 81%), with the second look 39%. A host with no GPU prints none.
looks_again() {
    local g n
    printf '%s\n' "$2" | grep -q 'no CUDA device here' && return 0
    read -r g n < <(printf '%s\n' "$2" | grep -m1 'exactly back or front' |
        sed 's/.*given up \([0-9]*\) of \([0-9]*\) exactly.*/\1 \2/')
    if [ "${n:-0}" -gt 1000 ] && [ $((2 * g)) -le "$n" ]; then
        ok "$1: the second look decides: gives up $g of $n exactly back or front (at most half)"
    else
        notok "$1: the second look decides: gives up at most half of the exactly back or front" "${g:-?} of ${n:-?}"
    fi
}
# run_exact TARGET HOST...: the exact data $data through HOST, and for a certified kernel the
# random and model data too ($space, $kind and the host options $hcfg of the loop below).
run_exact() {
    local target=$1 out
    shift
    out=$(exact_run "$target 3x3 $space $kind" $kind "$@" $hcfg $data --name "$kind $target 3x3 $space exact")
    printf '%s\n' "$out"
    [ $kind = certified ] || return 0
    case $space/$target in clip/opencl | clip/cuda | clip/cuda-emu) looks_again "$target 3x3 clip certified" "$out" ;; esac
    run_host "$target 3x3 $space certified random" "$@" $hcfg --random 1 10000 43 \
        --name "certified $target 3x3 $space random"
    out=$(run_host "$target 3x3 $space certified models" "$@" $hcfg --model $knot 4 7 \
        --model $models/teapot.bez 20 7 --name "certified $target 3x3 $space knot and teapot")
    printf '%s\n' "$out"
    gives_up_little "certified $target 3x3 $space" "$out"
}
mkdir -p "$tmp/cert"
command -v clang >/dev/null || missing clang "certified C kernels with clang -O3 -march=native"
for space in clip world; do
    for kind in certified plain; do
        dir="$tmp/cert/$space-$kind" cflag="" data=$cert_short
        [ $kind = certified ] && cflag=--certified data=$cert_data
        hcfg="--degree 3 3 --space $space --rule strict $cflag"
        mkdir -p "$dir"
        for te in $files; do
            "$P" $(args_for ${te%%:*} 3 $space "" $cflag) --target ${te%%:*} -o "$dir/ptp_3x3${te#*:}" ||
                notok "3x3 $space $kind ${te%%:*}" "ptpgen failed"
        done

        # C: gcc -O2 and -O2 -march=native (GNU C vectors, 4 and 16 lanes), clang -O3 -march=native.
        for cc in "gcc -O2" "gcc -O2 -march=native" "clang -O3 -march=native"; do
            command -v ${cc%% *} >/dev/null || continue
            if build_host_c ${cc%% *} "${cc#* }" "$dir/ptp_3x3.h" 3x3; then
                run_exact "c/$cc" "$tmp/host_c"
            else
                notok "c 3x3 $space $kind compiles with $cc" "$(head -5 "$tmp/err")"
            fi
        done
        gpu_runtimes run_exact "$dir" 3x3 "3x3 $space $kind"
    done
done
# mutant_verdict LABEL: the mutant run just made (its status, its output in $tmp/out) failed by
# calling unsafe classes.
mutant_verdict() {
    if [ $? = 0 ] && grep -q '^not ok - mutant.*certified: no unsafe class' "$tmp/out"; then
        ok "$1 is caught unsafe on exact data"
    else
        notok "$1 is caught unsafe" "it passed, or its mutation was not found"
    fi
}
# mutant_caught RULE MARK LABEL [DATA]: the mutated certified clip header $tmp/k.h (of --rule RULE),
# which must contain MARK (a grep pattern), is caught calling unsafe classes on exact data (DATA,
# else $cert_short).
mutant_caught() {
    grep -q "$2" "$tmp/k.h" && build_host_c gcc -O2 "$tmp/k.h" 3x3 &&
        ! "$tmp/host_c" --degree 3 3 --space clip --rule $1 --certified ${4:-$cert_short} --name mutant >"$tmp/out" 2>&1
    mutant_verdict "$3"
}
# The exact check can fail: a certified header whose bounds are 2^10 times too small must be
# caught calling patches back or front that are not.
"$P" --degree 3 --space clip --certified --target c --prefix ptp_3x3_ -o "$tmp/k.h" && sed -i 's/\* ER3 + /* ER3 * 0x1p-10f + /; s/, ER3, PTP_3X3_VABS/, ER3 * 0x1p-10f, PTP_3X3_VABS/' "$tmp/k.h"
mutant_caught strict 'ER3 \* 0x1p-10f' "a certified C header with its bounds 2^10 times too small"
# The bound is near the errors the exact data reach: 2^6 times too small, it is caught as well
# (about 40 unsafe of 10^6; with each plane's largest rounding depth for all its monomials and
# E R^3 for every monomial, the bound was about twice as loose, and such a mutant was unsafe once).
"$P" --degree 3 --space clip --certified --target c --prefix ptp_3x3_ -o "$tmp/k.h" && sed -i 's/\* ER3 + /* ER3 * 0x1p-6f + /; s/, ER3, PTP_3X3_VABS/, ER3 * 0x1p-6f, PTP_3X3_VABS/' "$tmp/k.h"
mutant_caught strict 'ER3 \* 0x1p-6f' "a certified C header with its bounds 2^6 times too small" "$cert_data"
# Certified C headers under the degenerate rule: a plane that a collapsed boundary edge zeros is
# exactly 0 there, so they keep the degenerate rule's culls of such patches (the teapot's lid and
# bottom, and the random sets' collapsed quarter) while staying safe on the exact data. Headers
# that treat those zeros as uncertain give up about a quarter of the random and teapot culls.
for cfg in "clip gcc -O2" "world clang -O3 -march=native"; do
    space=${cfg%% *} cc=${cfg#* }
    command -v ${cc%% *} >/dev/null || continue
    hcfg="--degree 3 3 --space $space --rule degenerate --certified"
    name="certified degenerate c/$cc 3x3 $space"
    if "$P" --degree 3 --space $space --rule degenerate --certified --target c --prefix ptp_3x3_ \
        -o "$tmp/k.h" && build_host_c ${cc%% *} "${cc#* }" "$tmp/k.h" 3x3; then
        run_host "$name exact" "$tmp/host_c" $hcfg $cert_short --name "$name exact"
        out=$(run_host "$name random" "$tmp/host_c" $hcfg --random 1 10000 43 \
            --model "$models/teapot.bez" 20 7 --name "$name random and teapot")
        printf '%s\n' "$out"
        gives_up_little "$name" "$out"
    else
        notok "$name compiles" "$(head -5 "$tmp/err")"
    fi
done
# cert_tri_run TARGET HOST...: the configuration of the loop below ($label, $targs) through HOST.
cert_tri_run() {
    local target=$1
    shift
    run_host "certified $target $label" "$@" $targs --name "certified $target $label"
}
# Triangular patches' certified kernels on every runtime, on exact data as well, far tangent
# corners included: there a second look (the C header's in double, OpenCL's and CUDA's in
# double-float) decides patches whose float values have the wrong signs, so host_c accepts a
# class that values() contradicts only when it is the exact one. GLSL, HLSL and WGSL give those
# patches up.
for td in tri1 tri2 tri3 tri4; do
    if ! "$P" $(args_for json $td clip "") --target json -o "$tmp/$td.json"; then
        notok "certified $td" "ptpgen --target json failed"
        continue
    fi
    for cfg in "clip strict" "clip degenerate" "world strict" "world degenerate"; do
        read -r tspace trule <<<"$cfg"
        dir="$tmp/cert/$td-$tspace-$trule" label="$td $tspace $trule"
        targs="$(host_degree $td) --space $tspace --rule $trule --certified --exact 8 5000 41 $cert_far --random 1 5000 43"
        mkdir -p "$dir"
        for te in $files; do
            [ ${te%%:*} = json ] && continue
            "$P" $(args_for ${te%%:*} $td $tspace $trule --certified) --target ${te%%:*} -o "$dir/ptp_$td${te#*:}" ||
                notok "certified $label ${te%%:*}" "ptpgen failed"
        done
        if build_host_c gcc "-O2 -march=native" "$dir/ptp_$td.h" $td; then
            run_host "certified c/gcc $label" "$tmp/host_c" $targs --name "certified c/gcc -O2 -march=native $label"
        else
            notok "certified c $label compiles" "$(head -5 "$tmp/err")"
        fi
        gpu_runtimes cert_tri_run "$dir" $td "certified $label"
    done
done
# ... and the far triangles catch a certified GLSL table kernel on lavapipe whose second look
# bounds by the sheared points' magnitudes (M2 = M: 11 unsafe of 44,000, far tangent corners).
if [ $have_gpu_tools = 1 ] && [ -x "$B/host_vulkan" ]; then
    "$P" $(args_for glsl tri3 clip strict --certified --kernel=table) --target glsl -o "$tmp/t.comp" &&
        sed 's/float M2 = .*;$/float M2 = M;/' "$tmp/t.comp" >"$tmp/m.comp"
    grep -q 'float M2 = M;' "$tmp/m.comp" && to_spirv glsl "$tmp/m" &&
        ! "$B/host_vulkan" "$tmp/k.spv" $(host_sched "$tmp/m.comp") $(host_degree tri3) \
            --space clip --rule strict --certified --exact 8 5000 41 $cert_far --name mutant >"$tmp/out" 2>&1
    mutant_verdict "a certified GLSL triangle kernel whose second look bounds by the differences' magnitudes"
fi
# ... and the exact check can fail there: a header that counts every plane as zero where edge 0 is
# collapsed, not only the planes along it, must be caught calling patches back that are not.
"$P" --degree 3 --space clip --rule degenerate --certified --target c --prefix ptp_3x3_ -o "$tmp/k.h" &&
    sed -i 's/lt = PTP_3X3_KLT(lt, v);/lt \&= PTP_3X3_KLT0(v) | PTP_3X3_KC(c0);/; s/s = PTP_3X3_VMIN(s, t);/amb |= ((t > F) | c0) == 0;/; s/notlt |= ((d\[x\] < -bound) | z) == 0;/notlt |= ((d[x] < -bound) | (col \& 1)) == 0;/' "$tmp/k.h"
mutant_caught degenerate '(t > F) | c0) == 0' "a certified degenerate C header that zeros planes off the collapsed edge"
# Certified GPU kernels under the degenerate rule test the patch's edges too (their points'
# bits) and count the planes along a collapsed one as exactly 0: like the C headers they keep the
# degenerate rule's culls (kernels without the test gave up about a quarter) and stay safe on the
# exact data, 10^6 patches like the strict ones, in both spaces on every runtime.
# degenerate_run TARGET CMD...: the host CMD on exact data, and on random and teapot patches
# ($space, $hcfg and $data of the loops below).
degenerate_run() {
    local name="certified $kname $1 3x3 $space $rule" out
    shift
    run_host "$name exact" "$@" $hcfg $data --name "$name exact"
    out=$(run_host "$name random" "$@" $hcfg --random 1 2000 43 --model "$models/teapot.bez" 20 7 \
        --name "$name random and teapot")
    printf '%s\n' "$out"
    [ $rule = degenerate ] && gives_up_little "$name" "$out"
    return 0
}
rule=degenerate kname=degenerate data=$cert_data
for space in clip world; do
    dir="$tmp/cert/$space-degenerate" hcfg="--degree 3 3 --space $space --rule degenerate --certified"
    mkdir -p "$dir"
    for te in $files; do
        "$P" $(args_for ${te%%:*} 3 $space degenerate --certified) --target ${te%%:*} -o "$dir/ptp_3x3${te#*:}" ||
            notok "3x3 $space certified degenerate ${te%%:*}" "ptpgen failed"
    done
    gpu_runtimes degenerate_run "$dir" 3x3 "3x3 $space certified degenerate"
done
# The paper's table kernel (--kernel table), certified, on every runtime (WGSL's --certified kernel
# above is already the table kernel): clip strict and world degenerate, on a fifth of the exact
# data. It shears each point to patch-local coordinates as it loads it (WGSL's reads the points
# as given, its terms differences of points); its second look (double-float, every plane whose
# float bound does not clear) and its collapsed-edge tests read the points as given. On lavapipe
# a patch that takes the second look costs about 70 us of CPU, a far tangent corner about 1.3 ms
# (5 s a run).
kname=table data=$cert_short
for cfg in "clip strict" "world degenerate"; do
    read -r space rule <<<"$cfg"
    dir="$tmp/cert/table-$space-$rule" hcfg="--degree 3 3 --space $space --rule $rule --certified"
    mkdir -p "$dir"
    for te in opencl:.cl glsl:.comp hlsl:.hlsl cuda:.cu; do
        "$P" $(args_for ${te%%:*} 3 $space $rule --certified --kernel=table) --target ${te%%:*} \
            -o "$dir/ptp_3x3${te#*:}" || notok "3x3 $space $rule certified table ${te%%:*}" "ptpgen failed"
    done
    gpu_runtimes degenerate_run "$dir" 3x3 "3x3 $space $rule certified table"
done
# ... and with --coordinates absolute, the points as given and each term reading differences of
# points (WGSL's form) with the second look from the points: OpenCL, clip strict.
name="certified table opencl 3x3 clip strict, --coordinates absolute"
if [ -x "$B/host_opencl" ]; then
    if "$P" $(args_for opencl 3 clip strict --certified --kernel=table) --coordinates absolute \
        --target opencl -o "$tmp/abs.cl"; then
        grep -q 'ptp_3x3_diff(' "$tmp/abs.cl" || notok "$name reads differences of points" "no diff( found"
        run_host "$name" "$B/host_opencl" "$tmp/abs.cl" --kernel ptp_3x3_classify $(host_sched "$tmp/abs.cl") \
            --degree 3 3 --space clip --rule strict --certified $cert_short --name "$name"
    else
        notok "$name" "ptpgen failed"
    fi
fi
# Patch-local coordinates pay on small patches far from the origin: on the far model (the knot's
# patches split 16 ways, 2^14 times their size from the origin) in world space, with eyes near
# it, the certified OpenCL table kernel culls about 5% more patch-views than with --coordinates
# absolute (31,448 against 29,929 of 32,768 from 8 views; plain float culls 31,448), where the
# second look, which reads the points as given, decides none. The host's double reference is
# not accurate there (world space, 2^14 from the origin), so only the kernels' culls are compared;
# the exact data above hold them to no unsafe class.
far=build/models/far.bez
[ -e $far ] || make -s $far >/dev/null 2>&1 || notok "the far model" "make $far failed"
if [ -x "$B/host_opencl" ]; then
    far_culls() { # far_culls KERNEL: the kernel's back and front patch-views on the far model, world
        "$B/host_opencl" "$1" --kernel ptp_3x3_classify $(host_sched "$1") --degree 3 3 --space world \
            --rule strict --certified --model $far 8 7 --name far 2>&1 |
            sed -n 's/.*: kernel front \([0-9]*\), back \([0-9]*\),.*/\1 \2/p' | awk '{ print $1 + $2 }'
    }
    name="far model, world space: the certified OpenCL table kernel culls at least 3% more than with --coordinates absolute"
    if "$P" --degree 3 --space world --certified --kernel table --target opencl --prefix ptp_3x3_ -o "$tmp/fl.cl" &&
        "$P" --degree 3 --space world --certified --kernel table --coordinates absolute --target opencl \
            --prefix ptp_3x3_ -o "$tmp/fa.cl"; then
        local_culls=$(far_culls "$tmp/fl.cl") absolute_culls=$(far_culls "$tmp/fa.cl")
        if [ -n "$local_culls" ] && [ -n "$absolute_culls" ] && [ "$absolute_culls" -gt 0 ] &&
            [ $((local_culls * 100)) -ge $((absolute_culls * 103)) ]; then
            ok "$name ($local_culls against $absolute_culls)"
        else
            notok "$name" "local ${local_culls:-?}, absolute ${absolute_culls:-?}"
        fi
    else
        notok "$name" "ptpgen failed"
    fi
fi
# ocl_mutant_caught DIR RULE SED MARK LABEL: the certified clip OpenCL table kernel of DIR (of
# --rule RULE), mutated by the sed script SED so that it contains MARK (a grep pattern), is caught
# calling unsafe classes on exact data; so is the CUDA kernel of DIR under the same mutation, run
# by the emulation.
ocl_mutant_caught() {
    local args="$(host_sched "$1/ptp_3x3.cl") --degree 3 3 --space clip --rule $2 --certified $cert_short --name mutant"
    if [ -x "$B/host_opencl" ]; then
        sed "$3" "$1/ptp_3x3.cl" >"$tmp/m.cl"
        grep -q "$4" "$tmp/m.cl" && ! "$B/host_opencl" "$tmp/m.cl" --kernel ptp_3x3_classify $args >"$tmp/out" 2>&1
        mutant_verdict "$5"
    fi
    if [ $have_emu = 1 ]; then
        mkdir -p "$tmp/m" && sed "$3" "$1/ptp_3x3.cu" >"$tmp/m/ptp_3x3.cu"
        grep -q "$4" "$tmp/m/ptp_3x3.cu" && cuda_emu_host "$tmp/m" 3x3 &&
            ! "$tmp/host_cuda_emu" $args >"$tmp/out" 2>&1
        mutant_verdict "$(echo "$5" | sed 's/OpenCL/CUDA/') (emulated)"
    fi
}
# ... and the exact check can fail there: an OpenCL table kernel that counts every plane as zero
# where any edge is collapsed, not only the planes along it, must be caught calling patches back
# or front that are not.
dir="$tmp/cert/table-clip-degenerate"
mkdir -p "$dir"
for t in opencl:.cl cuda:.cu; do
    "$P" $(args_for ${t%%:*} 3 clip degenerate --certified --kernel=table) --target ${t%%:*} -o "$dir/ptp_3x3${t#*:}"
done
ocl_mutant_caught "$dir" degenerate \
    's/ptp_3x3_zero\[plane\] & col/col/; s/ptp_3x3_zero\[ptp_3x3_own_plane\[i\]\] & col/col/' \
    '(col) == 0u' "a certified degenerate OpenCL table kernel that zeros planes off the collapsed edge"
# The certified table kernel's float bound (docs/errors.md): an OpenCL kernel whose float-pass
# bounds are 2^12 times too small is caught (about 6,400 unsafe of 200,000; 7 at 2^-6 of the
# bound, as the exact data's integer points round once sheared), though its second look, against
# the right bound, still runs where the mutated bound does not decide.
ocl_mutant_caught "$tmp/cert/table-clip-strict" strict 's/tau_k\[plane\] \* M + /tau_k[plane] * M * 0x1p-12f + /' \
    'M \* 0x1p-12f' "a certified OpenCL table kernel with its float bounds 2^12 times too small"
# The second look must count the planes it looks at again: an OpenCL kernel that drops their
# double-float flags (keeping only the planes the float bounds decided) is caught unsafe (about
# 7,100 of 2*10^5).
ocl_mutant_caught "$tmp/cert/table-clip-strict" strict 's/) & mine \* 3u;/) \& 0u;/' \
    ') & 0u;' "a certified OpenCL table kernel whose second look drops the planes it looks at again"
# The second look reads the points as given, so its bound takes their own magnitudes (M2), not
# the sheared points' (M), which are far smaller on the far tangent corners of --exact-far: an
# OpenCL kernel whose second look takes M is caught (about 20 unsafe of 204,000).
ocl_mutant_caught "$tmp/cert/table-clip-strict" strict 's/float M2 = .*;$/float M2 = M;/' \
    'float M2 = M;' "a certified OpenCL table kernel whose second look bounds by the differences' magnitudes"
# WGSL's likewise (u = 2^-23, no second look; none unsafe at 2^-10 of its bound): a kernel whose
# bounds are 2^12 times too small is caught (about 290 unsafe of 200,000).
if [ -x "$B/host_wgpu" ]; then
    sed 's/_tau_k\[plane\] \* M + /_tau_k[plane] * M * 0x1p-12f + /' "$tmp/cert/clip-certified/ptp_3x3.wgsl" >"$tmp/m.wgsl"
    if grep -q 'M \* 0x1p-12f' "$tmp/m.wgsl" && ! "$B/host_wgpu" "$tmp/m.wgsl" $(host_sched "$tmp/m.wgsl") \
        --degree 3 3 --space clip --rule strict --certified $cert_short --name mutant >"$tmp/out" 2>&1 &&
        grep -q '^not ok - mutant.*certified: no unsafe class' "$tmp/out"; then
        ok "a certified WGSL kernel with its float bounds 2^12 times too small is caught unsafe on exact data"
    else
        notok "a certified WGSL kernel with its float bounds 2^12 times too small is caught unsafe" \
            "it passed, or its mutation was not found"
    fi
fi
# The straight-line kernels: bounds 2^10 times too small (GLSL on lavapipe, OpenCL on PoCL) must
# make unsafe classes, and so must OpenCL's second look with bounds 2^30 times too small (about 20 unsafe, on the far tangent
# corners) or skipped (the float signs of the planes whose bounds do not clear: about 8,800).
"$P" --degree 3 --space clip --certified --kernel slp --target glsl --prefix ptp_3x3_ -o "$tmp/m.comp" &&
    "$P" --degree 3 --space clip --certified --kernel slp --target opencl --prefix ptp_3x3_ -o "$tmp/m.cl" &&
    sed -i 's/, ER3, /, ER3 * 0.0009765625f, /' "$tmp/m.comp" "$tmp/m.cl"
args="--degree 3 3 --space clip --rule strict --certified $cert_short --name mutant"
for m in glsl opencl; do
    if [ $m = glsl ]; then
        [ $have_gpu_tools = 1 ] && [ -x "$B/host_vulkan" ] || continue
        glslangValidator -V "$tmp/m.comp" -o "$tmp/m.spv" >/dev/null &&
            ! "$B/host_vulkan" "$tmp/m.spv" --block-threads 64 --patches-per-block 64 $args >"$tmp/out" 2>&1
    else
        [ -x "$B/host_opencl" ] || continue
        ! "$B/host_opencl" "$tmp/m.cl" --kernel ptp_3x3_classify --block-threads 64 --patches-per-block 64 \
            $args >"$tmp/out" 2>&1
    fi
    if [ $? = 0 ] && grep -q 'ER3 \* 0.0009765625f' "$tmp/m.comp" &&
        grep -q '^not ok - mutant.*certified: no unsafe class' "$tmp/out"; then
        ok "a certified straight-line $m kernel with bounds 2^10 times too small is caught unsafe"
    else
        notok "a certified straight-line $m kernel with bounds 2^10 times too small is caught unsafe" \
            "$(grep -m1 'unsafe' "$tmp/out")"
    fi
done
for m in 's/tau2_k\[i\] \* M2/tau2_k[i] * M2 * 0x1p-30f/:M2 \* 0x1p-30f:whose second look bounds are 2^30 times too small' \
    's/c = ptp_3x3_second_look(cp, eye, c, redo);/c = c;/:c = c;:that skips the second look'; do
    [ -x "$B/host_opencl" ] || break
    IFS=: read -r edit mark what <<<"$m"
    "$P" --degree 3 --space clip --certified --kernel slp --target opencl --prefix ptp_3x3_ -o "$tmp/l.cl" &&
        sed "$edit" "$tmp/l.cl" >"$tmp/m.cl" && grep -q "$mark" "$tmp/m.cl" &&
        ! "$B/host_opencl" "$tmp/m.cl" --kernel ptp_3x3_classify --block-threads 64 --patches-per-block 64 \
            $args >"$tmp/out" 2>&1
    if [ $? = 0 ] && grep -q '^not ok - mutant.*certified: no unsafe class' "$tmp/out"; then
        ok "a certified straight-line OpenCL kernel $what is caught unsafe"
    else
        notok "a certified straight-line OpenCL kernel $what is caught unsafe" "$(grep -m1 'unsafe' "$tmp/out")"
    fi
done
