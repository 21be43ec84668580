# gpu_lib.sh: what the GPU benchmark scripts share, sourced with B (the build folder) set: a
# temporary folder $tmp, lavapipe with mesa's shader cache, the bicubic schedule (PQ, Q), and the
# model: BigGuy where MODELS=DIR holds bigguy.bez, else the generated knot (bench/mkmodel.c).
if [ -n "${MODELS:-}" ] && [ -e "$MODELS/bigguy.bez" ]; then
    model=$MODELS/bigguy.bez
else
    model=build/models/knot.bez
    [ -e $model ] || make -s $model >/dev/null ||
        { echo "no $model: make $model failed" >&2; exit 1; }
fi
model_name=$(basename "$model" .bez)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export MESA_SHADER_CACHE_DIR=$PWD/build/cache/mesa
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
mkdir -p "$MESA_SHADER_CACHE_DIR"
# PQ threads and Q patches a block, as the bicubic kernels are scheduled
"$B/ptpgen" --degree 3 --target json -o "$tmp/k.json" || exit 1
read -r PQ Q < <(python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['schedule']; print(s['threads_per_patch']*s['patches_per_block'], s['patches_per_block'])" "$tmp/k.json")
