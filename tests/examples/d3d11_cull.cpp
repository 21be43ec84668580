// d3d11_cull.cpp: culls bicubic patches with ptpgen's HLSL kernel in a Direct3D 11 compute pass,
// using its host header, and checks every class against the C header. Build (docs/gpu-hosts.md):
//   ptpgen --degree 3 --target hlsl -o ptp_3x3.hlsl --host-header ptp_3x3_host.h
//   ptpgen --degree 3 --target c -o ptp_3x3.h
//   fxc /T cs_5_0 /E main /Fo ptp_3x3.cso ptp_3x3.hlsl
//   x86_64-w64-mingw32-g++-posix -std=c++17 -I. d3d11_cull.cpp -ld3d11 (MSVC: cl /std:c++17 ... d3d11.lib)
//   a.exe ptp_3x3.cso
// Direct3D 11 runs shader model 5 bytecode (DXBC, FXC's); DXC's cs_6_0 (DXIL) is for Direct3D 12.
// The kernel needs nothing past SM 5.0: structured buffers, a cbuffer, precise, mad; no 64-bit
// types, no wave operations, 64 threads a group.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <d3d11.h>

#define PTP_3X3_IMPLEMENTATION
#include "ptp_3x3.h"           // the C header: ptp_3x3_alpha, ptp_3x3_classify
#define PTP_3X3_NO_SOURCE      // the kernel comes compiled from a file (MSVC refuses its text)
#include "ptp_3x3_host.h"      // the kernel's host header: registers, constants, dispatch

static const unsigned GRID = 16, N = GRID * GRID; // GRID x GRID patches on a torus
static float cp[N * PTP_3X3_POINTS][4];           // their control points in clip space

static void check(HRESULT hr, const char *what)
{
    if (FAILED(hr)) {
        std::fprintf(stderr, "not ok - d3d11_cull: %s failed (0x%08lx)\n", what, (unsigned long)hr);
        std::exit(1);
    }
}
#define CHECK(x) check((x), #x)

// The torus seen by a camera 4 units away, tilted 0.6 rad, left-handed as Direct3D's view space
// (z into the screen); the points in clip space, clip = P * view. proj is
// XMMatrixPerspectiveFovLH(1, 1, zn, zf) as an XMFLOAT4X4 holds it: P's columns, one a row.
static void make_patches(float proj[16])
{
    const float h = 1.0f / std::tan(0.5f), zn = 0.1f, zf = 100.0f;
    const float c = std::cos(0.6f), s = std::sin(0.6f), tau = 6.2831853f;
    for (int k = 0; k < 16; k++)
        proj[k] = 0.0f;
    proj[0] = proj[5] = h;            // P(0,0), P(1,1)
    proj[10] = zf / (zf - zn);        // P(2,2): depth 0..1
    proj[14] = -zn * zf / (zf - zn);  // P(2,3)
    proj[11] = 1.0f;                  // P(3,2): clip w = view z
    for (unsigned i = 0; i < N * PTP_3X3_POINTS; i++) {
        unsigned p = i / 16, k = i % 16; // k = a*4 + b, u around the tube: dB/du x dB/dv points out
        float a = tau * ((float)(p / GRID) + (float)(k / 4) / 3.0f) / GRID;
        float b = tau * ((float)(p % GRID) + (float)(k % 4) / 3.0f) / GRID;
        float x = (1.0f + 0.4f * std::cos(a)) * std::cos(b), y = 0.4f * std::sin(a);
        float z = (1.0f + 0.4f * std::cos(a)) * std::sin(b);
        float view[4] = {x, c * y - s * z, s * y + c * z + 4.0f, 1.0f};
        for (int r = 0; r < 4; r++)
            cp[i][r] = proj[r] * view[0] + proj[4 + r] * view[1] + proj[8 + r] * view[2] + proj[12 + r];
    }
}

static std::vector<char> read_file(const char *path)
{
    std::vector<char> data;
    FILE *f = std::fopen(path, "rb");
    char buf[4096];
    size_t n;
    while (f && (n = std::fread(buf, 1, sizeof buf, f)) > 0)
        data.insert(data.end(), buf, buf + n);
    if (!f || data.empty()) {
        std::fprintf(stderr, "not ok - d3d11_cull: cannot read %s\n", path);
        std::exit(1);
    }
    std::fclose(f);
    return data;
}

int main(int argc, char **argv)
{
    float proj[16];
    uint32_t groups[3];
    ptp_3x3_params params = {}; // eye, patch_count, groups_x and the zero padding to 32 bytes
    static_assert(sizeof params % 16 == 0, "a constant buffer is whole 16-byte rows");
    make_patches(proj);
    params.eye[2] = ptp_3x3_alpha(proj, PTP_3X3_COLUMN_MAJOR); // eye (0, 0, alpha, 0), alpha < 0
    params.patch_count = N;
    ptp_3x3_dispatch(N, D3D11_CS_DISPATCH_MAX_THREAD_GROUPS_PER_DIMENSION, groups);
    params.groups_x = groups[0]; // the kernel numbers workgroup (x, y) as block y * groups_x + x

    ID3D11Device *dev;
    ID3D11DeviceContext *ctx;
    D3D_FEATURE_LEVEL level = D3D_FEATURE_LEVEL_11_0; // cs_5_0
    CHECK(D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, &level, 1, D3D11_SDK_VERSION,
                            &dev, nullptr, &ctx));
    std::vector<char> blob = read_file(argc > 1 ? argv[1] : "ptp_3x3.cso");
    ID3D11ComputeShader *cs;
    CHECK(dev->CreateComputeShader(blob.data(), blob.size(), nullptr, &cs));

    // t0: the points, StructuredBuffer<float4> (an SRV over a structured buffer of stride 16).
    D3D11_BUFFER_DESC bd = {sizeof cp, D3D11_USAGE_IMMUTABLE, D3D11_BIND_SHADER_RESOURCE, 0,
                            D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, sizeof cp[0]};
    D3D11_SUBRESOURCE_DATA init = {cp, 0, 0};
    ID3D11Buffer *points, *classes, *constants, *staging;
    CHECK(dev->CreateBuffer(&bd, &init, &points));
    D3D11_SHADER_RESOURCE_VIEW_DESC sd = {};
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFER; // Format DXGI_FORMAT_UNKNOWN: structured
    sd.Buffer.NumElements = N * PTP_3X3_POINTS;
    ID3D11ShaderResourceView *srv;
    CHECK(dev->CreateShaderResourceView(points, &sd, &srv));
    // u1: the classes, RWStructuredBuffer<uint>; a hull shader reads them later through an SRV.
    bd = {N * sizeof(uint32_t), D3D11_USAGE_DEFAULT,
          D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE, 0,
          D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, sizeof(uint32_t)};
    CHECK(dev->CreateBuffer(&bd, nullptr, &classes));
    D3D11_UNORDERED_ACCESS_VIEW_DESC ud = {};
    ud.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    ud.Buffer.NumElements = N;
    ID3D11UnorderedAccessView *uav;
    CHECK(dev->CreateUnorderedAccessView(classes, &ud, &uav));
    // b0: ptp_3x3_params byte for byte.
    bd = {sizeof params, D3D11_USAGE_IMMUTABLE, D3D11_BIND_CONSTANT_BUFFER, 0, 0, 0};
    init.pSysMem = &params;
    CHECK(dev->CreateBuffer(&bd, &init, &constants));
    bd = {N * sizeof(uint32_t), D3D11_USAGE_STAGING, 0, D3D11_CPU_ACCESS_READ, 0, 0}; // the read-back
    CHECK(dev->CreateBuffer(&bd, nullptr, &staging));

    // The pass. Direct3D 11 orders it before later work (no barrier); a renderer unbinds the UAV
    // before its hull shader reads the classes through an SRV.
    ctx->CSSetShader(cs, nullptr, 0);
    ctx->CSSetShaderResources(PTP_3X3_REGISTER_POINTS, 1, &srv);
    ctx->CSSetUnorderedAccessViews(PTP_3X3_REGISTER_CLASSES, 1, &uav, nullptr);
    ctx->CSSetConstantBuffers(PTP_3X3_REGISTER_PARAMS, 1, &constants);
    ctx->Dispatch(groups[0], groups[1], groups[2]);
    ctx->CopyResource(staging, classes);
    D3D11_MAPPED_SUBRESOURCE map;
    CHECK(ctx->Map(staging, 0, D3D11_MAP_READ, 0, &map)); // waits for the GPU
    const uint32_t *cls = static_cast<const uint32_t *>(map.pData);

    // Every class against the C header's on the same points: 0 front, 1 back, 2 silhouette.
    unsigned count[3] = {0, 0, 0}, wrong = 0;
    for (unsigned p = 0; p < N; p++) {
        unsigned want = ptp_3x3_classify(cp + p * PTP_3X3_POINTS, params.eye);
        if (cls[p] != want && wrong++ < 5)
            std::fprintf(stderr, "patch %u: kernel %u, C header %u\n", p, cls[p], want);
        count[want]++;
    }
    ctx->Unmap(staging, 0);
    std::printf("%s - d3d11_cull: %u of %u patches back-facing (front %u, silhouette %u) in %u x %u "
                "workgroups, %u classes differ from the C header's\n",
                wrong || !count[1] ? "not ok" : "ok", count[1], N, count[0], count[2], groups[0],
                groups[1], wrong);
    staging->Release(); constants->Release(); uav->Release(); classes->Release(); srv->Release();
    points->Release(); cs->Release(); ctx->Release(); dev->Release();
    return wrong || !count[1];
}
