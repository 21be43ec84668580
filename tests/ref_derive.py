# Independent reference for ptpgen: derives the tangent-plane control planes of a (n,m) patch
# or a triangular patch of degree d in the power basis, checks the degree drop, converts to
# Bernstein form, prints ptpgen-planes/1.
import argparse
import json
from fractions import Fraction
from itertools import combinations, product
from math import comb, factorial


def bernstein_power(d, i):
    """Power-basis coefficients of B^d_i(t) = C(d,i) t^i (1-t)^(d-i)."""
    return [comb(d, i) * comb(d - i, a - i) * (-1) ** (a - i) if a >= i else 0 for a in range(d + 1)]


def deriv(p):
    return [a * c for a, c in enumerate(p)][1:] or [0]


def mul(p, q):
    r = [0] * (len(p) + len(q) - 1)
    for a, x in enumerate(p):
        for b, y in enumerate(q):
            r[a + b] += x * y
    return r


def pad(p, size):
    assert len(p) <= size
    return p + [0] * (size - len(p))


def sub(p, q):
    size = max(len(p), len(q))
    return [x - y for x, y in zip(pad(p, size), pad(q, size))]


def to_scaled_bernstein(p, d):
    """c_I with p(t) = sum_I c_I t^I (1-t)^(d-I), for deg p <= d; the Bernstein
    coefficient is c_I / C(d,I), since C(d,I) C(I,a) / C(d,a) = C(d-a, I-a)."""
    return [sum(comb(d - a, i - a) * p[a] for a in range(i + 1)) for i in range(d + 1)]


def derive(n, m):
    du, dv = 3 * n - 2, 3 * m - 2          # claimed bidegree of T
    F = [bernstein_power(n, i) for i in range(n + 1)]
    G = [bernstein_power(m, j) for j in range(m + 1)]
    Fd, Gd = [deriv(f) for f in F], [deriv(g) for g in G]

    # Point k = i*(m+1)+j has B = F_i G_j, Bu = F_i' G_j, Bv = F_i G_j'. For j<k<l the weight of
    # cross4(b_j,b_k,b_l) is the 3x3 determinant over rows (B, Bu, Bv); expanding along the Bv row,
    # each cofactor term factors as U(u) V(v) with
    #   U = F_c (F_a F_b' - F_b F_a'),  V = G_a G_b G_c'   (a,b the Bu-row pair, c the Bv column).
    # Each factor is kept in the power basis padded to the naive degree 3n-1 / 3m-1 (for the
    # degree-drop check) and, top coefficient dropped, in scaled Bernstein form of degree du / dv.
    Up = {(a, b, c): pad(mul(F[c], sub(mul(F[a], Fd[b]), mul(F[b], Fd[a]))), du + 2)
          for a, b, c in product(range(n + 1), repeat=3)}
    Vp = {(a, b, c): pad(mul(mul(G[a], G[b]), Gd[c]), dv + 2)
          for a, b, c in product(range(m + 1), repeat=3)}
    Ub = {key: to_scaled_bernstein(p[:-1], du) for key, p in Up.items()}
    Vb = {key: to_scaled_bernstein(p[:-1], dv) for key, p in Vp.items()}

    npts = (n + 1) * (m + 1)
    ij = [divmod(k, m + 1) for k in range(npts)]
    # Power-basis coefficients of u^(3n-1) v^b and of u^a v^(3m-1) must vanish.
    top = [(du + 1, b) for b in range(dv + 2)] + [(a, dv + 1) for a in range(du + 1)]
    terms = []
    for j, k, l in combinations(range(npts), 3):
        # det = h_l (f_j g_k - f_k g_j) - h_k (f_j g_l - f_l g_j) + h_j (f_k g_l - f_l g_k)
        (u0, v0), (u1, v1), (u2, v2) = [
            ((ij[a][0], ij[b][0], ij[c][0]), (ij[a][1], ij[b][1], ij[c][1]))
            for a, b, c in ((j, k, l), (j, l, k), (k, l, j))]
        for a, b in top:
            if Up[u0][a] * Vp[v0][b] - Up[u1][a] * Vp[v1][b] + Up[u2][a] * Vp[v2][b]:
                raise ArithmeticError(f"degree drop fails for ({j},{k},{l}) at u^{a} v^{b}")
        for I, (x0, x1, x2) in enumerate(zip(Ub[u0], Ub[u1], Ub[u2])):
            for J, (y0, y1, y2) in enumerate(zip(Vb[v0], Vb[v1], Vb[v2])):
                c = x0 * y0 - x1 * y1 + x2 * y2
                if c:
                    w = Fraction(c, comb(du, I) * comb(dv, J))
                    terms.append((I * (dv + 1) + J, j, k, l, w))
    terms.sort()
    return {
        "format": "ptpgen-planes/1",
        "degree": [n, m],
        "plane_degree": [du, dv],
        "points": npts,
        "planes": (du + 1) * (dv + 1),
        "terms": [[P, j, k, l, str(w)] for P, j, k, l, w in terms],
    }


# Triangles: polynomials in (u, v) as dicts {(a, b): coefficient of u^a v^b}, w = 1 - u - v.

def poly_mul(p, q):
    r = {}
    for (a, b), x in p.items():
        for (c, e), y in q.items():
            r[a + c, b + e] = r.get((a + c, b + e), 0) + x * y
    return {k: v for k, v in r.items() if v}


def poly_lin(terms):
    """sum of c * p over (c, p)."""
    r = {}
    for c, p in terms:
        for k, v in p.items():
            r[k] = r.get(k, 0) + c * v
    return {k: v for k, v in r.items() if v}


def poly_pow(p, e):
    r = {(0, 0): 1}
    for _ in range(e):
        r = poly_mul(r, p)
    return r


def poly_diff(p, var):
    return {(a - (var == 0), b - (var == 1)): v * (a if var == 0 else b)
            for (a, b), v in p.items() if (a if var == 0 else b) > 0}


def tri_cells(d):
    """(i, j) in descending lexicographic order: the point (and plane) numbering."""
    return [(i, j) for i in range(d, -1, -1) for j in range(d - i, -1, -1)]


def tri_to_bernstein(p, D):
    """c_IJ with p = sum c_IJ D!/(I! J! K!) u^I v^J w^K, for total degree of p <= D:
    u^a v^b = u^a v^b (u + v + w)^(D-a-b) gives c_IJ += p_ab (D-a-b)! I! J! / ((I-a)! (J-b)! D!)."""
    f = factorial
    c = {}
    for (a, b), x in p.items():
        for I in range(a, D + 1):
            for J in range(b, D - I + 1):
                c[I, J] = c.get((I, J), 0) + Fraction(x * f(D - a - b) * f(I) * f(J),
                                                      f(I - a) * f(J - b) * f(D))
    return c


def derive_tri(d):
    D = 3 * d - 3                          # claimed degree of T
    w = {(0, 0): 1, (1, 0): -1, (0, 1): -1}
    cells = tri_cells(d)
    phi = [poly_mul({(i, j): factorial(d) // (factorial(i) * factorial(j) * factorial(d - i - j))},
                    poly_pow(w, d - i - j)) for i, j in cells]
    rows = [phi, [poly_diff(p, 0) for p in phi], [poly_diff(p, 1) for p in phi]]
    planes = {c: P for P, c in enumerate(tri_cells(D))}
    terms = []
    for j, k, l in combinations(range(len(cells)), 3):
        # The weight of cross4(b_j, b_k, b_l) in cross4(B, Bu, Bv) is the 3x3 determinant of
        # rows (phi, phi_u, phi_v) at columns j, k, l.
        col = [[r[x] for r in rows] for x in (j, k, l)]
        det = poly_lin([(s, poly_mul(poly_mul(col[0][a], col[1][b]), col[2][c]))
                        for a, b, c, s in ((0, 1, 2, 1), (1, 2, 0, 1), (2, 0, 1, 1),
                                           (2, 1, 0, -1), (1, 0, 2, -1), (0, 2, 1, -1))])
        if any(a + b > D for a, b in det):
            raise ArithmeticError(f"degree drop fails for ({j},{k},{l})")
        for (I, J), x in tri_to_bernstein(det, D).items():
            if x:
                terms.append((planes[I, J], j, k, l, x))
    terms.sort()
    return {
        "format": "ptpgen-planes/1",
        "domain": "triangle",
        "degree": d,
        "plane_degree": D,
        "points": len(cells),
        "planes": len(planes),
        "terms": [[P, j, k, l, str(x)] for P, j, k, l, x in terms],
    }


def main():
    ap = argparse.ArgumentParser(description="Reference derivation of ptpgen-planes/1 JSON.")
    ap.add_argument("--triangle", action="store_true", help="a triangular patch of degree N")
    ap.add_argument("degree", nargs="+", help="N M, or NxM; N with --triangle")
    args = ap.parse_args()
    if args.triangle:
        if len(args.degree) != 1 or not args.degree[0].isdigit() or int(args.degree[0]) < 1:
            ap.error("--triangle takes one degree N >= 1")
        print(json.dumps(derive_tri(int(args.degree[0]))))
        return
    parts = args.degree[0].lower().split("x") if len(args.degree) == 1 else args.degree
    if len(parts) != 2:
        ap.error("expected N M or NxM")
    n, m = map(int, parts)
    if n < 1 or m < 1:
        ap.error("degrees must be >= 1")
    print(json.dumps(derive(n, m)))


if __name__ == "__main__":
    main()
