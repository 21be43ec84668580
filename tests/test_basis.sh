#!/usr/bin/env bash
# test_basis.sh: the input forms --basis bspline and --order v-major. The C headers run on exact
# small-integer data against the default header (tests/basis_check.c: bit for bit), in three of
# the four spaces and rules, with gcc and clang, and classify_indexed_boundary on random masks; a
# header whose B-spline map or phantoms are wrong must fail; --certified headers of both forms
# make no unsafe class on exact data (tests/host_c.c); the GPU targets' code compiles (GLSL
# and HLSL through glslangValidator and spirv-val, CUDA through nvcc where present); the options'
# misuses are usage errors. Needs PTPGEN.
set -u
P=${PTPGEN:?set PTPGEN}
. "$(dirname "$0")/host_lib.sh"
make_tmp

# build CC FLAGS SPACE RULE [SED]: the five headers (bz_ default, vz_ v-major, bs_ B-spline, vs_
# both, ba_ absolute coordinates; the B-spline headers edited by sed script SED when given) and
# basis_check around them.
build() {
    local cc=$1 flags=$2 space=$3 rule=$4 v
    for v in "bz:" "vz:--order v-major" "bs:--basis bspline" "vs:--basis bspline --order v-major" \
        "ba:--coordinates absolute"; do
        "$P" --degree 3 --target c --space $space --rule $rule ${v#*:} --prefix ${v%%:*}_ \
            -o "$tmp/${v%%:*}.h" || return 1
        case $v in bs* | vs*) [ -n "${5:-}" ] && sed -i "$5" "$tmp/${v%%:*}.h" ;; esac
    done
    $cc -std=c11 -O2 $flags -Wall -Wextra -Werror -pedantic -Igen -Itests $([ $space = world ] && echo -DWORLD) \
        -include "$tmp/bz.h" -include "$tmp/vz.h" -include "$tmp/bs.h" -include "$tmp/vs.h" -include "$tmp/ba.h" \
        -DBZ_IMPLEMENTATION -DVZ_IMPLEMENTATION -DBS_IMPLEMENTATION -DVS_IMPLEMENTATION -DBA_IMPLEMENTATION \
        tests/basis_check.c -lm -o "$tmp/bc" 2>"$tmp/err"
}

# Three of the four spaces and rules (the forms change only the loads), each compiler once.
for cfg in "clip strict gcc:" "world degenerate gcc:-march=native" "world strict clang:-march=native"; do
    read -r space rule build <<<"$cfg"
    cc=${build%%:*} flags=${build#*:}
    command -v $cc >/dev/null || { missing $cc "input forms with $cc"; continue; }
    name="$space $rule ($cc${flags:+ $flags})"
    if build $cc "$flags" $space $rule; then
        "$tmp/bc" 2000 $((${#name} + 1)) "$name"
    else
        notok "$name: the input forms' headers compile" "$(grep -m3 error "$tmp/err")"
    fi
done

# A B-spline map with one weight wrong (row 1's 2 a2 taken as 4 a2) must fail.
if build gcc "" clip strict 's/\(bx1 = 4.0f \* hx0_1 + \)2.0f/\14.0f/' && ! "$tmp/bc" 500 3 mutant >"$tmp/out" &&
    grep -q '^not ok - mutant: --basis bspline = ' "$tmp/out"; then
    ok "a header whose B-spline map has a wrong weight fails"
else
    notok "a header whose B-spline map has a wrong weight fails" "$(grep -m2 '^not ok' "$tmp/out" 2>/dev/null)"
fi

# Phantoms extrapolated from the wrong vertex (2 p2 - p2) must fail.
if build gcc "" clip strict 's/2.0f \* cp\[q\[1\]\]/2.0f * cp[q[2]]/' && ! "$tmp/bc" 500 3 mutant >"$tmp/out" &&
    grep -q '^not ok - mutant: classify_indexed_boundary' "$tmp/out"; then
    ok "a header that extrapolates the phantoms from the wrong vertex fails"
else
    notok "a header that extrapolates the phantoms from the wrong vertex fails" "$(grep -m2 '^not ok' "$tmp/out" 2>/dev/null)"
fi

# --certified in the input forms on exact data (tests/host_c.c with HOST_BSPLINE / HOST_VMAJOR:
# the sets' Bezier points given as the B-spline vertices whose Bezier points they are, or
# transposed): never an unsafe class. One space and rule each; v-major Bezier input under the
# degenerate rule reads its collapsed edges through the order.
# cert_host HEADER DEFINES: builds host_c around HEADER (prefix ptp_3x3_).
cert_host() {
    gcc -std=c11 -O2 -march=native -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$1" \
        -DPTP_3X3_IMPLEMENTATION -DPFX=ptp_3x3_ -DUPFX=PTP_3X3_ $2 tests/host_c.c \
        build/gcc/libptptest.a -lm -o "$tmp/hc" 2>"$tmp/err"
}
for cfg in "clip strict:--basis bspline:-DHOST_BSPLINE" \
    "world degenerate:--basis bspline --order v-major:-DHOST_BSPLINE -DHOST_VMAJOR" \
    "world strict:--basis bspline --order v-major:-DHOST_BSPLINE -DHOST_VMAJOR" \
    "clip degenerate:--order v-major:-DHOST_VMAJOR"; do
    IFS=: read -r sr form defs <<<"$cfg"
    read -r space rule <<<"$sr"
    name="certified $space $rule $form"
    if "$P" --degree 3 --target c --certified --space $space --rule $rule $form --prefix ptp_3x3_ \
        -o "$tmp/c.h" && cert_host "$tmp/c.h" "$defs"; then
        run_host "$name" "$tmp/hc" --degree 3 3 --space $space --rule $rule --certified \
            --exact 4 10000 41 --name "$name"
    else
        notok "$name: the header compiles" "$(grep -m3 error "$tmp/err")"
    fi
done
# A certified B-spline header whose magnitudes ignore the map's weights (1 in place of 36) must
# make unsafe classes on the same data.
if "$P" --degree 3 --target c --certified --basis bspline --prefix ptp_3x3_ -o "$tmp/c.h" &&
    sed -i 's/36\.0001f/0.01f/; s/R \*= 36;/R *= 0.01;/' "$tmp/c.h" && cert_host "$tmp/c.h" -DHOST_BSPLINE &&
    ! "$tmp/hc" --degree 3 3 --space clip --rule strict --certified --exact 4 10000 41 --name mutant >"$tmp/out" &&
    grep -q '^not ok - mutant classify and values: certified: no unsafe class' "$tmp/out"; then
    ok "a certified B-spline header whose bound ignores the map's weights makes unsafe classes"
else
    notok "a certified B-spline header whose bound ignores the map's weights makes unsafe classes" \
        "$(grep -m2 '^not ok' "$tmp/out" 2>/dev/null)"
fi

# The GPU targets' straight-line code in both forms compiles.
for space in clip world; do
    o="--degree 3 --space $space --basis bspline --order v-major"
    if command -v glslangValidator >/dev/null && command -v spirv-val >/dev/null; then
        "$P" $o --target glsl -o "$tmp/k.comp" && glslangValidator -S comp -V "$tmp/k.comp" -o "$tmp/k.spv" >"$tmp/err" &&
            spirv-val "$tmp/k.spv" && ok "GLSL $space: --basis bspline --order v-major compiles and validates" ||
            notok "GLSL $space: --basis bspline --order v-major compiles" "$(grep -m3 ERROR "$tmp/err")"
        "$P" $o --target hlsl -o "$tmp/k.hlsl" && glslangValidator -D -S comp -e main -V "$tmp/k.hlsl" -o "$tmp/h.spv" >"$tmp/err" &&
            spirv-val "$tmp/h.spv" && ok "HLSL $space: --basis bspline --order v-major compiles and validates" ||
            notok "HLSL $space: --basis bspline --order v-major compiles" "$(grep -m3 ERROR "$tmp/err")"
    else
        missing "glslangValidator and spirv-val" "GLSL and HLSL input forms"
    fi
    NVCC=${NVCC:-/usr/local/cuda/bin/nvcc}
    if [ -x "$NVCC" ]; then
        "$P" $o --target cuda -o "$tmp/k.cu" && "$NVCC" -ptx -o "$tmp/k.ptx" "$tmp/k.cu" 2>"$tmp/err" &&
            ok "CUDA $space: --basis bspline --order v-major compiles" ||
            notok "CUDA $space: --basis bspline --order v-major compiles" "$(grep -m3 error "$tmp/err")"
    else
        missing nvcc "CUDA input forms"
    fi
done

# Misuses are usage errors (exit 2), with no output file.
for bad in "--degree 2 --basis bspline" "--domain triangle --degree 3 --order v-major" \
    "--degree 3 --basis bspline --certified --refine 2" "--degree 3 --order v-major --refine 2" \
    "--degree 3 --basis spline" "--degree 3 --order v-first"; do
    "$P" $bad --target c -o "$tmp/none.h" 2>"$tmp/err"
    rc=$?
    [ $rc = 2 ] && [ ! -e "$tmp/none.h" ] && ok "ptpgen $bad: usage error ($(head -1 "$tmp/err"))" ||
        notok "ptpgen $bad is a usage error" "exit $rc: $(head -1 "$tmp/err")"
done
for bad in "--kernel table" "--certified"; do
    "$P" --degree 3 --target glsl --basis bspline $bad >/dev/null 2>&1
    [ $? = 2 ] && ok "--target glsl --basis bspline $bad is a usage error (the table kernel)" ||
        notok "--target glsl --basis bspline $bad is a usage error" "it was accepted"
done
