// osd_model.cpp: `make cullrate`'s OpenSubdiv model: a closed cage of bench/osd_cage.h (a cube,
// prisms with fan caps of valence 5 and 6) 390 units from the origin, refined adaptively by Far
// (ENDCAP_BSPLINE_BASIS) at one isolation level, each B-spline patch converted in double to its
// Bezier points, checked to face outward, and written as a BEZ file (16 vertices a patch, first
// index along u):
//   osd_model LEVEL OUT.bez
#include "osd_cage.h"

#include <cstdio>
#include <cstdlib>

using namespace OpenSubdiv;

// 6 times the uniform cubic B-spline-to-Bezier map, row r.
static const int bspline_map[4][4] = {{1, 4, 1, 0}, {0, 4, 2, 0}, {0, 2, 4, 0}, {0, 1, 4, 1}};

// The cage's closed parts: a cube (valence 3) and prisms with fans of valence 5 and 6, their
// sides and centers.
static const int part_sides[3] = {4, 10, 12};
static const double part_at[3][3] = {{300, -200, 150}, {303, -200, 150}, {306, -200, 150}};

// A patch's Bezier points, u-major: point (i, j) at 4i + j, i along u.
typedef double Bezier[16][3];

// Converts a B-spline patch's 16 vertices cv (v-major, rows along v) to its Bezier points b.
static void to_bezier(const Refined &m, const Far::ConstIndexArray &cv, Bezier b)
{
    for (int i = 0; i < 4; i++)     // along u
        for (int j = 0; j < 4; j++) // along v
            for (int c = 0; c < 3; c++) {
                double s = 0;
                for (int a = 0; a < 4; a++)
                    for (int k = 0; k < 4; k++)
                        s += bspline_map[i][a] * bspline_map[j][k] * (double)m.v[4 * cv[k * 4 + a] + c];
                b[i * 4 + j][c] = s / 36;
            }
}

// Whether b faces outward as ptpgen orients it: dB/du x dB/dv at (1/2, 1/2) points away from the
// center of the nearest part of the cage.
static bool outward(const Bezier b)
{
    static const double w[4] = {1, 3, 3, 1}, dw[4] = {-1, -1, 1, 1}; // B_i(1/2), B_i'(1/2), scaled
    double p[3] = {0, 0, 0}, du[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, best = 1e300, dot = 0;
    int near = 0;
    for (int k = 0; k < 16; k++)
        for (int c = 0; c < 3; c++) {
            p[c] += w[k / 4] * w[k % 4] * b[k][c] / 64;
            du[c] += dw[k / 4] * w[k % 4] * b[k][c];
            dv[c] += w[k / 4] * dw[k % 4] * b[k][c];
        }
    for (int q = 0; q < 3; q++) {
        double d = 0;
        for (int c = 0; c < 3; c++)
            d += (p[c] - part_at[q][c]) * (p[c] - part_at[q][c]);
        if (d < best)
            best = d, near = q;
    }
    for (int c = 0; c < 3; c++)
        dot += (du[(c + 1) % 3] * dv[(c + 2) % 3] - du[(c + 2) % 3] * dv[(c + 1) % 3]) * (p[c] - part_at[near][c]);
    return dot > 0;
}

// Writes b's 16 points, one "x,y,z" line each.
static void put_patch(FILE *f, const Bezier b)
{
    for (int k = 0; k < 16; k++)
        std::fprintf(f, "%.9g,%.9g,%.9g\n", b[k][0], b[k][1], b[k][2]);
}

int main(int argc, char **argv)
{
    int level = argc == 3 ? std::atoi(argv[1]) : 0;
    if (level < 1 || level > 4) {
        std::fprintf(stderr, "usage: osd_model LEVEL(1..4) OUT.bez\n");
        return 2;
    }
    Lcg r{11};
    Cage cage;
    for (int k = 0; k < 3; k++)
        add_prism(cage, part_sides[k], k > 0, false, part_at[k], r);
    Refined m = refine(cage, level, Far::PatchTableFactory::Options::ENDCAP_BSPLINE_BASIS);
    const Far::PatchParamTable &params = m.table->GetPatchParamTable();
    FILE *f = std::fopen(argv[2], "w");
    if (!f) {
        std::perror(argv[2]);
        return 1;
    }
    std::fprintf(f, "%zu\n", params.size());
    for (size_t p = 0, n = params.size(); p < n; p++)
        for (int k = 0; k < 16; k++)
            std::fprintf(f, "%zu%s", p * 16 + k + 1, k < 15 ? "," : "\n");
    std::fprintf(f, "%zu\n", params.size() * 16);
    for (int a = 0, p = 0; a < m.table->GetNumPatchArrays(); a++)
        for (int i = 0; i < m.table->GetNumPatches(a); i++, p++) {
            Bezier b;
            if (params[p].GetBoundary() || m.table->GetPatchArrayDescriptor(a).GetNumControlVertices() != 16) {
                std::fprintf(stderr, "osd_model: patch %d is not an interior B-spline patch\n", p);
                return 1;
            }
            to_bezier(m, m.table->GetPatchVertices(a, i), b);
            if (!outward(b)) {
                std::fprintf(stderr, "osd_model: patch %d faces inward\n", p);
                return 1;
            }
            put_patch(f, b);
        }
    return std::fclose(f) != 0;
}
