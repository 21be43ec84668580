# kernels_lib.sh: what test_kernels.sh and test_certified.sh share (sourced): the environment of
# the runtimes, the tools this machine has, ptpgen's options per degree, and building and running
# each target's kernels through the hosts. Needs PTPGEN, BUILD and build/<cc>/libptptest.a.
P=${PTPGEN:?set PTPGEN}
B=${BUILD:?set BUILD}
models=models # the Utah teapot set; the knot (bench/mkmodel.c) stands in for a large model
knot=build/models/knot.bez
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
. tests/schedule.sh
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
[ -e $knot ] || make -s $knot >/dev/null 2>&1 || notok "the models" "make $knot failed"
[ -z "${MODELS:-}" ] || ls "$MODELS"/*.bez >/dev/null 2>&1 ||
    notok "the models" "MODELS=$MODELS has no .bez file"
# model_files: the bicubic models: models/*.bez, the knot, and MODELS=DIR's other .bez files.
model_files() {
    local f
    ls "$models"/*.bez
    echo $knot
    for f in ${MODELS:+"$MODELS"/*.bez}; do
        [ -e "$f" ] && [ ! -e "$models/$(basename "$f")" ] && echo "$f"
    done
}

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
# (ptpgen --list-targets refuses the others; a FLAG may be --name=value): json gets the degree alone.
# RULE may be "" (the default). Targets that name things get the prefix ptp_NxM_ of the default
# variant, which the hosts are built for (a variant's default prefix adds world_, certified_ ...).
args_for() {
    local a="$(degree_args $2)" opts f n d=$2
    opts=",$("$P" --list-targets | awk -v t="$1" '$1 == t { print $3 }'),"
    case $d in tri* | *x*) ;; *) d=${d}x$d ;; esac
    [[ $opts == *,prefix,* ]] && a="$a --prefix ptp_${d}_"
    [[ $opts == *,space,* ]] && a="$a --space $3"
    [[ -n $4 && $opts == *,rule,* ]] && a="$a --rule $4"
    shift 4
    for f in "$@"; do
        n=${f#--}
        [[ $opts == *,${n%%=*},* ]] && a="$a $f"
    done
    echo "$a"
}

# schedule FILE: prints "PQ Q", the threads and the patches of a workgroup: from a json file's
# schedule (the table kernel's), or from a GPU kernel's banner (either form's).
schedule() {
    case $1 in
    *.json) python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['schedule']; print(s['threads_per_patch']*s['patches_per_block'], s['patches_per_block'])" "$1" ;;
    *) kernel_schedule "$1" ;;
    esac
}

# host_sched KERNEL: the hosts' options for the workgroup of KERNEL's banner (either form).
host_sched() {
    kernel_schedule "$1" | sed 's/^/--block-threads /; s/ \([0-9]*\)$/ --patches-per-block \1/'
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
# cuda_compile DIR D: compiles DIR/ptp_D.cu with nvcc to PTX with the entry ptp_D_classify (the
# host, cuda_host, compiles it to an object); errors in $tmp/err.
cuda_compile() {
    "$NVCC" -ptx "$1/ptp_$2.cu" -o "$tmp/k.ptx" >"$tmp/err" 2>&1 &&
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
# A CUDA device runs the CUDA hosts where nvidia-smi lists one.
have_cuda_gpu=0
command -v nvidia-smi >/dev/null && nvidia-smi -L 2>/dev/null | grep -q '^GPU' && have_cuda_gpu=1
cuda_host_built=0
# cuda_host DIR D: builds tests/host_cuda.cu around DIR/ptp_D.cu into $tmp/host_cuda (errors in
# $tmp/err) and sets cuda_host_new to 1; without a CUDA device only the first call builds (the
# host compiles; nothing would run it: nvcc takes minutes on the large kernels), later ones set
# cuda_host_new to 0 and return 0.
cuda_host() {
    cuda_host_new=0
    [ $have_cuda_gpu = 1 ] || [ $cuda_host_built = 0 ] || return 0
    "$NVCC" -O2 -Igen -Itests -I"$1" -DKERNEL_FILE="\"ptp_$2.cu\"" -DKERNEL=ptp_${2}_classify \
        tests/host_cuda.cu build/gcc/libptptest.a -o "$tmp/host_cuda" >"$tmp/err" 2>&1 &&
        cuda_host_built=1 cuda_host_new=1
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

# gives_up_little NAME OUT [PCT]: the host output OUT on random and model patches (a quarter of
# the random ones with a collapsed edge) gives up at most PCT% (default 1) of the back or front patches (its first
# "given up" line); a host with no GPU prints none: skipped.
gives_up_little() {
    local g n pct=${3:-1}
    printf '%s\n' "$2" | grep -q 'no CUDA device here' && return 0
    read -r g n < <(printf '%s\n' "$2" | grep -m1 'front.*certified: given up' |
        sed 's/.*given up \([0-9]*\) of \([0-9]*\) back or front.*/\1 \2/')
    if [ "${n:-0}" -gt 400 ] && [ $((100 * g)) -le $((pct * n)) ]; then
        ok "$1: gives up $g of $n back or front on random or model patches (at most $pct%)"
    else
        notok "$1: gives up at most $pct% of back or front on random or model patches" "${g:-?} of ${n:-?}"
    fi
}
# gpu_runtimes RUN DIR D LABEL: the GPU kernels DIR/ptp_D.{cl,comp,hlsl,wgsl,cu} (degree D as
# degree_args takes it, default names) on every runtime this machine has: OpenCL on PoCL, GLSL
# and HLSL on lavapipe (as SPIR-V that spirv-val accepts), WGSL on wgpu-native, CUDA compiled by
# nvcc (and run where a GPU is) and emulated on the CPU. For each it calls RUN TARGET HOST... with
# the command that runs the kernel with the workgroup of its banner (host_sched); RUN appends the
# configuration and the data from its caller's variables, which the gr_ locals here do not hide.
# A kernel that does not compile is a "not ok" naming LABEL; DIR without a WGSL file skips WGSL.
gpu_runtimes() {
    local gr_run=$1 gr_dir=$2 gr_d=$3 gr_label=$4 lang extra gr_k="$2/ptp_$3"
    [ -x "$B/host_opencl" ] && $gr_run opencl "$B/host_opencl" "$gr_k.cl" --kernel ptp_${gr_d}_classify $(host_sched "$gr_k.cl")
    for lang in glsl hlsl; do
        [ $have_gpu_tools = 1 ] || break
        if ! to_spirv $lang "$gr_k"; then
            notok "$lang $gr_label compiles to SPIR-V that spirv-val accepts" "$(grep -m3 -i error "$tmp/err")"
            continue
        fi
        ok "$lang $gr_label compiles to SPIR-V that spirv-val accepts"
        [ -x "$B/host_vulkan" ] && $gr_run $lang "$B/host_vulkan" "$tmp/k.spv" \
            $(host_sched "$gr_k.$([ $lang = glsl ] && echo comp || echo hlsl)") $extra
    done
    [ -x "$B/host_wgpu" ] && [ -e "$gr_k.wgsl" ] && $gr_run wgsl "$B/host_wgpu" "$gr_k.wgsl" $(host_sched "$gr_k.wgsl")
    if [ -x "$NVCC" ]; then
        if cuda_compile "$gr_dir" $gr_d && cuda_host "$gr_dir" $gr_d; then
            ok "cuda $gr_label compiles with nvcc (-ptx with the entry ptp_${gr_d}_classify$([ $cuda_host_new = 1 ] && echo ', and the host')"
            cuda_no_fmad "$gr_label" "$gr_dir" $gr_d
            # The host runs wherever a GPU is (it says so when there is none).
            [ $cuda_host_new = 1 ] && $gr_run cuda "$tmp/host_cuda" $(host_sched "$gr_k.cu")
        else
            notok "cuda $gr_label compiles with nvcc" "$(grep -m3 -i error "$tmp/err")"
        fi
    fi
    if [ $have_emu = 1 ]; then
        if cuda_emu_host "$gr_dir" $gr_d; then
            $gr_run cuda-emu "$tmp/host_cuda_emu" $(host_sched "$gr_k.cu")
        else
            notok "cuda $gr_label builds for the emulation with $CUDA_EMU_CXX" "$(grep -m3 -i error "$tmp/err")"
        fi
    fi
    return 0
}
