#!/usr/bin/env bash
# test_osd.sh: OpenSubdiv's patches culled as they come, with the real library (libosd-dev):
# tests/examples/osd_cull.cpp (the README's example) built as a user builds it, and
# tests/osd_check.cpp checking its classes against OpenSubdiv's own evaluation of the surface.
# Needs PTPGEN (default build/gcc/ptpgen).
set -u
P=${PTPGEN:-build/gcc/ptpgen}
. "$(dirname "$0")/host_lib.sh"
make_tmp

if [ ! -e /usr/include/opensubdiv/version.h ]; then
    missing "OpenSubdiv (Debian package libosd-dev)" "OpenSubdiv's patches"
    exit 0
fi
CXX="g++ -std=c++11 -O2 -Wall -Wextra -Werror -pedantic -I$tmp"
if "$P" --degree 3 --basis bspline --order v-major --space world --target c --prefix ptp_osd_ -o "$tmp/ptp_osd.h" &&
    "$P" --degree 3 --space world --target c --prefix bz_ -o "$tmp/bz.h" &&
    $CXX -c tests/examples/osd_cull.cpp -o "$tmp/osd_cull.o" 2>"$tmp/err" &&
    $CXX -DPTP_OSD_IMPLEMENTATION -DBZ_IMPLEMENTATION tests/osd_check.cpp "$tmp/osd_cull.o" -losdCPU \
        -o "$tmp/osd_check" 2>>"$tmp/err"; then
    ok "tests/examples/osd_cull.cpp builds with OpenSubdiv (g++ -std=c++11, -losdCPU)"
    "$tmp/osd_check"
else
    notok "tests/examples/osd_cull.cpp and tests/osd_check.cpp build with OpenSubdiv" "$(grep -m3 error "$tmp/err")"
fi
