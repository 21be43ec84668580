// osd_check.cpp: B-spline input against OpenSubdiv itself. Cages made here (closed: extraordinary
// vertices of valence 3, 5 and 6; open: boundary edges and corners) are refined adaptively by Far
// (ENDCAP_BSPLINE_BASIS) and their patches culled by tests/examples/osd_cull.cpp. Checked against
// the surface Far::PatchTable::EvaluateBasis gives: the classes of the default Bezier header on
// each patch's Bezier points fitted in double to that surface, and the sign of
// (dB/ds x dB/dt) . (E - B) on a grid of every patch called back or front. Built with ptp_osd.h
// (implementation), bz.h, a default world-space header with prefix bz_, and cs.h, ptp_osd.h's
// --certified form with prefix cs_: osd_check [DIR]
// With DIR, each check also writes what tests/host_indexed.c reads into DIR/0, DIR/1, ...: the
// vertices, the indices, the boundary masks, the eyes and classify_indexed_boundary's classes.
#include "ptp_osd.h"
#include "bz.h"
#include "cs.h"
#include "osd_cage.h"

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <vector>

using namespace OpenSubdiv;

std::vector<unsigned char> osd_cull(const Far::PatchTable &table, const float (*vertices)[4], const float eye[4]);

static int failed;
static const char *dump_dir; // osd_check DIR
static int dumps;            // the checks written to it

// Writes the n elements of v to DIR/<dumps>/name; false when it cannot.
template <class T> static bool dump(const char *name, const std::vector<T> &v)
{
    std::string d = std::string(dump_dir) + "/" + std::to_string(dumps);
    mkdir(d.c_str(), 0777);
    FILE *f = std::fopen((d + "/" + name).c_str(), "wb");
    bool good = f && std::fwrite(v.data(), sizeof(T), v.size(), f) == v.size();
    return f && std::fclose(f) == 0 && good;
}

static void report(bool good, const char *what, const char *why)
{
    std::printf("%s - %s%s%s\n", good ? "ok" : "not ok", what, good ? "" : ": ", good ? "" : why);
    failed += !good;
}

// The surface of patch p at its own (s, t): position b, derivatives ds, dt (double).
static void evaluate(const Refined &m, int a, int i, int p, double s, double t, double b[3], double ds[3], double dt[3])
{
    Far::PatchTable::PatchHandle h;
    h.arrayIndex = a, h.patchIndex = p, h.vertIndex = p * 16;
    double w[16], wu[16], wv[16];
    m.table->GetPatchParam(a, i).Unnormalize(s, t);
    m.table->EvaluateBasis(h, s, t, w, wu, wv);
    const Far::ConstIndexArray cv = m.table->GetPatchVertices(h);
    for (int c = 0; c < 3; c++) {
        b[c] = ds[c] = dt[c] = 0;
        for (int k = 0; k < 16; k++) {
            double x = m.v[cv[k] * 4 + c];
            b[c] += w[k] * x, ds[c] += wu[k] * x, dt[c] += wv[k] * x;
        }
    }
}

// Bezier points (u-major) of patch p fitted to its surface at s, t in {0, 1/3, 2/3, 1}: the
// Bernstein matrix's inverse on both sides.
static void fit_bezier(float bz[16][4], const Refined &m, int a, int i, int p)
{
    static const double inv[4][4] = {{1, 0, 0, 0}, {-5.0 / 6, 3, -1.5, 1.0 / 3}, {1.0 / 3, -1.5, 3, -5.0 / 6}, {0, 0, 0, 1}};
    double g[4][4][3], h[4][4][3], ds[3], dt[3];
    for (int k = 0; k < 4; k++)
        for (int l = 0; l < 4; l++)
            evaluate(m, a, i, p, k / 3.0, l / 3.0, g[k][l], ds, dt);
    for (int k = 0; k < 4; k++) // along s
        for (int l = 0; l < 4; l++)
            for (int c = 0; c < 3; c++) {
                h[k][l][c] = 0;
                for (int q = 0; q < 4; q++)
                    h[k][l][c] += inv[k][q] * g[q][l][c];
            }
    for (int k = 0; k < 4; k++) // along t
        for (int l = 0; l < 4; l++) {
            for (int c = 0; c < 3; c++) {
                double x = 0;
                for (int q = 0; q < 4; q++)
                    x += inv[l][q] * h[k][q][c];
                bz[k * 4 + l][c] = (float)x;
            }
            bz[k * 4 + l][3] = 1.0f;
        }
}

// 1 when the surface of patch p contradicts class cls (back: a point of the 7 x 7 grid clearly
// faces the eye; front: one clearly faces away).
static bool contradicts(const Refined &m, int a, int i, int p, const double e[3], int cls)
{
    for (int k = 0; k <= 6; k++)
        for (int l = 0; l <= 6; l++) {
            double b[3], ds[3], dt[3], n[3], v[3], f;
            evaluate(m, a, i, p, k / 6.0, l / 6.0, b, ds, dt);
            n[0] = ds[1] * dt[2] - ds[2] * dt[1], n[1] = ds[2] * dt[0] - ds[0] * dt[2], n[2] = ds[0] * dt[1] - ds[1] * dt[0];
            for (int c = 0; c < 3; c++)
                v[c] = e[c] - b[c];
            f = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
            double tol = 1e-6 * std::sqrt((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
            if ((cls == BZ_BACK && f > tol) || (cls == BZ_FRONT && f < -tol))
                return true;
        }
    return false;
}

// OpenSubdiv's default end caps, Gregory patches, left unculled: the patches culled from eye, of
// the table's regular arrays (B-spline patches); the table's patches and end caps to np, ncaps.
static size_t gregory_culls(const Refined &g, const float eye[4], size_t *np, size_t *ncaps)
{
    size_t culled = 0;
    *np = *ncaps = 0;
    for (int a = 0; a < g.table->GetNumPatchArrays(); a++) {
        const size_t n = (size_t)g.table->GetNumPatches(a);
        *np += n;
        if (g.table->GetPatchArrayDescriptor(a).GetType() != Far::PatchDescriptor::REGULAR) {
            *ncaps += n;
            continue;
        }
        const Far::ConstIndexArray cv = g.table->GetPatchArrayVertices(a);
        const Far::ConstPatchParamArray pp = g.table->GetPatchParams(a);
        std::vector<unsigned char> boundary(n), cls(n);
        for (size_t p = 0; p < n; p++)
            boundary[p] = (unsigned char)pp[(int)p].GetBoundary();
        ptp_osd_classify_indexed_boundary((const float(*)[4])g.v.data(), (const uint32_t *)&cv[0], boundary.data(), n, eye, cls.data());
        for (size_t p = 0; p < n; p++)
            culled += cls[p] == BZ_BACK;
    }
    return culled;
}

// Runs the checks on cage c refined to level from neyes eyes around at.
static void check(const char *name, const Cage &c, int level, const double at[3], int neyes, Lcg &r)
{
    Refined m = refine(c, level, Far::PatchTableFactory::Options::ENDCAP_BSPLINE_BASIS);
    const Far::PatchParamTable &params = m.table->GetPatchParamTable();
    const size_t n = params.size(), nv = m.v.size() / 4;
    std::vector<float> bz(n * 64);
    std::vector<int> array(n), inner(n);
    size_t boundary = 0, bad_index = 0, views = 0, culled = 0, differ = 0, flips = 0, wrong = 0, unmasked = 0;
    char what[160], why[200];
    for (int a = 0, p = 0; a < m.table->GetNumPatchArrays(); a++)
        for (int i = 0; i < m.table->GetNumPatches(a); i++, p++) {
            array[p] = a, inner[p] = i;
            fit_bezier((float(*)[4]) & bz[p * 64], m, a, i, p);
            boundary += params[p].GetBoundary() != 0;
        }
    for (int x : m.table->GetPatchControlVerticesTable())
        bad_index += x < 0 || (size_t)x >= nv;
    std::snprintf(what, sizeof what, "%s, level %d: %zu patches (%zu on a boundary), every index a vertex", name, level, n, boundary);
    std::snprintf(why, sizeof why, "%zu indices out of range", bad_index);
    report(bad_index == 0 && n > 0, what, why);
    if (bad_index)
        return;
    std::vector<unsigned char> ref(n), none(n), masks(n), cert(n), dumped;
    size_t cert_culled = 0, cert_flips = 0, cert_wrong = 0;
    std::vector<float> eyes;
    const uint32_t *indices = (const uint32_t *)m.table->GetPatchControlVerticesTable().data();
    for (size_t p = 0; p < n; p++)
        masks[p] = (unsigned char)params[p].GetBoundary();
    Refined g = refine(c, level, Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    size_t gculled = 0, gviews = 0, gpatches = 0, gcaps = 0;
    for (int k = 0; k < neyes; k++) {
        double z = 2 * r.next() - 1, phi = 2 * M_PI * r.next(), rad = 2.5 + 3 * r.next(), e[3];
        e[0] = at[0] + rad * std::sqrt(1 - z * z) * std::cos(phi), e[1] = at[1] + rad * std::sqrt(1 - z * z) * std::sin(phi);
        e[2] = at[2] + rad * z;
        const float eye[4] = {(float)e[0], (float)e[1], (float)e[2], 1.0f};
        std::vector<unsigned char> cls = osd_cull(*m.table, (const float(*)[4])m.v.data(), eye);
        if (cls.size() != n) {
            report(false, name, "osd_cull refused the patch table");
            return;
        }
        bz_classify_batch((const float(*)[4])bz.data(), n, eye, ref.data());
        gculled += gregory_culls(g, eye, &gpatches, &gcaps);
        gviews += gpatches;
        ptp_osd_classify_indexed((const float(*)[4])m.v.data(), indices, n, eye, none.data());
        cs_classify_indexed_boundary((const float(*)[4])m.v.data(), indices, masks.data(), n, eye, cert.data());
        if (dump_dir) { // the reference of the GPU's indexed kernel
            dumped.resize(dumped.size() + n);
            ptp_osd_classify_indexed_boundary((const float(*)[4])m.v.data(), indices, masks.data(), n, eye, &dumped[dumped.size() - n]);
            eyes.insert(eyes.end(), eye, eye + 4);
        }
        for (size_t p = 0; p < n; p++) {
            views++;
            culled += cls[p] == BZ_BACK;
            differ += cls[p] != ref[p];
            flips += cls[p] + ref[p] == BZ_BACK && cls[p] != ref[p]; // back against front
            unmasked += none[p] != ref[p];
            if (cls[p] != BZ_SILHOUETTE)
                wrong += contradicts(m, array[p], inner[p], (int)p, e, cls[p]);
            cert_culled += cert[p] == BZ_BACK;
            cert_flips += cert[p] != BZ_SILHOUETTE && cert[p] != cls[p];
            if (cert[p] != BZ_SILHOUETTE)
                cert_wrong += contradicts(m, array[p], inner[p], (int)p, e, cert[p]);
        }
    }
    std::snprintf(what, sizeof what, "%s, level %d, %d eyes: classes = the Bezier header's on points fitted to "
                  "EvaluateBasis (%zu of %zu patch-views differ, culls %.2f%%)", name, level, neyes, differ, views,
                  100.0 * culled / views);
    std::snprintf(why, sizeof why, "%zu differ (at most 0.1%%), %zu back against front", differ, flips);
    report(flips == 0 && differ * 1000 <= views && culled > 0, what, why);
    std::snprintf(what, sizeof what, "%s, level %d: no patch called back or front against EvaluateBasis's "
                  "dB/ds x dB/dt on a 7 x 7 grid", name, level);
    std::snprintf(why, sizeof why, "%zu patch-views contradict it", wrong);
    report(wrong == 0, what, why);
    std::snprintf(what, sizeof what, "%s, level %d: --certified gives up %zu of %zu culls, and calls no patch back "
                  "or front that the plain header or EvaluateBasis's grid does not", name, level, culled - cert_culled, culled);
    std::snprintf(why, sizeof why, "%zu against the plain header, %zu against the grid", cert_flips, cert_wrong);
    report(cert_flips == 0 && cert_wrong == 0 && cert_culled * 100 >= culled * 99, what, why);
    if (boundary) {
        std::snprintf(what, sizeof what, "%s, level %d: without the boundary masks %zu patch-views differ", name, level, unmasked);
        report(unmasked > differ, what, "the masks change nothing");
    }
    if (dump_dir) {
        std::vector<uint32_t> b(masks.begin(), masks.end()), ix(indices, indices + 16 * n);
        std::snprintf(what, sizeof what, "%s, level %d: written to %s/%d", name, level, dump_dir, dumps);
        report(dump("vertices", m.v) && dump("indices", ix) && dump("boundary", b) && dump("eyes", eyes) &&
                   dump("classes", dumped), what, "cannot write the files");
        dumps++;
    }
    std::printf("# %s, level %d: culled %.2f%% with B-spline end caps, %.2f%% with Gregory end caps (%zu of %zu "
                "patches) left unculled\n", name, level, 100.0 * culled / views, 100.0 * gculled / gviews, gcaps, gpatches);
}

// extrapolate's exactness, which the certified header's classify_indexed_boundary trusts: 2 p1 - p2
// exact (p1 = 3, p2 = 1) is exact; p1 = 1, p2 = 2^-30 rounds (2 - 2^-30 is not a float).
static void check_exactness()
{
    float cp[16][4] = {}, inexact[16][4] = {};
    for (int k = 0; k < 16; k++)
        for (int c = 0; c < 4; c++)
            cp[k][c] = (float)(k / 4 + 1), inexact[k][c] = (k / 4 == 1) ? 1.0f : std::ldexp(1.0f, -30);
    // mask 1 (v = 0): rows along v, so v is the row k / 4; row 0's phantoms from rows 1 and 2
    const int good = cs_extrapolate(cp, 1), bad = cs_extrapolate(inexact, 1);
    report(good == 1 && cp[0][0] == 1.0f && bad == 0, "extrapolate tells exact phantoms (2 p1 - p2) from rounded ones",
           "it does not");
}

int main(int argc, char **argv)
{
    dump_dir = argc > 1 ? argv[1] : nullptr;
    Lcg r{7};
    const double far_away[3] = {300.0, -200.0, 150.0}; // patches small against their coordinates
    double at[3];
    Cage closed, open;
    for (int k = 0; k < 3; k++) { // a cube (valence 3), fans of valence 5 and 6
        at[0] = far_away[0] + 3 * k, at[1] = far_away[1], at[2] = far_away[2];
        add_prism(closed, k == 0 ? 4 : k == 1 ? 10 : 12, k > 0, false, at, r);
    }
    add_grid(open, 6, far_away, r);
    at[0] = far_away[0] + 5, at[1] = far_away[1] + 1, at[2] = far_away[2];
    add_prism(open, 8, false, true, at, r); // an open tube: boundary loops
    at[0] = far_away[0] - 2.5;
    add_disc(open, 5, at, r);                 // valence 5 inside, a boundary around
    check_exactness();
    for (int level = 2; level <= 3; level++) {
        at[0] = far_away[0] + 3, at[1] = far_away[1], at[2] = far_away[2];
        check("closed cage", closed, level, at, 40, r);
        at[0] = far_away[0] + 2.5, at[1] = far_away[1] + 1.5;
        check("open cage", open, level, at, 40, r);
    }
    return failed != 0;
}
