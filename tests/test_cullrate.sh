#!/usr/bin/env bash
# test_cullrate.sh: bench/cullrate's --model on a small model (a table, the exact check, names),
# its --pn (PN triangles of tessellated models) and its one-line errors on bad input; and
# pn_check. Needs CULLRATE, the built binary; PN_CHECK (default: pn_check beside it); MODELS, the
# .bez files.
set -u
C=${CULLRATE:?set CULLRATE}
P=${PN_CHECK:-$(dirname "$C")/pn_check}
models=${MODELS:-../shared/models}
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

# Bad input: one line on stderr and status 1, never a crash.
printf '1\n1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,17\n16\n' >"$tmp/index.bez"
for k in $(seq 0 15); do echo "$((k / 4)),$((k % 4)),0.5" >>"$tmp/index.bez"; done
head -c 40 "$tmp/index.bez" >"$tmp/short.bez"
for bad in "--model:$tmp/missing.bez:No such file" "--model:$tmp/index.bez:out of range" \
    "--model:$tmp/short.bez:not a BEZ" "--pn:$tmp/index.bez:out of range"; do
    o=${bad%%:*} rest=${bad#*:}
    f=${rest%%:*} want=${rest#*:}
    "$C" --eyes 2 "$o" "$f" >/dev/null 2>"$tmp/err"
    rc=$?
    if [ $rc = 1 ] && [ "$(wc -l <"$tmp/err")" = 1 ] && grep -q "$want" "$tmp/err"; then
        ok "cullrate $o $(basename "$f"): status 1, one line ($want)"
    else
        notok "cullrate $o $(basename "$f")" "status $rc: $(head -3 "$tmp/err")"
    fi
done
"$C" --eyes 2 --grid 0 --pn "$models/teacup.bez" >/dev/null 2>"$tmp/err"
[ $? = 2 ] && grep -q 'bad option or value: --grid 0' "$tmp/err" &&
    ok "cullrate --grid 0: status 2, the usage" ||
    notok "cullrate --grid 0" "$(head -2 "$tmp/err")"
