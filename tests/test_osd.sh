#!/usr/bin/env bash
# test_osd.sh: OpenSubdiv's patches culled as they come, with the real library (libosd-dev):
# tests/examples/osd_cull.cpp (the README's example) built as a user builds it, and
# tests/osd_check.cpp checking its classes against OpenSubdiv's own evaluation of the surface;
# and the GLSL kernel of --kernel indexed on lavapipe against classify_indexed_boundary.
# Needs PTPGEN (default build/gcc/ptpgen).
set -u
P=${PTPGEN:-build/gcc/ptpgen}
. "$(dirname "$0")/host_lib.sh"
make_tmp

if [ ! -e /usr/include/opensubdiv/version.h ]; then
    missing "OpenSubdiv (Debian package libosd-dev)" "OpenSubdiv's patches"
    exit 0
fi
CXX="g++ -std=c++11 -O2 -Wall -Wextra -Werror -pedantic -I$tmp -Ibench"
if "$P" --degree 3 --basis bspline --order v-major --space world --target c --prefix ptp_osd_ -o "$tmp/ptp_osd.h" &&
    "$P" --degree 3 --space world --target c --prefix bz_ -o "$tmp/bz.h" &&
    "$P" --degree 3 --basis bspline --order v-major --space world --target c --certified --prefix cs_ -o "$tmp/cs.h" &&
    $CXX -c tests/examples/osd_cull.cpp -o "$tmp/osd_cull.o" 2>"$tmp/err" &&
    $CXX -DPTP_OSD_IMPLEMENTATION -DBZ_IMPLEMENTATION -DCS_IMPLEMENTATION tests/osd_check.cpp "$tmp/osd_cull.o" -losdCPU \
        -o "$tmp/osd_check" 2>>"$tmp/err"; then
    ok "tests/examples/osd_cull.cpp builds with OpenSubdiv (g++ -std=c++11, -losdCPU)"
    mkdir -p "$tmp/dump"
    "$tmp/osd_check" "$tmp/dump"
else
    notok "tests/examples/osd_cull.cpp and tests/osd_check.cpp build with OpenSubdiv" "$(grep -m3 error "$tmp/err")"
fi

# The GLSL kernel of --kernel indexed (its vertices, indices and boundary masks as Far gives them)
# on lavapipe through tests/host_indexed.c, on the patch tables osd_check wrote: every class
# against classify_indexed_boundary's. A kernel whose phantoms are 3 p1 - p2 must fail.
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
if ! command -v glslangValidator >/dev/null || [ ! -e /usr/include/vulkan/vulkan.h ]; then
    missing "glslangValidator and the Vulkan headers" "the indexed GLSL kernel on OpenSubdiv's patches"
elif ! ls "$tmp"/dump/*/classes >/dev/null 2>&1; then
    notok "the indexed GLSL kernel on OpenSubdiv's patches" "osd_check wrote no patch tables"
elif "$P" --degree 3 --basis bspline --order v-major --space world --target glsl --kernel indexed --prefix ix_ \
    -o "$tmp/ix.comp" --host-header "$tmp/ix_host.h" && glslangValidator -V "$tmp/ix.comp" -o "$tmp/ix.spv" >"$tmp/err" &&
    gcc -std=c11 -O2 -Wall -Wextra -Werror -pedantic -I"$tmp" tests/host_indexed.c -lvulkan -o "$tmp/host_indexed" 2>>"$tmp/err"; then
    for d in "$tmp"/dump/*/; do
        run_host "indexed GLSL on OpenSubdiv's table $(basename "$d")" "$tmp/host_indexed" "$tmp/ix.spv" "$d" \
            "GLSL --kernel indexed --basis bspline on OpenSubdiv's table $(basename "$d") = classify_indexed_boundary"
    done
    sed 's/2\.0f \* p\[\([0-9]*\)\]\.x/3.0f * p[\1].x/' "$tmp/ix.comp" >"$tmp/m.comp"
    if glslangValidator -V "$tmp/m.comp" -o "$tmp/m.spv" >/dev/null && ! cmp -s "$tmp/ix.comp" "$tmp/m.comp" &&
        ! "$tmp/host_indexed" "$tmp/m.spv" "$tmp/dump/1" mutant >"$tmp/out" 2>&1 && grep -q '^not ok - mutant: ' "$tmp/out"; then
        ok "an indexed GLSL kernel whose phantoms are 3 p1 - p2 fails ($(grep -o '[0-9]* differ' "$tmp/out"))"
    else
        notok "an indexed GLSL kernel whose phantoms are 3 p1 - p2 fails" "$(cat "$tmp/out" 2>/dev/null)"
    fi
else
    notok "the indexed GLSL kernel and tests/host_indexed.c build" "$(grep -m3 -i error "$tmp/err")"
fi
