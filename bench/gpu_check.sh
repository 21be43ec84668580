#!/usr/bin/env bash
# gpu_check.sh: what needs a real GPU, in one run of a few minutes, as one table headed by the
# device's name: the renderer's cull methods over tessellation factors 1 to 64, the CUDA kernels
# (straight-line and table) on the exact test data and on random patches, with their speed.
#   bash bench/gpu_check.sh [MODEL.bez]   (default: BigGuy in $MODELS, else build/models/knot.bez,
#   else the teapot in models/; builds with gcc into build/gcc; needs nvcc, a Vulkan driver and
#   nvidia-smi or vulkaninfo)
set -u
cd "$(dirname "$0")/.."
. tests/schedule.sh
B=build/gcc
NVCC=${NVCC:-nvcc}
command -v "$NVCC" >/dev/null || NVCC=/usr/local/cuda/bin/nvcc
model=${1:-}
if [ -z "$model" ]; then
    for m in ${MODELS:+"$MODELS/bigguy.bez"} build/models/knot.bez models/teapot.bez; do
        [ -e "$m" ] && { model=$m; break; }
    done
fi
[ -e "$model" ] || { echo "gpu_check: no model (give MODEL.bez)" >&2; exit 2; }
orient=()
case $model in *teapot*) orient=(--up 0,0,1 --orientation in) ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
make -s CC=gcc $B/ptpgen $B/libptptest.a render >"$tmp/make.log" 2>&1 ||
    { echo "gpu_check: build failed:" >&2; tail -5 "$tmp/make.log" >&2; exit 1; }

device=$(nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | head -1)
echo "# gpu_check: ${device:-unknown device}; $(date -u +%Y-%m-%d); model $(basename "$model")"

# The renderer: every method at each factor from one view, 512x512, 5 frames (the best frame).
printf '%-14s' "render factor"
methods="none tcone ncone ptp ptp-tcs ptp-table ptp-certified ptp-tcs-certified"
for m in $methods; do printf ' %13s' "$m"; done
echo "   (frame ms, best of 5; culled)"
for f in 1 2 4 8 16 32 64; do
    printf '%-14s' "$f"
    for m in $methods; do
        line=$(timeout 60 build/render --model "$model" --eye 0,0,12 "${orient[@]}" --tess $f \
            --cull $m --size 512x512 --frames 5 2>&1 | tail -1)
        ms=$(sed -n 's/.* frame_min_ms=\([0-9.]*\).*/\1/p' <<<"$line")
        culled=$(sed -n 's/.* culled=\([0-9]*\).*/\1/p' <<<"$line")
        printf ' %13s' "${ms:-fail};${culled:--}"
    done
    echo
done

# CUDA: each kernel form, plain and certified, built with nvcc around tests/host_cuda.cu, on exact
# data (0 unsafe) and random patches (classes against the double reference), with the host's --bench.
for form in "slp" "table" "slp --certified" "table --certified"; do
    read -r kernel cert <<<"$form"
    build/gcc/ptpgen --degree 3 --target cuda --kernel $kernel $cert --prefix ptp_3x3_ -o "$tmp/ptp_3x3.cu" &&
        "$NVCC" -O2 -Igen -Itests -I"$tmp" -DKERNEL_FILE='"ptp_3x3.cu"' -DKERNEL=ptp_3x3_classify \
            tests/host_cuda.cu $B/libptptest.a -o "$tmp/host_cuda" >"$tmp/nvcc.log" 2>&1 ||
        { echo "cuda $form: build failed: $(head -3 "$tmp/nvcc.log")"; continue; }
    read -r pq q < <(kernel_schedule "$tmp/ptp_3x3.cu")
    cfg=(--degree 3 3 --space clip --rule strict --block-threads "$pq" --patches-per-block "$q" $cert)
    "$tmp/host_cuda" "${cfg[@]}" --exact 5 200 1 --random 1 65536 1 --name "cuda $form" >"$tmp/out" 2>&1
    echo "cuda $form: $(grep -c '^ok' "$tmp/out") ok, $(grep -c '^not ok' "$tmp/out") not ok"
    grep '^not ok' "$tmp/out" | head -3
    "$tmp/host_cuda" "${cfg[@]}" --random 1 1048576 1 --bench 5 --name "cuda $form bench" 2>&1 |
        sed -n 's/^# bench: /cuda '"$form"' bench: /p'
done
