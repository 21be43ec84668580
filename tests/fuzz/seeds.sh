#!/usr/bin/env bash
# seeds.sh: writes verify's fuzz seeds that are a table with one deliberate edit into DIR, and
# checks that `ptpgen verify` still judges each one as the seed is meant to be judged.
# Usage: bash tests/fuzz/seeds.sh PTPGEN DIR (the Makefile's $(B)/fuzz_seeds.ok runs it).
set -eu
ptpgen=$1
dir=$2
here=$(dirname "$0")
mkdir -p "$dir"

# seed NAME FROM EDIT RC TEXT: DIR/NAME is FROM (a bidegree: `ptpgen --degree FROM --target
# table`; else a hand-written seed in tests/fuzz/verify) with the sed script EDIT applied ('' for
# none; otherwise it must change the file); `ptpgen verify` on it must exit RC and print TEXT.
seed() {
    local name=$1 from=$2 edit=$3 rc=$4 text=$5 got=0 report
    if [[ $from =~ ^[0-9]+x[0-9]+$ ]]; then
        "$ptpgen" --degree "$from" --target table >"$dir/$name.orig"
    else
        cp "$here/verify/$from" "$dir/$name.orig"
    fi
    sed -e "$edit" "$dir/$name.orig" >"$dir/$name"
    if [ -n "$edit" ] && cmp -s "$dir/$name.orig" "$dir/$name"; then
        echo "seeds.sh: $name: the edit '$edit' changes nothing in $from" >&2
        exit 1
    fi
    rm "$dir/$name.orig"
    report=$("$ptpgen" verify "$dir/$name" 2>&1) || got=$?
    if [ "$got" != "$rc" ] || [[ $report != *"$text"* ]]; then
        printf 'seeds.sh: %s: ptpgen verify exits %s (want %s) without "%s":\n%s\n' \
            "$name" "$got" "$rc" "$text" "$report" >&2
        exit 1
    fi
}

seed table_1x1.h 1x1 '' 0 'RIGHT: exact: the 4 terms of bidegree 1x1'
seed table_2x2.h 2x2 '' 0 'RIGHT: exact: the 76 terms of bidegree 2x2'
# The first iwgt 5 instead of -1.
seed wrong_iwgt_1x1.h 1x1 '/_table_iwgt\[/{n;s/-1,/5,/}' 1 \
    ':41: wrong iwgt[0]: got 5, so iwgt/DENOM = 5, but the exact weight of the term on line 27 is -1'
# Plane 0 owned by thread 3 instead of 0.
seed wrong_owner_1x1.h 1x1 '/_table_owner\[/{n;s/0,/3,/}' 1 \
    ':53: sched slot 0 runs on thread 0 but writes plane 0, which owner (line 48) gives to thread 3'
# The first sched_wgt 7 instead of -1 (sched_iwgt left at -1).
seed wrong_sched_wgt_1x1.h 1x1 '/_table_sched_wgt\[/{n;s/-1\.0f/7.0f/}' 1 \
    ':60: sched slot 0 {0, 0, 1, 2}: weight 7, but the term (line 27) has weight -1'
# denom0_1x1.h with DENOM 1 and THREADS 3: its iwgt, owner and sched arrays are then checked.
seed threads3_1x1.h denom0_1x1.h 's/T_DENOM 0/T_DENOM 1/;s/T_THREADS 0/T_THREADS 3/' 1 \
    'WRONG: 5 problems (5 problems in iwgt, owner or the sched arrays)'
