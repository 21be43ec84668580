#!/usr/bin/env bash
# second_look.sh: what the GPU certified kernel's second look in double-float recovers, on lavapipe:
# the world-space bicubic GLSL kernel over BigGuy, plain, certified with the float bound alone
# (the second look switched off) and certified, with the culls given up and the dispatch time.
#   bash bench/second_look.sh BUILD [NEYES [SPACE]]   (BUILD holds ptpgen and host_vulkan; default 24 world)
set -u
B=$1 neyes=${2:-24} space=${3:-world}
. bench/gpu_lib.sh
"$B/ptpgen" --degree 3 --space "$space" --target glsl -o "$tmp/plain.comp" &&
    "$B/ptpgen" --degree 3 --space "$space" --certified --target glsl -o "$tmp/on.comp" || exit 1
sed 's/bool again = live &&/bool again = false \&\& live \&\&/' "$tmp/on.comp" >"$tmp/off.comp"
echo "BigGuy, $space space, $neyes eyes at 2 to 5 bounding radii (kref's model views), GLSL on lavapipe"
printf '%-22s %12s %14s %12s\n' kernel "given up" "back or front" "dispatch ms"
for k in plain off on; do
    glslangValidator -V "$tmp/$k.comp" -o "$tmp/$k.spv" >/dev/null || exit 1
    "$B/host_vulkan" "$tmp/$k.spv" --degree 3 3 --space "$space" --rule strict \
        $([ $k = plain ] || echo --certified) --block-threads "$PQ" --patches-per-block "$Q" \
        --model "$models/bigguy.bez" "$neyes" 7 --name "$k" >"$tmp/out" 2>&1
    grep -q '^not ok' "$tmp/out" && { grep '^not ok' "$tmp/out"; exit 1; }
    ms=$(sed -n 's/.*patches), \([0-9.]*\) ms in dispatches.*/\1/p' "$tmp/out")
    read -r up total < <(sed -n 's/.*given up \([0-9]*\) of \([0-9]*\) back or front.*/\1 \2/p' "$tmp/out")
    label=$(case $k in plain) echo plain ;; off) echo "certified, float bound" ;; on) echo "certified, second look" ;; esac)
    printf '%-22s %12s %14s %12s\n' "$label" "${up:-0}" "${total:--}" "$ms"
done
