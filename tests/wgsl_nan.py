"""wgsl_nan.py: checks that a generated WGSL kernel calls a patch with a NaN control point
silhouette (WGSL compilers may assume there is no NaN; run with build/venv/bin/python).

    wgsl_nan.py KERNEL.wgsl N M SPACE LABEL

Runs the kernel on Q copies of a flat (N, M) grid patch, seen from one side, and Q copies with
one coordinate of one control point NaN (each copy another point and coordinate that
the space reads); the flat
ones must come back front or back, the NaN ones silhouette. Prints "ok"/"not ok" lines.
"""
import math
import re
import struct
import sys

import wgpu


def patches(n, m, count, space):
    """count flat patches then count with a NaN coordinate, as a flat list of floats."""
    k = (n + 1) * (m + 1)
    flat = []
    for i in range(n + 1):
        for j in range(m + 1):
            flat += [i / n, j / m, 0.25 if space == "world" else 0.5, 1.0]
    out = flat * count
    axes = (0, 1, 3) if space == "clip" else (0, 1, 2, 3)  # clip space reads no z
    for p in range(count):
        q = list(flat)
        q[(p % k) * 4 + axes[p // k % len(axes)]] = math.nan
        out += q
    return out


def main():
    path, n, m, space, label = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
    code = open(path).read()
    group = int(re.search(r"@workgroup_size\((\d+)\)", code).group(1))
    q = int(re.search(r"_Q: u32 = (\d+)u", code).group(1))
    count = 4 * q
    data = patches(n, m, count, space)
    eye = [0.0, 0.0, 1.0, 0.0] if space == "clip" else [0.3, 0.4, 5.0, 1.0]
    dev = wgpu.gpu.request_adapter_sync().request_device_sync()
    pipe = dev.create_compute_pipeline(layout="auto", compute={
        "module": dev.create_shader_module(code=code), "entry_point": "main"})
    bp = dev.create_buffer_with_data(data=struct.pack(f"{len(data)}f", *data),
                                     usage=wgpu.BufferUsage.STORAGE)
    bc = dev.create_buffer(size=8 * count, usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_SRC)
    bu = dev.create_buffer_with_data(data=struct.pack("4f4I", *eye, 2 * count, 0, 0, 0),
                                     usage=wgpu.BufferUsage.UNIFORM)
    bind = dev.create_bind_group(layout=pipe.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": {"buffer": bp}}, {"binding": 1, "resource": {"buffer": bc}},
        {"binding": 3, "resource": {"buffer": bu}}])
    enc = dev.create_command_encoder()
    cp = enc.begin_compute_pass()
    cp.set_pipeline(pipe)
    cp.set_bind_group(0, bind)
    cp.dispatch_workgroups(2 * count // q)
    cp.end()
    dev.queue.submit([enc.finish()])
    cls = struct.unpack(f"{2 * count}I", dev.queue.read_buffer(bc))
    assert group % q == 0
    flat, nan = cls[:count], cls[count:]
    ok = all(c == flat[0] for c in flat) and flat[0] in (0, 1)
    print(f"{'ok' if ok else 'not ok'} - {label}: {count} flat patches are front or back "
          f"(classes {sorted(set(flat))})")
    bad = sum(c != 2 for c in nan)
    print(f"{'ok' if not bad else 'not ok'} - {label}: {count} patches with a NaN coordinate are "
          f"silhouette{f' ({bad} are not)' if bad else ''}")
    return 0 if ok and not bad else 1


if __name__ == "__main__":
    sys.exit(main())
