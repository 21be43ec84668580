// osd_cull.cpp: OpenSubdiv's patches culled as they come, one call: a Far::PatchTable built with
// ENDCAP_BSPLINE_BASIS, its vertex buffer as float4, the classes by patch index. ptp_osd.h is
// `ptpgen --degree 3 --basis bspline --order v-major --space world --target c --prefix ptp_osd_ -o ptp_osd.h`.
#include "ptp_osd.h"

#include <opensubdiv/far/patchTable.h>

#include <cstdint>
#include <vector>

// cls[p] = the class of patch p of table (0 front-facing, 1 back-facing, 2 silhouette) seen from
// eye (x, y, z, 1): vertices are the refined vertices and the local points of the end caps, as
// the patch table indexes them, with w = 1. Empty if a patch is not a 16-vertex B-spline patch.
std::vector<unsigned char> osd_cull(const OpenSubdiv::Far::PatchTable &table, const float (*vertices)[4],
                                    const float eye[4])
{
    const OpenSubdiv::Far::PatchTable::PatchVertsTable &indices = table.GetPatchControlVerticesTable();
    const OpenSubdiv::Far::PatchParamTable &params = table.GetPatchParamTable();
    const size_t count = params.size();
    std::vector<unsigned char> boundary(count), cls(count);
    for (int a = 0; a < table.GetNumPatchArrays(); a++)
        if (table.GetPatchArrayDescriptor(a).GetType() != OpenSubdiv::Far::PatchDescriptor::REGULAR)
            return std::vector<unsigned char>();
    for (size_t p = 0; p < count; p++)
        boundary[p] = (unsigned char)params[p].GetBoundary();
    // Far::Index is int: the same 32 bits as uint32_t (the indices are not negative).
    ptp_osd_classify_indexed_boundary(vertices, reinterpret_cast<const uint32_t *>(indices.data()),
                                      boundary.data(), count, eye, cls.data());
    return cls;
}
