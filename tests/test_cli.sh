#!/usr/bin/env bash
# test_cli.sh: runs the ptpgen command as users do: outputs, exit codes, messages, -o safety.
# Needs PTPGEN (the binary under test); PTPGEN_OTHER (another compiler's build) is compared to it.
set -u
P=${PTPGEN:?set PTPGEN to the ptpgen binary}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { echo "ok - $1"; }
notok() { echo "not ok - $1: $2"; }

# expect_fail NAME CODE PATTERN ARGS...: exit status CODE, stderr "ptpgen: ..." matching
# PATTERN (grep -E), nothing on stdout.
expect_fail() {
    local name=$1 code=$2 pat=$3 rc
    shift 3
    "$P" "$@" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ $rc -ne "$code" ]; then
        notok "$name" "exit $rc, expected $code ($(cat "$tmp/err"))"
    elif ! head -1 "$tmp/err" | grep -Eq "^ptpgen: .*($pat)"; then
        notok "$name" "message '$(cat "$tmp/err")' does not match /$pat/"
    elif [ -s "$tmp/out" ]; then
        notok "$name" "wrote to stdout"
    else
        ok "$name: exit $code, '$(head -1 "$tmp/err")'"
    fi
}

# Bad degrees.
for d in 0 -3 3x x3 3x0 0x3 abc 3x3x3 '' ' 3' 3.0 +3 3X3 '3 x3'; do
    expect_fail "--degree '$d' is a usage error" 2 "degree" --degree "$d"
done
expect_fail "--degree 99999999999999999999 names the limit" 2 "largest supported degree is 16" --degree 99999999999999999999
expect_fail "--degree 17 names the limit" 2 "largest supported degree is 16" --degree 17
expect_fail "--degree 3x17 names the limit" 2 "largest supported degree is 16" --degree 3x17
expect_fail "missing --degree" 2 "missing --degree"
expect_fail "--degree without its argument" 2 "needs an argument" --degree
expect_fail "unknown target" 2 "unknown target 'glsx'" --degree 3 --target glsx
expect_fail "--target without its argument" 2 "needs an argument" --degree 3 --target
expect_fail "unknown option" 2 "unknown option '--frobnicate'" --degree 3 --frobnicate
expect_fail "-o without its argument" 2 "needs an argument" --degree 3 -o
expect_fail "stray argument" 2 "unexpected argument 'foo'" --degree 3 foo
expect_fail "unwritable -o path" 1 "cannot write $tmp/no/such/dir/x.json" --degree 3 -o "$tmp/no/such/dir/x.json"
mkdir -p "$tmp/adir"
expect_fail "-o naming a directory" 1 "cannot write" --degree 3 -o "$tmp/adir"
if [ -e /dev/full ]; then
    "$P" --degree 3 >/dev/full 2>"$tmp/err"
    rc=$?
    [ $rc -eq 1 ] && grep -q '^ptpgen: cannot write standard output' "$tmp/err" &&
        ok "a full standard output is exit 1 with a message" ||
        notok "a full standard output is exit 1 with a message" "exit $rc: $(cat "$tmp/err")"
fi
# Nothing is left behind by failures: no output file, no temporary file.
echo keep >"$tmp/keep.json"
"$P" --degree 0 -o "$tmp/keep.json" 2>/dev/null
left=$(ls "$tmp" "$tmp/adir" | grep -c 'tmp-' || true)
[ "$(cat "$tmp/keep.json")" = keep ] && [ "$left" -eq 0 ] && [ ! -e "$tmp/no" ] &&
    ok "failed runs leave no partial or temporary file and keep an existing -o file" ||
    notok "failed runs leave no partial or temporary file" "$(ls -R "$tmp")"

# Devices are written in place, never replaced.
"$P" --degree 3 -o /dev/null && [ -c /dev/null ] && ok "-o /dev/null writes to the device and leaves it a device" ||
    notok "-o /dev/null" "$(ls -l /dev/null)"

# Help and version.
"$P" --help >"$tmp/out" 2>&1 && grep -q '^usage: ptpgen --degree' "$tmp/out" && ok "--help prints usage, exit 0" ||
    notok "--help prints usage, exit 0" "$(head -2 "$tmp/out")"
"$P" --version >"$tmp/out" 2>&1 && grep -Eq '^ptpgen [0-9]+\.[0-9]+\.[0-9]+$' "$tmp/out" && ok "--version" ||
    notok "--version" "$(cat "$tmp/out")"

# -o writes the same bytes as stdout, atomically, with a normal file mode.
"$P" --degree 2x3 -o "$tmp/a.json" && "$P" --degree=2x3 --target=json >"$tmp/b.json" &&
    cmp -s "$tmp/a.json" "$tmp/b.json" && [ "$(stat -c %a "$tmp/a.json")" = "$(printf %o $((0666 & ~$(umask))))" ] &&
    ok "-o FILE equals stdout, --opt=value works, file mode follows umask" ||
    notok "-o FILE equals stdout" "differs or mode $(stat -c %a "$tmp/a.json")"

# JSON shape and invariants, and agreement with the independent Python derivation.
cat >"$tmp/check.py" <<'PY'
import json, sys
from fractions import Fraction
doc = json.load(open(sys.argv[1]))
n, m = doc["degree"]
assert doc["format"] == "ptpgen-planes/1", doc["format"]
assert doc["plane_degree"] == [3 * n - 2, 3 * m - 2]
assert doc["points"] == (n + 1) * (m + 1)
assert doc["planes"] == (3 * n - 1) * (3 * m - 1)
keys = []
for t in doc["terms"]:
    p, j, k, l, w = t
    assert 0 <= p < doc["planes"] and 0 <= j < k < l < doc["points"], t
    f = Fraction(w)
    assert f != 0 and str(f) == w, ("weight not in lowest terms", t)
    keys.append((p, j, k, l))
assert keys == sorted(keys) and len(set(keys)) == len(keys), "terms not sorted or repeated"
if len(sys.argv) > 2:
    ref = json.load(open(sys.argv[2]))
    mine = {tuple(t[:4]): Fraction(t[4]) for t in doc["terms"]}
    theirs = {tuple(t[:4]): Fraction(t[4]) for t in ref["terms"]}
    diff = set(mine.items()) ^ set(theirs.items())
    assert not diff, ("differs from the reference", sorted(diff)[:5])
PY
for d in 1x1 2x2 3x3 4x4 1x3 3x1 2x3 3x2 1x6 5x2; do
    "$P" --degree $d >"$tmp/$d.json"
    if python3 "$tmp/check.py" "$tmp/$d.json" >"$tmp/err" 2>&1; then
        ok "json $d: ptpgen-planes/1 shape, sorted unique terms, lowest-terms weights"
    else
        notok "json $d shape" "$(tail -1 "$tmp/err")"
    fi
    python3 tests/ref_derive.py ${d%x*} ${d#*x} >"$tmp/ref.json" &&
        python3 "$tmp/check.py" "$tmp/$d.json" "$tmp/ref.json" >"$tmp/err" 2>&1 &&
        ok "json $d equals the independent power-basis derivation (tests/ref_derive.py)" ||
        notok "json $d equals the independent derivation" "$(tail -1 "$tmp/err")"
done

# The table header compiles cleanly and holds exactly the json's weights.
cat >"$tmp/dump.c" <<'C'
#include <stdio.h>
#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
int main(void)
{
    unsigned long x;
    printf("%lld\n", (long long)CAT(UP, DENOM));
    for (x = 0; x < CAT(UP, TERMS); x++)
        printf("%u %u %u %u %lld %a\n", CAT(LO, idx)[x][0], CAT(LO, idx)[x][1], CAT(LO, idx)[x][2],
               CAT(LO, idx)[x][3], (long long)CAT(LO, iwgt)[x], (double)CAT(LO, wgt)[x]);
    return 0;
}
C
cat >"$tmp/cmp_table.py" <<'PY'
import json, struct, sys
from fractions import Fraction
doc = json.load(open(sys.argv[1]))
lines = open(sys.argv[2]).read().split("\n")
D = int(lines[0])
rows = [l.split() for l in lines[1:] if l]
assert len(rows) == len(doc["terms"]), "term count"
for t, r in zip(doc["terms"], rows):
    w = Fraction(t[4])
    assert [int(v) for v in r[:4]] == t[:4], ("indices", t, r)
    assert Fraction(int(r[4]), D) == w, ("integer weight", t, r)
    nearest = struct.unpack("f", struct.pack("f", float(w)))[0]
    assert float.fromhex(r[5]) == nearest, ("float weight", t, r)
PY
for d in 1x1 2x2 3x3 4x4 2x3 3x1; do
    n=${d%x*}; m=${d#*x}
    "$P" --degree $d --target table -o "$tmp/t.h" && "$P" --degree $d -o "$tmp/t.json" || notok "table $d" "ptpgen failed"
    for cc in gcc clang; do
        command -v $cc >/dev/null || continue
        if $cc -std=c99 -Wall -Wextra -pedantic -Werror -include "$tmp/t.h" -DUP=PTP_${n}X${m}_ -DLO=ptp_${n}x${m}_ \
            "$tmp/dump.c" -o "$tmp/dump" 2>"$tmp/err" && "$tmp/dump" >"$tmp/dump.txt" &&
            python3 "$tmp/cmp_table.py" "$tmp/t.json" "$tmp/dump.txt" 2>"$tmp/err"; then
            ok "table $d compiles with $cc -std=c99 -pedantic -Werror; idx, exact integer and nearest-float weights match"
        else
            notok "table $d with $cc" "$(tail -3 "$tmp/err")"
        fi
    done
done
"$P" --degree 12 --target table | grep -q 'No integer form' && ! "$P" --degree 12 --target table | grep -q iwgt &&
    ok "table 12x12 says why it has no 64-bit integer form" || notok "table 12x12" "integer form note missing"

# Stats: the paper's matrix for bicubic.
"$P" --degree 3 --target stats >"$tmp/s.txt"
if grep -q '^ 5 10 17 21 21 17 10  5$' "$tmp/s.txt" && grep -q '^total 516$' "$tmp/s.txt" &&
    [ "$(grep -c '^ *[0-9]' "$tmp/s.txt")" -eq 8 ]; then
    ok "stats 3x3 prints the paper's 8x8 matrix and total 516"
else
    notok "stats 3x3" "$(cat "$tmp/s.txt")"
fi
"$P" --degree 2x4 --target stats | grep -q 'planes of bidegree 4x10' && ok "stats 2x4 names the plane bidegree 4x10" ||
    notok "stats 2x4" "plane bidegree missing"

# The supported range: every bidegree up to 8x8 and the corners of the 16x16 limit derive
# (the degree reductions' zero residuals are checked on each).
bad=""
for n in 1 2 3 4 5 6 7 8; do
    for m in 1 2 3 4 5 6 7 8; do
        "$P" --degree ${n}x$m --target stats >/dev/null 2>"$tmp/err" || bad="$bad ${n}x$m"
    done
done
[ -z "$bad" ] && ok "every bidegree 1x1 to 8x8 derives" || notok "every bidegree 1x1 to 8x8 derives" "failed:$bad"
for d in 16x1 1x16 16x16; do
    "$P" --degree $d --target stats >"$tmp/s.txt" 2>"$tmp/err" && grep -q '^total [0-9]' "$tmp/s.txt" &&
        ok "bidegree $d (the limit) derives without overflow" || notok "bidegree $d derives" "$(cat "$tmp/err")"
done

# gcc and clang builds produce the same bytes.
if [ -n "${PTPGEN_OTHER:-}" ] && [ -x "$PTPGEN_OTHER" ]; then
    same=1
    for d in 1 2x3 3 5x1 8; do
        for t in json table stats; do
            cmp -s <("$P" --degree $d --target $t) <("$PTPGEN_OTHER" --degree $d --target $t) || same=0
        done
    done
    [ $same = 1 ] && ok "gcc and clang builds write identical bytes (json, table, stats)" ||
        notok "gcc and clang builds write identical bytes" "they differ"
fi

# Installation.
make -s install PREFIX="$tmp/prefix" CC=gcc >/dev/null 2>&1 && (cd / && "$tmp/prefix/bin/ptpgen" --degree 2 >/dev/null) &&
    ok "make install PREFIX=... installs a ptpgen that runs from any directory" ||
    notok "make install" "failed"
