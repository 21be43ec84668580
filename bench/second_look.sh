#!/usr/bin/env bash
# second_look.sh: what the GPU certified kernel's second look in double-float recovers, and how
# often it runs: the world-space bicubic GLSL (or OpenCL) kernel over a model (bench/gpu_lib.sh:
# the knot, or BigGuy with MODELS=DIR), plain, certified with
# the float bound alone (the second look switched off) and certified (table kernels), with the culls given up
# against the double reference, the kernel's culls (back and front), the dispatch time and the
# patches that take the second look.
#   bash bench/second_look.sh BUILD [NEYES [SPACE [TARGET]]]   (BUILD holds ptpgen and host_vulkan,
#   or host_opencl for TARGET opencl; default 24 world glsl)
set -u
B=$1 neyes=${2:-24} space=${3:-world} target=${4:-glsl}
. bench/gpu_lib.sh
"$B/ptpgen" --degree 3 --space "$space" --kernel table --prefix sl_ --target "$target" -o "$tmp/plain.src" &&
    "$B/ptpgen" --degree 3 --space "$space" --certified --kernel table --prefix sl_ --target "$target" -o "$tmp/on.src" || exit 1
sed 's/bool again = live &&/bool again = false \&\& live \&\&/' "$tmp/on.src" >"$tmp/off.src"
# the patches that take the second look, as front (every other patch silhouette)
sed 's/cls\[pid\] = sl_class_of(f);/cls[pid] = again ? 0u : 2u;/' "$tmp/on.src" >"$tmp/again.src"
cmp -s "$tmp/on.src" "$tmp/off.src" || ! cmp -s "$tmp/on.src" "$tmp/again.src" || { echo "no second look found"; exit 1; }
echo "$model_name, $space space, $neyes eyes at 2 to 5 bounding radii (kref's model views), $target"
printf '%-22s %12s %14s %8s %12s\n' kernel "given up" "back or front" culls "dispatch ms"
for k in plain off on again; do
    if [ "$target" = glsl ]; then
        glslangValidator -S comp -V "$tmp/$k.src" -o "$tmp/$k.spv" >/dev/null || exit 1
        host=("$B/host_vulkan" "$tmp/$k.spv")
    else
        host=("$B/host_opencl" "$tmp/$k.src" --kernel sl_classify)
    fi
    "${host[@]}" --degree 3 3 --space "$space" --rule strict \
        $([ $k = plain ] || echo --certified) --block-threads "$PQ" --patches-per-block "$Q" \
        --model "$model" "$neyes" 7 --name "$k" >"$tmp/out" 2>&1
    read -r n b s < <(sed -n 's/.*: kernel front \([0-9]*\), back \([0-9]*\), silhouette \([0-9]*\).*/\1 \2 \3/p' "$tmp/out")
    if [ $k = again ]; then # its classes fail the host's checks by design
        echo "patches that take the second look: ${n:-?} of $((${n:-0} + ${b:-0} + ${s:-0}))"
        continue
    fi
    grep -q '^not ok' "$tmp/out" && { grep '^not ok' "$tmp/out"; exit 1; }
    ms=$(sed -n 's/.*patches), \([0-9.]*\) ms in dispatches.*/\1/p' "$tmp/out")
    read -r up total < <(sed -n 's/.*given up \([0-9]*\) of \([0-9]*\) back or front.*/\1 \2/p' "$tmp/out")
    label=$(case $k in plain) echo plain ;; off) echo "certified, float bound" ;; on) echo "certified, second look" ;; esac)
    printf '%-22s %12s %14s %8s %12s\n' "$label" "${up:-0}" "${total:--}" $((${n:-0} + ${b:-0})) "$ms"
done
