// osd_cage.h: polygon cages for OpenSubdiv (a few units across, with extraordinary vertices,
// boundaries and corners) and their adaptive refinement by Far into a patch table and its float4
// vertices; shared by tests/osd_check.cpp and bench/osd_model.cpp. Header-only, C++11.
#ifndef OSD_CAGE_H
#define OSD_CAGE_H

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <vector>

// A deterministic 64-bit LCG's doubles in [0, 1).
struct Lcg {
    uint64_t s;
    double next()
    {
        s = s * 6364136223846793005u + 1442695040888963407u;
        return (double)(s >> 11) / 9007199254740992.0; // 2^53;
    }
};

// A polygon cage: positions, and the faces' vertex counts and indices.
struct Cage {
    std::vector<float> pos;
    std::vector<int> counts, indices;
    int vertex(double x, double y, double z, Lcg &r)
    {
        const double j = 0.02; // a little noise: no symmetric ties
        pos.push_back((float)(x + j * r.next()));
        pos.push_back((float)(y + j * r.next()));
        pos.push_back((float)(z + j * r.next()));
        return (int)pos.size() / 3 - 1;
    }
    void face(std::initializer_list<int> v)
    {
        counts.push_back((int)v.size());
        indices.insert(indices.end(), v);
    }
};

// A prism of n sides around (cx, cy, cz), its caps (unless open) fans of n / 2 quads around a
// center of valence n / 2 (fan) or one quad (n = 4); faces counterclockwise seen from outside.
static inline void add_prism(Cage &c, int n, bool fan, bool open, const double at[3], Lcg &r)
{
    std::vector<int> bot(n), top(n);
    for (int i = 0; i < n; i++) {
        double a = 2 * M_PI * i / n;
        bot[i] = c.vertex(at[0] + std::cos(a), at[1] + std::sin(a), at[2] - 0.8, r);
        top[i] = c.vertex(at[0] + std::cos(a), at[1] + std::sin(a), at[2] + 0.8, r);
    }
    for (int i = 0; i < n; i++)
        c.face({bot[i], bot[(i + 1) % n], top[(i + 1) % n], top[i]});
    if (open)
        return;
    if (!fan) {
        c.face({top[0], top[1], top[2], top[3]});
        c.face({bot[3], bot[2], bot[1], bot[0]});
        return;
    }
    int ct = c.vertex(at[0], at[1], at[2] + 1.1, r), cb = c.vertex(at[0], at[1], at[2] - 1.1, r);
    for (int i = 0; i < n; i += 2) {
        c.face({ct, top[i], top[(i + 1) % n], top[(i + 2) % n]});
        c.face({cb, bot[(i + 2) % n], bot[(i + 1) % n], bot[i]});
    }
}

// A bumpy n x n grid of quads around at (boundary edges, corners of valence 2).
static inline void add_grid(Cage &c, int n, const double at[3], Lcg &r)
{
    std::vector<int> v((n + 1) * (n + 1));
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            v[i * (n + 1) + j] = c.vertex(at[0] + 0.5 * i, at[1] + 0.5 * j, at[2] + 0.4 * std::sin(1.3 * i + 0.7 * j), r);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            c.face({v[i * (n + 1) + j], v[(i + 1) * (n + 1) + j], v[(i + 1) * (n + 1) + j + 1], v[i * (n + 1) + j + 1]});
}

// A bumpy disc of n quads around a center of valence n (open: its rim is a boundary).
static inline void add_disc(Cage &c, int n, const double at[3], Lcg &r)
{
    std::vector<int> rim(2 * n);
    int ct = c.vertex(at[0], at[1], at[2] + 0.3, r);
    for (int i = 0; i < 2 * n; i++) {
        double a = M_PI * i / n;
        rim[i] = c.vertex(at[0] + std::cos(a), at[1] + std::sin(a), at[2] + 0.2 * (i % 2), r);
    }
    for (int i = 0; i < 2 * n; i += 2)
        c.face({ct, rim[i], rim[i + 1], rim[(i + 2) % (2 * n)]});
}

// A vertex for Far's stencils.
struct Point {
    float p[3];
    void Clear() { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const Point &s, float w)
    {
        for (int c = 0; c < 3; c++)
            p[c] += w * s.p[c];
    }
};

// The cage refined: its patch table and the vertices it indexes (w = 1).
struct Refined {
    std::unique_ptr<OpenSubdiv::Far::PatchTable> table;
    std::vector<float> v; // float4 each
};

static inline Refined refine(const Cage &c, int level, OpenSubdiv::Far::PatchTableFactory::Options::EndCapType caps)
{
    OpenSubdiv::Far::TopologyDescriptor d;
    d.numVertices = (int)c.pos.size() / 3;
    d.numFaces = (int)c.counts.size();
    d.numVertsPerFace = c.counts.data();
    d.vertIndicesPerFace = c.indices.data();
    OpenSubdiv::Sdc::Options so;
    so.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    typedef OpenSubdiv::Far::TopologyRefinerFactory<OpenSubdiv::Far::TopologyDescriptor> Factory;
    OpenSubdiv::Far::TopologyRefiner *r = Factory::Create(d, Factory::Options(OpenSubdiv::Sdc::SCHEME_CATMARK, so));
    r->RefineAdaptive(OpenSubdiv::Far::TopologyRefiner::AdaptiveOptions(level));
    OpenSubdiv::Far::PatchTableFactory::Options po(level);
    po.SetEndCapType(caps);
    OpenSubdiv::Far::PatchTable *table = OpenSubdiv::Far::PatchTableFactory::Create(*r, po);
    OpenSubdiv::Far::StencilTableFactory::Options sto;
    sto.generateOffsets = true;
    sto.generateIntermediateLevels = true;
    const OpenSubdiv::Far::StencilTable *st = OpenSubdiv::Far::StencilTableFactory::Create(*r, sto);
    const OpenSubdiv::Far::StencilTable *local = table->GetLocalPointStencilTable();
    if (local && local->GetNumStencils() > 0) {
        const OpenSubdiv::Far::StencilTable *all = OpenSubdiv::Far::StencilTableFactory::AppendLocalPointStencilTable(*r, st, local);
        delete st;
        st = all;
    }
    std::vector<Point> pts(d.numVertices + st->GetNumStencils());
    std::memcpy(pts.data(), c.pos.data(), c.pos.size() * sizeof(float));
    if (st->GetNumStencils() > 0) // none where every face is a regular patch
        st->UpdateValues(pts.data(), pts.data() + d.numVertices);
    Refined out{std::unique_ptr<OpenSubdiv::Far::PatchTable>(table), std::vector<float>(pts.size() * 4)};
    for (size_t k = 0; k < pts.size(); k++) {
        std::memcpy(&out.v[k * 4], pts[k].p, sizeof pts[k].p);
        out.v[k * 4 + 3] = 1.0f;
    }
    delete st;
    delete r;
    return out;
}

#endif
