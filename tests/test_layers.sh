#!/usr/bin/env bash
# test_layers.sh: gen/'s folders are layers (gen/README.md): a file includes headers of its own
# layer or of layers below it, never above, and every generator source lives in a layer.
cd "$(dirname "$0")/.."
layers=(core plan emit tools cli)
rank() { local i; for i in "${!layers[@]}"; do [ "${layers[$i]}" = "$1" ] && echo "$i" && return; done; echo -1; }

ok=0
for f in gen/*.c gen/*.h; do
    [ -e "$f" ] && { echo "not ok - $f is outside gen/'s layer folders"; ok=1; }
done
for f in gen/*/*.[ch]; do
    layer=$(basename "$(dirname "$f")")
    [ "$layer" = embed ] && continue
    r=$(rank "$layer")
    [ "$r" -lt 0 ] && { echo "not ok - $f: gen/$layer is not a layer"; ok=1; continue; }
    while read -r inc; do
        l=${inc%%/*}
        ri=$(rank "$l")
        if [ "$ri" -lt 0 ] || [ "$ri" -gt "$r" ]; then
            echo "not ok - $f includes \"$inc\", a layer above $layer"
            ok=1
        fi
    done < <(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f")
done
[ $ok = 0 ] && echo "ok - every gen/ source is in a layer and includes only its own layer or those below (${layers[*]})"
exit $ok
