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
for d in 0 -3 3x x3 3x0 0x3 abc 3x3x3 3X3x3 '' ' 3' 3.0 +3 '3 x3' 3Y3; do
    expect_fail "--degree '$d' is a usage error" 2 "degree" --degree "$d"
done
"$P" --degree 2X3 >"$tmp/a" && "$P" --degree 2x3 >"$tmp/b" && cmp -s "$tmp/a" "$tmp/b" &&
    ok "--degree 2X3 is 2x3" || notok "--degree 2X3 is 2x3" "refused or differs"
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
"$P" --help >"$tmp/help"
"$P" help >"$tmp/out" 2>"$tmp/err" && cmp -s "$tmp/out" "$tmp/help" && [ ! -s "$tmp/err" ] &&
    ok "ptpgen help prints the usage, exit 0" || notok "ptpgen help prints the usage" "$(head -2 "$tmp/out" "$tmp/err")"
# help verify|vectors (and verify --help, vectors -h) print that command's usage alone.
for a in "help verify:verify" "help vectors:vectors" "verify --help:verify" "vectors -h:vectors"; do
    c=${a#*:} a=${a%:*}
    "$P" $a >"$tmp/out" 2>"$tmp/err" && [ ! -s "$tmp/err" ] && head -1 "$tmp/out" | grep -q "^usage: ptpgen $c " &&
        ! grep -q -- '--threads-per-patch\|--list-targets\|--target' "$tmp/out" &&
        ok "ptpgen $a prints $c's usage alone, exit 0" || notok "ptpgen $a prints $c's usage alone" "$(head -2 "$tmp/out" "$tmp/err")"
done
# --help describes exactly the options of README.md's option table (README "Command line").
readme_opts=$(awk '/^## /{f = /^## Command line/} f' README.md | grep '^| `' | cut -d'|' -f2 |
    grep -o -- '--[a-z-]*' | sort -u | tr '\n' ' ')
help_opts=$(grep -E '^  (-[a-z], )?--' "$tmp/help" | grep -o -- '--[a-z-]*' | sort -u | tr '\n' ' ')
[ -n "$help_opts" ] && [ "$readme_opts" = "$help_opts" ] &&
    ok "--help describes the options of README.md's option table, no more, no fewer" ||
    notok "--help describes the options of README.md's option table" "README: $readme_opts; --help: $help_opts"
expect_fail "help with an unknown topic" 2 "help takes verify, vectors or nothing, not 'foo'" help foo
expect_fail "help with two topics" 2 "help takes verify, vectors or nothing, not 'x'" help verify x
"$P" --version >"$tmp/out" 2>&1 && grep -Eq '^ptpgen [0-9]+\.[0-9]+\.[0-9]+$' "$tmp/out" && ok "--version" ||
    notok "--version" "$(cat "$tmp/out")"

# --list-targets: the registry, one "name suffix options description" line per target.
"$P" --list-targets >"$tmp/targets" 2>"$tmp/err" && [ ! -s "$tmp/err" ] || notok "--list-targets" "$(cat "$tmp/err")"
targets=$(cut -d' ' -f1 "$tmp/targets" | tr '\n' ' ')
known=$("$P" --degree 3 --target none 2>&1 | sed -n 's/.*(expected \(.*\))$/\1/p' | sed 's/,//g; s/ or / /')
[ "$targets" = "$known " ] && [ "$(wc -l <"$tmp/targets")" -ge 8 ] &&
    ! grep -Ev '^[a-z]+ (-|[._a-z]+) (-|[a-z]+(,[a-z]+)*) [^ ].*$' "$tmp/targets" >/dev/null &&
    ok "--list-targets lists every target --target accepts (${targets% }), one well-formed line each" ||
    notok "--list-targets lists every target" "'$targets' against '$known'"
# Each target generates; where its output names its file (a banner), the name is the prefix
# without its '_' and the listed suffix, with --prefix too where the target takes it.
bad=""
while read -r t suffix opts _; do
    "$P" --degree 2x3 --target $t >"$tmp/g" 2>"$tmp/err" && [ -s "$tmp/g" ] || { bad="$bad $t"; continue; }
    name=$(head -1 "$tmp/g" | sed -n 's|^/\* \([^:]*\):.*|\1|p')
    [ -z "$name" ] || [ "$name" = "ptp_2x3$suffix" ] || bad="$bad $t($name)"
    case ",$opts," in *,prefix,*)
        "$P" --degree 2x3 --target $t --prefix cull_ | head -1 | grep -q "^/\* cull$suffix: " || bad="$bad $t(--prefix)" ;;
    esac
done <"$tmp/targets"
[ -z "$bad" ] && ok "every listed target generates, and banners name the file ptp_2x3<suffix> (cull<suffix> with --prefix cull_)" ||
    notok "listed targets and their suffixes" "failed:$bad"

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
assert doc["format"] == "ptpgen-planes/1", doc["format"]
if doc.get("domain") == "triangle":
    d = doc["degree"]
    assert doc["plane_degree"] == 3 * d - 3
    assert doc["points"] == (d + 1) * (d + 2) // 2
    assert doc["planes"] == (3 * d - 2) * (3 * d - 1) // 2
else:
    n, m = doc["degree"]
    assert "domain" not in doc
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
for d in 1 2 3 4; do
    "$P" --domain triangle --degree $d >"$tmp/tri$d.json" &&
        python3 tests/ref_derive.py --triangle $d >"$tmp/ref.json" &&
        python3 "$tmp/check.py" "$tmp/tri$d.json" "$tmp/ref.json" >"$tmp/err" 2>&1 &&
        ok "json triangle $d: well-formed and equal to the independent power-basis derivation (tests/ref_derive.py --triangle)" ||
        notok "json triangle $d equals the independent derivation" "$(tail -1 "$tmp/err")"
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
for d in 1x1 2x2 3x3 4x4 2x3 3x1 tri1 tri2 tri3 tri4; do
    case $d in
    tri*) args="--domain triangle --degree ${d#tri}" lo=ptp_${d}_ ;;
    *) args="--degree $d" lo=ptp_${d}_ ;;
    esac
    "$P" $args --target table -o "$tmp/t.h" && "$P" $args -o "$tmp/t.json" || notok "table $d" "ptpgen failed"
    for cc in gcc clang; do
        command -v $cc >/dev/null || continue
        if $cc -std=c99 -Wall -Wextra -pedantic -Werror -include "$tmp/t.h" -DUP=$(echo $lo | tr a-z A-Z) -DLO=${lo}table_ \
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

# The vendored C header and table header, implementation included, in one translation unit: no
# name collides, and the header's planes equal the table's loop.
cat >"$tmp/both.c" <<'C'
#define PTP_3X3_IMPLEMENTATION
#include "ptp_3x3.h"
#include "ptp_3x3_table.h"
#include <math.h>
#include <stdio.h>
static double cross4z(const float *a, const float *b, const float *c)
{
    return a[0] * ((double)b[1] * c[3] - (double)b[3] * c[1]) -
           b[0] * ((double)a[1] * c[3] - (double)a[3] * c[1]) +
           c[0] * ((double)a[1] * b[3] - (double)a[3] * b[1]);
}
int main(void)
{
    float cp[PTP_3X3_POINTS][4], t[PTP_3X3_PLANES][4];
    double z[PTP_3X3_PLANES] = {0};
    int x, p, c;
    for (p = 0; p < PTP_3X3_POINTS; p++)
        for (c = 0; c < 4; c++)
            cp[p][c] = (float)((p * 7 + c * 3) % 11) / 11.0f - 0.5f + (c == 3);
    ptp_3x3_planes((const float(*)[4])cp, t);
    for (x = 0; x < PTP_3X3_TERMS; x++)
    {
        const unsigned short *e = ptp_3x3_table_idx[x];
        z[e[0]] += ptp_3x3_table_wgt[x] * cross4z(cp[e[1]], cp[e[2]], cp[e[3]]);
    }
    for (p = 0; p < PTP_3X3_PLANES; p++)
        if (fabs(t[p][2] - z[p]) > 1e-4 * (1 + fabs(z[p]))) {
            printf("plane %d: header %g, table %g\n", p, t[p][2], z[p]);
            return 1;
        }
    return 0;
}
C
for cc in gcc clang; do
    command -v $cc >/dev/null || continue
    if $cc -std=c99 -Wall -Wextra -pedantic -Werror -Iout/3x3 "$tmp/both.c" -o "$tmp/both" -lm 2>"$tmp/err" &&
        "$tmp/both" >"$tmp/err" 2>&1; then
        ok "out/3x3/ptp_3x3.h (implementation) and ptp_3x3_table.h compile together with $cc; planes agree"
    else
        notok "ptp_3x3.h and ptp_3x3_table.h together with $cc" "$(head -3 "$tmp/err" | tr '\n' ' ')"
    fi
done

# Stats: the paper's matrix for bicubic.
"$P" --degree 3 --target stats >"$tmp/s.txt"
if grep -q '^ 5 10 17 21 21 17 10  5$' "$tmp/s.txt" && grep -q '^total 516$' "$tmp/s.txt" &&
    [ "$(sed -n '/^terms per plane/,/^total/p' "$tmp/s.txt" | grep -c '^ *[0-9]')" -eq 8 ] &&
    grep -q '^rounds R = 33, lower bound LB = 33' "$tmp/s.txt" &&
    grep -q '^efficiency 516 / (R \* P) = 516 / 528 = 97.7%$' "$tmp/s.txt" &&
    [ "$(sed -n '/^owning thread/,/^terms per thread/p' "$tmp/s.txt" | grep -c '^ *[0-9]')" -eq 8 ]; then
    ok "stats 3x3 prints the paper's 8x8 matrix, total 516, the owner map, R = LB = 33 and the efficiency"
else
    notok "stats 3x3" "$(cat "$tmp/s.txt")"
fi
"$P" --degree 2x4 --target stats | grep -q 'planes of bidegree 4x10' && ok "stats 2x4 names the plane bidegree 4x10" ||
    notok "stats 2x4" "plane bidegree missing"

# The operation counts of stats and of the header's MULS and FLOPS are those of the straight-line
# code as emitted: products " * ", multiply-adds VFMA(S) and the frame's VLOCAL, its reciprocal
# VRECIP0 (a flop on neither pipe), sums " + ", " - ", "+=", "-=" in the lanes body (loads, value
# stores and masks aside), in clip and world space; a doubling's repeats in a statement,
# ((u + u) + (u + u)), are one sum each (the compiler shares them).
count_ops() { # HEADER -> "muls flops adds"
    awk '/_vload\(q/ && !f {f = 1} /\/\* Strict:/ {f = 0}
         f && !/if \(d\)|vstoref\(/ {
             gsub(/_vload\([^)]*\)/, "L"); line = $0
             for (k = 1; k <= 6; k++)
                 if (gsub("\\(" (k > 1 ? "D" k - 1 : "u") " \\+ " (k > 1 ? "D" k - 1 : "u") "\\)", "D" k, line))
                     a++
             p += gsub(/ \* /, "", line); m += gsub(/VFMAS?\(|VLOCAL\(/, "", line)
             r += gsub(/VRECIP0\(/, "", line)
             a += gsub(/ \+ | - |\+=|-=/, "", line)
         } END {print p + m, p + 2 * m + a + r, a}' "$1"
}
for args in "--degree 3" "--domain triangle --degree 3" "--degree 2x3 --space world"; do
    stats=${args% --space world}
    sp=clip
    case $args in *world*) sp=world ;; esac
    # shellcheck disable=SC2086
    "$P" $args --target c -o "$tmp/ops.h" && "$P" $stats --target stats >"$tmp/ops.txt"
    got=$(count_ops "$tmp/ops.h")
    line=$(grep '^C straight-line code' "$tmp/ops.txt")
    if [ $sp = clip ]; then
        want=$(echo "$line" | sed -E 's/.*per patch ([0-9]+) flops, ([0-9]+) on the multiply pipes, ([0-9]+) on the add.*/\2 \1 \3/')
    else
        want=$(echo "$line" | sed -E 's/.*\), ([0-9]+), ([0-9]+) and ([0-9]+) \(world.*/\2 \1 \3/')
    fi
    hdr="$(grep -E '#define [A-Z0-9_]+_MULS ' "$tmp/ops.h" | awk '{print $3}') $(grep -E '#define [A-Z0-9_]+_FLOPS ' "$tmp/ops.h" | awk '{print $3}')"
    [ "$got" = "$want" ] && [ "$hdr" = "${want% *}" ] &&
        ok "$args: stats and MULS/FLOPS count the emitted code's operations ($got: multiply pipes, flops, add pipes)" ||
        notok "$args: operation counts" "emitted $got, stats $want, header $hdr"
done

# classify_batch prefetches AHEAD blocks on: at least 1,600 multiply-pipe operations (MULS) of
# work, 1 to 8 blocks.
for args in "--degree 3" "--domain triangle --degree 3" "--degree 2" "--domain triangle --degree 1"; do
    # shellcheck disable=SC2086
    "$P" $args --target c -o "$tmp/pf.h"
    m=$(awk '/^#define [A-Z0-9_]+_MULS / {print $3}' "$tmp/pf.h")
    a=$(awk '/^#define [A-Z0-9_]+_AHEAD / {print $3}' "$tmp/pf.h")
    want=$(((1600 + m - 1) / m))
    [ $want -gt 8 ] && want=8
    [ -n "$m" ] && [ "$a" = "$want" ] && grep -q "_lanes_block(soa, n, eye, cls + p);" "$tmp/pf.h" &&
        ok "$args: classify_batch prefetches $a blocks ahead (MULS $m) and runs the constant-stride lanes" ||
        notok "$args: the prefetch distance" "MULS $m, AHEAD $a, want $want"
done

# --refine and --certified: where they apply, and --refine's range.
expect_fail "--refine 7 names the limit" 2 "largest allowed is 6" --degree 3 --target c --refine 7
expect_fail "--refine x is a usage error" 2 "expected a whole number" --degree 3 --target c --refine x
expect_fail "--refine outside the C target is refused" 2 "--refine applies to target c \\(not glsl\\)$" --degree 3 --target glsl --refine 2
"$P" --degree 3 --target c --refine 2 --certified -o "$tmp/cr.h" &&
    grep -q '^#define PTP_3X3_CERTIFIED_REFINE2_CERTIFIED 1$' "$tmp/cr.h" &&
    grep -q '^static unsigned ptp_3x3_certified_refine2_split_class(const ptp_3x3_certified_refine2_cval \*d, int levels)$' "$tmp/cr.h" &&
    ok "--refine 2 --certified: prefix ptp_3x3_certified_refine2_, split_class on values with bounds" ||
    notok "--refine 2 --certified" "$(grep -m2 'CERTIFIED 1\|split_class(' "$tmp/cr.h" | tr '\n' ' ')"
expect_fail "--certified does not apply to verify" 2 "does not apply to verify" verify x.json --certified
"$P" --degree 3 --target c --certified --refine 0 -o "$tmp/c.h" && grep -q 'Generated by ptpgen .*: ptpgen --degree 3x3 --target c --certified$' "$tmp/c.h" &&
    ok "--certified is in the banner's command line, --refine 0 is no refinement" ||
    notok "--certified in the banner" "$(grep -m1 Generated "$tmp/c.h")"
# The table kernels' bounds take each target's unit roundoff: WGSL, which fixes no rounding mode,
# 2^-23, the others 2^-24. With --coordinates absolute every certified table kernel's terms read
# differences of points (two more roundings on each of a term's monomials), so the first plane's
# tau_k (one term) is the same on GLSL, HLSL, OpenCL and CUDA (the same schedule and table) and
# twice that on WGSL, whose --certified kernel is the table kernel over differences always. In
# patch-local coordinates (the default) the four agree again, with the frame's roundings instead.
for t in glsl hlsl opencl cuda wgsl; do
    "$P" --degree 3 --certified $([ $t = wgsl ] || echo --kernel table) --target $t -o "$tmp/k.$t" ||
        notok "--certified --target $t" "ptpgen failed"
    if [ $t = wgsl ]; then
        cp "$tmp/k.$t" "$tmp/ka.$t"
    else
        "$P" --degree 3 --certified --kernel table --coordinates absolute --target $t -o "$tmp/ka.$t" ||
            notok "--certified --coordinates absolute --target $t" "ptpgen failed"
    fi
done
first_tau() { # first_tau FILE...: the first tau_k of each
    for f in "$@"; do
        awk '/_tau_k[:[]/ { f = 1; next } f { gsub(/f,?/, ""); print $1; exit }' "$f"
    done | paste -sd' '
}
r=$(first_tau "$tmp"/ka.{glsl,hlsl,opencl,cuda,wgsl}) l=$(first_tau "$tmp"/k.{glsl,hlsl,opencl,cuda})
awk -v r="$r" -v l="$l" 'BEGIN { n = split(r, a, " "); m = split(l, b, " "); q = a[5] / a[1] / 2
    exit !(n == 5 && a[1] > 0 && a[2] == a[1] && a[3] == a[1] && a[4] == a[1] && q > 0.9999 && q < 1.0001 &&
           m == 4 && b[1] > 0 && b[2] == b[1] && b[3] == b[1] && b[4] == b[1] && b[1] != a[1]) }' &&
    ok "the certified GPU kernels' bounds agree, WGSL's twice the others' (u = 2^-23 against 2^-24)" ||
    notok "the certified GPU kernels' bounds agree, WGSL's twice the others'" "first tau_k: absolute ${r:-none}, local ${l:-none}"
# The certified table kernels' terms read b_j, b_k - b_j, b_l - b_j with --coordinates absolute
# (the generated diff, two a term; WGSL's through the template's fenced sub_rn) and the sheared
# points in patch-local coordinates, like the plain ones.
for t in glsl hlsl opencl cuda wgsl; do
    "$P" --degree 3 --kernel table --target $t -o "$tmp/p.$t" &&
        n=$(grep -c '_diff(pts' "$tmp/ka.$t") && [ "$(grep -c '_diff(' "$tmp/p.$t")" = 0 ] &&
        [ "$n" -gt 0 ] && [ "$n" = $((2 * $(grep -c '_certified_cross4z(pts' "$tmp/ka.$t"))) ] &&
        { [ $t = wgsl ] || [ "$(grep -c '_diff(' "$tmp/k.$t")" = 0 ]; } &&
        ok "the certified $t table kernel's terms read differences of points as given, the plain one's and the patch-local one's the points" ||
        notok "the certified $t table kernel's terms read differences of points" "diff in terms: ${n:-none}"
done
grep -q 'sub_rn(b, a)' "$tmp/k.wgsl" && ok "the certified WGSL kernel's differences go through sub_rn" ||
    notok "the certified WGSL kernel's differences go through sub_rn" "$(grep -m1 -A2 '_diff(b' "$tmp/k.wgsl")"

# The default prefix names the variant: ptp_NxM_, then world_, degenerate_, certified_, refineK_
# for the options given, in that order, in every target that takes them; the file name follows.
for c in "c --space world --rule degenerate --certified:ptp_3x3_world_degenerate_certified_" \
    "c --refine 2 --rule degenerate:ptp_3x3_degenerate_refine2_" "c --rule strict --space clip:ptp_3x3_" \
    "opencl --certified --space world:ptp_3x3_world_certified_" "cuda --rule degenerate:ptp_3x3_degenerate_" \
    "glsl --space world --planes:ptp_3x3_world_" "table:ptp_3x3_"; do
    pfx=${c#*:} file=${pfx%_}
    if "$P" --degree 3 --target ${c%%:*} -o "$tmp/v.out" && grep -q "\b${pfx}[a-z]" "$tmp/v.out" &&
        head -1 "$tmp/v.out" | grep -q "^/\* ${file}[._]" && ! tail -n +2 "$tmp/v.out" | grep -v "^ \* Generated by" |
        grep -o "ptp_3x3_[a-z0-9_]*" | grep -v "^${pfx}" | grep -qv "^ptp_3x3_table"; then
        ok "--target ${c%%:*}: default prefix $pfx, file name $file"
    else
        notok "--target ${c%%:*}: default prefix $pfx" "$(head -1 "$tmp/v.out"; grep -o "ptp_3x3_[a-z0-9_]*" "$tmp/v.out" | sort -u | head -3)"
    fi
done

# Each generation option is accepted exactly by the targets --list-targets names for it, and
# changes their bytes (besides the command line they quote); any other target refuses it (exit 2)
# with one line naming the targets it applies to.
# opt_args OPTION [TARGET_OPTIONS]: the arguments that set OPTION (the GPU targets take a schedule
# for their table kernel).
opt_args() {
    case $1 in
    space) echo --space world ;; rule) echo --rule degenerate ;; planes) echo --planes ;;
    certified) echo --certified ;; refine) echo --refine 1 ;; prefix) echo --prefix x_ ;;
    schedule) echo --threads-per-patch 2 --patches-per-block 3 ;;
    kernel) echo --kernel table ;;
    esac
    [[ $1 = schedule && ,${2:-}, == *,kernel,* ]] && echo --kernel table
}
for opt in space rule planes certified refine prefix schedule kernel; do
    bad="" takers=$(awk -v o="$opt" '("," $3 ",") ~ ("," o ",") { printf "%s%s", s, $1; s = ", " }' "$tmp/targets")
    [ -n "$takers" ] || bad=" no target takes it"
    while read -r t _ opts _; do
        "$P" --degree 2x3 --target $t $(opt_args $opt "$opts") >"$tmp/out" 2>"$tmp/err"
        rc=$?
        case ",$opts," in
        *,$opt,*) [ $rc -eq 0 ] && [ -s "$tmp/out" ] &&
            ! cmp -s <(grep -v 'ptpgen --degree' "$tmp/out") <("$P" --degree 2x3 --target $t | grep -v 'ptpgen --degree') ||
            bad="$bad $t(exit $rc or the same bytes)" ;;
        *) [ $rc -eq 2 ] && [ ! -s "$tmp/out" ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] &&
            grep -Eq "^ptpgen: --[a-z-]+ applies to targets? $takers \(not $t\)$" "$tmp/err" ||
            bad="$bad $t(exit $rc: $(cat "$tmp/err"))" ;;
        esac
    done <"$tmp/targets"
    [ -z "$bad" ] && ok "$(opt_args $opt | cut -d' ' -f1) changes the output of $takers; other targets refuse it, naming those" ||
        notok "$opt applies only where listed" "$bad"
done
# The GPU targets' two forms: options of one are refused with the other, each with one line.
expect_fail "--threads-per-patch needs the table kernel on a GPU target" 2 "--threads-per-patch applies to --kernel table$" --degree 3 --target glsl --threads-per-patch 4
# --certified keeps the form: the straight-line kernel where the target certifies it, WGSL's the
# table kernel.
for t in glsl hlsl opencl cuda wgsl; do
    k=slp
    [ $t = wgsl ] && k=table
    "$P" --degree 3 --target $t --certified -o "$tmp/d.$t" && "$P" --degree 3 --target $t --certified \
        --kernel $k -o "$tmp/e.$t" && cmp -s <(sed 1,3d "$tmp/d.$t") <(sed 1,3d "$tmp/e.$t") &&
        ok "--certified --target $t is --kernel $k" || notok "--certified --target $t is --kernel $k" "the outputs differ"
done
expect_fail "WGSL's straight-line code is not certified" 2 "--certified wgsl code is the table kernel" --degree 3 --target wgsl --certified --kernel slp
expect_fail "--certified --kernel indexed is refused" 2 "--kernel indexed is not certified" --degree 3 --target glsl --certified --kernel indexed
expect_fail "--certified GPU B-spline input is refused" 2 "with --certified is the C target's" --degree 3 --target glsl --certified --kernel slp --basis bspline
expect_fail "--stage function with --kernel table is refused" 2 "not --kernel table$" --degree 3 --target hlsl --stage function --kernel table
expect_fail "--stage function with --planes is refused" 2 "--planes applies to kernels" --degree 3 --target wgsl --stage function --planes
expect_fail "--stage function --certified is refused for WGSL" 2 "is the table kernel" --degree 3 --target wgsl --stage function --certified
expect_fail "--coordinates with WGSL's certified table kernel is refused" 2 "wgsl's certified table kernel reads the coordinates as given" --degree 3 --target wgsl --certified --coordinates local
expect_fail "--kernel lanes is OpenCL's" 2 "--kernel lanes is OpenCL's" --degree 3 --target glsl --kernel lanes
expect_fail "--kernel lanes is not certified" 2 "not with --certified$" --degree 3 --target opencl --kernel lanes --certified
expect_fail "--kernel lanes writes no values" 2 "not with --planes$" --degree 3 --target opencl --kernel lanes --planes
expect_fail "--kernel lanes takes whole vectors of patches" 2 "must be a multiple of 16" --degree 3 --target opencl --kernel lanes --patches-per-block 40
expect_fail "an unknown --kernel is named" 2 "kernel" --degree 3 --target glsl --kernel fast
expect_fail "--planes for the C header is refused" 2 "--planes applies to targets glsl, hlsl, opencl, cuda, wgsl \\(not c\\)$" --degree 3 --target c --planes
expect_fail "--space for json is refused" 2 "--space applies to targets c, glsl, hlsl, opencl, cuda, wgsl \\(not json\\)" --degree 3 --space world

# Each option at most once.
expect_fail "a repeated --degree" 2 "option --degree is given twice" --degree 3 --degree 4
expect_fail "-o and --output together" 2 "option --output is given twice" --degree 3 -o "$tmp/x" --output "$tmp/y"
expect_fail "a repeated flag" 2 "option --planes is given twice" --degree 3 --target glsl --planes --planes
expect_fail "a repeated --seed" 2 "option --seed is given twice" vectors --degree 3 --count 2 --seed 1 --seed=2

# Scheduler options: bad values are usage errors.
for v in 0 -1 abc 1025 4x ''; do
    expect_fail "--threads-per-patch '$v' is a usage error" 2 "threads-per-patch" --degree 3 --threads-per-patch "$v"
done
expect_fail "a huge --threads-per-patch is named as given" 2 "'99999999999': the largest allowed is 1024" \
    --degree 3 --threads-per-patch 99999999999
expect_fail "--threads-per-patch beyond the planes is refused" 2 "exceeds the 64 planes" --degree 3 --threads-per-patch 65
for v in 0 -2 x 1025; do
    expect_fail "--patches-per-block '$v' is a usage error" 2 "patches-per-block" --degree 3 --patches-per-block "$v"
done
expect_fail "P*Q over 1024 is refused" 2 "1024" --degree 3 --threads-per-patch 16 --patches-per-block 65
expect_fail "--threads-per-patch without its argument" 2 "needs an argument" --degree 3 --threads-per-patch
expect_fail "unknown --space" 2 "unknown space 'eye' \\(expected clip or world\\)" --degree 3 --space eye
expect_fail "unknown --rule" 2 "unknown rule 'lenient' \\(expected strict or degenerate\\)" --degree 3 --rule lenient
for v in 3abc 'a-b' '' 'x y' 'abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmn'; do
    expect_fail "--prefix '$v' is a usage error" 2 "prefix" --degree 3 --target c --prefix "$v"
done
# A prefix without a trailing '_' gets one: --prefix ptp_3x3 names ptp_3x3_planes.
"$P" --degree 3 --target c --prefix ptp_3x3 >"$tmp/p1.out" && "$P" --degree 3 --target c --prefix ptp_3x3_ >"$tmp/p2.out" &&
    grep -q 'ptp_3x3_planes' "$tmp/p1.out" && ! grep -q 'ptp_3x3planes' "$tmp/p1.out" && cmp -s "$tmp/p1.out" "$tmp/p2.out" &&
    ok "--prefix ptp_3x3 appends the '_': the same file as --prefix ptp_3x3_" ||
    notok "--prefix ptp_3x3 appends the '_'" "$(grep -o 'ptp_3x3[a-z]*' "$tmp/p1.out" | sort -u | head -3 | tr '\n' ' ')"
"$P" --degree 2x3 --target opencl --prefix cull_ | grep -q 'void cull_classify(' &&
    ! "$P" --degree 2x3 --target opencl --prefix cull_ | grep -q 'ptp_2x3' &&
    ok "--prefix names every generated identifier" || notok "--prefix" "default names remain"

# The longest prefix accepted (62 characters) writes the same code as a short one: with the
# prefix (and its upper case) renamed and runs of spaces squeezed (alignment follows the names'
# length), everything below the banner is equal, so no expression was cut short.
long=$(printf 'p%.0s' $(seq 61))_
long_up=$(echo "$long" | tr a-z A-Z)
bad=""
for d in "--degree 4" "--domain triangle --degree 4"; do
    for t in c glsl hlsl opencl cuda wgsl; do
        for v in "" "--planes" "--certified" "--certified --space world --rule degenerate" "--refine 2"; do
            "$P" $d --target $t $v --prefix q_ >"$tmp/short.out" 2>/dev/null || continue
            "$P" $d --target $t $v --prefix "$long" | sed "s/$long/q_/g; s/$long_up/Q_/g" >"$tmp/long.out"
            cmp -s <(tail -n +6 "$tmp/short.out" | sed 's/  */ /g') \
                   <(tail -n +6 "$tmp/long.out" | sed 's/  */ /g') || bad="$bad [$d $t $v]"
        done
    done
done
[ -z "$bad" ] && ok "a 62-character --prefix writes the same code as a short one (every target, degree 4 and triangle 4)" ||
    notok "a 62-character --prefix" "differs:$bad"

# The schedule in json: every term exactly once, only in its owner's slots, R = the largest load.
cat >"$tmp/sched.py" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
s = doc["schedule"]
P, R = s["threads_per_patch"], s["rounds"]
want_P, want_Q = int(sys.argv[2]), int(sys.argv[3])
assert (P, s["patches_per_block"]) == (want_P, want_Q), (P, s["patches_per_block"])
owner, slots, terms = s["owner"], s["slots"], doc["terms"]
assert len(owner) == doc["planes"] and len(slots) == R * P
assert all(0 <= o < P for o in owner) and set(owner) == set(range(P)), "every thread owns a plane"
seen = []
for x, e in enumerate(slots):
    if e is None:
        continue
    assert owner[e[0]] == x % P, ("slot of a plane another thread owns", x, e)
    seen.append(tuple(e))
assert sorted(seen) == sorted(tuple(t) for t in terms), "slots are not the terms, each once"
loads = [sum(1 for x, e in enumerate(slots) if e is not None and x % P == t) for t in range(P)]
assert loads == s["loads"] and R == max(loads), (loads, s["loads"], R)
count = [0] * doc["planes"]
for t in terms:
    count[t[0]] += 1
lb = max(-(-len(terms) // P), max(count))
assert s["lower_bound"] == lb and R >= lb and (R > lb or s["proven_optimal"])
for t in range(P):  # round-major: a thread's padding comes after its terms
    mine = [slots[r * P + t] for r in range(R)]
    assert None not in mine[:loads[t]] and all(e is None for e in mine[loads[t]:])
PY
# sched_case P Q ARGS...: ptpgen ARGS gives a valid schedule with P threads and Q patches.
sched_case() {
    local Pw=$1 Q=$2
    shift 2
    "$P" "$@" >"$tmp/s.json" && python3 "$tmp/sched.py" "$tmp/s.json" "$Pw" "$Q" >"$tmp/err" 2>&1 &&
        ok "schedule for $*: P=$Pw Q=$Q, each term once, owner-only slots, R = max load >= LB" ||
        notok "schedule for $*" "$(tail -1 "$tmp/err")"
}
sched_case 16 8 --degree 3
sched_case 7 18 --degree 3x3 --threads-per-patch 7
sched_case 32 4 --degree 2x3 --threads-per-patch 32
sched_case 4 32 --degree 1x1
sched_case 16 3 --degree 4x2 --patches-per-block 3
sched_case 32 4 --degree 5
sched_case 1 128 --degree 6x1 --threads-per-patch 1

# The table's scheduled arrays, run as P threads would, give the same planes as the plain loop.
cat >"$tmp/run_sched.c" <<'C'
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
static double cross4z(const double *a, const double *b, const double *c)
{
    return a[0] * (b[1] * c[3] - b[3] * c[1]) - b[0] * (a[1] * c[3] - a[3] * c[1]) +
           c[0] * (a[1] * b[3] - a[3] * b[1]);
}
int main(void)
{
    static double b[CAT(UP, POINTS)][4], plain[CAT(UP, PLANES)], sched[CAT(UP, PLANES)];
    int x, p, c;
    srand(7);
    for (p = 0; p < CAT(UP, POINTS); p++)
        for (c = 0; c < 4; c++)
            b[p][c] = rand() / (double)RAND_MAX - 0.5 + (c == 3);
    for (x = 0; x < CAT(UP, TERMS); x++)
        plain[CAT(LO, idx)[x][0]] += CAT(LO, wgt)[x] *
            cross4z(b[CAT(LO, idx)[x][1]], b[CAT(LO, idx)[x][2]], b[CAT(LO, idx)[x][3]]);
    for (x = 0; x < CAT(UP, SLOTS); x++) { /* thread x % THREADS, round x / THREADS */
        const unsigned short *e = CAT(LO, sched_idx)[x];
        if (CAT(LO, owner)[e[0]] != x % CAT(UP, THREADS)) {
            printf("slot %d writes plane %u of thread %u\n", x, e[0], CAT(LO, owner)[e[0]]);
            return 1;
        }
        sched[e[0]] += CAT(LO, sched_wgt)[x] * cross4z(b[e[1]], b[e[2]], b[e[3]]);
    }
    for (p = 0; p < CAT(UP, PLANES); p++)
        if (fabs(plain[p] - sched[p]) > 1e-12 * (1 + fabs(plain[p]))) {
            printf("plane %d: %g vs %g\n", p, plain[p], sched[p]);
            return 1;
        }
    return 0;
}
C
for c in "3x3" "2x3 --threads-per-patch 8" "3x1 --threads-per-patch 5" "4x4"; do
    set -- $c
    d=$1; n=${d%x*}; m=${d#*x}
    if "$P" --degree "$@" --target table -o "$tmp/t.h" &&
        gcc -std=c99 -Wall -Wextra -pedantic -Werror -include "$tmp/t.h" -DUP=PTP_${n}X${m}_ -DLO=ptp_${n}x${m}_table_ \
            "$tmp/run_sched.c" -o "$tmp/run_sched" -lm 2>"$tmp/err" && "$tmp/run_sched" >"$tmp/err" 2>&1; then
        ok "table $c: the scheduled loop (owner-only writes, padding included) equals the plain loop"
    else
        notok "table $c scheduled loop" "$(tail -2 "$tmp/err")"
    fi
done

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
        for t in $targets; do
            cmp -s <("$P" --degree $d --target $t) <("$PTPGEN_OTHER" --degree $d --target $t) || same=0
        done
    done
    [ $same = 1 ] && ok "gcc and clang builds write identical bytes (json, table, stats)" ||
        notok "gcc and clang builds write identical bytes" "they differ"
fi

# Generated kernels: a banner with the version, command line and "do not edit", no timestamps:
# two runs give the same bytes.
# (--planes where the target takes it.)
awk '$3 ~ /(^|,)space(,|$)/ { print $1, ($3 ~ /(^|,)planes(,|$)/ ? "--planes" : "") }' "$tmp/targets" >"$tmp/kernels"
while read -r t pl; do
    "$P" --degree 2x3 --target $t --space world $pl >"$tmp/k1" && "$P" --degree 2x3 --target $t --space world $pl >"$tmp/k2"
    if cmp -s "$tmp/k1" "$tmp/k2" && head -3 "$tmp/k1" | grep -q "Generated by ptpgen [0-9.]*: ptpgen --degree 2x3 --target $t --space world${pl:+ $pl}\$" &&
        head -3 "$tmp/k1" | grep -q "do not edit" && ! grep -Eq '20[0-9][0-9]-[0-9][0-9]-[0-9][0-9]|[0-9]:[0-9][0-9]:[0-9][0-9]' "$tmp/k1"; then
        ok "$t kernel: banner with version and command line, deterministic bytes, no timestamp"
    else
        notok "$t kernel banner" "$(head -3 "$tmp/k1")"
    fi
done <"$tmp/kernels"

# verify and vectors: usage errors.
expect_fail "verify without a file" 2 "missing the FILE" verify
expect_fail "verify of a missing file" 2 "cannot read $tmp/none.h" verify "$tmp/none.h"
expect_fail "verify with a generator option" 2 "option --target does not apply to verify" verify out/3x3/ptp_3x3_table.h --target glsl
expect_fail "vectors without --count and --seed" 2 "vectors needs --count" vectors --degree 3
expect_fail "vectors --count 0" 2 "vectors needs --count" vectors --degree 3 --count 0 --seed 1
expect_fail "vectors --count too large" 2 "largest allowed is 1000000" vectors --degree 3 --count 1000001 --seed 1
expect_fail "vectors --seed not a number" 2 "--seed 'x'" vectors --degree 3 --count 5 --seed x
expect_fail "--count outside vectors" 2 "option --count does not apply to code generation" --degree 3 --count 5

# verify accepts every vendored table and json, and names a wrong one (exit 1).
bad=""
for f in out/*x*/ptp_*_table.h out/*x*/ptp_*.json; do
    d=$(basename "$(dirname "$f")")
    "$P" verify "$f" --degree "$d" >"$tmp/out" 2>&1 || bad="$bad $f"
done
[ -z "$bad" ] && ok "verify accepts every vendored table and json (exit 0)" || notok "verify accepts the vendored tables" "rejected:$bad"
sed '0,/-9.0f/s//-9.5f/' out/3x3/ptp_3x3_table.h >"$tmp/wrong.h"
"$P" verify "$tmp/wrong.h" >"$tmp/out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "wrong.h:[0-9]*:.*weight" "$tmp/out" &&
    ok "verify names a wrong weight with its line, exit 1" || notok "verify of a wrong weight" "exit $rc: $(head -2 "$tmp/out")"

# --domain triangle: triangular patches of one degree; the json names the domain.
"$P" --domain triangle --degree 3 >"$tmp/t3.json" && "$P" --degree 3 --domain=triangle >"$tmp/t3b.json" &&
    cmp -s "$tmp/t3.json" "$tmp/t3b.json" && grep -q '"command": "ptpgen --domain triangle --degree 3 --target json"' "$tmp/t3.json" &&
    grep -q '^  "domain": "triangle",$' "$tmp/t3.json" && grep -q '^  "degree": 3,$' "$tmp/t3.json" &&
    grep -q '^  "plane_degree": 6,$' "$tmp/t3.json" && grep -q '^  "points": 10,$' "$tmp/t3.json" &&
    grep -q '^  "planes": 28,$' "$tmp/t3.json" &&
    ok "--domain triangle --degree 3: json with domain, degree 3, plane degree 6, 10 points, 28 planes (either option first)" ||
    notok "--domain triangle json" "$(head -8 "$tmp/t3.json")"
"$P" --domain triangle --degree 1 | tr -d ' \n' | grep -q '"terms":\[\[0,0,1,2,"1"\]\]' &&
    ok "--domain triangle --degree 1: one term, t_0 = cross4(b0, b1, b2)" || notok "triangle degree 1" "other terms"
"$P" --degree 3 >"$tmp/q.json" && "$P" --domain quad --degree 3 >"$tmp/q2.json" && cmp -s "$tmp/q.json" "$tmp/q2.json" &&
    ! grep -q '"domain"' "$tmp/q.json" && ok "--domain quad is the default, byte for byte, and its json names no domain" ||
    notok "--domain quad" "differs"
"$P" --domain triangle --degree 3 --target c >"$tmp/c3.h" && "$P" --degree 2x3 --target c >"$tmp/q23.h" &&
    grep -q '^#define PTP_TRI3_DOMAIN_TRIANGLE 1$' "$tmp/c3.h" && grep -q '^#define PTP_TRI3_DEGREE 3$' "$tmp/c3.h" &&
    ! grep -q '^#define .*\(DEGREE_U\|DOMAIN_QUAD\)' "$tmp/c3.h" && grep -q '^#define PTP_2X3_DOMAIN_QUAD 1$' "$tmp/q23.h" &&
    grep -q '^#define PTP_2X3_DEGREE_V 3$' "$tmp/q23.h" && ! grep -q '^#define .*DOMAIN_TRIANGLE' "$tmp/q23.h" &&
    ok "C headers record their domain: DOMAIN_TRIANGLE and DEGREE, or DOMAIN_QUAD and DEGREE_U, DEGREE_V" ||
    notok "C header domain macros" "$(grep -h 'DOMAIN\|DEGREE' "$tmp/c3.h" "$tmp/q23.h" | tr '\n' ' ')"
"$P" --domain triangle --degree 3 --target table >"$tmp/t3.h" && grep -q 'static const unsigned short ptp_tri3_table_idx\[PTP_TRI3_TERMS\]' "$tmp/t3.h" &&
    grep -q 'Control point k = (3-i)(4-i)/2 + 3-i-j' "$tmp/t3.h" &&
    ok "--domain triangle --target table: prefix ptp_tri3_, the triangular numbering" || notok "triangle table" "$(head -5 "$tmp/t3.h")"
"$P" --domain triangle --degree 3 --target stats >"$tmp/s" &&
    [ "$(sed -n '/^terms per plane/,/^total/p' "$tmp/s" | sed '1d;$d' | awk '{ printf "%d", NF }')" = 1234567 ] &&
    grep -q '^degree 3: 10 points, planes of degree 6: 28 planes, 105 terms$' "$tmp/s" &&
    ok "--domain triangle --target stats: 105 terms, the counts printed as a triangle" || notok "triangle stats" "$(head -9 "$tmp/s")"
bad=""
while read -r t suffix opts desc; do
    "$P" --domain triangle --degree 2 --target $t >"$tmp/o" 2>"$tmp/err" && [ -s "$tmp/o" ] || bad="$bad $t"
    case ",$opts," in *,space,*)
        head -1 "$tmp/o" | grep -q "^/\* ptp_tri2$suffix: back-patch culling of degree 2 triangular Bezier patches" &&
            grep -q 'k = (2-i)(3-i)/2 + 2-i-j with b_ijk weighted by u^i v^j w^k' "$tmp/o" || bad="$bad $t(banner)" ;;
    esac
done <"$tmp/targets"
[ -z "$bad" ] && ok "--domain triangle: every target generates; the C and kernel banners name ptp_tri2<suffix> and the triangular numbering" ||
    notok "--domain triangle targets" "failed:$bad"
expect_fail "--domain triangle --degree 3x3 is a usage error" 2 "--degree for triangles takes one degree" --domain triangle --degree 3x3
expect_fail "--domain triangle --degree 29 names the limit" 2 "largest supported degree is 28" --domain triangle --degree 29
expect_fail "--domain hexagon is a usage error" 2 "unknown domain 'hexagon' \(expected quad or triangle\)" --domain hexagon --degree 3
expect_fail "--domain triangle without --degree" 2 "missing --degree N \(" --domain triangle
"$P" --domain triangle --degree 3 --target c --refine 2 -o "$tmp/r3.h" &&
    grep -q 'Generated by ptpgen .*: ptpgen --domain triangle --degree 3 --target c --refine 2$' "$tmp/r3.h" &&
    grep -q '^static unsigned ptp_tri3_refine2_split_class(const float \*d, int levels)$' "$tmp/r3.h" &&
    grep -q '^static void ptp_tri3_refine2_split_piece(' "$tmp/r3.h" &&
    grep -q '^    cn = (d\[0\] < 0.0f) + (d\[21\] < 0.0f) + (d\[27\] < 0.0f);$' "$tmp/r3.h" &&
    grep -q '^#define PTP_TRI3_REFINE2_REFINE 2$' "$tmp/r3.h" &&
    ok "--domain triangle --refine 2: prefix ptp_tri3_refine2_, the triangular split, corners 0, 21, 27 of degree 6" ||
    notok "--domain triangle --refine" "$(grep -m3 'split_class\|cn =' "$tmp/r3.h" | tr '\n' ' ')"
expect_fail "--domain triangle --refine outside the C target is refused" 2 "--refine applies to target c \(not cuda\)$" --domain triangle --degree 2 --target cuda --refine 2
"$P" --domain triangle --degree 2 --target c --refine 2 --certified -o "$tmp/tcr.h" &&
    grep -q '^static void ptp_tri2_certified_refine2_split_step(ptp_tri2_certified_refine2_cval \*w, int m, const unsigned char \*e)$' "$tmp/tcr.h" &&
    ok "--domain triangle --refine 2 --certified: the triangular split on values with bounds" ||
    notok "--domain triangle --refine 2 --certified" "$(grep -m1 'split_step(' "$tmp/tcr.h")"
# verify --domain triangle: the vendored triangles right (domain and degree from the document,
# or given), wrong variants named, the domain checked against the document's.
bad=""
for f in out/tri*/ptp_tri*_table.h out/tri*/ptp_tri*.json; do
    d=$(basename "$(dirname "$f")")
    "$P" verify "$f" >"$tmp/out" 2>&1 && "$P" verify "$f" --domain triangle --degree ${d#tri} >>"$tmp/out" 2>&1 &&
        grep -q "RIGHT: exact: the [0-9]* terms of degree ${d#tri} agree" "$tmp/out" || bad="$bad $f"
done
[ -z "$bad" ] && ok "verify accepts every vendored triangle table and json, with and without --domain triangle --degree d (exit 0)" ||
    notok "verify accepts the vendored triangles" "rejected:$bad"
sed '0,/    3.0f,/s//    3.5f,/' out/tri3/ptp_tri3_table.h >"$tmp/wrongt.h"
"$P" verify "$tmp/wrongt.h" --domain triangle >"$tmp/out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "wrongt.h:28: wrong weight: plane 1, cross4(b0, b1, b4): got 3.5, expected 3 (the weight is on line 136)" "$tmp/out" && grep -q "against the 105 terms of degree 3" "$tmp/out" &&
    ok "verify --domain triangle names a wrong weight with its line, exit 1" || notok "verify of a wrong triangle weight" "exit $rc: $(head -2 "$tmp/out")"
"$P" verify out/tri2/ptp_tri2_table.h --convention v-first >"$tmp/out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "WRONG: all weights negated: .*for a triangle that is also the exact table in the u-first index convention" "$tmp/out" &&
    ok "verify of a u-first triangle table as v-first: negated, the u-first convention named, exit 1" || notok "verify triangle v-first" "exit $rc: $(tail -1 "$tmp/out")"
expect_fail "verify --domain quad of a triangle json is refused" 2 "t3.json:5: the document names --domain triangle, not quad" verify "$tmp/t3.json" --domain quad
expect_fail "verify --domain triangle of a quad table is refused" 2 "the array name names --domain quad, not triangle" verify out/2x2/ptp_2x2_table.h --domain triangle
expect_fail "verify --domain triangle --degree 2x3 is a usage error" 2 "--degree for triangles takes one degree" verify "$tmp/t3.json" --domain triangle --degree 2x3
for c in "1 clip" "2 world" "3 clip" "3 world"; do
    set -- $c
    "$P" vectors --domain triangle --degree $1 --count 200 --seed 5 --space $2 >"$tmp/v.json" &&
        "$P" --domain triangle --degree $1 >"$tmp/t.json" &&
        grep -q "^  \"domain\": \"triangle\",\$" "$tmp/v.json" &&
        python3 tests/check_vectors.py "$tmp/v.json" "$tmp/t.json" >"$tmp/out" 2>&1 &&
        ok "vectors triangle $1 $2: values and classes recomputed exactly by tests/check_vectors.py ($(tail -1 "$tmp/out"))" ||
        notok "vectors triangle $1 $2 independent check" "$(tail -2 "$tmp/out")"
done

# vectors: the same seed gives the same bytes, another seed other bytes; an independent check.
"$P" vectors --degree 2x3 --count 50 --seed 7 >"$tmp/v1.json" && "$P" vectors --degree 2x3 --count 50 --seed 7 -o "$tmp/v2.json" &&
    "$P" vectors --degree 2x3 --count 50 --seed 8 >"$tmp/v3.json" && cmp -s "$tmp/v1.json" "$tmp/v2.json" &&
    ! cmp -s "$tmp/v1.json" "$tmp/v3.json" && ok "vectors: the same seed gives the same bytes, another seed others" ||
    notok "vectors determinism" "differs"
for c in "2x3 clip" "3x3 world" "1x1 clip" "3x2 world"; do
    set -- $c
    "$P" vectors --degree $1 --count 200 --seed 11 --space $2 >"$tmp/v.json" && "$P" --degree $1 >"$tmp/t.json" &&
        python3 tests/check_vectors.py "$tmp/v.json" "$tmp/t.json" >"$tmp/out" 2>&1 &&
        ok "vectors $1 $2: values and classes recomputed exactly by tests/check_vectors.py ($(tail -1 "$tmp/out"))" ||
        notok "vectors $1 $2 independent check" "$(tail -2 "$tmp/out")"
done

# vectors --format c, the execution check: ptpgen's own C header's classify, built with gcc and
# with clang, run on the include's points gives the include's classes.
for c in "2x3 clip strict" "3x3 world degenerate" "1x2 clip degenerate" "4x3 world strict"; do
    set -- $c
    pre=ptp_$1 PRE=$(echo "PTP_$1" | tr x X)
    if ! "$P" vectors --degree $1 --count 300 --seed 3 --space $2 --format c -o "$tmp/v.h" ||
        ! "$P" --degree $1 --target c --space $2 --rule $3 --prefix ${pre}_ -o "$tmp/$pre.h"; then
        notok "vectors --format c $c" "ptpgen failed"
        continue
    fi
    for cc in gcc clang; do
        if $cc -std=c11 -Wall -Wextra -Werror -pedantic -O1 -I"$tmp" -DHEADER="\"$pre.h\"" \
            -DVECTORS='"v.h"' -DCLASSIFY=${pre}_classify -D${PRE}_IMPLEMENTATION \
            -DCLASS=ptp_vectors_class_$3 -o "$tmp/vc" tests/vectors_c.c -lm >"$tmp/out" 2>&1 &&
            "$tmp/vc" >"$tmp/out" 2>&1; then
            ok "vectors --format c $c ($cc): the C header's classify agrees ($(tail -1 "$tmp/out"))"
        else
            notok "vectors --format c $c ($cc)" "$(head -3 "$tmp/out" | tr '\n' ' ')"
        fi
    done
done
# classify_batch's transposition (tests/batch_c.c): tiles of 16 (AVX-512), 8 (AVX2) and 4
# (SSE2) patches, a tile overlapping the one before (9 points), the narrower tile of a 3-point
# patch, NO_SSE; a tile storing a coordinate to the wrong row must fail.
batch_c() { # batch_c HEADER PREFIX CC [SED]: builds and runs tests/batch_c.c (SED edits HEADER)
    local up=$(echo $2 | tr a-z A-Z)
    cp "$1" "$tmp/b.h" && { [ -z "${4:-}" ] || sed -i "$4" "$tmp/b.h"; } &&
        $3 -Wall -Wextra -Werror -pedantic -include "$tmp/b.h" -D${up}IMPLEMENTATION -DPFX=$2 \
            -DUPFX=$up tests/batch_c.c -o "$tmp/bc" 2>"$tmp/err" && "$tmp/bc" >"$tmp/out" 2>&1
}
"$P" --degree 3 --target c --prefix ptp_3x3_ -o "$tmp/b3.h" &&
    "$P" --degree 2 --target c --space world --rule degenerate --prefix ptp_2x2_ -o "$tmp/b2.h" &&
    "$P" --domain triangle --degree 1 --target c --prefix ptp_tri1_ -o "$tmp/bt.h" ||
    notok "classify_batch headers" "ptpgen failed"
avx2=$(grep -qw avx2 /proc/cpuinfo && echo "-mavx2 -mfma")
for c in "b3 ptp_3x3_ gcc -std=c11 -O2 -march=native" "b3 ptp_3x3_ clang -std=c11 -O2 -march=native" \
    "b3 ptp_3x3_ gcc -std=c11 -O2 $avx2" "b3 ptp_3x3_ gcc -std=c11 -O2" \
    "b3 ptp_3x3_ clang -std=c11 -O2 -march=native -DPTP_3X3_NO_SSE" \
    "b2 ptp_2x2_ gcc -std=c11 -O2 -march=native" "bt ptp_tri1_ clang -std=c11 -O2 -march=native"; do
    set -- $c
    h=$1 pre=$2
    shift 2
    if batch_c "$tmp/$h.h" $pre "$*"; then
        ok "classify_batch $h.h ($*) equals classify and classify_soa: $(cat "$tmp/out")"
    else
        notok "classify_batch $h.h ($*)" "$(head -3 "$tmp/err" "$tmp/out" | tr '\n' ' ')"
    fi
done
# The -march=native mutant breaks the tile this CPU's widest vectors take: 16 (AVX-512) or 8 (AVX).
if grep -qw avx512f /proc/cpuinfo; then
    native="-march=native|s/soa + 5 \* PTP_3X3_LANES, c1_2_1/soa + 9 * PTP_3X3_LANES, c1_2_1/"
else
    native="-march=native|s/soa + 5 \* PTP_3X3_LANES, c1_1_1/soa + 6 * PTP_3X3_LANES, c1_1_1/"
    grep -qw avx /proc/cpuinfo || native=""
fi
for c in ${native:+"$native"} "|0,/PTP_3X3_SHUFFLE(a, b, 2, 3, 6, 7)/s//PTP_3X3_SHUFFLE(a, b, 2, 6, 3, 7)/"; do
    if batch_c "$tmp/b3.h" ptp_3x3_ "gcc -std=c11 -O2 ${c%%|*}" "${c#*|}" || ! grep -q FAIL "$tmp/out"; then
        notok "classify_batch mutant ${c#*|} fails" "$(head -3 "$tmp/err" "$tmp/out" | tr '\n' ' ')"
    else
        ok "classify_batch with a broken tile (gcc ${c%%|*}) fails: $(cat "$tmp/out")"
    fi
done
"$P" vectors --degree 2x3 --count 40 --seed 9 --format c >"$tmp/v.h" &&
    "$P" vectors --degree 2x3 --count 40 --seed 9 >"$tmp/v.json" &&
    python3 - "$tmp/v.h" "$tmp/v.json" <<'PY' && ok "vectors --format c holds the json's cases" || notok "vectors --format c" "differs from json"
import json, re, sys
c, j = open(sys.argv[1]).read(), json.load(open(sys.argv[2]))
def arr(name):
    body = re.search(name + r"\[[^=]*= \{(.*?)\n\};", c, re.S).group(1)
    return [float(x) for x in re.findall(r"-?[0-9][0-9.e+-]*(?=[,}\s])", re.sub(r"/\*.*?\*/", "", body))]
cases = j["cases"]
assert arr("ptp_vectors_points") == [float(x) for k in cases for p in k["points"] for x in p]
assert arr("ptp_vectors_eye") == [float(x) for k in cases for x in k["eye"]]
assert arr("ptp_vectors_values") == [float(x) for k in cases for x in k["values_double"]]
assert arr("ptp_vectors_class_strict") == [k["class_strict"] for k in cases]
assert arr("ptp_vectors_class_degenerate") == [k["class_degenerate"] for k in cases]
assert "#define PTP_VECTORS_COUNT 40 " in c and "#define PTP_VECTORS_K 12 " in c
PY
expect_fail "vectors --format other" 2 "unknown format 'xml' \(expected json or c\)" vectors --degree 2 --count 1 --seed 1 --format xml
expect_fail "--format outside vectors" 2 "option --format does not apply to verify" verify x.h --format c

# verify --convention: a v-first table passes with --convention v-first and fails without.
"$P" --degree 2x3 --target json >"$tmp/t23.json" && python3 - "$tmp/t23.json" >"$tmp/vf.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1])); n, m = t["degree"]
def pt(k): i, j = divmod(k, m + 1); return j * (n + 1) + i
def pl(p): i, j = divmod(p, 3 * m - 1); return j * (3 * n - 1) + i
out = []
for e in t["terms"]:
    q = [pt(x) for x in e[1:4]]
    s = sorted(q)
    odd = sum(1 for a in range(3) for b in range(a + 1, 3) if q[a] > q[b]) % 2
    w = e[4] if not odd else (e[4][1:] if str(e[4]).startswith("-") else "-" + str(e[4]))
    out.append([pl(e[0])] + s + [w])
print(json.dumps({"degree": [n, m], "terms": out}))
PY
"$P" verify "$tmp/vf.json" --convention v-first >"$tmp/out" 2>&1 && grep -q "RIGHT: exact" "$tmp/out" &&
    ok "verify --convention v-first passes a v-first table" || notok "verify --convention v-first" "$(tail -1 "$tmp/out")"
"$P" verify "$tmp/vf.json" >"$tmp/out" 2>&1
[ $? -eq 1 ] && grep -q "WRONG: the v-first index convention.*--convention v-first" "$tmp/out" &&
    ok "verify without --convention names the v-first table and the option" || notok "verify of a v-first table" "$(tail -1 "$tmp/out")"
expect_fail "verify --convention other" 2 "unknown convention 'w-first' \(expected u-first or v-first\)" verify x.h --convention w-first
expect_fail "--convention outside verify" 2 "option --convention does not apply to vectors" vectors --degree 2 --count 1 --seed 1 --convention v-first

# verify says what it checked and what it could not: the C header's functions.
"$P" verify out/3x3/ptp_3x3.h >"$tmp/out" 2>&1
grep -q "ignored: .*functions from line .*ptpgen vectors --format c" "$tmp/out" &&
    grep -q "RIGHT: right to float precision .*the code of its functions is not checked" "$tmp/out" &&
    ok "verify of the C header: its functions are named as not checked" || notok "verify of the C header" "$(cat "$tmp/out")"
printf 'void f(float *t) {\n    t[0] = -1.0f;\n}\n' >"$tmp/code.c"
expect_fail "verify of code without a table says it cannot check code" 2 "code.c:1: functions but no table arrays.*ptpgen vectors --format c" verify "$tmp/code.c"
printf 'int idx[][4] = {{0, 0, 1, 2}};\nfloat wgt[] = {-27/7};\n' >"$tmp/div.h"
expect_fail "verify of an integer-division weight" 2 "div.h:2: integer division: C evaluates -27/7 as -3; write -27.0f/7 or -3.85714293f" verify "$tmp/div.h" --degree 1

# out/ is what ptpgen generates now, from the gcc and from the clang build, byte for byte.
for bin in "$P" "${PTPGEN_OTHER:-}"; do
    [ -n "$bin" ] && [ -x "$bin" ] || continue
    rm -rf "$tmp/out"
    if make -s out OUTDIR="$tmp/out" PTPGEN_BIN="$bin" >"$tmp/err" 2>&1 &&
        diff -r -x README.md out "$tmp/out" >"$tmp/err" 2>&1; then
        ok "out/ is byte-identical to what $bin generates now"
    else
        notok "out/ is byte-identical to what $bin generates now" "$(head -3 "$tmp/err" | tr '\n' ' ')"
    fi
done

# Installation.
make -s install PREFIX="$tmp/prefix" CC=gcc >/dev/null 2>&1 && (cd / && "$tmp/prefix/bin/ptpgen" --degree 2 >/dev/null) &&
    ok "make install PREFIX=... installs a ptpgen that runs from any directory" ||
    notok "make install" "failed"
