#!/usr/bin/env bash
# test_indexed.sh: --kernel indexed, the straight-line kernel that reads each patch's points from
# a vertex buffer through indices (and, with --basis bspline, OpenSubdiv's boundary masks). Every
# GPU target's kernel compiles (GLSL and HLSL through glslangValidator and spirv-val, OpenCL on
# PoCL, CUDA with nvcc, WGSL with wgpu-native); the GLSL and HLSL kernels run on lavapipe
# (tests/host_indexed.c) on the teapot's own indices against the C header's classify_indexed, and a
# kernel reading a wrong index must fail; the host header's slots; the misuses are usage errors.
# OpenSubdiv's patches run in test_osd.sh. Needs PTPGEN.
set -u
P=${PTPGEN:?set PTPGEN}
. "$(dirname "$0")/host_lib.sh"
make_tmp
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
export POCL_CACHE_DIR=$PWD/build/cache/pocl MESA_SHADER_CACHE_DIR=$PWD/build/cache/mesa
mkdir -p "$POCL_CACHE_DIR" "$MESA_SHADER_CACHE_DIR"
NVCC=${NVCC:-/usr/local/cuda/bin/nvcc}
PY=${PTP_VENV:-build/venv}/bin/python
have_spirv=1
for tool in glslangValidator spirv-val; do
    command -v $tool >/dev/null || { missing $tool "indexed GLSL and HLSL kernels"; have_spirv=0; }
done

# A compile-only OpenCL host: builds the program on the first platform (PoCL) and finds the kernel.
cat >"$tmp/clb.c" <<'C'
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char **argv)
{
    static char src[1 << 23], log[4096];
    const char *s = src;
    cl_platform_id pf;
    cl_device_id dev;
    cl_int e;
    FILE *f = fopen(argv[1], "rb");
    if (argc != 3 || !f || (fread(src, 1, sizeof src - 1, f), fclose(f)) || clGetPlatformIDs(1, &pf, NULL) ||
        clGetDeviceIDs(pf, CL_DEVICE_TYPE_ALL, 1, &dev, NULL))
        return 2;
    cl_context c = clCreateContext(NULL, 1, &dev, NULL, NULL, &e);
    cl_program p = clCreateProgramWithSource(c, 1, &s, NULL, &e);
    e = clBuildProgram(p, 1, &dev, "", NULL, NULL);
    clGetProgramBuildInfo(p, dev, CL_PROGRAM_BUILD_LOG, sizeof log, log, NULL);
    if (e == CL_SUCCESS)
        clCreateKernel(p, argv[2], &e);
    printf("%s\n", log);
    return e != CL_SUCCESS;
}
C
have_cl=0
gcc -std=c11 -O2 "$tmp/clb.c" -lOpenCL -o "$tmp/clb" 2>/dev/null && have_cl=1 || missing "OpenCL (headers, ICD loader)" "indexed OpenCL kernels"
# A compile-only WGSL host: wgpu-native's shader module and compute pipeline (naga's validation).
have_wgpu=0
"$PY" -c 'import wgpu' 2>/dev/null && have_wgpu=1 || missing "wgpu-native (tests/deps.sh)" "indexed WGSL kernels"
cat >"$tmp/wgsl_build.py" <<'PY'
import sys, wgpu
d = wgpu.utils.get_default_device()
m = d.create_shader_module(code=open(sys.argv[1]).read())
d.create_compute_pipeline(layout="auto", compute={"module": m, "entry_point": "main"})
PY
[ -x "$NVCC" ] || missing nvcc "indexed CUDA kernels"

# compiles NAME: $tmp/NAME.{comp,hlsl,cl,cu,wgsl} (prefix ix_) with each target's compiler.
compiles() {
    local n=$1 what="--kernel indexed $2"
    if [ $have_spirv = 1 ]; then
        glslangValidator -V "$tmp/$n.comp" -o "$tmp/$n.spv" >"$tmp/err" && spirv-val "$tmp/$n.spv" 2>>"$tmp/err" &&
            ok "GLSL $what compiles and validates" || notok "GLSL $what compiles" "$(grep -m3 ERROR "$tmp/err")"
        glslangValidator -D -V -S comp -e main "$tmp/$n.hlsl" -o "$tmp/$n.h.spv" >"$tmp/err" &&
            spirv-val "$tmp/$n.h.spv" 2>>"$tmp/err" && ok "HLSL $what compiles and validates" ||
            notok "HLSL $what compiles" "$(grep -m3 ERROR "$tmp/err")"
    fi
    [ $have_cl = 1 ] && { "$tmp/clb" "$tmp/$n.cl" ix_classify >"$tmp/err" 2>&1 &&
        ok "OpenCL $what builds on PoCL" || notok "OpenCL $what builds on PoCL" "$(grep -m3 error "$tmp/err")"; }
    [ -x "$NVCC" ] && { "$NVCC" -ptx "$tmp/$n.cu" -o "$tmp/$n.ptx" 2>"$tmp/err" && grep -q '\.entry ix_classify' "$tmp/$n.ptx" &&
        ok "CUDA $what compiles with nvcc" || notok "CUDA $what compiles with nvcc" "$(grep -m3 error "$tmp/err")"; }
    [ $have_wgpu = 1 ] && { "$PY" "$tmp/wgsl_build.py" "$tmp/$n.wgsl" >"$tmp/err" 2>&1 &&
        ok "WGSL $what builds with wgpu-native" || notok "WGSL $what builds with wgpu-native" "$(tail -5 "$tmp/err")"; }
    return 0
}
for cfg in "bz:--degree 3" "bs:--degree 3 --basis bspline --order v-major --space world --planes" \
    "tri:--domain triangle --degree 2 --rule degenerate"; do
    n=${cfg%%:*} o=${cfg#*:}
    for t in glsl:comp hlsl:hlsl opencl:cl cuda:cu wgsl:wgsl; do
        "$P" $o --target ${t%%:*} --kernel indexed --prefix ix_ -o "$tmp/$n.${t#*:}" ||
            notok "ptpgen $o --target ${t%%:*} --kernel indexed" "it failed"
    done
    compiles $n "$o"
done

# The host header's slots: the indices at 4 (OpenCL, CUDA: argument 5), the boundary masks at 5
# (argument 6) only with --basis bspline; the others as in the default kernel.
hh() { "$P" --degree 3 --target $1 --kernel indexed --prefix ix_ ${2:-} -o "$tmp/h.k" --host-header "$tmp/h.h" && cat "$tmp/h.h"; }
if hh glsl | grep -q '^#define IX_BINDING_INDICES 4 ' && ! hh glsl | grep -q BOUNDARY &&
    hh glsl "--basis bspline" | grep -q '^#define IX_BINDING_BOUNDARY 5 ' && hh glsl | grep -q '^#define IX_BINDING_POINTS 0 ' &&
    hh hlsl "--basis bspline" | grep -q '^#define IX_REGISTER_BOUNDARY 5 .*t5' && hh wgsl | grep -q '^#define IX_BINDING_INDICES 4 ' &&
    hh opencl "--basis bspline" | grep -q '^#define IX_ARG_BOUNDARY 6 ' && hh cuda | grep -q '^#define IX_ARG_INDICES 5 ' &&
    "$P" --degree 3 --target glsl --host-header "$tmp/d.h" -o "$tmp/d.comp" && ! grep -q INDICES "$tmp/d.h"; then
    ok "the host headers of --kernel indexed declare the indices at 4 (argument 5), the boundary masks at 5 (6)"
else
    notok "the host headers of --kernel indexed declare their slots" "$(grep -E 'INDICES|BOUNDARY' "$tmp/h.h")"
fi

# The teapot (collapsed edges) and the knot, with their own indices, on lavapipe: GLSL and HLSL.
bez_runs() {
    local lang=$1 spv=$2 m
    for m in models/teapot.bez build/models/knot.bez; do
        [ -e "$m" ] || { missing "$m (make build/models/knot.bez)" "the indexed kernel on $m"; continue; }
        mkdir -p "$tmp/$(basename $m)"
        "$tmp/indexed_bez" "$m" 12 7 "$tmp/$(basename $m)" &&
            run_host "$lang indexed $m" "$tmp/host_indexed_$lang" "$spv" "$tmp/$(basename $m)" \
                "$lang --kernel indexed on $m's indices = classify_indexed"
    done
}
if [ $have_spirv = 0 ] || [ ! -e /usr/include/vulkan/vulkan.h ]; then
    missing "glslangValidator and the Vulkan headers" "the indexed kernels on lavapipe"
elif "$P" --degree 3 --space world --target c --prefix bz_ -o "$tmp/bz.h" &&
    gcc -std=c11 -O2 -Wall -Wextra -Werror -pedantic -Ibench -I"$tmp" tests/indexed_bez.c bench/bezfile.c -lm \
        -o "$tmp/indexed_bez" 2>"$tmp/err"; then
    for lang in glsl hlsl; do
        mkdir -p "$tmp/$lang"
        ext=comp
        [ $lang = hlsl ] && ext=hlsl
        if "$P" --degree 3 --space world --target $lang --kernel indexed --prefix ix_ -o "$tmp/$lang/ix.$ext" \
            --host-header "$tmp/$lang/ix_host.h" && glslangValidator -V $([ $lang = hlsl ] && echo -D -S comp -e main) \
            "$tmp/$lang/ix.$ext" -o "$tmp/$lang/ix.spv" >"$tmp/err" &&
            gcc -std=c11 -O2 -Wall -Wextra -Werror -pedantic -I"$tmp/$lang" tests/host_indexed.c -lvulkan \
                -o "$tmp/host_indexed_$lang" 2>>"$tmp/err"; then
            bez_runs $lang "$tmp/$lang/ix.spv"
        else
            notok "$lang --kernel indexed and tests/host_indexed.c build" "$(grep -m3 -i error "$tmp/err")"
        fi
    done
    # A kernel that reads point 1 of each patch from index 2 must fail.
    sed 's/+ 1u\]\];/+ 2u]];/' "$tmp/glsl/ix.comp" >"$tmp/m.comp"
    if ! cmp -s "$tmp/m.comp" "$tmp/glsl/ix.comp" && glslangValidator -V "$tmp/m.comp" -o "$tmp/m.spv" >/dev/null &&
        [ -x "$tmp/host_indexed_glsl" ] && ! "$tmp/host_indexed_glsl" "$tmp/m.spv" "$tmp/teapot.bez" mutant >"$tmp/out" 2>&1 &&
        grep -q '^not ok - mutant: ' "$tmp/out"; then
        ok "an indexed GLSL kernel reading a wrong index fails ($(grep -o '[0-9]* differ' "$tmp/out"))"
    else
        notok "an indexed GLSL kernel reading a wrong index fails" "$(cat "$tmp/out" 2>/dev/null)"
    fi
else
    notok "tests/indexed_bez.c builds" "$(grep -m3 error "$tmp/err")"
fi

# Misuses are usage errors (exit 2), with no output file.
for bad in "--target glsl --kernel indexed --stage function" "--target cuda --kernel indexed --certified" \
    "--target c --kernel indexed" "--target glsl --kernel indexed --threads-per-patch 4" "--target glsl --kernel index"; do
    "$P" --degree 3 $bad -o "$tmp/none" 2>"$tmp/err"
    rc=$?
    [ $rc = 2 ] && [ ! -e "$tmp/none" ] && ok "ptpgen $bad: usage error ($(head -1 "$tmp/err"))" ||
        notok "ptpgen $bad is a usage error" "exit $rc: $(head -1 "$tmp/err")"
done
