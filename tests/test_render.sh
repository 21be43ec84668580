#!/usr/bin/env bash
# test_render.sh: build/render (`make render`) on lavapipe: culling never changes the image (and
# a broken cull pass does), the ptp kernels' classes (the straight-line compute kernel, the paper's
# table kernel, the TCS that classifies its own patch, the certified kernel) agree with the kernel tests' reference and
# ptpgen's C header, TCONE and NCONE cull what bench/cones.c culls, on the dumped inputs;
# tessellation work drops by exactly the culled share; bad input is one line and exit 1 or 2.
# CC picks the compiler (default gcc). Under CI=true a missing tool is a failure, never a skip.
set -u
cd "$(dirname "$0")/.."
CC=${CC:-gcc}
M=models                    # the teapot
KNOT=build/models/knot.bez  # bench/mkmodel.c's model, in BigGuy's place
path_of() { if [ "$1" = knot ]; then echo $KNOT; else echo $M/$1.bez; fi; }
LVP=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
failed=0

check() { # check OK NAME [DETAIL]
    if [ "$1" = 1 ]; then echo "ok - $2"; else echo "not ok - $2${3:+: $3}"; failed=1; fi
}

missing=""
command -v glslangValidator >/dev/null 2>&1 || missing="$missing glslangValidator"
[ -e /usr/include/vulkan/vulkan.h ] || missing="$missing vulkan.h"
[ -e "$LVP" ] || missing="$missing lavapipe"
if [ -n "$missing" ]; then
    if [ "${CI:-}" = true ]; then
        check 0 "render: the tools are there" "missing:$missing"
        exit 1
    fi
    echo "# skip: render needs$missing"
    exit 0
fi
# Every run on lavapipe, whatever else the machine has: the counts below are lavapipe's.
export VK_ICD_FILENAMES=$LVP

if make -s CC="$CC" render $KNOT >"$T/make.log" 2>&1; then
    check 1 "render: make render builds build/render with $CC"
else
    check 0 "render: make render with $CC" "$(head -5 "$T/make.log" | tr '\n' ' ')"
    exit 1
fi
R=build/render
B=build/$CC
make -s CC="$CC" $B/libptptest.a >"$T/lib.log" 2>&1 &&
    $B/ptpgen --degree 3 --target c --space clip --prefix rc_s_ -o "$T/rc_s.h" &&
    $B/ptpgen --degree 3 --target c --space clip --certified --prefix rc_c_ -o "$T/rc_c.h" &&
    $CC -std=c11 -Wall -Wextra -Werror -pedantic -O2 -Igen -Itests -I"$T" -Ibench -Ibench/render \
        -o "$T/render_check" tests/render_check.c bench/render/bez.c bench/cones.c \
        $B/libptptest.a -lm >"$T/cc.log" 2>&1
check $([ -x "$T/render_check" ] && echo 1 || echo 0) \
    "render: builds tests/render_check.c around ptpgen's clip-space C headers and kref" \
    "$(cat "$T/lib.log" "$T/cc.log" | head -3 | tr '\n' ' ')"

# The value of KEY in an output line.
val() { sed -n "s/.* $2=\([^ ]*\).*/\1/p" <<<" $1"; }

# One view: MODEL EYE UP ORIENTATION. Renders every method, compares, checks the dumps.
view() {
    local model=$1 eye=$2 up=$3 orient=$4 name="$1 eye $2 orientation $4" m line
    local args=(--model "$(path_of $model)" --eye "$eye" --up "$up" --orientation "$orient"
                --tess 4 --size 160x120 --frames 1)
    if ! line=$($R "${args[@]}" --cull none --png "$T/none.png" 2>"$T/err"); then
        check 0 "render: $name, --cull none runs" "$(cat "$T/err")"
        return
    fi
    local patches tes_none covered
    patches=$(val "$line" patches)
    tes_none=$(val "$line" tes_invocations)
    covered=$(python3 tests/render_png.py info "$T/none.png" | cut -d' ' -f3)
    check $([ "${covered:-0}" -gt 1920 ] && echo 1 || echo 0) \
        "render: $name: the image is a valid PNG and the model covers $covered of 19200 pixels"
    check $([ "$tes_none" = $((patches * 25)) ] && [ "$(val "$line" tcs_patches)" = "$patches" ] && echo 1 || echo 0) \
        "render: $name: --cull none tessellates all $patches patches (25 evaluations each at factor 4)" "$line"
    for m in ptp ptp-table ptp-tcs ptp-certified ptp-tcs-certified tcone ncone; do
        if ! line=$($R "${args[@]}" --cull $m --png "$T/$m.png" --dump-clip "$T/$m.dump" 2>"$T/err"); then
            check 0 "render: $name, --cull $m runs" "$(cat "$T/err")"
            continue
        fi
        local culled tes d
        culled=$(val "$line" culled)
        tes=$(val "$line" tes_invocations)
        d=$(python3 tests/render_png.py diff "$T/none.png" "$T/$m.png")
        check $([ "$d" = 0 ] && echo 1 || echo 0) \
            "render: $name: --cull $m (culls $culled of $patches) gives the image of --cull none pixel for pixel" \
            "$d pixels differ"
        check $([ $((tes * patches)) = $((tes_none * (patches - culled))) ] && echo 1 || echo 0) \
            "render: $name: --cull $m: tes_invocations $tes = $tes_none * kept / patches" "$line"
        case $m in
        ptp*) "$T/render_check" $m "$T/$m.dump" "render: $name: --cull $m" ;;
        *) "$T/render_check" $m "$T/$m.dump" "$(path_of $model)" "render: $name: --cull $m" ;;
        esac
        [ $? -le 1 ] || check 0 "render: $name: --cull $m: the checker reads the dump"
    done
    # A broken cull pass (alpha of the wrong sign: it culls front-facing patches) must show.
    line=$($R "${args[@]}" --cull ptp --flip-alpha --png "$T/flip.png" 2>&1)
    d=$(python3 tests/render_png.py diff "$T/none.png" "$T/flip.png")
    check $([ "${d:-0}" -gt 0 ] && echo 1 || echo 0) \
        "render: $name: a cull pass with alpha negated (culls $(val "$line" culled)) changes $d pixels: the equality above can fail" \
        "$line"
}

view knot 0,0,12 0,1,0 out
view knot 9,4,-7 0,1,0 out
view knot -4,-2,5 0,1,0 out
view knot 0,0,12 0,1,0 in
view teapot 8,-6,5 0,0,1 in
view teapot -8,-8,4 0,0,1 in
view teapot -6,3,-4 0,0,1 in

# Bad input: one line on standard error, nothing on standard output, exit 1 (the input) or 2
# (the command line).
bad() { # bad STATUS LABEL ARGS...
    local want=$1 label=$2 rc
    shift 2
    $R "$@" >"$T/out" 2>"$T/err"
    rc=$?
    check $([ $rc = "$want" ] && [ "$(wc -l <"$T/err")" = 1 ] && [ ! -s "$T/out" ] && echo 1 || echo 0) \
        "render: $label: exit $want with one line ($(head -c 100 "$T/err"))" \
        "exit $rc, stderr: $(head -3 "$T/err" | tr '\n' ' ')"
}
ok_args=(--eye 0,0,12 --tess 2 --cull ptp --size 16x16 --frames 1)
printf '1\n1,2,3\n' >"$T/short.bez"
printf '1\n1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16\n1\n0,0,0\n' >"$T/range.bez"
printf '1\n1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1\n1\n0,x,0\n' >"$T/coord.bez"
printf 'many\n' >"$T/count.bez"
: >"$T/empty.bez"
bad 1 "a missing model" --model "$T/none.bez" "${ok_args[@]}"
bad 1 "a short index line" --model "$T/short.bez" "${ok_args[@]}"
bad 1 "an index out of range" --model "$T/range.bez" "${ok_args[@]}"
bad 1 "a malformed coordinate" --model "$T/coord.bez" "${ok_args[@]}"
bad 1 "a malformed patch count" --model "$T/count.bez" "${ok_args[@]}"
bad 1 "an empty file" --model "$T/empty.bez" "${ok_args[@]}"
bad 1 "no such Vulkan device" --model $M/teapot.bez "${ok_args[@]}" --device 99
VK_ICD_FILENAMES=$T/none.json bad 1 "no Vulkan driver" --model $M/teapot.bez "${ok_args[@]}"
bad 2 "--tess 0" --model $M/teapot.bez --eye 0,0,12 --tess 0 --cull ptp
bad 2 "--tess 2x" --model $M/teapot.bez --eye 0,0,12 --tess 2x --cull ptp
bad 2 "--eye with two numbers" --model $M/teapot.bez --eye 0,12 --tess 2 --cull ptp
bad 2 "--size 0x16" --model $M/teapot.bez "${ok_args[@]}" --size 0x16
bad 2 "--cull backface" --model $M/teapot.bez --eye 0,0,12 --tess 2 --cull backface
bad 2 "an unknown option" --model $M/teapot.bez "${ok_args[@]}" --fast
bad 2 "a missing value" --model $M/teapot.bez "${ok_args[@]}" --frames
bad 2 "no --eye" --model $M/teapot.bez --tess 2 --cull ptp
exit $failed
