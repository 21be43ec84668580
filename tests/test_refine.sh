#!/usr/bin/env bash
# test_refine.sh: C headers emitted with --refine K, run by tests/host_refine.c on random patches
# and the models: decided classes kept, refined ones never against 33x33 samples, and it can fail.
# Needs PTPGEN and build/<cc>/libptptest.a for each C compiler.
set -u
P=${PTPGEN:?set PTPGEN}
models=${MODELS:-../shared/models}
. "$(dirname "$0")/host_lib.sh"
make_tmp

# host D SPACE RULE K CC [SED]: builds host_refine around a --refine K header (edited by sed
# script SED when given) into $tmp/hr; prints nothing, returns the build status.
host() {
    local d=$1 n=${1%x*} m=${1#*x}
    "$P" --degree $d --target c --space $2 --rule $3 --refine $4 --prefix ptp_${d}_ -o "$tmp/r.h" || return 1
    [ -n "${6:-}" ] && sed -i "$6" "$tmp/r.h"
    $5 -std=c11 -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$tmp/r.h" \
        -DPTP_${n}X${m}_IMPLEMENTATION -DPFX=ptp_${d}_ -DUPFX=PTP_${n}X${m}_ tests/host_refine.c \
        "build/$5/libptptest.a" -lm -o "$tmp/hr" 2>"$tmp/err"
}

for cc in gcc clang; do
    command -v $cc >/dev/null || { notok "refine with $cc" "$cc is missing"; continue; }
    for cfg in "3x3 clip strict 3" "3x3 world degenerate 2" "2x3 clip degenerate 4"; do
        set -- $cfg
        data="--random 2 3000 11"
        [ $1 = 3x3 ] && data="$data --model $models/teacup.bez 20 3 --model $models/teaspoon.bez 20 4"
        if host $1 $2 $3 $4 $cc; then
            "$tmp/hr" --degree ${1%x*} ${1#*x} --space $2 --rule $3 $data --name "refine $4 $1 $2 $3 ($cc)"
        else
            notok "refine $cfg compiles with $cc" "$(head -3 "$tmp/err")"
        fi
    done
done

# A broken subdivision (a piece out of levels called back) must be caught by the samples.
if host 3x3 clip strict 2 gcc 's|return PTP_3X3_SILHOUETTE; /\* the corners differ|return levels == 0 ? PTP_3X3_BACK : PTP_3X3_SILHOUETTE; /* the corners differ|' &&
    ! "$tmp/hr" --degree 3 3 --space clip --rule strict --random 2 3000 5 --name mutant >"$tmp/out" 2>&1 &&
    grep -q '^not ok - mutant: no refined class contradicts' "$tmp/out"; then
    ok "a --refine header that calls an undecided piece back fails the sample check"
else
    notok "a --refine header that calls an undecided piece back fails the sample check" "it passed"
fi
