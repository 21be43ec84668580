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
# also runs on random data, where its classes must be the double reference's or silhouette.
# Every runtime's certified kernel sees 10^6 exact patches (lavapipe's through GLSL; HLSL, the
# same runtime, the first fifth: its runs cost 2 minutes each). Their points are integers, so the GPU
# kernels' differences of points are exact there; 5% (clip) to 7% (world) of them take the GPU
# kernels' double-float second look (its planes whose float bounds do not clear); on lavapipe, where
# GLSL and HLSL sum every plane again from the rounds' tables, a run costs about 70 us of CPU a
# patch (with GLIBC_TUNABLES above; about 2 minutes for each of its runs on a loaded machine), on
# PoCL 4 to 5 us. The seven certified degenerate runs below took 458 s together (load average 6).
# Both also take 4,000 far tangent corners (--exact-far: points 2^22 to 2^23 from the eye, 2^13
# to 2^15 times their extent), where a second look bounded by the differences' magnitudes fails.
# Most of them take the second look: about 1.3 ms a patch on lavapipe (5 s a run), 1 us on PoCL.
cert_far="--exact-far 4 1000 41"
cert_data="--exact 100 10000 41 $cert_far" cert_short="--exact 20 10000 41 $cert_far"
# exact_data TARGET: the exact data of a certified TARGET kernel.
exact_data() {
    [ "$1" = hlsl ] && echo "$cert_short" || echo "$cert_data"
}
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
# run_exact TARGET HOST...: the exact data $data through HOST, and for a certified kernel the
# random data too ($space, $kind and the host options $hcfg of the loop below).
run_exact() {
    local target=$1 d=$data
    shift
    [ $kind = certified ] && d=$(exact_data $target)
    exact_run "$target 3x3 $space $kind" $kind "$@" $hcfg $d --name "$kind $target 3x3 $space exact"
    [ $kind = certified ] && run_host "$target 3x3 $space certified random" "$@" $hcfg \
        --random 1 10000 43 --name "certified $target 3x3 $space random"
    return 0
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
        read -r PQ Q < <(schedule "$dir/ptp_3x3.comp") # either GPU form

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
# corners included: there a second look (the C header's in double, the GPU kernels' in
# double-float) decides patches whose float values have the wrong signs, so host_c accepts a
# class that values() contradicts only when it is the exact one. WGSL has no second look and
# gives those patches up.
for td in tri1 tri2 tri3 tri4; do
    if ! "$P" $(args_for json $td clip "") --target json -o "$tmp/$td.json"; then
        notok "certified $td" "ptpgen --target json failed"
        continue
    fi
    read -r PQ Q < <(schedule "$tmp/$td.json")
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
# ... and the far triangles catch a certified GLSL kernel on lavapipe whose second look bounds by
# the differences' magnitudes (M2 = M: 11 unsafe of 44,000, far tangent corners).
if [ $have_gpu_tools = 1 ] && [ -x "$B/host_vulkan" ]; then
    sed 's/float M2 = .*;$/float M2 = M;/' "$tmp/cert/tri3-clip-strict/ptp_tri3.comp" >"$tmp/m.comp"
    read -r PQ Q < <(schedule "$tmp/tri3.json")
    grep -q 'float M2 = M;' "$tmp/m.comp" && to_spirv glsl "$tmp/m" &&
        ! "$B/host_vulkan" "$tmp/k.spv" --block-threads $PQ --patches-per-block $Q $(host_degree tri3) \
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
# exact data, 10^6 patches like the strict ones (clip space on every runtime; world space on PoCL,
# lavapipe's GLSL and HLSL, and wgpu). Every certified GPU kernel's terms read differences of
# points, whose float bound gives up little (WGSL, which has no second look, relies on it).
# gpu_degenerate TARGET SPACE CMD...: the host CMD on exact data, and on random and teapot patches.
gpu_degenerate() {
    local target=$1 space=$2 name="certified degenerate $1 3x3 $2" out
    shift 2
    hcfg="--degree 3 3 --space $space --rule degenerate --certified"
    run_host "$name exact" "$@" $hcfg $(exact_data $target) --name "$name exact"
    out=$(run_host "$name random" "$@" $hcfg --random 1 2000 43 --model "$models/teapot.bez" 20 7 \
        --name "$name random and teapot")
    printf '%s\n' "$out"
    gives_up_little "$name" "$out"
}
for space in clip world; do
    dir="$tmp/cert/$space-degenerate"
    mkdir -p "$dir"
    for te in $files; do
        "$P" $(args_for ${te%%:*} 3 $space degenerate --certified) --target ${te%%:*} -o "$dir/ptp_3x3${te#*:}" ||
            notok "3x3 $space certified degenerate ${te%%:*}" "ptpgen failed"
    done
    read -r PQ Q < <(schedule "$dir/ptp_3x3.json")
    [ -x "$B/host_opencl" ] && gpu_degenerate opencl $space "$B/host_opencl" "$dir/ptp_3x3.cl" \
        --kernel ptp_3x3_classify --block-threads $PQ --patches-per-block $Q
    for lang in glsl hlsl; do
        [ $have_gpu_tools = 1 ] && [ -x "$B/host_vulkan" ] || continue
        if to_spirv $lang "$dir/ptp_3x3"; then
            gpu_degenerate $lang $space "$B/host_vulkan" "$tmp/k.spv" --block-threads $PQ \
                --patches-per-block $Q $extra
        else
            notok "$lang 3x3 $space certified degenerate compiles to SPIR-V" "$(grep -m3 -i error "$tmp/err")"
        fi
    done
    [ -x "$B/host_wgpu" ] && gpu_degenerate wgsl $space "$B/host_wgpu" "$dir/ptp_3x3.wgsl" \
        --block-threads $PQ --patches-per-block $Q
    if [ -x "$NVCC" ] && [ $space = clip ]; then
        if cuda_compile "$dir" 3x3 && cuda_host "$dir" 3x3; then
            ok "cuda 3x3 $space certified degenerate compiles with nvcc (-ptx$([ $cuda_host_new = 1 ] && echo ' and the host'))"
            cuda_no_fmad "3x3 $space certified degenerate" "$dir" 3x3
            [ $cuda_host_new = 1 ] && gpu_degenerate cuda $space "$tmp/host_cuda" --block-threads $PQ --patches-per-block $Q
        else
            notok "cuda 3x3 $space certified degenerate compiles with nvcc" "$(grep -m3 -i error "$tmp/err")"
        fi
    fi
    if [ $have_emu = 1 ]; then
        if cuda_emu_host "$dir" 3x3; then
            gpu_degenerate cuda-emu $space "$tmp/host_cuda_emu" --block-threads $PQ --patches-per-block $Q
        else
            notok "cuda 3x3 $space certified degenerate builds for the emulation" "$(grep -m3 -i error "$tmp/err")"
        fi
    fi
done
# ocl_mutant_caught DIR RULE SED MARK LABEL: the certified clip OpenCL kernel of DIR (of --rule
# RULE), mutated by the sed script SED so that it contains MARK (a grep pattern), is caught
# calling unsafe classes on exact data; so is the CUDA kernel of DIR under the same mutation, run
# by the emulation.
ocl_mutant_caught() {
    local sched="--block-threads $(schedule "$1/ptp_3x3.json" | sed 's/ / --patches-per-block /')"
    local args="$sched --degree 3 3 --space clip --rule $2 --certified $cert_short --name mutant"
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
# ... and the exact check can fail there: an OpenCL kernel that counts every plane as zero where
# any edge is collapsed, not only the planes along it, must be caught calling patches back or
# front that are not.
ocl_mutant_caught "$tmp/cert/clip-degenerate" degenerate \
    's/ptp_3x3_zero\[plane\] & col/col/; s/ptp_3x3_zero\[ptp_3x3_own_plane\[i\]\] & col/col/' \
    '(col) == 0u' "a certified degenerate OpenCL kernel that zeros planes off the collapsed edge"
# The certified GPU kernels' terms read differences of points (docs/errors.md: differences). The
# exact data are integer points, whose differences are exact and whose float errors stay far below
# the bound (none unsafe at 2^-6 of it, 21 at 2^-10): an OpenCL kernel whose float-pass bounds are
# 2^12 times too small is caught (about 1,100 unsafe of 200,000), though its second look, against
# the right bound, still runs where the mutated bound does not decide.
ocl_mutant_caught "$tmp/cert/clip-certified" strict 's/tau_k\[plane\] \* M + /tau_k[plane] * M * 0x1p-12f + /' \
    'M \* 0x1p-12f' "a certified OpenCL kernel with its float bounds 2^12 times too small"
# The second look must count the planes it looks at again: an OpenCL kernel that drops their
# double-float flags (keeping only the planes the float bounds decided) is caught unsafe (about
# 4,000 of 2*10^5).
ocl_mutant_caught "$tmp/cert/clip-certified" strict 's/) & mine \* 3u;/) \& 0u;/' \
    ') & 0u;' "a certified OpenCL kernel whose second look drops the planes it looks at again"
# The second look reads the points themselves, so its bound takes their own magnitudes (M2), not
# the differences' (M), which are 2^26 to 2^30 times smaller on the far tangent corners of
# --exact-far: an OpenCL kernel whose second look takes M is caught there (7 unsafe of 4,000,
# where rounding in double-float flips an exactly zero corner plane), though on the --exact data
# alone, whose points are not far from the eye against their extent, it is not (none of 10^6).
ocl_mutant_caught "$tmp/cert/clip-certified" strict 's/float M2 = .*;$/float M2 = M;/' \
    'float M2 = M;' "a certified OpenCL kernel whose second look bounds by the differences' magnitudes"
# WGSL's likewise (u = 2^-23, no second look; none unsafe at 2^-10 of its bound): a kernel whose
# bounds are 2^12 times too small is caught (about 290 unsafe of 200,000).
if [ -x "$B/host_wgpu" ]; then
    sed 's/_tau_k\[plane\] \* M + /_tau_k[plane] * M * 0x1p-12f + /' "$tmp/cert/clip-certified/ptp_3x3.wgsl" >"$tmp/m.wgsl"
    if grep -q 'M \* 0x1p-12f' "$tmp/m.wgsl" && ! "$B/host_wgpu" "$tmp/m.wgsl" \
        $(schedule "$tmp/cert/clip-certified/ptp_3x3.json" | sed 's/^/--block-threads /; s/ / --patches-per-block /2') \
        --degree 3 3 --space clip --rule strict --certified $cert_short --name mutant >"$tmp/out" 2>&1 &&
        grep -q '^not ok - mutant.*certified: no unsafe class' "$tmp/out"; then
        ok "a certified WGSL kernel with its float bounds 2^12 times too small is caught unsafe on exact data"
    else
        notok "a certified WGSL kernel with its float bounds 2^12 times too small is caught unsafe" \
            "it passed, or its mutation was not found"
    fi
fi
