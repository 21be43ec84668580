#!/usr/bin/env bash
# test_examples.sh: the README's examples (tests/examples/) compile and run: cull.c with gcc and
# clang on the generated knot (build/models/knot.bez) against world space, cull.tesc with
# glslangValidator, and the shaders that cull their own patch (cull_patch.tesc, the hull shader
# cull_patch.hlsl) on --stage function's files with glslangValidator; the README shows them
# verbatim. The Direct3D 11 compute pass d3d11_cull.cpp compiles and links with mingw-w64.
# Needs PTPGEN (default build/gcc/ptpgen).
set -u
P=${PTPGEN:-build/gcc/ptpgen}
model=build/models/knot.bez # bench/mkmodel.c
[ -e $model ] || make -s $model >/dev/null 2>&1 || echo "not ok - the model: make $model failed"
ex=tests/examples
. tests/host_lib.sh # ok, notok, missing, make_tmp
make_tmp
STD="-std=c11 -O2 -Wall -Wextra -Werror -pedantic"

# in_readme FILE: 0 if README.md contains FILE's whole text verbatim.
in_readme() {
    python3 -c 'import sys; sys.exit(open(sys.argv[1]).read() not in open("README.md").read())' "$1"
}

for f in $ex/cull.c $ex/cull.tesc $ex/cull_patch.tesc $ex/cull_patch.hlsl; do
    if in_readme "$f"; then
        ok "README.md shows $f verbatim"
    else
        notok "README.md shows $f verbatim" "the file's text is not in README.md"
    fi
done
sed '5s/$/ /' $ex/cull.c >"$tmp/changed.c"
if in_readme "$tmp/changed.c"; then
    notok "the verbatim check catches a changed example" "a copy with a trailing blank passed"
else
    ok "the verbatim check catches a changed example"
fi

# build CC SOURCE: compiles SOURCE with tests/examples/check_cull.c into $tmp/run.
build() {
    $1 $STD -I"$tmp" -Ibench -o "$tmp/run" "$2" $ex/check_cull.c bench/bezfile.c -lm 2>"$tmp/err"
}
if ! { "$P" --degree 3 --target c -o "$tmp/ptp_3x3.h" &&
    "$P" --degree 3 --target c --space world --prefix world_ -o "$tmp/world.h" &&
    "$P" --degree 3 --target c --space world --certified --prefix cert_ -o "$tmp/cert.h"; } 2>"$tmp/err"; then
    notok "the example's headers" "$P failed: $(head -1 "$tmp/err")"
elif ! grep -q '_alpha(' "$tmp/ptp_3x3.h"; then
    notok "cull.c compiles" "the header has no alpha helper (ptp_3x3_alpha)"
else
    for cc in gcc clang; do
        command -v $cc >/dev/null || { notok "cull.c with $cc" "$cc is missing"; continue; }
        if build $cc $ex/cull.c; then
            "$tmp/run" "$model" "cull.c ($cc, $STD) on the knot from 8 eyes"
        else
            notok "cull.c compiles with $cc $STD" "$(head -3 "$tmp/err")"
        fi
    done
    # The check must be able to fail: the example with alpha negated culls the front faces.
    sed 's/eye\[2\] = ptp_3x3_alpha/eye[2] = -ptp_3x3_alpha/' $ex/cull.c >"$tmp/negated.c"
    if build gcc "$tmp/negated.c" && ! "$tmp/run" "$model" negated >"$tmp/out" 2>&1 &&
        grep -q '^not ok - negated' "$tmp/out"; then
        ok "cull.c with alpha negated fails the world-space check"
    else
        notok "cull.c with alpha negated fails the world-space check" "$(head -3 "$tmp/out" "$tmp/err")"
    fi
fi

if ! command -v glslangValidator >/dev/null; then
    notok "cull.tesc compiles" "glslangValidator is missing (apt-get install glslang-tools)"
elif glslangValidator -V $ex/cull.tesc -o "$tmp/cull.spv" >"$tmp/err" 2>&1 &&
    { ! command -v spirv-val >/dev/null || spirv-val "$tmp/cull.spv" >>"$tmp/err" 2>&1; }; then
    ok "cull.tesc compiles with glslangValidator -V and validates"
else
    notok "cull.tesc compiles with glslangValidator -V" "$(grep -m3 -i error "$tmp/err")"
fi

# The shaders that cull their own patch, on the functions of --stage function: the GLSL
# tessellation control shader and the HLSL hull shader compile to SPIR-V that validates; a
# functions file with a wrong name does not compile (the include is really used).
stage_shader() { # LABEL FILE FLAGS...: compiles FILE with the functions in $tmp
    local label=$1 f=$2
    shift 2
    if glslangValidator "$@" -I"$tmp" "$f" -o "$tmp/stage.spv" >"$tmp/err" 2>&1 && spirv-val "$tmp/stage.spv" >>"$tmp/err" 2>&1; then
        ok "$label compiles with glslangValidator and validates"
    else
        notok "$label compiles with glslangValidator" "$(grep -m3 -i error "$tmp/err")"
    fi
}
if command -v glslangValidator >/dev/null && command -v spirv-val >/dev/null &&
    "$P" --degree 3 --target glsl --stage function -o "$tmp/ptp_3x3.glsl" &&
    "$P" --degree 3 --target hlsl --stage function -o "$tmp/ptp_3x3.hlsli"; then
    stage_shader "cull_patch.tesc (GLSL tessellation control)" $ex/cull_patch.tesc -V
    stage_shader "cull_patch.hlsl (HLSL hull shader)" $ex/cull_patch.hlsl -D -V -S tesc -e main
    "$P" --degree 3 --target glsl --stage function --certified --prefix ptp_3x3_ -o "$tmp/ptp_3x3.glsl" &&
        "$P" --degree 3 --target hlsl --stage function --certified --prefix ptp_3x3_ -o "$tmp/ptp_3x3.hlsli" &&
        stage_shader "cull_patch.tesc on --certified functions" $ex/cull_patch.tesc -V &&
        stage_shader "cull_patch.hlsl on --certified functions" $ex/cull_patch.hlsl -D -V -S tesc -e main
    "$P" --degree 3 --target glsl --stage function --prefix other_ -o "$tmp/ptp_3x3.glsl"
    if ! glslangValidator -V -I"$tmp" $ex/cull_patch.tesc -o "$tmp/stage.spv" >/dev/null 2>&1; then
        ok "cull_patch.tesc fails to compile without ptp_3x3_classify_patch"
    else
        notok "cull_patch.tesc fails to compile without ptp_3x3_classify_patch" "it compiled"
    fi
else
    notok "the --stage function shaders compile" "glslangValidator, spirv-val or ptpgen failed"
fi

# The Direct3D 11 compute pass, d3d11_cull.cpp, on the HLSL kernel's host header and the C header:
# it compiles and links with mingw-w64 (d3d11.h, libd3d11); running it needs Windows and a GPU.
# The HLSL kernel itself compiles with glslang in test_kernels.sh and test_host_header.sh.
MINGW=x86_64-w64-mingw32-g++-posix
D3D="$MINGW -std=c++17 -O2 -Wall -Wextra -Werror"
d3d11() { # SOURCE: compiles and links SOURCE into $tmp/d3d/d3d11_cull.exe; errors in $tmp/err
    $D3D -I"$tmp/d3d" -o "$tmp/d3d/d3d11_cull.exe" "$1" -ld3d11 2>"$tmp/err"
}
if ! command -v $MINGW >/dev/null; then
    missing "$MINGW (Debian package g++-mingw-w64-x86-64-posix)" "d3d11_cull.cpp compiles and links"
elif ! { mkdir -p "$tmp/d3d" && "$P" --degree 3 --target c -o "$tmp/d3d/ptp_3x3.h" &&
    "$P" --degree 3 --target hlsl -o "$tmp/d3d/ptp_3x3.hlsl" --host-header "$tmp/d3d/ptp_3x3_host.h"; } 2>"$tmp/err"; then
    notok "d3d11_cull.cpp's headers" "$P failed: $(head -1 "$tmp/err")"
else
    if d3d11 $ex/d3d11_cull.cpp && [ -s "$tmp/d3d/d3d11_cull.exe" ]; then
        ok "d3d11_cull.cpp compiles and links with $D3D -ld3d11"
    else
        notok "d3d11_cull.cpp compiles and links with $D3D -ld3d11" "$(grep -m3 -i error "$tmp/err")"
    fi
    # The check must be able to fail: the example's dispatch call misspelled does not compile.
    sed 's/ptp_3x3_dispatch(/ptp_3x3_dispach(/' $ex/d3d11_cull.cpp >"$tmp/d3d/misspelled.cpp"
    if ! d3d11 "$tmp/d3d/misspelled.cpp" && grep -q "ptp_3x3_dispach" "$tmp/err"; then
        ok "d3d11_cull.cpp with the host header's dispatch misspelled fails to compile"
    else
        notok "d3d11_cull.cpp with the host header's dispatch misspelled fails to compile" \
            "$(grep -m1 -i error "$tmp/err" || echo it compiled)"
    fi
fi
