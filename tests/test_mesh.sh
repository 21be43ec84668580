#!/usr/bin/env bash
# test_mesh.sh: the degree-1 triangle header's classify_mesh and classify_clusters, run by
# tests/host_mesh.c (C and C++) on indexed meshes against classify, kref and a loop; mutants fail.
# Needs PTPGEN and build/<cc>/libptptest.a for each C compiler.
set -u
P=${PTPGEN:?set PTPGEN}
. "$(dirname "$0")/host_lib.sh"
make_tmp

# host CC FLAGS OPTIONS [SED]: builds host_mesh around `ptpgen --domain triangle --degree 1
# --target c OPTIONS` (edited by sed script SED when given) into $tmp/hm; returns the status.
host() {
    local x=
    case $1 in *++) x="-x c++" ;; esac
    "$P" --domain triangle --degree 1 --target c $3 --prefix ptp_tri1_ -o "$tmp/m.h" || return 1
    [ -n "${4:-}" ] && sed -i "$4" "$tmp/m.h"
    $1 $2 -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$tmp/m.h" -DPTP_TRI1_IMPLEMENTATION \
        -DPFX=ptp_tri1_ -DUPFX=PTP_TRI1_ $x tests/host_mesh.c -x none "build/$5/libptptest.a" -lm \
        -o "$tmp/hm" 2>"$tmp/err"
}

# The fused kernel: AVX-512 where the CPU has it (-march=native, and -mavx512f alone), AVX with
# -mavx2 -mfma (8 wide, then 4, then 1 in blocks of 21; patch-local coordinates take the FMA).
avx512=
grep -qw avx512f /proc/cpuinfo 2>/dev/null && avx512="gcc:gcc:-std=c11 -mavx512f"
[ -z "$avx512" ] && echo "# skip: the fused AVX-512 kernel (this CPU has no AVX-512)"

# The variants of the header, each with gcc and clang as built for speed and as plain C, and
# from C++; certified ones on more exact (integer, adversarial) data.
for cfg in "clip strict" "clip degenerate" "world strict" "world degenerate" "clip strict --certified" \
    "world strict --certified"; do
    set -- $cfg
    opts="--space $1 --rule $2 ${3:-}"
    data="--random 2 3000 17 --exact 5 2000 19"
    [ -n "${3:-}" ] && data="--random 1 3000 17 --exact 10 20000 23"
    # gathers: the fused kernel (certified: the gathers into classify_soa) of AVX-512 or AVX2 with
    # -march=native and of AVX (8 wide, then 4, then 1 in blocks of 21), SSE2 (4, then 1 in blocks
    # of 5), scalar
    for build in ${avx512:+"$avx512"} "gcc:gcc:-std=c11" "gcc:gcc:-std=c11 -march=native" "gcc:gcc:-std=c11 -mavx2 -mfma -DPTP_TRI1_MESH_LANES=21" \
        "gcc:gcc:-std=c11 -DPTP_TRI1_MESH_LANES=5" "gcc:gcc:-std=c11 -DPTP_TRI1_NO_VECTOR -DPTP_TRI1_NO_SSE" \
        "clang:clang:-std=c11 -O3 -march=native" "g++:gcc:-std=c++11" "g++:gcc:-std=c++17 -march=native" \
        "clang++:clang:-std=c++20 -march=native"; do
        IFS=: read -r cc lib flags <<<"$build"
        command -v $cc >/dev/null || { missing $cc "mesh entry points with $cc"; continue; }
        name="mesh $1 $2${3:+ $3} ($cc $flags)"
        if host $cc "$flags" "$opts" "" $lib; then
            run_host "$name" "$tmp/hm" --degree 1 1 --domain triangle --space $1 --rule $2 ${3:-} $data --name "$name"
        else
            notok "$name compiles" "$(grep -m3 error "$tmp/err")"
        fi
    done
done

# mutant NAME FLAGS SED LINE: a header edited by SED, built with gcc FLAGS, must fail with the
# check line LINE.
mutant() {
    if host gcc "-std=c11 $2" "--space clip --rule strict" "$3" gcc &&
        ! "$tmp/hm" --degree 1 1 --domain triangle --space clip --rule strict --random 2 3000 5 --exact 5 1000 3 \
            --name mutant >"$tmp/out" 2>&1 && grep -q "^not ok - mutant $4" "$tmp/out"; then
        ok "$1 fails"
    else
        notok "$1 fails" "it passed: $(grep -m2 '^not ok' "$tmp/out" 2>/dev/null)"
    fi
}
# every gather (SSE2 and scalar; the fused kernel or AVX2 with -march=native) takes vertex
# (3 - k) % 3
swap='s|3 \* (l + (size_t)i) + k|3 * (l + (size_t)i) + (3 - k) % 3|g; s|vertices\[ix\[3 \* l + k\]\]\[c\]|vertices[ix[3 * l + (3 - k) % 3]][c]|'
swap="$swap; s|ix + 3 \\* l + k)|ix + 3 * l + (3 - k) % 3)|; s|indices + 3 \\* l + 1)|indices + 3 * l + 9)|"
swap="$swap; s|indices + 3 \\* l + 2)|indices + 3 * l + 1)|; s|indices + 3 \\* l + 9)|indices + 3 * l + 2)|"
for flags in "" "-mavx2" "-march=native"; do
    mutant "a mesh header that gathers a triangle's vertices 1 and 2 swapped${flags:+ ($flags)}" "$flags" "$swap" \
        "classify_mesh equals classify"
done
mutant "a mesh header whose cluster is back when any triangle is" "" \
    's|((all \& 1u) + 2u \* (1u - (all \& 1u))|((any \& 1u) + 2u * (1u - (any \& 1u))|' \
    "classify_clusters equals the loop"
# the fused kernel (AVX-512, and AVX with -mavx2) with an FMA in the value (rounds differently:
# collapsed triangles get nonzero values), and with a zero value called back
for isa in "avx512f:_mm512:_mm512_set1_epi32(1)" "avx2:_mm256:_mm256_set1_ps(-1.0f)"; do
    IFS=: read -r cpu v one <<<"$isa"
    grep -qw $cpu /proc/cpuinfo 2>/dev/null || { echo "# skip: fused $cpu kernel mutants (no $cpu)"; continue; }
    mutant "a fused $cpu mesh kernel that contracts a product into an FMA" "-m$cpu -mfma" \
        "s|${v}_sub_ps(${v}_mul_ps(g0, m1_2), ${v}_mul_ps(g1, m0_2))|${v}_fmsub_ps(g0, m1_2, ${v}_mul_ps(g1, m0_2))|" \
        "classify_mesh equals classify"
    mutant "a fused $cpu mesh kernel that calls a zero value back" "-m$cpu -mfma" \
        "s|_CMP_LT_OQ), $one|_CMP_LE_OQ), $one|" "classify_mesh equals classify"
done

# A dense mesh: the knot (bench/mkmodel.c) tessellated 8 x 8 a patch (368,640 triangles, welded by
# bench/tess.c) from 40 eyes at 1.2 to 5 bounding radii, every triangle called back or front
# against its exact sign (tests/dense_mesh.c). Patch-local coordinates (the default) must call no
# front-facing triangle back, alone or in a back cluster; the absolute coordinates must (the
# check can fail: about 250 such triangles in 14.7 million triangle-views).
knot=build/models/knot.bez
[ -e $knot ] || make -s $knot >/dev/null 2>&1 || notok "dense mesh" "make $knot failed"
dense() { # COORDINATES FLAGS: builds and runs dense_mesh; its output in $tmp/dense
    "$P" --domain triangle --degree 1 --target c --space world --coordinates $1 --prefix dm_ -o "$tmp/dm.h" &&
        gcc -std=c11 -O2 $2 -Wall -Wextra -Werror -pedantic -Igen -Itests -Ibench -include "$tmp/dm.h" \
            -DDM_IMPLEMENTATION -c tests/dense_mesh.c -o "$tmp/dm.o" 2>"$tmp/err" &&
        gcc -std=c11 -O2 -Ibench "$tmp/dm.o" bench/bezfile.c bench/exact.c bench/tess.c bench/cones.c -lm \
            -o "$tmp/dm" 2>>"$tmp/err" && "$tmp/dm" $knot 8 40 3 "dense knot, $1 coordinates${2:+ ($2)}" >"$tmp/dense"
}
for flags in "" "-march=native"; do
    dense local "$flags"
    cat "$tmp/dense"
    grep -q '^ok - dense knot' "$tmp/dense" || notok "dense knot, local coordinates${flags:+ ($flags)}" "$(head -3 "$tmp/err")"
done
if ! dense absolute "" && grep -q '^not ok - dense knot' "$tmp/dense"; then
    ok "dense knot, absolute coordinates: front-facing triangles called back ($(sed -n 's/^not ok - [^:]*: //p' "$tmp/dense"))"
else
    notok "dense knot, absolute coordinates calls front-facing triangles back" "$(cat "$tmp/dense" "$tmp/err" | head -3)"
fi
