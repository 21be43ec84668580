// ptp_1x1_world.wgsl: TEST FIXTURE, written by hand: not ptpgen output. A direct WGSL port of
// `ptpgen --degree 1 --target glsl --space world` for tests/host_wgpu.c until ptpgen emits WGSL.
//
// Back-patch culling of bidegree 1x1 Bezier patches in world space: the 4 control planes of
// T = cross4(B, dB/du, dB/dv) dotted with the homogeneous eye; rule strict (back iff every value
// < 0, front iff every value > 0, a NaN makes the patch silhouette). Classes: 0 front, 1 back,
// 2 silhouette. Schedule as the GLSL kernel's: 4 threads per patch (one plane each), 32 patches
// per workgroup of 128 invocations, 1 round.
// Bindings (group 0): 0 control points, 1 classes, 3 { eye, patch_count }. Workgroup (x, y)
// handles the patches of block y * num_workgroups.x + x.

struct Params {
    eye: vec4<f32>,
    patch_count: u32,
}

@group(0) @binding(0) var<storage, read> cp: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> cls: array<u32>;
@group(0) @binding(3) var<uniform> params: Params;

const P: u32 = 4u; // threads per patch
const Q: u32 = 32u; // patches per workgroup
const K: u32 = 4u; // control points per patch
const L: u32 = 4u; // control planes per patch

// Thread t owns the planes own_plane[own_start[t] .. own_start[t+1]-1].
var<private> own_start: array<u32, 5> = array<u32, 5>(0u, 1u, 2u, 3u, 4u);
var<private> own_plane: array<u32, 4> = array<u32, 4>(0u, 1u, 2u, 3u);
// Round 0: thread t adds w0[t] * term(plane | j << 16 = pj0[t], k | l << 16 = kl0[t]).
var<private> pj0: array<u32, 4> = array<u32, 4>(0x00000u, 0x00001u, 0x00002u, 0x10003u);
var<private> kl0: array<u32, 4> = array<u32, 4>(0x20001u, 0x30001u, 0x30002u, 0x30002u);
var<private> w0: array<f32, 4> = array<f32, 4>(-1.0, -1.0, 1.0, 1.0);

var<workgroup> pts: array<vec4<f32>, 128>; // Q * K
var<workgroup> acc: array<f32, 128>; // Q * L
var<workgroup> flags: array<u32, 128>; // Q * P

// e . cross4(a, b, c). WGSL has no `precise`: see tests/README.md (exact zeros) for why the
// products of the 2x2 minors may be contracted on other drivers.
fn eye_cross4(a: vec4<f32>, b: vec4<f32>, c: vec4<f32>, e: vec4<f32>) -> f32 {
    let x = a.y * (b.z * c.w - b.w * c.z) - b.y * (a.z * c.w - a.w * c.z) +
        c.y * (a.z * b.w - a.w * b.z);
    let y = a.x * (b.z * c.w - b.w * c.z) - b.x * (a.z * c.w - a.w * c.z) +
        c.x * (a.z * b.w - a.w * b.z);
    let z = a.x * (b.y * c.w - b.w * c.y) - b.x * (a.y * c.w - a.w * c.y) +
        c.x * (a.y * b.w - a.w * b.y);
    let w = a.x * (b.y * c.z - b.z * c.y) - b.x * (a.y * c.z - a.z * c.y) +
        c.x * (a.y * b.z - a.z * b.y);
    return e.x * x - e.y * y + e.z * z - e.w * w;
}

// Bit 0: d is not < 0; bit 1: d is not > 0 (NaN sets both).
fn flags_of(d: f32) -> u32 {
    return select(1u, 0u, d < 0.0) | select(2u, 0u, d > 0.0);
}

// Strict rule: back iff every value < 0, front iff every value > 0.
fn class_of(f: u32) -> u32 {
    return select(select(2u, 0u, (f & 2u) == 0u), 1u, (f & 1u) == 0u);
}

@compute @workgroup_size(128)
fn main(@builtin(local_invocation_id) lid3: vec3<u32>,
        @builtin(workgroup_id) wid: vec3<u32>,
        @builtin(num_workgroups) nwg: vec3<u32>) {
    let lid = lid3.x;
    let q = lid / P;
    let t = lid % P;
    let pid = (wid.y * nwg.x + wid.x) * Q + q;
    let live = pid < params.patch_count;
    var f = 0u;

    // The patch's control points into workgroup memory, P threads cooperating.
    for (var i = t; i < K; i += P) {
        if (live) {
            pts[q * K + i] = cp[pid * K + i];
        }
    }
    workgroupBarrier();

    // Accumulate the planes this thread owns: no other thread touches them.
    for (var i = own_start[t]; i < own_start[t + 1u]; i++) {
        acc[q * L + own_plane[i]] = 0.0;
    }
    let pj = pj0[t];
    let kl = kl0[t];
    acc[q * L + (pj & 0xffffu)] += w0[t] *
        eye_cross4(pts[q * K + (pj >> 16u)], pts[q * K + (kl & 0xffffu)],
                   pts[q * K + (kl >> 16u)], params.eye);

    // The signs of the owned planes; then one thread combines the patch's.
    for (var i = own_start[t]; i < own_start[t + 1u]; i++) {
        f |= flags_of(acc[q * L + own_plane[i]]);
    }
    flags[q * P + t] = f;
    workgroupBarrier();
    if (live && t == 0u) {
        for (var i = 1u; i < P; i++) {
            f |= flags[q * P + i];
        }
        cls[pid] = class_of(f);
    }
}
