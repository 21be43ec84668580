// osd_model.cpp: `make cullrate`'s OpenSubdiv model: a closed cage of bench/osd_cage.h (a cube,
// prisms with fan caps of valence 5 and 6) 390 units from the origin, refined adaptively by Far
// (ENDCAP_BSPLINE_BASIS) at one isolation level, each B-spline patch converted in double to its
// Bezier points and written as a BEZ file (16 vertices a patch, first index along u):
//   osd_model LEVEL OUT.bez
#include "osd_cage.h"

#include <cstdio>
#include <cstdlib>

using namespace OpenSubdiv;

// 6 times the uniform cubic B-spline-to-Bezier map, row r.
static const int bspline_map[4][4] = {{1, 4, 1, 0}, {0, 4, 2, 0}, {0, 2, 4, 0}, {0, 1, 4, 1}};

// Writes patch p's Bezier points, u-major, from its 16 vertices (v-major, rows along v).
static void put_patch(FILE *f, const Refined &m, const Far::ConstIndexArray &cv)
{
    for (int i = 0; i < 4; i++)     // along u
        for (int j = 0; j < 4; j++) // along v
            for (int c = 0; c < 3; c++) {
                double s = 0;
                for (int a = 0; a < 4; a++)
                    for (int b = 0; b < 4; b++)
                        s += bspline_map[i][a] * bspline_map[j][b] * (double)m.v[4 * cv[b * 4 + a] + c];
                std::fprintf(f, "%.9g%s", s / 36, c < 2 ? "," : "\n");
            }
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
    for (int k = 0; k < 3; k++) { // a cube (valence 3), fans of valence 5 and 6
        const double at[3] = {300.0 + 3 * k, -200.0, 150.0};
        add_prism(cage, k == 0 ? 4 : k == 1 ? 10 : 12, k > 0, false, at, r);
    }
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
            if (params[p].GetBoundary() || m.table->GetPatchArrayDescriptor(a).GetNumControlVertices() != 16) {
                std::fprintf(stderr, "osd_model: patch %d is not an interior B-spline patch\n", p);
                return 1;
            }
            put_patch(f, m, m.table->GetPatchVertices(a, i));
        }
    return std::fclose(f) != 0;
}
