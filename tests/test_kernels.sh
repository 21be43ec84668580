#!/usr/bin/env bash
# test_kernels.sh: emits every kernel target, compiles it and executes it on this machine, and
# checks values and classes against the double reference (tests/kref.c) through the hosts.
# Needs PTPGEN (the generator under test), BUILD (the folder with the OpenCL and Vulkan hosts) and
# build/<cc>/libptptest.a for each C compiler.
set -u
P=${PTPGEN:?set PTPGEN}
B=${BUILD:?set BUILD}
models=${MODELS:-../shared/models}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export POCL_CACHE_DIR=$PWD/build/cache/pocl MESA_SHADER_CACHE_DIR=$PWD/build/cache/mesa
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
# lavapipe allocates a workgroup's coroutine frames (hundreds of KB for the certified kernels) and
# frees them after it; glibc then gives the memory back to the system, and the next workgroup
# pays a page fault a page. Keeping it (no mmap below 32 MB, no trim below 1 GB) makes the
# certified lavapipe runs about 3 times faster (2.2 million page faults on 3*10^4 exact patches).
export GLIBC_TUNABLES=${GLIBC_TUNABLES:-glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824}
mkdir -p "$POCL_CACHE_DIR" "$MESA_SHADER_CACHE_DIR"
NVCC=${NVCC:-/usr/local/cuda/bin/nvcc}

. tests/host_lib.sh
# data_args DEGREE: the patch sets of a configuration: 10,000 random patches, and for bicubic
# each model with random eyes (one host run per line).
data_args() {
    echo "--random 1 10000 $seed"
    if [ "$1" = 3x3 ]; then
        for f in "$models"/*.bez; do
            [ -e "$f" ] && echo "--model $f 6 $seed"
        done
    fi
}

have_gpu_tools=1
for tool in glslangValidator spirv-val; do
    command -v $tool >/dev/null || { missing $tool "GLSL and HLSL kernels"; have_gpu_tools=0; }
done
[ -x "$B/host_opencl" ] || missing "the OpenCL host (OpenCL headers and ICD loader)" "OpenCL kernels"
[ -x "$B/host_vulkan" ] || missing "the Vulkan host (libvulkan)" "GLSL and HLSL kernels"
[ -x "$NVCC" ] || missing nvcc "CUDA kernels"
# CUDA kernels also run on the CPU, through tests/cuda_emu.h built with a C++ compiler.
CUDA_EMU_CXX=${CUDA_EMU_CXX:-g++}
have_emu=1
command -v "$CUDA_EMU_CXX" >/dev/null || { missing "$CUDA_EMU_CXX" "CUDA kernels emulated on the CPU"; have_emu=0; }
[ -x "$B/host_wgpu" ] || missing "the WGSL host (wgpu-native: tests/deps.sh)" "WGSL kernels"
ls "$models"/*.bez >/dev/null 2>&1 || missing "$models" "kernels on the shared models"

# The files a configuration needs, as target:suffix (ptpgen --list-targets): json for the schedule,
# and every target that takes --space (the C header and the kernels).
files="json:.json $("$P" --list-targets | awk '$3 ~ /(^|,)space(,|$)/ { printf "%s:%s ", $1, $2 }')"

# degree_args DEGREE: ptpgen's options for a degree of the matrix: NxM, or triN for the
# triangular patch of degree N.
degree_args() {
    case $1 in
    tri*) echo "--domain triangle --degree ${1#tri}" ;;
    *) echo "--degree $1" ;;
    esac
}

# host_degree DEGREE: the hosts' options for it (tests/kref.h).
host_degree() {
    case $1 in
    tri*) echo "--degree ${1#tri} ${1#tri} --domain triangle" ;;
    *) echo "--degree ${1%x*} ${1#*x}" ;;
    esac
}

# args_for TARGET DEGREE SPACE RULE FLAG...: the options of a configuration that TARGET takes
# (ptpgen --list-targets refuses the others): json, read for its schedule, gets the degree alone.
# RULE may be "" (the default). Targets that name things get the prefix ptp_NxM_ of the default
# variant, which the hosts are built for (a variant's default prefix adds world_, certified_ ...).
args_for() {
    local a="$(degree_args $2)" opts f d=$2
    opts=",$("$P" --list-targets | awk -v t="$1" '$1 == t { print $3 }'),"
    case $d in tri* | *x*) ;; *) d=${d}x$d ;; esac
    [[ $opts == *,prefix,* ]] && a="$a --prefix ptp_${d}_"
    [[ $opts == *,space,* ]] && a="$a --space $3"
    [[ -n $4 && $opts == *,rule,* ]] && a="$a --rule $4"
    shift 4
    for f in "$@"; do
        [[ $opts == *,${f#--},* ]] && a="$a $f"
    done
    echo "$a"
}

# schedule FILE.json: prints "PQ Q", the threads and the patches of a workgroup.
schedule() {
    python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['schedule']; print(s['threads_per_patch']*s['patches_per_block'], s['patches_per_block'])" "$1"
}

# build_host_c CC FLAGS HEADER D: builds tests/host_c.c around the C header HEADER of bidegree D
# (default names) with compiler CC and options FLAGS into $tmp/host_c; errors in $tmp/err.
build_host_c() {
    local cc=$1 flags=$2 h=$3 d=$4 up
    up=$(echo "ptp_${d}_" | tr a-z A-Z)
    $cc -std=c11 $flags -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$h" \
        -D${up}IMPLEMENTATION -DPFX=ptp_${d}_ -DUPFX=$up tests/host_c.c \
        "build/$cc/libptptest.a" -lm -o "$tmp/host_c" 2>"$tmp/err"
}
# to_spirv LANG BASE: compiles BASE.comp (LANG glsl) or BASE.hlsl (hlsl) to $tmp/k.spv and
# validates it with spirv-val; errors in $tmp/err. Sets extra to the host option LANG needs.
to_spirv() {
    if [ "$1" = glsl ]; then
        extra=""
        glslangValidator -V "$2.comp" -o "$tmp/k.spv" >"$tmp/err" 2>&1 || return 1
    else
        extra=--groups-x-constant
        glslangValidator -D -V -S comp -e main "$2.hlsl" -o "$tmp/k.spv" >"$tmp/err" 2>&1 || return 1
    fi
    spirv-val "$tmp/k.spv" 2>>"$tmp/err"
}
# cuda_compile DIR D: compiles DIR/ptp_D.cu with nvcc to an object and to PTX with the entry
# ptp_D_classify; errors in $tmp/err.
cuda_compile() {
    "$NVCC" -c "$1/ptp_$2.cu" -o "$tmp/k.o" >"$tmp/err" 2>&1 &&
        "$NVCC" -ptx "$1/ptp_$2.cu" -o "$tmp/k.ptx" >>"$tmp/err" 2>&1 &&
        grep -q "\.entry ptp_${2}_classify" "$tmp/k.ptx"
}
# cuda_no_fmad LABEL DIR D: nvcc's default build (-fmad=true) of DIR/ptp_D.cu, whose PTX
# cuda_compile left in $tmp/k.ptx, contracts none of its products into an FMA: its PTX is that
# of -fmad=false but for the rounding modifier .rn (which -fmad=false puts on every add, sub and
# mul; the default only on the kernel's __fmul_rn), so its fma.rn.f32 are the kernel's own
# __fmaf_rn; and it has no mul.f32 without .rn, which ptxas could still fuse with an add.
cuda_no_fmad() {
    local n f
    if ! "$NVCC" -ptx -fmad=false "$2/ptp_$3.cu" -o "$tmp/k_nofmad.ptx" 2>"$tmp/err"; then
        notok "cuda $1 compiles with nvcc -fmad=false" "$(head -5 "$tmp/err")"
        return
    fi
    n=$(grep -c 'fma\.rn\.f32' "$tmp/k.ptx") f=$(grep -c 'fma\.rn\.f32' "$tmp/k_nofmad.ptx")
    if cmp -s <(sed -E 's/(add|sub|mul)\.rn\.f32/\1.f32/' "$tmp/k.ptx") \
        <(sed -E 's/(add|sub|mul)\.rn\.f32/\1.f32/' "$tmp/k_nofmad.ptx") && ! grep -q 'mul\.f32' "$tmp/k.ptx"; then
        ok "cuda $1: nvcc's default -fmad=true contracts no product (the PTX of -fmad=false, $n fma.rn.f32)"
    else
        notok "cuda $1: nvcc's default -fmad=true contracts no product" \
            "fma.rn.f32 $n by default, $f with -fmad=false; $(grep -c 'mul\.f32' "$tmp/k.ptx") mul.f32 without .rn"
    fi
}
# cuda_host DIR D: builds tests/host_cuda.cu around DIR/ptp_D.cu into $tmp/host_cuda; errors in
# $tmp/err.
cuda_host() {
    "$NVCC" -O2 -Igen -Itests -I"$1" -DKERNEL_FILE="\"ptp_$2.cu\"" -DKERNEL=ptp_${2}_classify \
        tests/host_cuda.cu build/gcc/libptptest.a -o "$tmp/host_cuda" >"$tmp/err" 2>&1
}

# cuda_emu_host DIR D [FILE]: builds tests/host_cuda.cu around DIR/FILE (default ptp_D.cu) for the
# emulation on the CPU (tests/cuda_emu.h: the kernel's roundings as written, no contraction) into
# $tmp/host_cuda_emu; errors in $tmp/err.
cuda_emu_host() {
    "$CUDA_EMU_CXX" -x c++ -std=c++17 -O2 -march=native -ffp-contract=off -fno-fast-math -Wall -Wextra \
        -Wno-unused-parameter -Werror -pedantic -DCUDA_EMU -Igen -Itests -I"$1" \
        -DKERNEL_FILE="\"${3:-ptp_$2.cu}\"" -DKERNEL=ptp_${2}_classify tests/host_cuda.cu -x none \
        build/gcc/libptptest.a -lm -o "$tmp/host_cuda_emu" >"$tmp/err" 2>&1
}

# gpu_runtimes RUN DIR D LABEL: the GPU kernels DIR/ptp_D.{cl,comp,hlsl,wgsl,cu} (degree D as
# degree_args takes it, default names) on every runtime this machine has: OpenCL on PoCL, GLSL
# and HLSL on lavapipe (as SPIR-V that spirv-val accepts), WGSL on wgpu-native, CUDA compiled by
# nvcc (and run where a GPU is) and emulated on the CPU. For each it calls RUN TARGET HOST... with
# the command that runs the kernel with $PQ threads and $Q patches a workgroup; RUN appends the
# configuration and the data from its caller's variables, which the gr_ locals here do not hide.
# A kernel that does not compile is a "not ok" naming LABEL.
gpu_runtimes() {
    local gr_run=$1 gr_dir=$2 gr_d=$3 gr_label=$4 lang extra
    local sched="--block-threads $PQ --patches-per-block $Q"
    [ -x "$B/host_opencl" ] && $gr_run opencl "$B/host_opencl" "$gr_dir/ptp_$gr_d.cl" --kernel ptp_${gr_d}_classify $sched
    for lang in glsl hlsl; do
        [ $have_gpu_tools = 1 ] || break
        if ! to_spirv $lang "$gr_dir/ptp_$gr_d"; then
            notok "$lang $gr_label compiles to SPIR-V that spirv-val accepts" "$(grep -m3 -i error "$tmp/err")"
            continue
        fi
        ok "$lang $gr_label compiles to SPIR-V that spirv-val accepts"
        [ -x "$B/host_vulkan" ] && $gr_run $lang "$B/host_vulkan" "$tmp/k.spv" $sched $extra
    done
    [ -x "$B/host_wgpu" ] && $gr_run wgsl "$B/host_wgpu" "$gr_dir/ptp_$gr_d.wgsl" $sched
    if [ -x "$NVCC" ]; then
        if cuda_compile "$gr_dir" $gr_d && cuda_host "$gr_dir" $gr_d; then
            ok "cuda $gr_label compiles with nvcc (-c, -ptx with the entry ptp_${gr_d}_classify, and the host)"
            cuda_no_fmad "$gr_label" "$gr_dir" $gr_d
            # The host runs wherever a GPU is (it says so when there is none).
            $gr_run cuda "$tmp/host_cuda" $sched
        else
            notok "cuda $gr_label compiles with nvcc" "$(grep -m3 -i error "$tmp/err")"
        fi
    fi
    if [ $have_emu = 1 ]; then
        if cuda_emu_host "$gr_dir" $gr_d; then
            $gr_run cuda-emu "$tmp/host_cuda_emu" $sched
        else
            notok "cuda $gr_label builds for the emulation with $CUDA_EMU_CXX" "$(grep -m3 -i error "$tmp/err")"
        fi
    fi
    return 0
}

# exercise_run TARGET HOST...: exercise's configuration (its $d, $hcfg, $pl and $label) through
# HOST on each patch set of data_args; WGSL on exact data too (collapsed edges: exact zeros).
exercise_run() {
    local target=$1 data
    shift
    data_args $d | while read -r data; do
        if [ $target = wgsl ]; then
            [ "${data%% *}" = --random ] && data="$data --exact 10 200 $seed"
            # A 4x4 WGSL kernel takes about 1 ms a patch on lavapipe: a tenth of the patches.
            [ $d = 4x4 ] && data=${data/--random 1 10000/--random 1 1000} && data=${data/--exact 10 200/--exact 10 20}
        fi
        run_host "$target $label" "$@" $hcfg $pl $data --name "$target $label ${data%% *}"
    done
}

# exercise DIR D SPACE RULE PLANES PQ Q LABEL: compiles the kernels DIR/ptp_D.{h,cl,comp,hlsl,cu,wgsl}
# (degree D as degree_args takes it, default names) and runs each on the data of data_args against the reference.
exercise() {
    local dir=$1 d=$2 pl="" PQ=$6 Q=$7 label=$8 cc data
    local hcfg="$(host_degree $2) --space $3 --rule $4"
    [ "$5" = 1 ] && pl=--planes

    # C, with gcc and clang.
    for cc in gcc clang; do
        command -v $cc >/dev/null || continue
        if build_host_c $cc -O2 "$dir/ptp_$d.h" $d; then
            data_args $d | while read -r data; do
                run_host "c $label ($cc)" "$tmp/host_c" $hcfg $data --name "c/$cc $label ${data%% *}"
            done
        else
            notok "c $label compiles with $cc" "$(head -5 "$tmp/err")"
        fi
    done
    gpu_runtimes exercise_run "$dir" $d "$label"
}

# Freshly generated kernels, with --planes: every degree (triangles too), space and rule of the
# matrix.
seed=1
mkdir -p "$tmp/gen"
for d in 1x1 2x2 3x3 4x4 2x3 3x1 tri1 tri2 tri3; do
    for space in clip world; do
        for rule in strict degenerate; do
            seed=$((seed + 1))
            for te in $files; do
                "$P" $(args_for ${te%%:*} $d $space $rule --planes) --target ${te%%:*} -o "$tmp/gen/ptp_$d${te#*:}" || notok "$d $space $rule ${te%%:*}" "ptpgen failed"
            done
            read -r PQ Q < <(schedule "$tmp/gen/ptp_$d.json")
            exercise "$tmp/gen" $d $space $rule 1 $PQ $Q "$d $space $rule"
        done
    done
done

# The vendored kernels in out/ (clip space, strict rule, no values), exactly like fresh ones.
for dir in out/*x*/ out/tri*/; do
    d=$(basename "$dir")
    seed=$((seed + 1))
    read -r PQ Q < <(schedule "out/$d/ptp_$d.json")
    exercise "out/$d" $d clip strict 0 $PQ $Q "vendored out/$d"
done

# Without --planes the kernels write only the classes (OpenCL gets a null planes pointer).
"$P" --degree 3 --target opencl -o "$tmp/k.cl" && [ -x "$B/host_opencl" ] &&
    run_host "opencl without --planes" "$B/host_opencl" "$tmp/k.cl" --kernel ptp_3x3_classify --degree 3 3 \
        --space clip --rule strict --block-threads 128 --patches-per-block 8 --random 1 10000 99 --name "opencl 3x3 without --planes"
if [ $have_gpu_tools = 1 ] && [ -x "$B/host_vulkan" ]; then
    "$P" --degree 3 --target glsl -o "$tmp/k.comp" && to_spirv glsl "$tmp/k" &&
        run_host "glsl without --planes" "$B/host_vulkan" "$tmp/k.spv" --degree 3 3 --space clip --rule strict \
            --block-threads 128 --patches-per-block 8 --random 1 10000 99 --name "glsl 3x3 without --planes"
    "$P" --degree 3 --target hlsl -o "$tmp/k.hlsl" && to_spirv hlsl "$tmp/k" &&
        run_host "hlsl without --planes" "$B/host_vulkan" "$tmp/k.spv" --degree 3 3 --space clip --rule strict \
            --block-threads 128 --patches-per-block 8 --groups-x-constant --random 1 10000 99 --name "hlsl 3x3 without --planes"
    # A non-default schedule: 7 threads per patch, 5 patches per workgroup.
    "$P" --degree 2x3 --target glsl --space world --planes --threads-per-patch 7 --patches-per-block 5 -o "$tmp/k.comp" &&
        to_spirv glsl "$tmp/k" &&
        run_host "glsl P=7 Q=5" "$B/host_vulkan" "$tmp/k.spv" --degree 2 3 --space world --rule strict --block-threads 35 \
            --patches-per-block 5 --planes --random 1 3000 7 --name "glsl 2x3 world, 7 threads per patch, 5 patches per group"
fi

if [ -x "$B/host_wgpu" ]; then
    "$P" --degree 2x3 --target wgsl --space world --planes --threads-per-patch 7 --patches-per-block 5 -o "$tmp/k.wgsl" &&
        run_host "wgsl P=7 Q=5" "$B/host_wgpu" "$tmp/k.wgsl" --degree 2 3 --space world --rule strict --block-threads 35 \
            --patches-per-block 5 --planes --random 1 3000 7 --name "wgsl 2x3 world, 7 threads per patch, 5 patches per group"
    # A generated WGSL kernel with one weight's sign flipped must fail its checks.
    "$P" --degree 2 --target wgsl --planes -o "$tmp/k.wgsl" && sed -i '0,/ -1.0f,/s// 1.0f,/' "$tmp/k.wgsl"
    if grep -q '^    -0.166666672f, -2.0f, 1.0f,' "$tmp/k.wgsl" &&
        ! "$B/host_wgpu" "$tmp/k.wgsl" --degree 2 2 --space clip --rule strict --block-threads 128 --patches-per-block 16 \
            --planes --random 1 2000 5 --name mutant >"$tmp/out" 2>&1 && grep -q '^not ok - mutant: .*plane values' "$tmp/out"; then
        ok "a 2x2 WGSL kernel with one weight's sign flipped fails its check"
    else
        notok "a 2x2 WGSL kernel with one weight's sign flipped fails its check" "it passed, or the weight was not found"
    fi
fi

# The CUDA emulation can fail: a 2x2 kernel with one weight's sign flipped (its values), and a
# bicubic kernel without one of its two barriers (its classes: without the first, threads read
# points not loaded yet; without the second, thread 0 combines flags not written yet, which only
# blocks that run thread 0 first show, hence the emulation's alternating thread order).
# emu_mutant SED CHECK LABEL ARGS...: the kernel $tmp/m/k.cu edited by SED fails the check lines
# matching CHECK when the emulation runs it with ARGS.
emu_mutant() {
    local sed=$1 check=$2 label=$3
    shift 3
    sed -i "$sed" "$tmp/m/k.cu"
    if ! cmp -s "$tmp/m/k.cu" "$tmp/m/orig.cu" && cuda_emu_host "$tmp/m" $d k.cu &&
        ! "$tmp/host_cuda_emu" "$@" --name mutant >"$tmp/out" 2>&1 && grep -q "^not ok - mutant: $check" "$tmp/out"; then
        ok "$label fails its check (emulated)"
    else
        notok "$label fails its check (emulated)" "it passed, or the mutation was not made"
    fi
}
if [ $have_emu = 1 ]; then
    mkdir -p "$tmp/m"
    d=2x2
    "$P" --degree 2 --target cuda --planes -o "$tmp/m/orig.cu" && cp "$tmp/m/orig.cu" "$tmp/m/k.cu"
    emu_mutant '0,/ -1.0f,/s// 1.0f,/' '.*plane values' "a 2x2 CUDA kernel with one weight's sign flipped" \
        --degree 2 2 --space clip --rule strict --block-threads 128 --patches-per-block 16 --planes --random 1 2000 5
    d=3x3
    for n in 1 2; do
        cp out/3x3/ptp_3x3.cu "$tmp/m/orig.cu" && cp "$tmp/m/orig.cu" "$tmp/m/k.cu"
        emu_mutant "$(awk -v n=$n '/__syncthreads\(\);/ && ++k == n { print NR "d" }' "$tmp/m/orig.cu")" \
            '.*classes agree' "a 3x3 CUDA kernel without barrier $n of 2" --degree 3 3 --space clip --rule strict \
            --block-threads 128 --patches-per-block 8 --random 1 2000 5
    done
fi

# mutant SED CHECK WHAT [FLAGS]: a bicubic C header edited by sed script SED must fail the check
# lines matching CHECK ("not ok - mutant CHECK") when run on random patches (gcc -O2 FLAGS).
mutant() {
    "$P" --degree 3 --target c -o "$tmp/k.h" && sed -i "$1" "$tmp/k.h"
    if build_host_c gcc "-O2 ${4:-}" "$tmp/k.h" 3x3 &&
        ! "$tmp/host_c" --degree 3 3 --space clip --rule strict --random 1 2000 5 --name mutant >"$tmp/out" 2>&1 &&
        grep -q "^not ok - mutant $2" "$tmp/out"; then
        ok "a C header with $3 fails its check"
    else
        notok "a C header with $3 fails its check" "it passed or did not fail by its exit status"
    fi
}
# The checks can fail: the table (values) and the straight-line code (classify) each.
mutant '0,/-9.0f/s//-9.5f/' '.*plane values' "one table weight changed (-9 -> -9.5)"
mutant '0,/u = -((g0 \* m1_5/s//u = ((g0 * m1_5/' 'classify_batch' "one straight-line term's sign flipped"
mutant '0,/VFMA(g2, m0_8, u)/s//VFMA(g2, -m0_8, u)/' 'classify_batch' "one fused plane's minor's sign flipped"
# The strict masks, < made <= (a zero plane counted negative): in vectors (SSE) and, where the CPU
# has AVX-512, in mask registers.
mutant 's/((k) \& ((v) < 0.0f))/((k) \& ((v) <= 0.0f))/' 'classify_batch' "the strict masks' < made <= (vectors)"
if grep -qw avx512f /proc/cpuinfo; then
    mutant 's/_CMP_LT_OS)$/_CMP_LE_OS)/' 'classify_batch' "the strict masks' < made <= (AVX-512 mask registers)" -march=native
else
    echo "ok - a C header with the AVX-512 strict masks' < made <= fails its check # SKIP this CPU has no AVX-512"
fi

# The vectorized paths as users build them for speed: clang -O3 -march=native (its vectorizer),
# gcc -O2 -march=native (GNU C vectors, AVX-512 here) and -mavx2 (8 lanes); with and without the
# SSE transposition; and gcc's scalar fallback (NO_VECTOR).
for variant in "clang -O3 -march=native" "clang -O3 -march=native -DPTP_3X3_NO_SSE" \
    "clang -O3 -march=native -DPTP_4X4_NO_SSE" "gcc -O2 -march=native" "gcc -O2 -march=native -DPTP_4X4_NO_SSE" \
    "gcc -O2 -mavx2 -mfma" "gcc -O2 -DPTP_3X3_NO_VECTOR"; do
    d=3x3 space=clip rule=strict
    case "$variant" in *4X4*) d=4x4 space=world rule=degenerate ;; *avx2*) space=world ;; esac
    n=${d%x*} cc=${variant%% *}
    command -v $cc >/dev/null || { notok "$cc for the vectorized paths" "$cc is missing"; continue; }
    case "$variant" in *avx2*) grep -qw avx2 /proc/cpuinfo || {
        echo "ok - c $variant # SKIP this CPU has no AVX2"
        continue
    } ;; esac
    "$P" --degree $d --target c --space $space --rule $rule --prefix ptp_${d}_ -o "$tmp/k.h" &&
        build_host_c $cc "${variant#* }" "$tmp/k.h" $d &&
        run_host "c $d $space $rule $variant" "$tmp/host_c" --degree $n $n --space $space \
            --rule $rule --random 2 5003 17 --name "c/$variant $d $space $rule" ||
        notok "c $d $variant compiles" "$(head -5 "$tmp/err")"
done

# Several degrees, and a custom prefix, in one C program; a header included twice.
"$P" --degree 2 --target c -o "$tmp/a.h" && "$P" --degree 3 --target c --space world --prefix cull_ -o "$tmp/b.h"
cat >"$tmp/multi.c" <<'C'
#define PTP_2X2_IMPLEMENTATION
#define CULL_IMPLEMENTATION
#include "a.h"
#include "b.h"
#include "a.h"
int main(void)
{
    static float cp2[9][4], cp3[16][4];
    const float eye[4] = {0, 0, 1, 0};
    unsigned char cls[1];
    int k;
    for (k = 0; k < 16; k++) {
        cp3[k][0] = (float)(k / 4);
        cp3[k][1] = (float)(k % 4);
        cp3[k][3] = 1;
        if (k < 9) {
            cp2[k][0] = (float)(k / 3);
            cp2[k][1] = (float)(k % 3);
            cp2[k][3] = 1;
        }
    }
    cull_classify_batch((const float (*)[4])cp3, 1, eye, cls);
    /* C before C23 does not add const to a pointer to array implicitly: users cast. */
    return !(ptp_2x2_classify((const float (*)[4])cp2, eye) == PTP_2X2_FRONT &&
             cull_classify((const float (*)[4])cp3, eye) == CULL_FRONT &&
             cls[0] == CULL_FRONT && PTP_2X2_PLANES == 25 && CULL_PLANES == 64);
}
C
for cc in gcc clang; do
    command -v $cc >/dev/null || continue
    $cc -std=c99 -Wall -Wextra -pedantic -Werror -I"$tmp" "$tmp/multi.c" -o "$tmp/multi" 2>"$tmp/err" && "$tmp/multi" &&
        ok "C headers of two degrees (one with --prefix cull_), one included twice, in one program ($cc)" ||
        notok "C headers of two degrees in one program ($cc)" "$(grep -m1 error "$tmp/err")"
done

# Variants side by side: the bicubic clip, world and certified C headers and the table header,
# under their default names (ptp_3x3_, ptp_3x3_world_, ptp_3x3_certified_, ptp_3x3_ table), in one
# translation unit with every implementation, as C and C++; each records its variant in macros.
# The patch (3i, 3j, 0, 1) has dB/du x dB/dv along +z: front for an eye above it (w > 0), back
# below, and back above when the eye's w is negative (the negated eye).
"$P" --degree 3 --target c -o "$tmp/ptp_3x3.h" && "$P" --degree 3 --target c --space world -o "$tmp/ptp_3x3_world.h" &&
    "$P" --degree 3 --target c --certified -o "$tmp/ptp_3x3_certified.h" &&
    "$P" --degree 3 --target table -o "$tmp/ptp_3x3_table.h" || notok "variant headers" "ptpgen failed"
cat >"$tmp/variants.c" <<'C'
#define PTP_3X3_IMPLEMENTATION
#define PTP_3X3_WORLD_IMPLEMENTATION
#define PTP_3X3_CERTIFIED_IMPLEMENTATION
#include "ptp_3x3.h"
#include "ptp_3x3_world.h"
#include "ptp_3x3_certified.h"
#include "ptp_3x3_table.h"
#if !(PTP_3X3_SPACE_CLIP && PTP_3X3_RULE_STRICT && !PTP_3X3_CERTIFIED && PTP_3X3_REFINE == 0 &&         \
      PTP_3X3_WORLD_SPACE_WORLD && PTP_3X3_WORLD_DEGREE_U == 3 && PTP_3X3_WORLD_DEGREE_V == 3 &&         \
      PTP_3X3_CERTIFIED_CERTIFIED == 1 && PTP_3X3_CERTIFIED_SPACE_CLIP && PTP_3X3_TERMS == 516) ||       \
    defined(PTP_3X3_SPACE_WORLD) || defined(PTP_3X3_WORLD_SPACE_CLIP) || defined(PTP_3X3_RULE_DEGENERATE)
#error "the variant macros"
#endif
int main(void)
{
    static float cp[16][4];
    const float up[4] = {0, 0, 1, 0}, above[4] = {1, 1, 5, 1}, below[4] = {1, 1, -5, 1};
    const float negw[4] = {-1, -1, -5, -1}; /* the point (1, 1, 5) with w = -1 */
    float d[64];
    int k, ok;
    for (k = 0; k < 16; k++) {
        cp[k][0] = (float)(3 * (k / 4));
        cp[k][1] = (float)(3 * (k % 4));
        cp[k][3] = 1;
    }
    ptp_3x3_values((const float (*)[4])cp, up, d);
    ok = ptp_3x3_classify((const float (*)[4])cp, up) == PTP_3X3_FRONT && d[0] > 0 &&
         ptp_3x3_certified_classify((const float (*)[4])cp, up) == PTP_3X3_CERTIFIED_FRONT &&
         ptp_3x3_world_classify((const float (*)[4])cp, above) == PTP_3X3_WORLD_FRONT &&
         ptp_3x3_world_classify((const float (*)[4])cp, below) == PTP_3X3_WORLD_BACK &&
         ptp_3x3_world_classify((const float (*)[4])cp, negw) == PTP_3X3_WORLD_BACK &&
         ptp_3x3_table_idx[0][0] == 0;
    return !ok;
}
C
for cc in "gcc -std=c99" "clang -std=c99" "g++ -std=c++11 -x c++" "clang++ -std=c++11 -x c++"; do
    command -v ${cc%% *} >/dev/null || continue
    $cc -Wall -Wextra -pedantic -Werror -I"$tmp" "$tmp/variants.c" -o "$tmp/variants" 2>"$tmp/err" && "$tmp/variants" &&
        ok "bicubic clip, world, certified and table headers in one program, default names, orientation ($cc)" ||
        notok "bicubic clip, world, certified and table headers in one program ($cc)" "$(grep -m2 error "$tmp/err")"
done

# alpha(): projections stored as glm (OpenGL, Vulkan, reversed Z) and DirectXMath (LH, RH,
# reversed Z) store them give clip-space classes equal to the world-space header's on the models
# (tests/host_alpha.c, with the default-named headers above), built as C and as C++.
for cc in "gcc -std=c11" "g++ -std=c++11 -x c++"; do
    command -v ${cc%% *} >/dev/null || continue
    if ! ls "$models"/bigguy.bez "$models"/teapot.bez >/dev/null 2>&1; then
        missing "$models" "alpha() on the models"
    elif $cc -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -I"$tmp" tests/host_alpha.c -x none \
        build/gcc/libptptest.a -lm -o "$tmp/host_alpha" 2>"$tmp/err"; then
        run_host "alpha ($cc)" "$tmp/host_alpha" "$models"/bigguy.bez "$models"/teapot.bez
    else
        notok "host_alpha compiles with $cc" "$(grep -m2 error "$tmp/err")"
    fi
done

# C++: bicubic headers (clip, world, certified, refine 2) with their implementations compile as
# C++11 to C++20 with g++ and clang++, -pedantic -Werror, and the hosts (C and C++ alike) pass
# at C++11 and C++20; -ffast-math and its parts are refused by #error saying why.
for cfg in "clip" "world" "clip --certified" "world --refine 2"; do
    set -- $cfg
    space=$1 host=host_c cflag=""
    shift
    case "$*" in *refine*) host=host_refine ;; *certified*) cflag=--certified ;; esac
    "$P" --degree 3 --target c --space $space "$@" --prefix ptp_3x3_ -o "$tmp/x.h" || notok "c++ 3x3 $cfg" "ptpgen failed"
    for cxx in g++ clang++; do
        command -v $cxx >/dev/null || { missing $cxx "C++ builds of the C header"; continue; }
        cc=gcc
        [ $cxx = clang++ ] && cc=clang
        for std in c++11 c++14 c++17 c++20; do
            if ! $cxx -std=$std -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$tmp/x.h" \
                -DPTP_3X3_IMPLEMENTATION -DPFX=ptp_3x3_ -DUPFX=PTP_3X3_ -x c++ tests/$host.c -x none \
                "build/$cc/libptptest.a" -lm -o "$tmp/host_cxx" 2>"$tmp/err"; then
                notok "c++ 3x3 $cfg compiles with $cxx -std=$std" "$(grep -m3 error "$tmp/err")"
            elif [ $std = c++11 ] || [ $std = c++20 ]; then
                run_host "c++ 3x3 $cfg ($cxx -std=$std)" "$tmp/host_cxx" --degree 3 3 --space $space \
                    --rule strict $cflag --random 1 3000 23 --name "c++/$cxx -std=$std 3x3 $cfg"
            else
                ok "c++ 3x3 $cfg compiles with $cxx -std=$std -pedantic -Werror"
            fi
        done
    done
done
"$P" --degree 3 --target c -o "$tmp/x.h"
for cc in gcc clang g++ clang++; do
    command -v $cc >/dev/null || continue
    for flag in -ffast-math -ffinite-math-only "-fassociative-math -fno-signed-zeros -fno-trapping-math"; do
        # clang defines no macro for -fassociative-math alone: only gcc's __ASSOCIATIVE_MATH__ is seen
        [[ $cc == clang* && $flag == -fassoc* ]] && continue
        lang=c
        [[ $cc == *++ ]] && lang=c++
        if printf '#define PTP_3X3_IMPLEMENTATION\n#include "x.h"\nint main(void) { return 0; }\n' |
            $cc -x $lang $flag -I"$tmp" -c - -o "$tmp/fm.o" 2>"$tmp/err"; then
            notok "c header refuses $cc $flag" "it compiled"
        elif grep -q 'error.*do not compile this header.*-ffast-math.*NaN checks' "$tmp/err"; then
            ok "c header refuses $cc $flag with #error saying why"
        else
            notok "c header refuses $cc $flag with its #error" "$(grep -m1 error "$tmp/err")"
        fi
    done
done

# Certified kernels (--certified) against exact classes. kref's --exact data are integer patches
# built to sit on the edge between the classes (planar through the eye, the eye on a corner's
# tangent plane, collapsed edges, +-1 noise), classified exactly in 128-bit integers. A
# certified kernel must never call a patch back or front that is not exactly back or front
# under the strict rule ("unsafe"); the plain float kernel, on the first fifth of the same data,
# must be unsafe somewhere, which shows that the data reach the rounding. Each certified kernel
# also runs on random data, where its classes must be the double reference's or silhouette.
# Every target's certified kernel sees 10^6 exact patches. Their points are integers, so the GPU
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
    local target=$1
    shift
    exact_run "$target 3x3 $space $kind" $kind "$@" $hcfg $data --name "$kind $target 3x3 $space exact"
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
        read -r PQ Q < <(schedule "$dir/ptp_3x3.json")

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
    if grep -q "$2" "$tmp/k.h" && build_host_c gcc -O2 "$tmp/k.h" 3x3 &&
        ! "$tmp/host_c" --degree 3 3 --space clip --rule $1 --certified ${4:-$cert_short} --name mutant >"$tmp/out" 2>&1 &&
        grep -q '^not ok - mutant.*certified: no unsafe class' "$tmp/out"; then
        ok "$3 is caught unsafe on exact data"
    else
        notok "$3 is caught unsafe" "it passed, or its mutation was not found"
    fi
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
# gives_up_little NAME OUT [PCT]: the host output OUT on random and teapot patches (a quarter with
# a collapsed edge) gives up at most PCT% (default 1) of the back or front patches (its first
# "given up" line); a host with no GPU prints none: skipped.
gives_up_little() {
    local g n pct=${3:-1}
    printf '%s\n' "$2" | grep -q 'no CUDA device here' && return 0
    read -r g n < <(printf '%s\n' "$2" | grep -m1 'front.*certified: given up' |
        sed 's/.*given up \([0-9]*\) of \([0-9]*\) back or front.*/\1 \2/')
    if [ "${n:-0}" -gt 400 ] && [ $((100 * g)) -le $((pct * n)) ]; then
        ok "$1: gives up $g of $n back or front on random and teapot patches (at most $pct%)"
    else
        notok "$1: gives up at most $pct% of back or front on random and teapot patches" "${g:-?} of ${n:-?}"
    fi
}
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
# exact data, 10^6 patches like the strict ones (clip space on every target; world space on PoCL,
# lavapipe's GLSL and HLSL, and wgpu). Every certified GPU kernel's terms read differences of
# points, whose float bound gives up little (WGSL, which has no second look, relies on it).
# gpu_degenerate TARGET SPACE CMD...: the host CMD on exact data, and on random and teapot patches.
gpu_degenerate() {
    local target=$1 space=$2 name="certified degenerate $1 3x3 $2" out
    shift 2
    hcfg="--degree 3 3 --space $space --rule degenerate --certified"
    run_host "$name exact" "$@" $hcfg $cert_data --name "$name exact"
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
            ok "cuda 3x3 $space certified degenerate compiles with nvcc (-c, -ptx and the host)"
            cuda_no_fmad "3x3 $space certified degenerate" "$dir" 3x3
            gpu_degenerate cuda $space "$tmp/host_cuda" --block-threads $PQ --patches-per-block $Q
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
# The certified GPU kernels' terms read differences of points (README: Differences of points). The
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
