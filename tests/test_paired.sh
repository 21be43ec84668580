#!/usr/bin/env bash
# test_paired.sh: bench/paired.sh (make bench-paired) on stand-in binaries whose rates are known:
# the medians, the per-round time ratios' median and its 95% interval, and its errors.
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
ok() { echo "ok - $1"; }
not_ok() {
    echo "not ok - $1"
    fails=$((fails + 1))
}

# a: always 6 M patches/s; b: 6 / r in its r-th run (r = 1, 2, ...), so that b's time is r times
# a's in round r; bad: fails.
printf '#!/bin/sh\necho "classify_batch 6.000"\n' >"$tmp/a"
cat >"$tmp/b" <<EOF
#!/bin/sh
r=\$((\$(cat "$tmp/count" 2>/dev/null || echo 0) + 1))
echo \$r >"$tmp/count"
awk -v r=\$r 'BEGIN { printf "classify_batch %.6f\n", 6 / r }'
EOF
printf '#!/bin/sh\nexit 3\n' >"$tmp/bad"
chmod +x "$tmp/a" "$tmp/b" "$tmp/bad"

# 9 rounds: b's ratios are 1 to 9, median 5; P(Binomial(9, 1/2) <= 1) = 10/512 <= 2.5% <
# P(<= 2) = 46/512, so the interval is the 2nd and 8th ratios.
if bash bench/paired.sh 9 0 a="$tmp/a" b="$tmp/b" >"$tmp/out" 2>&1 &&
    grep -Eq '^a +6\.000 +6\.000 +6\.000 +\(reference\)$' "$tmp/out" &&
    grep -Eq '^b +1\.200 +0\.667 +6\.000 +5\.000 \[2\.000, 8\.000\]$' "$tmp/out"; then
    ok "paired.sh: medians, the time ratio's median and its order-statistic 95% interval"
else
    not_ok "paired.sh on known rates: $(cat "$tmp/out")"
fi
rm -f "$tmp/count"
if bash bench/paired.sh 5 0 a="$tmp/a" b="$tmp/b" 2>&1 | grep -q '^b .* 3\.000 \[too few rounds for an interval\]$'; then
    ok "paired.sh: 5 rounds are too few for a 95% interval, and it says so"
else
    not_ok "paired.sh with 5 rounds gives no interval"
fi
if ! bash bench/paired.sh 3 0 a="$tmp/a" bad="$tmp/bad" >"$tmp/out" 2>&1 && grep -q 'paired: .*bad failed' "$tmp/out"; then
    ok "paired.sh: a failing build stops it with a message"
else
    not_ok "paired.sh with a failing build: $(cat "$tmp/out")"
fi
if taskset -c 0 bash bench/paired.sh 1 last a="$tmp/a" b="$tmp/b" | grep -q 'on CPU 0:'; then
    ok "paired.sh: CPU last is the last CPU it may run on"
else
    not_ok "paired.sh: CPU last under taskset -c 0"
fi
bash bench/paired.sh 3 0 a="$tmp/a" >"$tmp/out" 2>&1
if [ $? = 2 ] && grep -q '^usage: ' "$tmp/out"; then
    ok "paired.sh: fewer than two builds is a usage error"
else
    not_ok "paired.sh with one build: $(cat "$tmp/out")"
fi
bash bench/paired.sh x3 0 a="$tmp/a" b="$tmp/b" >"$tmp/out" 2>&1
if [ $? = 2 ] && grep -q "ROUNDS must be a positive integer, not 'x3'" "$tmp/out"; then
    ok "paired.sh: a bad round count is an error that names it"
else
    not_ok "paired.sh with ROUNDS x3: $(cat "$tmp/out")"
fi
[ $fails = 0 ]
