"""wgsl_contract.py: probes whether a WGSL difference of products a*b - c*d with a*b == c*d is
exactly zero on this device (wgpu-native through wgpu-py; run with build/venv/bin/python).

WGSL has no `precise` and naga emits no NoContraction, so a driver may fuse a*b - c*d into
fma(a, b, -(c*d)), which returns the rounding error of c*d instead of 0. Each form below runs on
65536 pairs whose float product rounds; prints "ok"/"not ok" lines (tests/README.md, exact zeros).
"""
import random
import struct
import sys

import wgpu

N = 1 << 16

# The forms: the plain expression; the products through an integer XOR with a zero the compiler
# cannot see (the host's zero padding after patch_count), which no contraction crosses; and
# fma() itself, whose answer tells whether this device fuses at all (information, not a check).
FORMS = {
    "plain a*b - c*d": "o[i] = a * b - c * d;",
    "products through bitcast<u32> ^ zero": (
        "let p = bitcast<f32>(bitcast<u32>(a * b) ^ u.zero);\n"
        "    let q = bitcast<f32>(bitcast<u32>(c * d) ^ u.zero);\n"
        "    o[i] = p - q;"),
    "fma(a, b, -(c*d))": "o[i] = fma(a, b, -(c * d));",
}

SHADER = """
struct U { n: u32, zero: u32 }
@group(0) @binding(0) var<storage, read> v: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> o: array<f32>;
@group(0) @binding(2) var<uniform> u: U;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) g: vec3<u32>) {
    let i = g.x;
    if (i >= u.n) { return; }
    let a = v[i].x; let b = v[i].y; let c = v[i].z; let d = v[i].w;
    BODY
}
"""


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def run(dev, body, data):
    """Runs one form over data (a flat list of a, b, c, d); returns the N results."""
    pipe = dev.create_compute_pipeline(
        layout="auto",
        compute={"module": dev.create_shader_module(code=SHADER.replace("BODY", body)),
                 "entry_point": "main"})
    bi = dev.create_buffer_with_data(data=struct.pack(f"{4 * N}f", *data),
                                     usage=wgpu.BufferUsage.STORAGE)
    bu = dev.create_buffer_with_data(data=struct.pack("4I", N, 0, 0, 0),
                                     usage=wgpu.BufferUsage.UNIFORM)
    bo = dev.create_buffer(size=4 * N,
                           usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_SRC)
    group = dev.create_bind_group(layout=pipe.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": {"buffer": bi}},
        {"binding": 1, "resource": {"buffer": bo}},
        {"binding": 2, "resource": {"buffer": bu}}])
    enc = dev.create_command_encoder()
    cp = enc.begin_compute_pass()
    cp.set_pipeline(pipe)
    cp.set_bind_group(0, group)
    cp.dispatch_workgroups(N // 64)
    cp.end()
    dev.queue.submit([enc.finish()])
    return struct.unpack(f"{N}f", dev.queue.read_buffer(bo))


def main():
    adapter = wgpu.gpu.request_adapter_sync()
    dev = adapter.request_device_sync()
    print(f"# device: {adapter.info['device']} ({adapter.info['backend_type']})")
    rng = random.Random(1)
    data, err = [], []
    for _ in range(N):
        a, b = f32(rng.uniform(-1e3, 1e3)), f32(rng.uniform(-1e3, 1e3))
        data += [a, b, a, b]
        err.append(a * b - f32(a * b))  # exact in double: what a fused form returns
    rounded = sum(e != 0 for e in err)
    failed = 0
    for name, body in FORMS.items():
        out = run(dev, body, data)
        nonzero = sum(x != 0 for x in out)
        fused = sum(x == e and e != 0 for x, e in zip(out, err))
        if name.startswith("fma"):
            print(f"# {name}: fused on this device in {fused} of {rounded} cases whose product "
                  f"rounds ({'fuses' if fused else 'does not fuse, so no contraction shows here'})")
        elif nonzero:
            failed += 1
            print(f"not ok - WGSL {name} is exactly 0 when a*b == c*d: {nonzero} of {N} are not "
                  f"({fused} equal to the rounding error: contracted into an FMA)")
        else:
            print(f"ok - WGSL {name} is exactly 0 when a*b == c*d ({N} pairs, {rounded} with a "
                  f"rounded product)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
