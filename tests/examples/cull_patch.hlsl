// cull_patch.hlsl: a hull shader whose patch-constant function culls its own bicubic patch, no
// compute pass. ptp_3x3.hlsli is `ptpgen --degree 3 --target hlsl --stage function -o ptp_3x3.hlsli`.
#include "ptp_3x3.hlsli"

// alpha: the clip-space eye (0, 0, alpha, 0) of the projection (README: alpha).
cbuffer Draw : register(b0) { float level; float alpha; };

struct ControlPoint { float4 pos : SV_Position; };
struct PatchFactors {
    float edges[4] : SV_TessFactor;
    float inside[2] : SV_InsideTessFactor;
};

PatchFactors cull_patch(InputPatch<ControlPoint, 16> patch)
{
    float4 cp[16]; // the patch's clip-space control points, k = i*4 + j with i along u
    for (uint k = 0; k < 16; k++)
        cp[k] = patch[k].pos;
    // Class 1 is back-facing: factors of 0 discard the patch before the domain shader.
    uint c = ptp_3x3_classify_patch(cp, float4(0.0f, 0.0f, alpha, 0.0f));
    float t = c == 1u ? 0.0f : level;
    PatchFactors f;
    f.edges[0] = f.edges[1] = f.edges[2] = f.edges[3] = t;
    f.inside[0] = f.inside[1] = t;
    return f;
}

[domain("quad")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(16)]
[patchconstantfunc("cull_patch")]
ControlPoint main(InputPatch<ControlPoint, 16> patch, uint i : SV_OutputControlPointID)
{
    return patch[i];
}
