# Independent check of ptpgen test vectors (ptpgen-vectors/1) against a ptpgen-planes/1 table:
# recomputes every value exactly (fractions, cross4 of Appendix A), its double and both classes.
"""usage: python3 tests/check_vectors.py VECTORS.json TABLE.json

VECTORS.json is `ptpgen vectors --degree NxM ...` output, TABLE.json is `ptpgen --degree NxM`
(or both with `--domain triangle --degree D`).
Exits 0 and prints a one-line summary when everything matches; 1 otherwise (the first few
mismatches on standard error). Python's standard library only."""
import json
import sys
from fractions import Fraction
from math import lcm


def det3(a, b, c, rows):
    """det of the 3x3 matrix with columns a, b, c restricted to the given rows."""
    p, q, r = rows
    return (a[p] * (b[q] * c[r] - b[r] * c[q])
            - b[p] * (a[q] * c[r] - a[r] * c[q])
            + c[p] * (a[q] * b[r] - a[r] * b[q]))


def cross4(a, b, c):
    """Appendix A of Loop, Niessner and Eisenacher: cross4(a, b, c) . d = -det[a b c d]."""
    return (det3(a, b, c, (1, 2, 3)), -det3(a, b, c, (0, 2, 3)),
            det3(a, b, c, (0, 1, 3)), -det3(a, b, c, (0, 1, 2)))


def classify(values, rule):
    pos = sum(1 for d in values if d > 0)
    neg = sum(1 for d in values if d < 0)
    if rule == "strict":
        return 1 if neg == len(values) else 0 if pos == len(values) else 2
    return 1 if pos == 0 else 0 if neg == 0 else 2


def is_int(x):
    return isinstance(x, int) and not isinstance(x, bool)


def check(vec, table, complain):
    """Checks the document; returns the summary line (complain is called on every mismatch),
    or None when its header does not match the table."""
    if table.get("domain") == "triangle":
        d = table["degree"]
        npoints, nplanes, name = (d + 1) * (d + 2) // 2, (3 * d - 2) * (3 * d - 1) // 2, "tri%d" % d
    else:
        n, m = table["degree"]
        npoints, nplanes, name = (n + 1) * (m + 1), (3 * n - 1) * (3 * m - 1), "%dx%d" % (n, m)
    space = vec.get("space")
    header = [("format", vec.get("format"), "ptpgen-vectors/1"),
              ("domain", vec.get("domain"), table.get("domain")),
              ("degree", vec.get("degree"), table["degree"]),
              ("points", vec.get("points"), npoints), ("planes", vec.get("planes"), nplanes)]
    wrong = ["%s is %r, want %r" % h for h in header if h[1] != h[2]]
    if space not in ("clip", "world"):
        wrong.append("space is %r" % space)
    if wrong:  # nothing else can be checked against this table
        complain("; ".join(wrong))
        return None
    # Each plane over the common denominator of its weights: sum of integer weight * value.
    den = [1] * nplanes
    for p, _, _, _, w in table["terms"]:
        den[p] = lcm(den[p], Fraction(w).denominator)
    triples = sorted({(j, k, l) for _, j, k, l, _ in table["terms"]})
    index = {jkl: i for i, jkl in enumerate(triples)}
    plane_terms = [[] for _ in range(nplanes)]  # (triple index, integer weight)
    for p, j, k, l, w in table["terms"]:
        plane_terms[p].append((index[j, k, l], int(Fraction(w) * den[p])))
    classes = {"strict": [0, 0, 0], "degenerate": [0, 0, 0]}
    kinds = {}
    zeros = 0
    for c, case in enumerate(vec["cases"]):
        eye, points = case["eye"], case["points"]
        if (len(eye) != 4 or len(points) != npoints or any(len(b) != 4 for b in points)
                or not all(is_int(x) for x in eye + [x for b in points for x in b])):
            complain("case %d: eye or points malformed" % c)
            continue
        dots = []  # eye . cross4 of every triple (clip: eye.z * its z)
        for j, k, l in triples:
            x = cross4(points[j], points[k], points[l])
            dots.append(eye[2] * x[2] if space == "clip" else sum(e * y for e, y in zip(eye, x)))
        t = [Fraction(sum(w * dots[i] for i, w in plane_terms[p]), den[p]) for p in range(nplanes)]
        if len(case["values"]) != nplanes or len(case["values_double"]) != nplanes:
            complain("case %d: %d values, %d doubles, want %d" % (
                c, len(case["values"]), len(case["values_double"]), nplanes))
            continue
        for p in range(nplanes):
            got = case["values"][p]
            if Fraction(got) != t[p] or str(t[p]) != got:
                complain("case %d plane %d: value %s, recomputed %s" % (c, p, got, t[p]))
            if case["values_double"][p] != float(t[p]):
                complain("case %d plane %d: double %r, nearest to %s is %r" % (
                    c, p, case["values_double"][p], t[p], float(t[p])))
        for rule in ("strict", "degenerate"):
            want, got = classify(t, rule), case["class_" + rule]
            if got != want:
                complain("case %d: class_%s %r, recomputed %d" % (c, rule, got, want))
            classes[rule][want] += 1
        zeros += t.count(0)
        kinds[case.get("kind")] = kinds.get(case.get("kind"), 0) + 1
    return ("check_vectors: %d cases of %s %s, %d values (%d exactly zero) match; "
            "strict front/back/silhouette %s, degenerate %s; kinds %s" % (
                len(vec["cases"]), name, space, len(vec["cases"]) * nplanes, zeros,
                "/".join(map(str, classes["strict"])),
                "/".join(map(str, classes["degenerate"])),
                ", ".join("%s %d" % kv for kv in sorted(kinds.items(), key=str))))


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 1
    try:
        with open(argv[1]) as f:
            vec = json.load(f)
        with open(argv[2]) as f:
            table = json.load(f)
    except (OSError, ValueError) as e:
        print("check_vectors: %s" % e, file=sys.stderr)
        return 1
    bad = []

    def complain(msg):
        if len(bad) < 10:
            print("check_vectors: " + msg, file=sys.stderr)
        bad.append(msg)

    try:
        summary = check(vec, table, complain)
    except (KeyError, TypeError, ValueError, ZeroDivisionError, IndexError) as e:
        complain("malformed document: %r" % e)
    if bad:
        print("check_vectors: %d mismatch(es)" % len(bad), file=sys.stderr)
        return 1
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
