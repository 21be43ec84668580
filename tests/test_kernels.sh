#!/usr/bin/env bash
# test_kernels.sh: emits every kernel target, compiles it and executes it on this machine, and
# checks values and classes against the double reference (tests/kref.c) through the hosts; the
# certified kernels are test_certified.sh's. Needs PTPGEN (the generator under test), BUILD (the
# folder with the OpenCL and Vulkan hosts) and build/<cc>/libptptest.a for each C compiler.
set -u
. tests/kernels_lib.sh

# data_args DEGREE: the patch sets of a configuration: 10,000 random patches, and for bicubic
# each model with random eyes (one host run per line).
data_args() {
    echo "--random 1 10000 $seed"
    if [ "$1" = 3x3 ]; then
        for f in $(model_files); do
            echo "--model $f 6 $seed"
        done
    fi
}

# exercise_run TARGET HOST...: exercise's configuration (its $d, $hcfg, $pl and $label) through
# HOST on each patch set of data_args; WGSL on exact data too (collapsed edges: exact zeros).
exercise_run() {
    local target=$1 data
    shift
    data_args $d | while read -r data; do
        if [ $target = wgsl ]; then
            [ "${data%% *}" = --random ] && data="$data --exact 10 200 $seed"
            # A 4x4 WGSL kernel takes about 1 ms a patch on lavapipe: a tenth of the patches.
            [ $d = 4x4 ] && data=${data/--random 1 10000/--random 1 1000} && data=${data/--exact 10 200/--exact 10 20}
        fi
        run_host "$target $label" "$@" $hcfg $pl $data --name "$target $label ${data%% *}"
    done
}

# exercise DIR D SPACE RULE PLANES LABEL [GPU]: compiles the kernels DIR/ptp_D.{h,cl,comp,hlsl,cu,wgsl}
# (degree D as degree_args takes it, default names) and runs each on the data of data_args against
# the reference; with GPU, the GPU kernels alone (the C header is another configuration's).
exercise() {
    local dir=$1 d=$2 pl="" label=$6 cc data
    local hcfg="$(host_degree $2) --space $3 --rule $4"
    [ "$5" = 1 ] && pl=--planes

    # C, with gcc and clang.
    for cc in gcc clang; do
        [ -z "${7:-}" ] || break
        command -v $cc >/dev/null || continue
        if build_host_c $cc -O2 "$dir/ptp_$d.h" $d; then
            data_args $d | while read -r data; do
                run_host "c $label ($cc)" "$tmp/host_c" $hcfg $data --name "c/$cc $label ${data%% *}"
            done
        else
            notok "c $label compiles with $cc" "$(head -5 "$tmp/err")"
        fi
    done
    gpu_runtimes exercise_run "$dir" $d "$label"
}

# Freshly generated kernels, with --planes: every degree (triangles too), space and rule of the
# matrix, in both GPU forms: the straight-line kernel and the paper's table kernel. The table
# kernel runs on two corners of the matrix, clip strict and world degenerate, on the GPU runtimes
# only (the C header does not depend on the GPU form: the straight-line configuration runs it).
# The biquartic (4x4) straight-line code, minutes of compilation on every runtime, runs once: the
# vendored out/4x4 below (clip strict; the writer is the same for every degree and space). Its
# table kernels, half a minute to a minute of compilation each on lavapipe, run on the clip strict
# corner alone.
seed=1
mkdir -p "$tmp/gen"
fresh="1x1 2x2 3x3 4x4 2x3 3x1 tri1 tri2 tri3"
for d in $fresh; do
    for space in clip world; do
        for rule in strict degenerate; do
            for kernel in slp table; do
                if [ $kernel = table ]; then
                    [ $space/$rule = clip/strict ] || [ $space/$rule = world/degenerate ] || continue
                    [ $d = 4x4 ] && [ $space/$rule != clip/strict ] && continue
                elif [ $d = 4x4 ]; then
                    continue
                fi
                seed=$((seed + 1))
                for te in $files; do
                    "$P" $(args_for ${te%%:*} $d $space $rule --planes --kernel=$kernel) --target ${te%%:*} \
                        -o "$tmp/gen/ptp_$d${te#*:}" || notok "$d $space $rule $kernel ${te%%:*}" "ptpgen failed"
                done
                exercise "$tmp/gen" $d $space $rule 1 "$d $space $rule $kernel" $([ $kernel = table ] && echo gpu)
            done
        done
    done
done

# The vendored kernels in out/ (clip space, strict rule, no values), exactly like fresh ones. Their
# C headers are the generator's bytes (test_cli regenerates out/) but for the banner: the fresh
# clip strict configuration above ran them, except 4x4's (no fresh straight-line 4x4) and those
# of degrees it has not.
for dir in out/*x*/ out/tri*/; do
    d=$(basename "$dir")
    seed=$((seed + 1))
    case " $fresh " in *" $d "*) [ $d != 4x4 ] && gpu=gpu || gpu="" ;; *) gpu="" ;; esac
    exercise "out/$d" $d clip strict 0 "vendored out/$d" $gpu
done

# OpenCL's --kernel lanes (16 patches a work-item in float16 vectors, for CPU devices) on PoCL:
# both spaces and rules, quads and triangles, patch-local and absolute coordinates, random
# patches (and for bicubic the models) against the reference, a workgroup of 32 patches and a
# patch count that leaves spare lanes; a kernel with one term's sign flipped must fail its check.
if [ -x "$B/host_opencl" ]; then
    for cfg in "3x3 clip strict" "3x3 world degenerate" "2x3 world strict --coordinates absolute" \
        "tri2 clip degenerate --patches-per-block 32"; do
        read -r d space rule extra <<<"$cfg"
        if "$P" $(degree_args $d) --target opencl --space $space --rule $rule --kernel lanes \
            --prefix ptp_${d}_ ${extra:-} -o "$tmp/l.cl"; then
            data="--random 1 4999 $((++seed))"
            [ $d = 3x3 ] && data="$data $(model_files | sed 's/^/--model /; s/$/ 3 7/' | tr '\n' ' ')"
            run_host "opencl lanes $cfg" "$B/host_opencl" "$tmp/l.cl" --kernel ptp_${d}_classify \
                $(host_degree $d) --space $space --rule $rule $(host_sched "$tmp/l.cl") $data \
                --name "opencl lanes $d $space $rule${extra:+ $extra}"
        else
            notok "opencl --kernel lanes $cfg" "ptpgen failed"
        fi
    done
    "$P" --degree 3 --target opencl --kernel lanes -o "$tmp/l.cl" && sed -i '0,/u = -((/s//u = ((/' "$tmp/l.cl"
    if grep -q 'u = ((' "$tmp/l.cl" && ! "$B/host_opencl" "$tmp/l.cl" --kernel ptp_3x3_classify --degree 3 3 \
        --space clip --rule strict $(host_sched "$tmp/l.cl") --random 1 2000 5 --name mutant >"$tmp/out" 2>&1 &&
        grep -q '^not ok - mutant: .*classes agree' "$tmp/out"; then
        ok "an OpenCL lanes kernel with one term's sign flipped fails its check"
    else
        notok "an OpenCL lanes kernel with one term's sign flipped fails its check" "it passed, or the term was not found"
    fi
fi

# Patch-local coordinates on the GPU. On the far model (the knot's patches split 16 ways, 2^14
# times their size from the origin; clip space, where the double reference is accurate),
# every plane value of the plain table kernel and of the straight-line kernel on PoCL stays within
# the bound of patch-local coordinates (--local-bound); the table kernel with --coordinates
# absolute must exceed it. (OpenCL's fma rounds once, as the bound assumes; lavapipe rounds GLSL's
# fma as a product and a sum, so there the shear rounds relative to o w, not to the sheared value,
# and its values exceed the local bound too, though 200 times less than in absolute coordinates.)
far=build/models/far.bez
[ -e $far ] || make -s $far >/dev/null 2>&1 || notok "the far model" "make $far failed"
if [ -x "$B/host_opencl" ]; then
    for k in table slp "table --coordinates absolute"; do
        name="far model, opencl --kernel $k, within the local coordinates' bound"
        if ! "$P" --degree 3 --target opencl --space clip --planes --kernel $k --prefix ptp_3x3_ \
            -o "$tmp/f.cl"; then
            notok "$name" "ptpgen failed"
            continue
        fi
        cmd=("$B/host_opencl" "$tmp/f.cl" --kernel ptp_3x3_classify --degree 3 3 --space clip
            --rule strict $(host_sched "$tmp/f.cl") --planes --local-bound --model $far 2 7 --name "$name")
        case $k in
        *absolute)
            if ! "${cmd[@]}" >"$tmp/out" 2>&1 && grep -q '^not ok - .*plane values within' "$tmp/out"; then
                ok "far model, opencl --kernel $k: the values exceed the local coordinates' bound"
            else
                notok "far model, opencl --kernel $k: the values exceed the local coordinates' bound" \
                    "they did not, or the host failed otherwise"
            fi ;;
        *) run_host "$name" "${cmd[@]}" ;;
        esac
    done
fi

# Without --planes the kernels write only the classes (OpenCL gets a null planes pointer).
"$P" --degree 3 --target opencl --kernel table -o "$tmp/k.cl" && [ -x "$B/host_opencl" ] &&
    run_host "opencl without --planes" "$B/host_opencl" "$tmp/k.cl" --kernel ptp_3x3_classify --degree 3 3 \
        --space clip --rule strict --block-threads 128 --patches-per-block 8 --random 1 10000 99 --name "opencl 3x3 table without --planes"
if [ $have_gpu_tools = 1 ] && [ -x "$B/host_vulkan" ]; then
    "$P" --degree 3 --target glsl --kernel table -o "$tmp/k.comp" && to_spirv glsl "$tmp/k" &&
        run_host "glsl without --planes" "$B/host_vulkan" "$tmp/k.spv" --degree 3 3 --space clip --rule strict \
            --block-threads 128 --patches-per-block 8 --random 1 10000 99 --name "glsl 3x3 table without --planes"
    "$P" --degree 3 --target hlsl --kernel table -o "$tmp/k.hlsl" && to_spirv hlsl "$tmp/k" &&
        run_host "hlsl without --planes" "$B/host_vulkan" "$tmp/k.spv" --degree 3 3 --space clip --rule strict \
            --block-threads 128 --patches-per-block 8 --groups-x-constant --random 1 10000 99 --name "hlsl 3x3 table without --planes"
    # A non-default straight-line workgroup: 7 patches.
    "$P" --degree 2x3 --target glsl --space world --planes --patches-per-block 7 -o "$tmp/k.comp" && to_spirv glsl "$tmp/k" &&
        run_host "glsl Q=7" "$B/host_vulkan" "$tmp/k.spv" --degree 2 3 --space world --rule strict --block-threads 7 \
            --patches-per-block 7 --planes --random 1 3000 7 --name "glsl 2x3 world, straight-line, 7 patches per group"
    # A straight-line GLSL kernel with one term's sign flipped must disagree with the reference.
    "$P" --degree 3 --target glsl -o "$tmp/k.comp" && sed -i '0,/u = -((/s//u = ((/' "$tmp/k.comp"
    if grep -q 'u = ((' "$tmp/k.comp" && to_spirv glsl "$tmp/k" &&
        ! "$B/host_vulkan" "$tmp/k.spv" --degree 3 3 --space clip --rule strict --block-threads 64 --patches-per-block 64 \
            --random 1 2000 5 --name mutant >"$tmp/out" 2>&1 && grep -q '^not ok - mutant: .*classes agree' "$tmp/out"; then
        ok "a straight-line GLSL kernel with one term's sign flipped fails its check"
    else
        notok "a straight-line GLSL kernel with one term's sign flipped fails its check" "it passed, or the term was not found"
    fi
    # A non-default table schedule: 7 threads per patch, 5 patches per workgroup.
    "$P" --degree 2x3 --target glsl --space world --planes --kernel table --threads-per-patch 7 --patches-per-block 5 -o "$tmp/k.comp" &&
        to_spirv glsl "$tmp/k" &&
        run_host "glsl P=7 Q=5" "$B/host_vulkan" "$tmp/k.spv" --degree 2 3 --space world --rule strict --block-threads 35 \
            --patches-per-block 5 --planes --random 1 3000 7 --name "glsl 2x3 world, 7 threads per patch, 5 patches per group"
fi

if [ -x "$B/host_wgpu" ]; then
    "$P" --degree 2x3 --target wgsl --space world --planes --kernel table --threads-per-patch 7 --patches-per-block 5 -o "$tmp/k.wgsl" &&
        run_host "wgsl P=7 Q=5" "$B/host_wgpu" "$tmp/k.wgsl" --degree 2 3 --space world --rule strict --block-threads 35 \
            --patches-per-block 5 --planes --random 1 3000 7 --name "wgsl 2x3 world, 7 threads per patch, 5 patches per group"
    # A generated WGSL kernel with one weight's sign flipped must fail its checks.
    "$P" --degree 2 --target wgsl --planes --kernel table -o "$tmp/k.wgsl" && sed -i '0,/ -1.0f,/s// 1.0f,/' "$tmp/k.wgsl"
    if grep -q '^    -0.166666672f, -2.0f, 1.0f,' "$tmp/k.wgsl" &&
        ! "$B/host_wgpu" "$tmp/k.wgsl" --degree 2 2 --space clip --rule strict --block-threads 128 --patches-per-block 16 \
            --planes --random 1 2000 5 --name mutant >"$tmp/out" 2>&1 && grep -q '^not ok - mutant: .*plane values' "$tmp/out"; then
        ok "a 2x2 WGSL kernel with one weight's sign flipped fails its check"
    else
        notok "a 2x2 WGSL kernel with one weight's sign flipped fails its check" "it passed, or the weight was not found"
    fi
fi

# The CUDA emulation can fail: a 2x2 kernel with one weight's sign flipped (its values), and a
# bicubic kernel without one of its two barriers (its classes: without the first, threads read
# points not loaded yet; without the second, thread 0 combines flags not written yet, which only
# blocks that run thread 0 first show, hence the emulation's alternating thread order).
# emu_mutant SED CHECK LABEL ARGS...: the kernel $tmp/m/k.cu edited by SED fails the check lines
# matching CHECK when the emulation runs it with ARGS.
emu_mutant() {
    local sed=$1 check=$2 label=$3
    shift 3
    sed -i "$sed" "$tmp/m/k.cu"
    if ! cmp -s "$tmp/m/k.cu" "$tmp/m/orig.cu" && cuda_emu_host "$tmp/m" $d k.cu &&
        ! "$tmp/host_cuda_emu" "$@" --name mutant >"$tmp/out" 2>&1 && grep -q "^not ok - mutant: $check" "$tmp/out"; then
        ok "$label fails its check (emulated)"
    else
        notok "$label fails its check (emulated)" "it passed, or the mutation was not made"
    fi
}
if [ $have_emu = 1 ]; then
    mkdir -p "$tmp/m"
    d=2x2
    "$P" --degree 2 --target cuda --planes --kernel table -o "$tmp/m/orig.cu" && cp "$tmp/m/orig.cu" "$tmp/m/k.cu"
    emu_mutant '0,/ -1.0f,/s// 1.0f,/' '.*plane values' "a 2x2 CUDA kernel with one weight's sign flipped" \
        --degree 2 2 --space clip --rule strict --block-threads 128 --patches-per-block 16 --planes --random 1 2000 5
    d=3x3
    for n in 1 2; do
        "$P" --degree 3 --target cuda --kernel table -o "$tmp/m/orig.cu" && cp "$tmp/m/orig.cu" "$tmp/m/k.cu"
        emu_mutant "$(awk -v n=$n '/__syncthreads\(\);/ && ++k == n { print NR "d" }' "$tmp/m/orig.cu")" \
            '.*classes agree' "a 3x3 CUDA kernel without barrier $n of 2" --degree 3 3 --space clip --rule strict \
            --block-threads 128 --patches-per-block 8 --random 1 2000 5
    done
fi

# mutant SED CHECK WHAT [FLAGS]: a bicubic C header edited by sed script SED must fail the check
# lines matching CHECK ("not ok - mutant CHECK") when run on random patches (gcc -O2 FLAGS).
mutant() {
    "$P" --degree 3 --target c -o "$tmp/k.h" && sed -i "$1" "$tmp/k.h"
    if build_host_c gcc "-O2 ${4:-}" "$tmp/k.h" 3x3 &&
        ! "$tmp/host_c" --degree 3 3 --space clip --rule strict --random 1 2000 5 --name mutant >"$tmp/out" 2>&1 &&
        grep -q "^not ok - mutant $2" "$tmp/out"; then
        ok "a C header with $3 fails its check"
    else
        notok "a C header with $3 fails its check" "it passed or did not fail by its exit status"
    fi
}
# The checks can fail: the table (values) and the straight-line code (classify) each.
mutant '0,/-9.0f/s//-9.5f/' '.*plane values' "one table weight changed (-9 -> -9.5)"
mutant '0,/u = -((g0 \* m1_5/s//u = ((g0 * m1_5/' 'classify_batch' "one straight-line term's sign flipped"
# (a minor without point 0: in patch-local coordinates point 0 is near the origin, its minors near 0)
mutant '0,/VFMA(g5, m1_4, u)/s//VFMA(g5, -m1_4, u)/' 'classify and values: .*plane values' "one fused plane's minor's sign flipped"
# The strict masks, < made <= (a zero plane counted negative): in vectors (SSE) and, where the CPU
# has AVX-512, in mask registers.
mutant 's/((k) \& ((v) < 0.0f))/((k) \& ((v) <= 0.0f))/' 'classify_batch' "the strict masks' < made <= (vectors)"
if grep -qw avx512f /proc/cpuinfo; then
    mutant 's/_CMP_LT_OS)$/_CMP_LE_OS)/' 'classify_batch' "the strict masks' < made <= (AVX-512 mask registers)" -march=native
else
    echo "ok - a C header with the AVX-512 strict masks' < made <= fails its check # SKIP this CPU has no AVX-512"
fi

# The vectorized paths as users build them for speed: clang -O3 -march=native (its vectorizer),
# gcc -O2 -march=native (GNU C vectors, AVX-512 here) and -mavx2 (8 lanes); with and without the
# SSE transposition; and gcc's scalar fallback (NO_VECTOR).
for variant in "clang -O3 -march=native" "clang -O3 -march=native -DPTP_3X3_NO_SSE" \
    "clang -O3 -march=native -DPTP_4X4_NO_SSE" "gcc -O2 -march=native" "gcc -O2 -march=native -DPTP_4X4_NO_SSE" \
    "gcc -O2 -mavx2 -mfma" "gcc -O2 -DPTP_3X3_NO_VECTOR"; do
    d=3x3 space=clip rule=strict
    case "$variant" in *4X4*) d=4x4 space=world rule=degenerate ;; *avx2*) space=world ;; esac
    n=${d%x*} cc=${variant%% *}
    command -v $cc >/dev/null || { notok "$cc for the vectorized paths" "$cc is missing"; continue; }
    case "$variant" in *avx2*) grep -qw avx2 /proc/cpuinfo || {
        echo "ok - c $variant # SKIP this CPU has no AVX2"
        continue
    } ;; esac
    "$P" --degree $d --target c --space $space --rule $rule --prefix ptp_${d}_ -o "$tmp/k.h" &&
        build_host_c $cc "${variant#* }" "$tmp/k.h" $d &&
        run_host "c $d $space $rule $variant" "$tmp/host_c" --degree $n $n --space $space \
            --rule $rule --random 2 5003 17 --name "c/$variant $d $space $rule" ||
        notok "c $d $variant compiles" "$(head -5 "$tmp/err")"
done

# Several degrees, and a custom prefix, in one C program; a header included twice.
"$P" --degree 2 --target c -o "$tmp/a.h" && "$P" --degree 3 --target c --space world --prefix cull_ -o "$tmp/b.h"
cat >"$tmp/multi.c" <<'C'
#define PTP_2X2_IMPLEMENTATION
#define CULL_IMPLEMENTATION
#include "a.h"
#include "b.h"
#include "a.h"
int main(void)
{
    static float cp2[9][4], cp3[16][4];
    const float eye[4] = {0, 0, 1, 0};
    unsigned char cls[1];
    int k;
    for (k = 0; k < 16; k++) {
        cp3[k][0] = (float)(k / 4);
        cp3[k][1] = (float)(k % 4);
        cp3[k][3] = 1;
        if (k < 9) {
            cp2[k][0] = (float)(k / 3);
            cp2[k][1] = (float)(k % 3);
            cp2[k][3] = 1;
        }
    }
    cull_classify_batch((const float (*)[4])cp3, 1, eye, cls);
    /* C before C23 does not add const to a pointer to array implicitly: users cast. */
    return !(ptp_2x2_classify((const float (*)[4])cp2, eye) == PTP_2X2_FRONT &&
             cull_classify((const float (*)[4])cp3, eye) == CULL_FRONT &&
             cls[0] == CULL_FRONT && PTP_2X2_PLANES == 25 && CULL_PLANES == 64);
}
C
for cc in gcc clang; do
    command -v $cc >/dev/null || continue
    $cc -std=c99 -Wall -Wextra -pedantic -Werror -I"$tmp" "$tmp/multi.c" -o "$tmp/multi" 2>"$tmp/err" && "$tmp/multi" &&
        ok "C headers of two degrees (one with --prefix cull_), one included twice, in one program ($cc)" ||
        notok "C headers of two degrees in one program ($cc)" "$(grep -m1 error "$tmp/err")"
done

# Variants side by side: the bicubic clip, world and certified C headers and the table header,
# under their default names (ptp_3x3_, ptp_3x3_world_, ptp_3x3_certified_, ptp_3x3_ table), in one
# translation unit with every implementation, as C and C++; each records its variant in macros.
# The patch (3i, 3j, 0, 1) has dB/du x dB/dv along +z: front for an eye above it (w > 0), back
# below, and back above when the eye's w is negative (the negated eye).
"$P" --degree 3 --target c -o "$tmp/ptp_3x3.h" && "$P" --degree 3 --target c --space world -o "$tmp/ptp_3x3_world.h" &&
    "$P" --degree 3 --target c --certified -o "$tmp/ptp_3x3_certified.h" &&
    "$P" --degree 3 --target table -o "$tmp/ptp_3x3_table.h" || notok "variant headers" "ptpgen failed"
cat >"$tmp/variants.c" <<'C'
#define PTP_3X3_IMPLEMENTATION
#define PTP_3X3_WORLD_IMPLEMENTATION
#define PTP_3X3_CERTIFIED_IMPLEMENTATION
#include "ptp_3x3.h"
#include "ptp_3x3_world.h"
#include "ptp_3x3_certified.h"
#include "ptp_3x3_table.h"
#if !(PTP_3X3_SPACE_CLIP && PTP_3X3_RULE_STRICT && !PTP_3X3_CERTIFIED && PTP_3X3_REFINE == 0 &&         \
      PTP_3X3_WORLD_SPACE_WORLD && PTP_3X3_WORLD_DEGREE_U == 3 && PTP_3X3_WORLD_DEGREE_V == 3 &&         \
      PTP_3X3_CERTIFIED_CERTIFIED == 1 && PTP_3X3_CERTIFIED_SPACE_CLIP && PTP_3X3_TERMS == 516) ||       \
    defined(PTP_3X3_SPACE_WORLD) || defined(PTP_3X3_WORLD_SPACE_CLIP) || defined(PTP_3X3_RULE_DEGENERATE)
#error "the variant macros"
#endif
int main(void)
{
    static float cp[16][4];
    const float up[4] = {0, 0, 1, 0}, above[4] = {1, 1, 5, 1}, below[4] = {1, 1, -5, 1};
    const float negw[4] = {-1, -1, -5, -1}; /* the point (1, 1, 5) with w = -1 */
    float d[64];
    int k, ok;
    for (k = 0; k < 16; k++) {
        cp[k][0] = (float)(3 * (k / 4));
        cp[k][1] = (float)(3 * (k % 4));
        cp[k][3] = 1;
    }
    ptp_3x3_values((const float (*)[4])cp, up, d);
    ok = ptp_3x3_classify((const float (*)[4])cp, up) == PTP_3X3_FRONT && d[0] > 0 &&
         ptp_3x3_certified_classify((const float (*)[4])cp, up) == PTP_3X3_CERTIFIED_FRONT &&
         ptp_3x3_world_classify((const float (*)[4])cp, above) == PTP_3X3_WORLD_FRONT &&
         ptp_3x3_world_classify((const float (*)[4])cp, below) == PTP_3X3_WORLD_BACK &&
         ptp_3x3_world_classify((const float (*)[4])cp, negw) == PTP_3X3_WORLD_BACK &&
         ptp_3x3_table_idx[0][0] == 0;
    return !ok;
}
C
for cc in "gcc -std=c99" "clang -std=c99" "g++ -std=c++11 -x c++" "clang++ -std=c++11 -x c++"; do
    command -v ${cc%% *} >/dev/null || continue
    $cc -Wall -Wextra -pedantic -Werror -I"$tmp" "$tmp/variants.c" -o "$tmp/variants" 2>"$tmp/err" && "$tmp/variants" &&
        ok "bicubic clip, world, certified and table headers in one program, default names, orientation ($cc)" ||
        notok "bicubic clip, world, certified and table headers in one program ($cc)" "$(grep -m2 error "$tmp/err")"
done

# alpha(): projections stored as glm (OpenGL, Vulkan, reversed Z) and DirectXMath (LH, RH,
# reversed Z) store them give clip-space classes equal to the world-space header's on the models
# (tests/host_alpha.c, with the default-named headers above), built as C and as C++.
for cc in "gcc -std=c11" "g++ -std=c++11 -x c++"; do
    command -v ${cc%% *} >/dev/null || continue
    if ! ls $knot "$models"/teapot.bez >/dev/null 2>&1; then
        notok "alpha() on the models" "no $knot or $models/teapot.bez"
    elif $cc -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -I"$tmp" tests/host_alpha.c -x none \
        build/gcc/libptptest.a -lm -o "$tmp/host_alpha" 2>"$tmp/err"; then
        run_host "alpha ($cc)" "$tmp/host_alpha" $knot "$models"/teapot.bez
    else
        notok "host_alpha compiles with $cc" "$(grep -m2 error "$tmp/err")"
    fi
done

# C++: bicubic headers (clip, world, certified, refine 2) with their implementations compile as
# C++11 to C++20 with g++ and clang++, -pedantic -Werror, and the hosts (C and C++ alike) pass
# at C++11 and C++20; -ffast-math and its parts are refused by #error saying why.
for cfg in "clip" "world" "clip --certified" "world --refine 2"; do
    set -- $cfg
    space=$1 host=host_c cflag=""
    shift
    case "$*" in *refine*) host=host_refine ;; *certified*) cflag=--certified ;; esac
    "$P" --degree 3 --target c --space $space "$@" --prefix ptp_3x3_ -o "$tmp/x.h" || notok "c++ 3x3 $cfg" "ptpgen failed"
    for cxx in g++ clang++; do
        command -v $cxx >/dev/null || { missing $cxx "C++ builds of the C header"; continue; }
        cc=gcc
        [ $cxx = clang++ ] && cc=clang
        for std in c++11 c++14 c++17 c++20; do
            if ! $cxx -std=$std -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$tmp/x.h" \
                -DPTP_3X3_IMPLEMENTATION -DPFX=ptp_3x3_ -DUPFX=PTP_3X3_ -x c++ tests/$host.c -x none \
                "build/$cc/libptptest.a" -lm -o "$tmp/host_cxx" 2>"$tmp/err"; then
                notok "c++ 3x3 $cfg compiles with $cxx -std=$std" "$(grep -m3 error "$tmp/err")"
            elif [ $std = c++11 ] || [ $std = c++20 ]; then
                run_host "c++ 3x3 $cfg ($cxx -std=$std)" "$tmp/host_cxx" --degree 3 3 --space $space \
                    --rule strict $cflag --random 1 3000 23 --name "c++/$cxx -std=$std 3x3 $cfg"
            else
                ok "c++ 3x3 $cfg compiles with $cxx -std=$std -pedantic -Werror"
            fi
        done
    done
done
"$P" --degree 3 --target c -o "$tmp/x.h"
for cc in gcc clang g++ clang++; do
    command -v $cc >/dev/null || continue
    for flag in -ffast-math -ffinite-math-only "-fassociative-math -fno-signed-zeros -fno-trapping-math"; do
        # clang defines no macro for -fassociative-math alone: only gcc's __ASSOCIATIVE_MATH__ is seen
        [[ $cc == clang* && $flag == -fassoc* ]] && continue
        lang=c
        [[ $cc == *++ ]] && lang=c++
        if printf '#define PTP_3X3_IMPLEMENTATION\n#include "x.h"\nint main(void) { return 0; }\n' |
            $cc -x $lang $flag -I"$tmp" -c - -o "$tmp/fm.o" 2>"$tmp/err"; then
            notok "c header refuses $cc $flag" "it compiled"
        elif grep -q 'error.*do not compile this header.*-ffast-math.*NaN checks' "$tmp/err"; then
            ok "c header refuses $cc $flag with #error saying why"
        else
            notok "c header refuses $cc $flag with its #error" "$(grep -m1 error "$tmp/err")"
        fi
    done
done
