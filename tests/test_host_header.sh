#!/usr/bin/env bash
# test_host_header.sh: --host-header (docs/gpu-hosts.md): for every GPU target and both kernels of
# 3x3, the header compiles as C99 and C++11 (in two files of one program), its dispatch function
# covers every block, its source is the kernel byte for byte, its workgroup is the kernel's
# Schedule: line, and (GLSL, HLSL) its parameter offsets and bindings are glslang's reflection of
# the kernel; the option's usage errors and no partial files; and tests/examples/vulkan_cull.c runs
# the GLSL kernel through its host header on lavapipe against the C header's classes.
# Needs PTPGEN (default build/gcc/ptpgen).
set -u
. tests/schedule.sh
P=${PTPGEN:-build/gcc/ptpgen}
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ok() { echo "ok - $1"; }
notok() { echo "not ok - $1: $2"; }
CSTD="-std=c99 -Wall -Wextra -Werror -pedantic"
CXXSTD="-std=c++11 -Wall -Wextra -Werror -pedantic"

# The program around a header h.h: writes the embedded source to argv[1], checks the dispatch
# function, prints the workgroup ("THREADS PATCHES"). other.c includes the header a second time.
cat >"$tmp/check.c" <<'EOF'
#include "h.h"
#include <stdio.h>
static int bad;
static void expect(uint32_t n, uint32_t max, uint32_t x, uint32_t y)
{
    uint32_t g[3] = {9, 9, 9};
    ptp_3x3_dispatch(n, max, g);
    if (g[0] != x || g[1] != y || g[2] != 1u) {
        fprintf(stderr, "dispatch(%lu, %lu) = %lu %lu %lu, expected %lu %lu 1\n", (unsigned long)n,
                (unsigned long)max, (unsigned long)g[0], (unsigned long)g[1], (unsigned long)g[2],
                (unsigned long)x, (unsigned long)y);
        bad = 1;
    }
}
/* A 2-D grid: x within max, x * y covering every block, no empty row. */
static void covers(uint32_t n, uint32_t max)
{
    uint32_t g[3], q = PTP_3X3_PATCHES_PER_WORKGROUP;
    uint64_t blocks = ((uint64_t)n + q - 1) / q;
    ptp_3x3_dispatch(n, max, g);
    if (g[0] > (max ? max : 65535u) || g[1] < 2u || (uint64_t)g[0] * g[1] < blocks ||
        (uint64_t)g[0] * (g[1] - 1u) >= blocks || g[2] != 1u) {
        fprintf(stderr, "dispatch(%lu, %lu) = %lu %lu %lu for %llu blocks\n", (unsigned long)n,
                (unsigned long)max, (unsigned long)g[0], (unsigned long)g[1], (unsigned long)g[2],
                (unsigned long long)blocks);
        bad = 1;
    }
}
int other(void);
int main(int argc, char **argv)
{
    uint32_t q = PTP_3X3_PATCHES_PER_WORKGROUP;
    FILE *f = argc > 1 ? fopen(argv[1], "wb") : NULL;
    if (!f || fwrite(ptp_3x3_source, 1, PTP_3X3_SOURCE_SIZE, f) != PTP_3X3_SOURCE_SIZE || fclose(f))
        return 2;
    expect(0, 0, 0, 1);
    expect(1, 0, 1, 1);
    expect(q, 0, 1, 1);
    expect(q + 1, 0, 2, 1);
    expect(q * 7, 7, 7, 1);
    expect(q * 7 + 1, 7, 4, 2);
    covers(q * 1000 + 3, 64);
    covers(q * 65535 + 1, 0);
    covers(4294967295u, 0);
    printf("%lu %lu\n", (unsigned long)PTP_3X3_WORKGROUP_SIZE, (unsigned long)q);
    return bad || other() != (int)PTP_3X3_POINTS;
}
EOF
printf '#include "h.h"\nint other(void) { return PTP_3X3_POINTS; }\n' >"$tmp/other.c"

# build DIR: compiles DIR/h.h into DIR/c (C99) and DIR/cxx (C++11); 0 if both compile.
build() {
    gcc $CSTD -I"$1" -o "$1/c" "$tmp/check.c" "$tmp/other.c" 2>"$1/err" &&
        g++ $CXXSTD -I"$1" -o "$1/cxx" -x c++ "$tmp/check.c" -x c++ "$tmp/other.c" 2>>"$1/err"
}

# reflect KERNEL TARGET DIR: every parameter offset and buffer binding of DIR/h.h against glslang's
# reflection of the kernel (GLSL, HLSL through glslang's HLSL front end).
reflect() {
    local k=$1 t=$2 d=$3 name off want
    if [ "$t" = hlsl ]; then
        glslangValidator -V -D -e main -S comp -q "$k" -o /dev/null >"$d/refl" 2>&1 || return 1
    else
        glslangValidator -V -S comp -q "$k" -o /dev/null >"$d/refl" 2>&1 || return 1
    fi
    while read -r name off; do
        [ "$name" = pad ] && continue
        grep -q "^$name: offset $off," "$d/refl" || { echo "$name at $off, glslang: $(grep "^$name:" "$d/refl")"; return 1; }
    done < <(sed -n 's/.*offsetof(ptp_3x3_params, \([a-z_]*\)) == \([0-9]*\).*/\1 \2/p' "$d/h.h")
    want=$(sed -n 's/.*sizeof(ptp_3x3_params) == \([0-9]*\).*/\1/p' "$d/h.h")
    off=$(sed -n 's/^Params: .* size \([0-9]*\),.*/\1/p' "$d/refl")
    align=4
    [ "$t" = hlsl ] && align=16 # a constant buffer: whole 16-byte rows
    [ -n "$off" ] && [ "$off" -le "$want" ] && [ $((want % align)) -eq 0 ] ||
        { echo "block of $off bytes, the header's $want"; return 1; }
    for pair in POINTS:cp:ControlPoints CLASSES:cls:Classes; do
        IFS=: read -r name var blk <<<"$pair"
        [ "$t" = hlsl ] && blk=$var
        want=$(sed -n "s/^#define PTP_3X3_BINDING_$name \([0-9]*\).*/\1/p" "$d/h.h")
        grep -q "^$blk: offset -1, .* binding $want," "$d/refl" || { echo "binding of $blk is not $want"; return 1; }
    done
}

for t in glsl hlsl opencl cuda wgsl; do
    for kern in slp table; do
        d=$tmp/$t-$kern
        mkdir -p "$d"
        what="$t --kernel $kern"
        if ! "$P" --degree 3 --target $t --kernel $kern -o "$d/kernel" --host-header "$d/h.h" 2>"$d/err"; then
            notok "$what: kernel and host header" "$(head -1 "$d/err")"
            continue
        fi
        if build "$d"; then
            ok "$what: the host header compiles as C99 and C++11 ($CSTD; g++ $CXXSTD), included by two files"
        else
            notok "$what: the host header compiles as C99 and C++11" "$(head -3 "$d/err")"
            continue
        fi
        for lang in c cxx; do
            if "$d/$lang" "$d/source.$lang" >"$d/wg.$lang" 2>"$d/err"; then
                ok "$what ($lang): dispatch of 0, 1, Q, Q+1, 7Q, 7Q+1 patches and 2-D grids past max_groups_x cover every block"
            else
                notok "$what ($lang): dispatch" "$(head -3 "$d/err")"
            fi
        done
        if cmp -s "$d/source.c" "$d/kernel" && cmp -s "$d/source.cxx" "$d/kernel"; then
            ok "$what: the embedded source is the kernel byte for byte ($(wc -c <"$d/kernel") bytes)"
        else
            notok "$what: the embedded source is the kernel byte for byte" "$(cmp "$d/source.c" "$d/kernel" 2>&1)"
        fi
        sched=$(kernel_schedule "$d/kernel")
        if [ -n "$sched" ] && [ "$sched" = "$(cat "$d/wg.c")" ]; then
            ok "$what: the workgroup (threads, patches) is the kernel's Schedule: line ($sched)"
        else
            notok "$what: the workgroup is the kernel's Schedule: line" "header '$(cat "$d/wg.c")', kernel '$sched'"
        fi
        case $t in glsl | hlsl)
            if msg=$(reflect "$d/kernel" $t "$d"); then
                ok "$what: parameter offsets, block size and bindings match glslang's reflection"
            else
                notok "$what: parameter offsets and bindings match glslang's reflection" "$msg"
            fi ;;
        esac
    done
done

# The checks can fail: a wrong offset stops the compile; a wrong workgroup fails the Schedule check.
d=$tmp/glsl-slp
mkdir -p "$tmp/bad"
sed 's/params, patch_count) == 16/params, patch_count) == 20/' "$d/h.h" >"$tmp/bad/h.h"
if ! cmp -s "$d/h.h" "$tmp/bad/h.h" && ! build "$tmp/bad" && grep -q params_patch_count "$tmp/bad/err"; then
    ok "a header with a wrong offset fails its static assertion (C99 and C++11)"
else
    notok "a header with a wrong offset fails its static assertion" "it compiled"
fi
sed 's/^#define PTP_3X3_PATCHES_PER_WORKGROUP 64u/#define PTP_3X3_PATCHES_PER_WORKGROUP 32u/' "$d/h.h" >"$tmp/bad/h.h"
if build "$tmp/bad" && "$tmp/bad/c" "$tmp/bad/src" >"$tmp/bad/wg" &&
    [ "$(cat "$tmp/bad/wg")" != "$(kernel_schedule "$d/kernel")" ]; then
    ok "a header with another workgroup differs from the kernel's Schedule: line"
else
    notok "a header with another workgroup differs from the kernel's Schedule: line" "not caught"
fi

if gcc $CSTD -DPTP_3X3_NO_SOURCE -I"$d" -c -o "$tmp/bad/o.o" "$tmp/other.c" 2>"$tmp/bad/err" &&
    ! gcc -E -DPTP_3X3_NO_SOURCE -I"$d" "$tmp/other.c" | grep -q 'ptp_3x3_source\[\]' &&
    gcc -E -I"$d" "$tmp/other.c" | grep -q 'ptp_3x3_source\[\]'; then
    ok "PTP_3X3_NO_SOURCE leaves the source out (for MSVC's 65535-byte literals)"
else
    notok "PTP_3X3_NO_SOURCE leaves the source out" "$(head -2 "$tmp/bad/err")"
fi

# Usage errors, and no file, partial or whole, when a run fails.
expect_usage() {
    local name=$1 pat=$2
    shift 2
    if "$P" --degree 3 "$@" >"$tmp/out" 2>"$tmp/err"; then
        notok "$name" "accepted"
    elif [ $? -eq 2 ] && grep -Eq "^ptpgen: .*($pat)" "$tmp/err" && [ ! -e "$tmp/u.h" ]; then
        ok "$name: '$(head -1 "$tmp/err")'"
    else
        notok "$name" "$(head -1 "$tmp/err")"
    fi
}
expect_usage "--host-header with --target c is a usage error" "applies to targets glsl" --target c --host-header "$tmp/u.h"
expect_usage "--host-header with --target json is a usage error" "applies to targets" --target json --host-header "$tmp/u.h"
expect_usage "--host-header with --stage function is a usage error" "compute kernels" --target glsl --stage function --host-header "$tmp/u.h"
expect_usage "--host-header naming -o's file is a usage error" "another file" --target glsl -o "$tmp/u.h" --host-header "$tmp/u.h"
expect_usage "--host-header without a file name is a usage error" "needs" --target glsl --host-header
if "$P" --help | grep -q -- '--host-header F'; then ok "--help shows --host-header"; else notok "--help shows --host-header" "missing"; fi
if ! "$P" --degree 3 --target glsl -o "$tmp/k.comp" --host-header "$tmp/none/h.h" 2>"$tmp/err" &&
    [ ! -e "$tmp/k.comp" ] && [ -z "$(ls "$tmp/none" 2>/dev/null)" ]; then
    ok "an unwritable --host-header leaves no kernel and no partial file: '$(head -1 "$tmp/err")'"
else
    notok "an unwritable --host-header leaves no files" "$(ls "$tmp")"
fi

# The Vulkan example on lavapipe, and with a host header whose workgroup is wrong.
ex=$tmp/vk
mkdir -p "$ex"
if ! { "$P" --degree 3 --target glsl -o "$ex/ptp_3x3.comp" --host-header "$ex/ptp_3x3_host.h" &&
    "$P" --degree 3 --target c -o "$ex/ptp_3x3.h" &&
    glslangValidator -V "$ex/ptp_3x3.comp" -o "$ex/ptp_3x3.spv" >"$ex/err"; } 2>>"$ex/err"; then
    notok "vulkan_cull.c's kernel, headers and SPIR-V" "$(tail -3 "$ex/err")"
elif ! gcc -std=c11 -O2 -Wall -Wextra -Werror -pedantic -I"$ex" -o "$ex/run" tests/examples/vulkan_cull.c \
    -lvulkan -lm 2>"$ex/err"; then
    notok "vulkan_cull.c compiles (gcc -std=c11 -Wall -Wextra -Werror -pedantic)" "$(head -3 "$ex/err")"
else
    "$ex/run" "$ex/ptp_3x3.spv" || true
    sed -i 's/^#define PTP_3X3_PATCHES_PER_WORKGROUP 64u/#define PTP_3X3_PATCHES_PER_WORKGROUP 128u/' "$ex/ptp_3x3_host.h"
    if gcc -std=c11 -O2 -I"$ex" -o "$ex/bad" tests/examples/vulkan_cull.c -lvulkan -lm 2>"$ex/err" &&
        ! "$ex/bad" "$ex/ptp_3x3.spv" >"$ex/out" 2>&1 && grep -q '^not ok - vulkan_cull' "$ex/out"; then
        ok "vulkan_cull.c with a host header of the wrong workgroup fails its check"
    else
        notok "vulkan_cull.c with a host header of the wrong workgroup fails its check" "$(tail -2 "$ex/out" "$ex/err")"
    fi
fi
