#!/usr/bin/env bash
# test_cullrate.sh: bench/cullrate's --model on a small model (a table, the exact check, names),
# its --pn (PN triangles of tessellated models), its default models and --models, and its
# one-line errors on bad input (bench/bezfile.c's messages), the OpenSubdiv model of make
# cullrate (bench/osd_model.cpp); and pn_check. Needs CULLRATE, the built binary; PN_CHECK
# (default: pn_check beside it). Runs from the repository's root.
set -u
C=${CULLRATE:?set CULLRATE}
P=${PN_CHECK:-$(dirname "$C")/pn_check}
models=models
. "$(dirname "$0")/host_lib.sh"
make_tmp

# two_models OUT OPTION NAMES ARGS...: cullrate ARGS (two models given with OPTION) into $tmp/OUT;
# checks both tables, named as the grep pattern NAMES, their exact checks and certified rows.
two_models() {
    local out=$tmp/$1 label="cullrate $2" names=$3
    shift 3
    if "$C" --eyes 50 --threads 1 "$@" >"$out" 2>"$tmp/err"; then
        ok "$label runs two models"
    else
        notok "$label runs two models" "status $?: $(head -2 "$tmp/err")"
    fi
    [ "$(grep -c "$names" "$out")" = 2 ] &&
        ok "$label names each model by its file's base name, with its patch count" ||
        notok "$label names each model by its file's base name" "$(grep patches "$out")"
    [ "$(grep -c 'exact check: [0-9]* control values, 0 mismatches' "$out")" = 2 ] &&
        ok "$label: the exact control values agree with the double ones on both models" ||
        notok "$label: exact check" "$(grep 'sign check' "$out")"
    local safe='^  ptpgen certified .* 0       0         - .* 0       0         -$'
    [ "$(grep -c "$safe" "$out")" = 2 ] &&
        ok "$label: no unsafe certified cull and no false alarm" ||
        notok "$label: certified rows" "$(grep 'ptpgen certified' "$out")"
}

# Two models, one under another name.
ln -s "$(realpath "$models/teacup.bez")" "$tmp/my cup.bez"
two_models out --model '^teaspoon: 16 patches\|^my cup: 26 patches' \
    --model "$models/teaspoon.bez" --model "$tmp/my cup.bez"
[ "$(grep -c '^  ptpgen cert ref 3 .* 0       0         - .* 0       0         -$' "$tmp/out")" = 2 ] &&
    ok "cullrate --model: no unsafe --refine 3 --certified cull and no false alarm" ||
    notok "cullrate --model: --refine 3 --certified rows" "$(grep 'ptpgen cert ref' "$tmp/out")"

# PN triangles: pn_check's unit checks, then cullrate on two tessellated models (2 triangles a
# quad of the --grid tessellation).
run_host "pn_check" "$P"
two_models pn --pn '^teacup PN: 468 patches\|^teaspoon PN: 288 patches' \
    --pn "$models/teacup.bez" --grid 3 --pn "$models/teaspoon.bez"
! grep -q 'ptpgen refine' "$tmp/pn" && [ "$(grep -c '^  ptpgen strict ' "$tmp/pn")" = 2 ] &&
    ok "cullrate --pn: rows for the triangle kernels only" ||
    notok "cullrate --pn: rows" "$(grep -c 'ptpgen' "$tmp/pn") ptpgen rows"
# The rates at each radius: TCONE <= NCONE <= certified <= strict <= CVis upper bound, the cones
# and CVis with no unsafe cull, CVis lower <= upper.
awk '/ patches, bounding radius/ { m = $1 }
     /^  (TCONE|NCONE|ptpgen strict|ptpgen certified|CVis lower|CVis upper)/ {
         n = $1 == "ptpgen" || $1 == "CVis" ? $1 " " $2 : $1
         o = $1 == "CVis" ? 2 : n ~ / / ? 1 : 0 # words in the name after the first
         for (r = 0; r < 2; r++) {
             rate[m, n, r] = $(3 + o + 5 * r) + 0
             uns[m, n, r] = $(4 + o + 5 * r)
         }
     }
     END {
         split("TCONE|NCONE|ptpgen certified|ptpgen strict|CVis upper", chain, "|")
         for (k in rate) { split(k, f, SUBSEP); models[f[1]] = 1 }
         for (mm in models) for (r = 0; r < 2; r++) {
             for (i = 1; i < 5; i++)
                 if (rate[mm, chain[i], r] > rate[mm, chain[i + 1], r]) bad = bad " " mm chain[i]
             if (rate[mm, "CVis lower", r] > rate[mm, "CVis upper", r]) bad = bad " " mm "CVis"
             if (uns[mm, "TCONE", r] != 0 || uns[mm, "NCONE", r] != 0 ||
                 uns[mm, "CVis lower", r] != 0)
                 bad = bad " " mm "unsafe"
             cnt++
         }
         if (cnt != 4) bad = bad " " cnt " model-radii"
         print bad == "" ? "ordered" : "not ordered:" bad
     }' "$tmp/pn" >"$tmp/order"
[ "$(cat "$tmp/order")" = ordered ] &&
    ok "cullrate --pn: TCONE <= NCONE <= certified <= strict <= CVis; cones and CVis safe" ||
    notok "cullrate --pn: rates" "$(cat "$tmp/order")"

# The default models (the knot and the far model, built here when missing, and models/), and
# --models DIR: its .bez files whose names are not measured yet, by name.
for f in knot far; do
    [ -e build/models/$f.bez ] || make -s build/models/$f.bez >/dev/null 2>&1
done
mkdir "$tmp/dir" "$tmp/none"
cp $models/teaspoon.bez "$tmp/dir/b.bez"
cp $models/teacup.bez "$tmp/dir/a.bez"
cp $models/teapot.bez "$tmp/dir/teapot.bez"
"$C" --eyes 2 --threads 1 --models "$tmp/dir" >"$tmp/def" 2>"$tmp/err"
got=$(sed -n 's/^\([a-z ]*PN\|[a-z]*\): \([0-9]*\) patches.*/\1 \2/p' "$tmp/def" | tr '\n' ,)
want="knot 2880,teapot 32,teacup 26,teaspoon 16,far 4096,knot PN 23040,teapot PN 240,a 26,b 16,"
[ "$got" = "$want" ] && ok "cullrate's defaults and --models DIR: $want" ||
    notok "cullrate's defaults and --models DIR" "got $got (want $want): $(head -2 "$tmp/err")"
# The closing table of ptpgen strict in absolute (before) and local coordinates (after): a row per
# bicubic model and radius; on the far model local coordinates make no unsafe cull and no fewer culls.
rows=$(awk '/^ptpgen strict \(plain float\) in absolute/ { t = 1; next }
            t && $2 ~ /^[25]x$/ { n++; if ($1 == "far" && ($6 != 0 || $5 < $3)) bad++ }
            END { print n + 0, bad + 0 }' "$tmp/def")
[ "$rows" = "14 0" ] &&
    ok "cullrate: absolute vs local coordinates, 7 models x 2 radii; far: local safe, no fewer culls" ||
    notok "cullrate: absolute against local coordinates" "rows and bad rows: $rows"
"$C" --eyes 2 --models "$tmp/none" >/dev/null 2>"$tmp/err"
[ $? = 1 ] && [ "$(cat "$tmp/err")" = "cullrate: --models $tmp/none: no .bez file there" ] &&
    ok "cullrate --models with no .bez file: status 1, one line" ||
    notok "cullrate --models with no .bez file" "$(head -3 "$tmp/err")"
(abs=$(realpath "$C") && cd "$tmp" && "$abs" --eyes 2 >/dev/null 2>err)
[ $? = 1 ] && [ "$(cat "$tmp/err")" = \
    "cullrate: build/models/knot.bez: cannot open: No such file or directory" ] &&
    ok "cullrate away from the repository's root: a missing default model is an error" ||
    notok "cullrate away from the repository's root" "$(head -3 "$tmp/err")"

# Bad input: one line on stderr, status 1, never a crash; the BEZ reader names the file, the line
# and what it expected there. Each case: NAME, the file's text (printf), the message after
# "cullrate: FILE:".
verts() { for k in $(seq 0 15); do printf '%d,%d,0.5\n' $((k / 4)) $((k % 4)); done; }
idx16='1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16'
bez_case() {
    local name=$1 want=$2 o=${3:---model}
    "$C" --eyes 2 "$o" "$tmp/$name.bez" >/dev/null 2>"$tmp/err"
    rc=$?
    if [ $rc = 1 ] && [ "$(cat "$tmp/err")" = "cullrate: $tmp/$name.bez:$want" ]; then
        ok "cullrate $o $name.bez: status 1, \"$want\""
    else
        notok "cullrate $o $name.bez" "status $rc: $(head -3 "$tmp/err") (want \"$want\")"
    fi
}
{ printf '1\n%s\n16\n' "${idx16%16}17"; verts; } >"$tmp/index.bez"
bez_case index '2: vertex index 17 is out of range 1..16 (index 16 of 16)'
bez_case index '2: vertex index 17 is out of range 1..16 (index 16 of 16)' --pn
{ printf '2\n%s\n%s\n16\n' $idx16 "${idx16/#1,/0,}"; verts; } >"$tmp/zero.bez"
bez_case zero '3: vertex index 0 is out of range 1..16 (index 1 of 16)'
printf '1\n%s\n' "${idx16%,16}" >"$tmp/fifteen.bez"
bez_case fifteen '2: expected 16 comma-separated vertex indices, found 15'
printf '1\n%s,1\n' $idx16 >"$tmp/seventeen.bez"
bez_case seventeen '2: expected 16 comma-separated vertex indices, found 17'
printf '1\n%s\n' "${idx16/,7,/,seven,}" >"$tmp/word.bez"
bez_case word '2: expected a vertex index (a whole number from 1), found "seven" (index 7 of 16)'
printf '3\n%s\n%s\n' $idx16 $idx16 >"$tmp/patches.bez"
bez_case patches '4: unexpected end of file, expected 3 patch lines, found 2'
printf '1\n%s\n' $idx16 >"$tmp/nocount.bez"
bez_case nocount '3: unexpected end of file, expected the vertex count'
{ printf '1\n%s\n32\n' $idx16; verts; } >"$tmp/eof.bez"
bez_case eof '20: unexpected end of file, expected 32 vertex lines, found 16'
{ printf '1\n%s\n16\n' $idx16; verts | sed '5s/.*/1,2/'; } >"$tmp/two.bez"
bez_case two '8: expected x,y,z (3 comma-separated numbers), found 2 fields'
{ printf '1\n%s\n16\n' $idx16; verts | sed '16s/0.5$/x/'; } >"$tmp/coord.bez"
bez_case coord '19: expected a finite number, found "x" (z of vertex 16)'
{ printf '1\n%s\n16\n' $idx16; verts | sed '3s/^0/1e39/'; } >"$tmp/float.bez"
bez_case float '6: coordinate 1e39 is beyond float'"'"'s range (x of vertex 3)'
{ printf '1\n%s\n16\n' $idx16; verts; printf '\n0,0,0\n'; } >"$tmp/tail.bez"
bez_case tail '21: expected the end of the file after 16 vertex lines, found "0,0,0"'
printf 'many\n' >"$tmp/count.bez"
bez_case count '1: expected the patch count (a whole number 1..10000000), found "many"'
: >"$tmp/empty.bez"
bez_case empty '1: unexpected end of file, expected the patch count'
bez_case missing ' cannot open: No such file or directory'
# Spaces and tabs around numbers, CRLF line ends and blank lines at the end are accepted.
{ printf ' 1 \r\n %s \r\n16\r\n' "${idx16//,/ ,	}"; verts | sed 's/,/ , /g; s/$/\r/'; printf '\n\n'; } \
    >"$tmp/spaces.bez"
"$C" --eyes 2 --threads 1 --model "$tmp/spaces.bez" >"$tmp/out" 2>"$tmp/err" &&
    grep -q '^spaces: 1 patches' "$tmp/out" &&
    ok "cullrate reads a BEZ file with spaces and tabs around numbers, CRLF and blank lines" ||
    notok "cullrate: spaces, CRLF and blank lines" "$(head -3 "$tmp/err")"
"$C" --eyes 2 --grid 0 --pn "$models/teacup.bez" >/dev/null 2>"$tmp/err"
[ $? = 2 ] && grep -q 'bad option or value: --grid 0' "$tmp/err" &&
    ok "cullrate --grid 0: status 2, the usage" ||
    notok "cullrate --grid 0" "$(head -2 "$tmp/err")"

# The OpenSubdiv model of `make cullrate` (bench/osd_model.cpp, level 2): ptpgen strict culls
# what the exact bracket does, within 0.5 points, at both radii; local coordinates make no unsafe
# cull where absolute ones make some, and certified none.
if [ ! -e /usr/include/opensubdiv/version.h ]; then
    missing "OpenSubdiv (Debian package libosd-dev)" "cullrate's OpenSubdiv model"
elif g++ -std=c++11 -O2 -Wall -Wextra -Werror -pedantic -Ibench bench/osd_model.cpp -losdCPU \
    -o "$tmp/osd_model" 2>"$tmp/err" && "$tmp/osd_model" 2 "$tmp/osd2.bez" &&
    "$C" --eyes 200 --threads 1 --model "$tmp/osd2.bez" >"$tmp/out" 2>"$tmp/err"; then
    row() { grep "^  $1 " "$tmp/out" | awk -v c=$2 '{ print $c }'; }
    s2=$(row "ptpgen strict" 4) s5=$(row "ptpgen strict" 9) x2=$(row "CVis lower bound" 5) x5=$(row "CVis lower bound" 10)
    if awk -v a="${s2%\%}" -v b="${x2%\%}" -v c="${s5%\%}" -v d="${x5%\%}" \
        'BEGIN { exit !(a > 40 && (b - a) < 0.5 && (a - b) < 0.5 && (d - c) < 0.5 && (c - d) < 0.5) }'; then
        ok "cullrate's OpenSubdiv model: ptpgen strict culls $s2 and $s5, the exact bracket $x2 and $x5"
    else
        notok "cullrate's OpenSubdiv model: ptpgen strict culls what the exact bracket does" "strict $s2 $s5, exact $x2 $x5"
    fi
    [ "$(row "ptpgen strict" 5)$(row "ptpgen strict" 10)$(row "ptpgen certified" 5)$(row "ptpgen certified" 10)" = 0000 ] &&
        [ "$(row "ptpgen absolute" 5)" -gt 0 ] &&
        ok "cullrate's OpenSubdiv model: no unsafe strict or certified cull, $(row "ptpgen absolute" 5) in absolute coordinates" ||
        notok "cullrate's OpenSubdiv model: unsafe culls" "$(grep -E 'ptpgen (strict|absolute|certified) ' "$tmp/out")"
else
    notok "bench/osd_model.cpp builds and cullrate runs its model" "$(head -3 "$tmp/err")"
fi
