#!/usr/bin/env bash
# test_refine.sh: C headers emitted with --refine K, run by tests/host_refine.c on random patches
# and the models: decided classes kept, refined ones never against samples of the function (33 a
# side), quads and triangles (degrees 1 to 4), and it can fail. --refine K --certified headers also
# run on the exact data (no unsafe back or front; 10^6 patches in three configurations) and refine
# as many patches as the plain ones.
# Needs PTPGEN and build/<cc>/libptptest.a for each C compiler.
set -u
P=${PTPGEN:?set PTPGEN}
models=models
. "$(dirname "$0")/host_lib.sh"
make_tmp

# host D SPACE RULE K CC [SED]: builds host_refine around a --refine K header (K may carry
# --certified after the number; the header edited by sed
# script SED when given) into $tmp/hr; D is a bidegree NxM or triN, a triangle of degree N.
# Sets dom to the domain's host arguments; prints nothing, returns the build status.
host() {
    local d=$1 opt up
    if [ "${d#tri}" != "$d" ]; then
        opt="--domain triangle --degree ${d#tri}" up=PTP_TRI${d#tri}_ dom="--domain triangle --degree ${d#tri} ${d#tri}"
    else
        opt="--degree $d" up=PTP_${d%x*}X${d#*x}_ dom="--degree ${d%x*} ${d#*x}"
    fi
    "$P" $opt --target c --space $2 --rule $3 --refine $4 --prefix ${up,,} -o "$tmp/r.h" || return 1
    [ -n "${6:-}" ] && sed -i "$6" "$tmp/r.h"
    $5 -std=c11 -O2 -Wall -Wextra -Werror -pedantic -Igen -Itests -include "$tmp/r.h" \
        -D${up}IMPLEMENTATION -DPFX=${up,,} -DUPFX=$up tests/host_refine.c \
        "build/$5/libptptest.a" -lm -o "$tmp/hr" 2>"$tmp/err"
}

for cc in gcc clang; do
    command -v $cc >/dev/null || { notok "refine with $cc" "$cc is missing"; continue; }
    for cfg in "3x3 clip strict 3" "3x3 world degenerate 2" "2x3 clip degenerate 4" \
        "tri1 clip strict 2" "tri2 world degenerate 3" "tri3 clip strict 3" "tri4 world strict 2" \
        "3x3 world strict 3 --certified" "3x3 clip degenerate 3 --certified" \
        "2x2 world degenerate 3 --certified" "tri3 world strict 3 --certified" \
        "tri3 clip degenerate 2 --certified" "tri2 world strict 3 --certified"; do
        set -- $cfg
        cert=${5:-}
        data="--random 2 3000 11"
        [ $1 = 3x3 ] && data="$data --model $models/teacup.bez 20 3 --model $models/teaspoon.bez 20 4"
        [ $1 = tri4 ] && data="--random 2 1000 11"
        if host $1 $2 $3 "$4 $cert" $cc; then
            "$tmp/hr" $dom --space $2 --rule $3 $cert $data ${cert:+--exact 20 200 7} \
                --name "refine $4${cert:+ $cert} $1 $2 $3 ($cc)"
        else
            notok "refine $cfg compiles with $cc" "$(head -3 "$tmp/err")"
        fi
    done
done

# refined D SPACE RULE K [--certified]: the number of patches the header refines from silhouette
# to back or front on random patches (and the models for 3x3), with gcc.
refined() {
    local data="--random 2 3000 11"
    [ $1 = 3x3 ] && data="$data --model $models/teacup.bez 20 3 --model $models/teaspoon.bez 20 4"
    host $1 $2 $3 "$4 ${5:-}" gcc && "$tmp/hr" $dom --space $2 --rule $3 ${5:-} $data --name n |
        sed -n 's/^# n: [0-9]* patches, \([0-9]*\) refined.*/\1/p'
}
# 10^6 exact patches per space (and both rules, quads and triangles) for --refine 3 --certified:
# no back or front the exact classes contradict (about 15 s each with gcc -O2).
for cfg in "3x3 clip strict" "3x3 world degenerate" "tri3 world strict"; do
    set -- $cfg
    if host $1 $2 $3 "3 --certified" gcc; then
        "$tmp/hr" $dom --space $2 --rule $3 --certified --exact 100 10000 41 \
            --name "refine 3 --certified $1 $2 $3, 10^6 exact patches"
    else
        notok "refine 3 --certified $cfg compiles with gcc" "$(head -3 "$tmp/err")"
    fi
done

# Far from the silhouette, certification costs the refinement (almost) nothing: the certified
# header refines at least the plain one's count less 0.1% of the patches (3000 to 10,520).
for cfg in "3x3 world strict 3" "3x3 clip degenerate 3" "tri3 world strict 3" "2x2 world degenerate 3"; do
    set -- $cfg
    a=$(refined $cfg) b=$(refined $cfg --certified)
    if [ -n "$a" ] && [ -n "$b" ] && [ $((b + 10)) -ge $a ]; then
        ok "refine $cfg: certified refines $b patches, plain $a"
    else
        notok "refine $cfg: certified refines $b patches, plain $a" "more than 10 fewer"
    fi
done

# mutant NAME D SED: a header edited by SED must fail the sample check on random patches.
mutant() {
    if host $2 clip strict 2 gcc "$3" &&
        ! "$tmp/hr" $dom --space clip --rule strict --random 2 3000 5 --name mutant >"$tmp/out" 2>&1 &&
        grep -q '^not ok - mutant: no refined class contradicts' "$tmp/out"; then
        ok "$1"
    else
        notok "$1" "it passed"
    fi
}
# A broken subdivision (a piece out of levels called back) must be caught by the samples.
for d in 3x3 tri3; do
    up=PTP_${d^^}_
    mutant "a --refine header ($d) that calls an undecided piece back fails the sample check" $d \
        "s|return ${up/X/X}SILHOUETTE; /\* the corners differ|return levels == 0 ? ${up}BACK : ${up}SILHOUETTE; /* the corners differ|"
done
# A triangle split that leaves the middle piece out (the corner at u = 1 taken twice) must be
# caught by the crafted functions, and so must a de Casteljau step that takes a wrong neighbour.
mutant "a --refine header (tri3) whose four pieces miss the middle triangle fails the sample check" \
    tri3 's|{{1, 2}, {0, 2}, {0, 1}}}|{{0, 0}, {0, 1}, {0, 2}}}|'
mutant "a --refine header (tri3) whose de Casteljau step takes a wrong neighbour fails the sample check" \
    tri3 's|b = w\[x + (e\[1\] ? r + e\[1\] : 0)\]|b = w[x + (e[1] ? r + 1 : 0)]|'
# cmutant NAME SED DATA CHECK: a 3x3 world strict --refine 3 --certified header edited by SED must
# fail the check named CHECK on DATA.
cmutant() {
    if host 3x3 world strict "3 --certified" gcc "$2" &&
        ! "$tmp/hr" $dom --space world --rule strict --certified $3 --name mutant >"$tmp/out" 2>&1 &&
        grep -q "^not ok - mutant: $4" "$tmp/out"; then
        ok "$1"
    else
        notok "$1" "it passed"
    fi
}
# One that ignores the bound's sign (v < b for v < -b: values within their bound of zero
# certified) must make unsafe classes on the exact data.
cmutant "a --refine --certified header that certifies values within their bound fails the exact check" \
    's/\.v < -d\[/.v < d[/g' "--exact 20 200 7" "on exact data no back or front is unsafe"
# One whose averages drop the rounding term (|s| 2^-54) must fail the check of mid.
cmutant "a --refine --certified header whose averages drop the rounding term fails the check of mid" \
    's/(s < 0 ? -s : s) \* 5.5511151231257827e-17/0.0/' "--random 1 200 5" "mid's bound covers the rounding"
