{{BANNER}}
struct Params {
    eye: vec4<f32>,
    patch_count: u32,
    zero: u32, /* the host's zero padding: an integer 0 the compiler cannot know */
}

@group(0) @binding(0) var<storage, read> cp: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> cls: array<u32>;
{{PLANES_BUFFER}}{{INDEXED}}@group(0) @binding(3) var<uniform> params: Params;

/* x * y rounded to a float: through an integer XOR with a zero known only at run time, which no
 * FMA contraction can cross (WGSL has no `precise`). */
fn mul_rn(x: f32, y: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x * y) ^ params.zero);
}

/* b - a rounded to floats, through the same XOR: no reassociation or contraction crosses it. */
fn sub_rn(b: vec4<f32>, a: vec4<f32>) -> vec4<f32> {
    return bitcast<vec4<f32>>(bitcast<vec4<u32>>(b - a) ^ vec4<u32>(params.zero));
}

{{TABLES}}{{SHARED}}
{{FUNCTIONS}}@compute @workgroup_size({{BLOCK_THREADS}})
fn main(@builtin(local_invocation_id) lid3: vec3<u32>, @builtin(workgroup_id) wid: vec3<u32>,
        @builtin(num_workgroups) nwg: vec3<u32>) {
    let eye = params.eye;
    let patch_count = params.patch_count;
{{BODY}}}
