#!/usr/bin/env bash
# paired.sh: `make bench-paired`: builds of bench_cull compared in alternating rounds on one core,
# each against the first by the median of its per-round time ratios, with a 95% interval.
#   bench/paired.sh ROUNDS CPU NAME=BINARY...   (each BINARY a bench_cull; NAME its label; CPU
#   "last": the last CPU this process may run on)
# A round runs every binary once with --batch (classify_batch's best time), pinned to CPU, in an
# order rotated each round, so that a slow spell of the machine falls on every binary alike. The
# interval of the median ratio is distribution-free (order statistics of the rounds' ratios).
set -u
[ $# -ge 4 ] || { echo "usage: bench/paired.sh ROUNDS CPU NAME=BINARY NAME=BINARY..." >&2; exit 2; }
rounds=$1 cpu=$2
shift 2
case $rounds in
'' | *[!0-9]* | 0) echo "paired: ROUNDS must be a positive integer, not '$rounds'" >&2; exit 2 ;;
esac
if [ "$cpu" = last ]; then
    cpu=$(taskset -cp $$ | sed 's/.*: //; s/.*,//; s/.*-//')
fi
names=() bins=()
for a in "$@"; do
    names+=("${a%%=*}")
    bins+=("${a#*=}")
done
n=${#bins[@]}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for ((r = 0; r < rounds; r++)); do
    for ((k = 0; k < n; k++)); do
        i=$(((r + k) % n))
        line=$(taskset -c "$cpu" "${bins[$i]}" --batch) || {
            echo "paired: ${bins[$i]} failed" >&2
            exit 1
        }
        echo "$r ${line#classify_batch }" >>"$tmp/$i"
    done
done
echo "classify_batch (clip space, strict rule), $rounds alternating rounds on CPU $cpu:" \
    "M patches/s, and the time against ${names[0]}'s in the same round"
printf '%-12s %8s %8s %8s   %s\n' build median min max 'time ratio: median [95% interval]'
for ((i = 0; i < n; i++)); do
    paste -d " " "$tmp/0" "$tmp/$i" | awk -v name="${names[$i]}" -v first=$((i == 0)) '
    { rate[NR] = $4; ratio[NR] = $2 / $4 }
    function sort(a, m,   i, j, t) {
        for (i = 2; i <= m; i++)
            for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
    }
    function median(a, m) { return m % 2 ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2 }
    END {
        m = NR
        sort(rate, m)
        sort(ratio, m)
        # the largest k with P(Binomial(m, 1/2) < k) <= 2.5%: [ratio_k, ratio_(m+1-k)] holds the
        # median ratio with at least 95% probability
        p = 0.5 ^ m; cdf = p; k = 0
        for (j = 0; j < m && cdf <= 0.025; j++) { k = j + 1; p = p * (m - j) / (j + 1); cdf += p }
        if (first)
            cmp = "(reference)"
        else if (k)
            cmp = sprintf("%.3f [%.3f, %.3f]", median(ratio, m), ratio[k], ratio[m + 1 - k])
        else
            cmp = sprintf("%.3f [too few rounds for an interval]", median(ratio, m))
        printf "%-12s %8.3f %8.3f %8.3f   %s\n", name, median(rate, m), rate[1], rate[m], cmp
    }'
done
