#!/usr/bin/env bash
# test_cullrate.sh: bench/cullrate's --model on a small model (a table, the exact check, names)
# and its one-line errors on bad input. Needs CULLRATE, the built binary; MODELS, the .bez files.
set -u
C=${CULLRATE:?set CULLRATE}
models=${MODELS:-../shared/models}
. "$(dirname "$0")/host_lib.sh"
make_tmp

# A run on two models, one under another name: both tables, their checks, no unsafe certified cull.
ln -s "$(realpath "$models/teacup.bez")" "$tmp/my cup.bez"
if "$C" --eyes 50 --threads 1 --model "$models/teaspoon.bez" --model "$tmp/my cup.bez" \
    >"$tmp/out" 2>"$tmp/err"; then
    ok "cullrate --model runs two models"
else
    notok "cullrate --model runs two models" "status $?: $(head -2 "$tmp/err")"
fi
[ "$(grep -c '^teaspoon: 16 patches\|^my cup: 26 patches' "$tmp/out")" = 2 ] &&
    ok "cullrate names each model by its file's base name" ||
    notok "cullrate names each model by its file's base name" "$(grep patches "$tmp/out")"
[ "$(grep -c 'exact check: [0-9]* control values, 0 mismatches' "$tmp/out")" = 2 ] &&
    ok "cullrate's exact control values agree with the double ones on both models" ||
    notok "cullrate's exact check" "$(grep 'sign check' "$tmp/out")"
grep -q '^  ptpgen certified .* 0       0         - .* 0       0         -$' "$tmp/out" &&
    ok "cullrate: no unsafe certified cull and no false alarm" ||
    notok "cullrate: certified row" "$(grep 'ptpgen certified' "$tmp/out")"

# Bad input: one line on stderr and status 1, never a crash.
printf '1\n1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,17\n16\n' >"$tmp/index.bez"
for k in $(seq 0 15); do echo "$((k / 4)),$((k % 4)),0.5" >>"$tmp/index.bez"; done
head -c 40 "$tmp/index.bez" >"$tmp/short.bez"
for bad in "$tmp/missing.bez:No such file" "$tmp/index.bez:out of range" "$tmp/short.bez:not a BEZ"; do
    f=${bad%%:*} want=${bad#*:}
    "$C" --eyes 2 --model "$f" >/dev/null 2>"$tmp/err"
    rc=$?
    if [ $rc = 1 ] && [ "$(wc -l <"$tmp/err")" = 1 ] && grep -q "$want" "$tmp/err"; then
        ok "cullrate --model $(basename "$f"): status 1, one line ($want)"
    else
        notok "cullrate --model $(basename "$f")" "status $rc: $(head -3 "$tmp/err")"
    fi
done
