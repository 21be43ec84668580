#!/usr/bin/env bash
# run_bench.sh: prints `make bench`'s table: the bench_cull rows of each bidegree, the OpenCL kernels
# on PoCL and the GLSL kernels on lavapipe (straight-line and table), the WGSL kernel on
# wgpu-native (lavapipe) through the test hosts' --bench, ptpgen's own time, and bench_tri's
# triangle rows.
#   bench/run_bench.sh BUILD CC "CFLAGS" DEGREE...   (BUILD holds ptpgen, bench/ and the hosts)
set -u
. tests/schedule.sh
B=$1 CC=$2 FLAGS=$3
shift 3
GPU_MAX=65536 GPU_RUNS=3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export POCL_CACHE_DIR=$PWD/build/cache/pocl MESA_SHADER_CACHE_DIR=$PWD/build/cache/mesa
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
mkdir -p "$POCL_CACHE_DIR" "$MESA_SHADER_CACHE_DIR"

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
cache=/sys/devices/system/cpu/cpu0/cache
l2=$(cat $cache/index2/size 2>/dev/null || echo ?)
l3=$(cat $cache/index3/size 2>/dev/null || echo ?)
case $("$CC" --version 2>/dev/null) in
*clang*) ccname=clang ;;
*"Free Software Foundation"*) ccname=gcc ;;
*) ccname=$(basename "$CC") ;;
esac
ccver=$("$CC" -dumpfullversion 2>/dev/null || "$CC" -dumpversion)
# fail MESSAGE: stops the bench.
fail() {
    echo "run_bench: $1" >&2
    exit 1
}
read -r _ peak1 peakall ncpu bits < <("$B/bench/peak") || fail "$B/bench/peak failed"
cores="$ncpu core$([ "$ncpu" = 1 ] || echo s)"

echo "ptpgen bench: ${cpu:-unknown CPU}, $ccname $ccver $FLAGS, 1 core (pinned) unless stated;" \
    "L2 $l2, L3 $l3"
echo "peak (measured): $peak1 GFLOP/s on 1 core, $peakall GFLOP/s on $cores" \
    "(FMA+ADD mix of $bits-bit vectors, an FMA counted as 2 flops)"
# line COLUMNS...: one line of the table, aligned with bench_cull's rows.
line() { printf '%-8s  %-37s %10s %11s %8s %7s %8s  %s\n' "$@"; }
line bidegree path Mpatches/s flops/patch GFLOP/s %peak 'vs paper' differs

# gpu_row DEGREE LABEL RATE FLOPS PAPER_RATE CHECK: a row of a kernel on all cores (RATE patches/s,
# or empty when unavailable), with the paper loop's flops and against the all-core peak.
gpu_row() {
    local mp gf pk vs
    if [ -z "$3" ]; then
        line "$1" "$2" unavailable - - - - "${6:--}"
        return
    fi
    read -r mp gf pk vs < <(awk -v r="$3" -v f="$4" -v p="$5" -v pk="$peakall" 'BEGIN {
        g = r * f * 1e-9; printf "%.3f %.1f %.1f%% %.1fx\n", r * 1e-6, g, 100 * g / pk, r / p }')
    line "$1" "$2" "$mp" "$4" "$gf" "$pk" "$vs" "$6"
}
# bench_field FIELD: FIELD of the "# bench:" line in $tmp/out ("" if none).
bench_field() {
    sed -n "s/^# bench: .*$1=\\([0-9.]*\\).*/\\1/p" "$tmp/out" | head -1
}
# gpu_bench HOST ARGS...: runs a kernel host with --bench, first on 1024 patches, then, if a
# dispatch of 0.25 s holds more, on that many (at most GPU_MAX), best of GPU_RUNS. Sets rate
# (patches/s, "" when there is none), check (its check column) and rc (the host's exit status).
gpu_bench() {
    local n=1024 more
    "$@" --random 1 "$n" 1 --name bench --bench 1 >"$tmp/out" 2>&1
    rc=$?
    rate=$(bench_field patches_per_s)
    if [ $rc = 0 ] && [ -n "$rate" ]; then
        more=$(awk -v r="$rate" -v m=$GPU_MAX 'BEGIN { n = int(r / 4); print (n > m ? m : n) }')
        if [ "$more" -gt $n ]; then
            n=$more
            "$@" --random 1 "$n" 1 --name bench --bench $GPU_RUNS >"$tmp/out" 2>&1
            rc=$?
            rate=$(bench_field patches_per_s)
        fi
    fi
    if [ -z "$rate" ]; then
        check="host exit $rc"
    elif [ $rc = 0 ]; then
        check="ref ok, $n"
    else
        check="ref FAILED, $n"
    fi
}

# kernel_cfg KERNEL DEGREE: the hosts' options for a clip-space strict kernel of bidegree DEGREE,
# with the workgroup of its banner (tests/schedule.sh).
kernel_cfg() {
    kernel_schedule "$1" | sed 's/^/--block-threads /; s/ \([0-9]*\)$/ --patches-per-block \1/'
    echo "--degree ${2%x*} ${2#*x} --space clip --rule strict"
}

notes=()
gen=""
for d in "$@"; do
    "$B/bench/bench_cull_$d" --peak "$peak1" "$peakall" >"$tmp/rows" || fail "bench_cull_$d failed"
    grep -v '^#' "$tmp/rows"
    while IFS= read -r line; do notes+=("$line"); done < <(grep '^#' "$tmp/rows")
    # the paper loop's patches/s and flops, for the kernels' rows
    read -r paper flops < <(awk '$2 == "paper" && $3 == "loop" { print $4 * 1e6, $5 }' "$tmp/rows")
    # the straight-line program's flops, for the straight-line kernels' rows
    slpflops=$(awk '$2 == "classify_batch" && $3 ~ /^[0-9.]+$/ { print $4 }' "$tmp/rows" | head -1)
    # The kernels: the straight-line kernel (default) and the paper's table kernel (table), each
    # dispatched as its banner's schedule says.
    for kernel in slp table; do
        kn=$([ $kernel = table ] && echo " table")
        fl=$([ $kernel = table ] && echo "$flops" || echo "$slpflops")

        # OpenCL on PoCL
        rate="" check=""
        if [ -x "$B/host_opencl" ] && "$B/ptpgen" --degree "$d" --target opencl --kernel $kernel -o "$tmp/k.cl"; then
            gpu_bench "$B/host_opencl" "$tmp/k.cl" --kernel "ptp_${d}_classify" $(kernel_cfg "$tmp/k.cl" $d)
        fi
        gpu_row "$d" "OpenCL$kn (PoCL), $cores" "$rate" "$fl" "$paper" "$check"
        if [ $kernel = slp ]; then # in float16 vectors, 16 patches a work-item (CPU devices)
            rate="" check=""
            if [ -x "$B/host_opencl" ] && "$B/ptpgen" --degree "$d" --target opencl --kernel lanes -o "$tmp/k.cl"; then
                gpu_bench "$B/host_opencl" "$tmp/k.cl" --kernel "ptp_${d}_classify" $(kernel_cfg "$tmp/k.cl" $d)
            fi
            gpu_row "$d" "OpenCL lanes (PoCL), $cores" "$rate" "$fl" "$paper" "$check"
        fi

        # GLSL on lavapipe
        rate="" check=""
        if [ -x "$B/host_vulkan" ] && command -v glslangValidator >/dev/null &&
            "$B/ptpgen" --degree "$d" --target glsl --kernel $kernel -o "$tmp/k.comp" &&
            glslangValidator -V "$tmp/k.comp" -o "$tmp/k.spv" >/dev/null 2>&1; then
            gpu_bench "$B/host_vulkan" "$tmp/k.spv" $(kernel_cfg "$tmp/k.comp" $d)
        fi
        gpu_row "$d" "GLSL$kn (lavapipe), $cores" "$rate" "$fl" "$paper" "$check"

        # WGSL on wgpu-native (lavapipe through Vulkan): the straight-line kernel
        [ $kernel = table ] && continue
        rate="" check=""
        if [ -x "$B/host_wgpu" ] && "$B/ptpgen" --degree "$d" --target wgsl -o "$tmp/k.wgsl"; then
            gpu_bench "$B/host_wgpu" "$tmp/k.wgsl" $(kernel_cfg "$tmp/k.wgsl" $d)
        fi
        gpu_row "$d" "WGSL (wgpu, lavapipe), $cores" "$rate" "$fl" "$paper" "$check"
    done

    gen+="${gen:+, }$d $("$B/bench/bench_cull_$d" --gen "$B/ptpgen" || echo ?) ms"
done
for v in "$B"/bench/bench_cull_3x3_*; do
    [ -x "$v" ] || continue
    "$v" --peak "$peak1" "$peakall" >"$tmp/rows" || fail "$v failed"
    grep -v '^#' "$tmp/rows"
    while IFS= read -r line; do notes+=("$line"); done < <(grep '^#' "$tmp/rows")
done
echo "generation time (ptpgen --target c, clip, strict; whole process, median of 21): $gen"
echo
printf '%s\n' "${notes[@]}"
cat <<EOF
# paper loop: the table's terms in order, cross4's z only (16 flops a term: 14 for cross4.z,
#   1 weight product, 1 accumulation) and alpha * d per plane; classify, classify_batch (AoS in,
#   transposed in blocks of LANES) and classify_soa: the emitted header's straight-line code, its
#   FLOPS per patch.
# classify_batch on all cores: one pinned thread per CPU it may use, each on its own slice; %peak of
#   the all-core peak. Each row is the best of at least 5 runs (0.3 s or more); the paper loop and
#   classify run on the first patches, as many as 20 ms hold, the others on all.
# differs: patches whose class differs from classify's, over the patches that path ran.
# OpenCL, GLSL and WGSL: one dispatch of the hosts' random patches (tests/kref.c), as many as 0.25 s
#   hold (1024 to $GPU_MAX, the number after "ref ok"), best of $GPU_RUNS (of 1 at 1024); kernel and
#   class read-back only (compilation and upload excluded), on every core; flops: the straight-line
#   kernels' as classify's, the table kernels' as the paper loop's (its terms, plus padding
#   slots); "ref ok": the host checked the classes against the double reference.
EOF
echo
# the triangle rows: the degree-1 mesh path and its baselines, PN triangles and bicubic patches
"$B/bench/bench_tri" || fail "bench_tri failed"
