#!/usr/bin/env bash
# man_check.sh: docs/ptpgen.1 names exactly the options `ptpgen --help` prints, so the two cannot
# drift. Needs PTPGEN (the binary); MAN overrides the page checked.
set -u
P=${PTPGEN:?set PTPGEN to the ptpgen binary}
man=${MAN:-$(dirname "$0")/../docs/ptpgen.1}
help_opts=$("$P" --help | grep -E '^  (-[a-z], )?--' | grep -o -- '--[a-z-]*' | sort -u | tr '\n' ' ')
man_opts=$(sed 's/\\-/-/g' "$man" | awk '/^\.SH OPTIONS/ {f = 1; next} /^\.SH/ {f = 0} f' |
    grep -o -- '--[a-z-]*' | sort -u | tr '\n' ' ')
if [ -n "$help_opts" ] && [ "$help_opts" = "$man_opts" ]; then
    echo "ok - docs/ptpgen.1's OPTIONS name exactly the options of ptpgen --help"
else
    echo "not ok - docs/ptpgen.1's OPTIONS and ptpgen --help differ: --help: $help_opts; man: $man_opts"
    exit 1
fi
