#!/usr/bin/env python3
"""figures.py: `make figures`: build/render on the generated knot (build/models/knot.bez) and the
teapot (models/), or BigGuy and the teapot of --models DIR, for every cull method over
tessellation factors 1..64 from fixed views; writes bench/figures/: the Figure-1 images of one
view, plots of frame time and of tessellation-evaluation invocations against the factor (gnuplot),
table.md with the numbers, and raw.txt with every output line.

  figures.py RENDER OUT_DIR [--models DIR] [--quick | --one-view]   (--quick: factors 1, 4, 16;
  one view; 1 frame. --one-view: every factor and frame, the first view of each model)
"""
import os
import struct
import subprocess
import sys
import zlib

METHODS = ["none", "tcone", "ncone", "ptp", "ptp-tcs", "ptp-table", "ptp-certified", "ptp-tcs-certified"]
FACTORS = [1, 2, 4, 8, 16, 32, 64]
SIZE = "512x512"
FRAMES = 3
# model: (file, extra options, eyes), the first for Figure 1; the teapot's dB/du x dB/dv faces
# in. select_models fills it in.
MODELS = {}
BIG_EYES = ["0,0,12", "9,4,-7", "-10,3,5"]
TEAPOT = (["--up", "0,0,1", "--orientation", "in"], ["8,-6,5", "-8,-8,4", "-6,3,-4"])


def select_models(folder):
    """The knot and models/teapot.bez, or with a folder its bigguy.bez and teapot.bez."""
    if folder:
        big = ("bigguy", os.path.join(folder, "bigguy.bez"))
        teapot = os.path.join(folder, "teapot.bez")
    else:
        big, teapot = ("knot", "build/models/knot.bez"), "models/teapot.bez"
    for path in (big[1], teapot):
        if not os.path.isfile(path):
            sys.exit("figures.py: no model %s%s" % (path, "" if folder else
                                                    " (make build/models/knot.bez)"))
    MODELS[big[0]] = (big[1], [], BIG_EYES)
    MODELS["teapot"] = (teapot,) + TEAPOT
TIMES = ["frame_ms", "frame_min_ms", "frame_cpu_ms", "cull_cpu_ms", "draw_cpu_ms"]


def run(render, args):
    """One build/render run: its key=value line as a dict (and the raw line)."""
    out = subprocess.run([render] + args, check=True, capture_output=True, text=True).stdout
    line = out.strip().splitlines()[-1]
    return dict(kv.split("=", 1) for kv in line.split()), line


def measure(render, out, factors, eyes_of, frames):
    """rows[(model, method, factor)] = averages over the views; raw lines into raw.txt."""
    rows = {}
    with open(os.path.join(out, "raw.txt"), "w") as raw:
        for name, (path, extra, eyes) in MODELS.items():
            for factor in factors:
                for method in METHODS:
                    got = []
                    for eye in eyes_of(eyes):
                        kv, line = run(render, ["--model", path, "--eye", eye,
                                                "--tess", str(factor), "--cull", method,
                                                "--size", SIZE, "--frames", str(frames)] + extra)
                        raw.write(line + "\n")
                        got.append(kv)
                    rows[(name, method, factor)] = {
                        k: sum(float(g[k]) for g in got) / len(got)
                        for k in TIMES + ["culled", "patches", "tes_invocations"]}
                    row = rows[(name, method, factor)]
                    row["device"] = got[0]["device"]
                    print("%s %s tess %d: %.1f ms CPU" % (name, method, factor,
                                                          row["frame_cpu_ms"]), flush=True)
    return rows


def plot(rows, out, factors, frames):
    """One data file per model (a column per method) and two gnuplot PNGs per model."""
    for name in MODELS:
        dat = os.path.join(out, name + ".dat")
        with open(dat, "w") as f:
            f.write("# tess %s\n" % " ".join("%s_frame_cpu_ms %s_tes" % (m, m) for m in METHODS))
            for t in factors:
                cols = ("%.3f %.0f" % (rows[(name, m, t)]["frame_cpu_ms"],
                                       rows[(name, m, t)]["tes_invocations"]) for m in METHODS)
                f.write("%d %s\n" % (t, " ".join(cols)))
        for what, col, ylabel in (("frame_ms", 0, "CPU time of a frame (ms, median of %d)"
                                   % frames), ("tes", 1, "tessellation evaluation invocations")):
            curves = ", ".join("'%s' using 1:%d with linespoints title '%s'"
                               % (dat, 2 + 2 * i + col, m) for i, m in enumerate(METHODS))
            script = ("set terminal pngcairo size 720,480 noenhanced\n"
                      "set output '%s'\nset logscale xy\nset xtics (%s)\n"
                      "set xlabel 'tessellation factor'\nset ylabel '%s'\nset key top left\n"
                      "set title '%s, %s, lavapipe (every stage on the CPU)'\nplot %s\n"
                      % (os.path.join(out, "%s_%s.png" % (name, what)),
                         ", ".join(str(t) for t in factors), ylabel, name, SIZE, curves))
            subprocess.run(["gnuplot"], input=script, text=True, check=True)


def table(rows, out, factors, views, frames):
    """table.md: per model and factor, every method's culled share, work and times."""
    dev = next(iter(rows.values()))["device"]
    lines = ["# build/render: frame time against tessellation factor", "",
             "`make figures`: %s, %d view(s) per model, %d frames each, averaged over the views; "
             "device %s, which runs every stage on the CPU. Times in milliseconds, medians over "
             "the frames: the process's CPU time (lavapipe's threads included: the work, whatever "
             "else the shared machine runs) of the cull pass's submission, of the draw's and of "
             "the whole frame (transform, cull and draw submitted and waited for in turn); the "
             "frame's wall time (best and median frame, which depend on the machine's load). "
             "`vs none`: CPU time of the frame against `--cull none`."
             % (SIZE, views, frames, dev), ""]
    for name in MODELS:
        lines += ["## %s" % name, "",
                  "| tess | method | culled | tes_invocations | cull CPU | draw CPU | frame CPU "
                  "| frame wall, best | median | vs none |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for t in factors:
            base = rows[(name, "none", t)]["frame_cpu_ms"]
            for m in METHODS:
                r = rows[(name, m, t)]
                lines.append("| %d | %s | %.1f%% | %.0f | %.2f | %.2f | %.2f | %.2f | %.2f | "
                             "%.2fx |" % (t, m, 100 * r["culled"] / r["patches"],
                                          r["tes_invocations"], r["cull_cpu_ms"],
                                          r["draw_cpu_ms"], r["frame_cpu_ms"],
                                          r["frame_min_ms"], r["frame_ms"],
                                          r["frame_cpu_ms"] / base))
        lines.append("")
    with open(os.path.join(out, "table.md"), "w") as f:
        f.write("\n".join(lines))


def compress_png(path):
    """Rewrites build/render's PNG (stored zlib blocks) with its IDAT deflated: the same pixels,
    a twentieth of the bytes in the repository."""
    data = open(path, "rb").read()
    pos, chunks = 8, []
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        chunks.append((data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]))
        pos += 12 + n
    idat = zlib.compress(zlib.decompress(b"".join(b for k, b in chunks if k == b"IDAT")), 9)
    with open(path, "wb") as f:
        f.write(data[:8])
        for kind, body in [c for c in chunks if c[0] == b"IHDR"] + [(b"IDAT", idat),
                                                                      (b"IEND", b"")]:
            f.write(struct.pack(">I", len(body)) + kind + body +
                    struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))


def figure1(render, out):
    """The first model from its first view at factor 8: the image, and per method the overview."""
    name = next(iter(MODELS))
    path, extra, eyes = MODELS[name]
    base = ["--model", path, "--eye", eyes[0], "--tess", "8",
            "--size", SIZE, "--frames", "1"] + extra
    paths = [os.path.join(out, "fig1_%s_%s.png" % (name, m)) for m in ["image"] + METHODS[1:]]
    run(render, base + ["--cull", "none", "--png", paths[0]])
    for m, path in zip(METHODS[1:], paths[1:]):
        run(render, base + ["--cull", m, "--overview", path])
    for path in paths:
        compress_png(path)


def main():
    render, out, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    folder = args[args.index("--models") + 1] if "--models" in args[:-1] else None
    select_models(folder)
    quick = "--quick" in args
    views = 1 if quick or "--one-view" in args else 3
    factors = [1, 4, 16] if quick else FACTORS
    eyes_of = lambda eyes: eyes[:views]
    frames = 1 if quick else FRAMES
    os.makedirs(out, exist_ok=True)
    figure1(render, out)
    rows = measure(render, out, factors, eyes_of, frames)
    plot(rows, out, factors, frames)
    table(rows, out, factors, views, frames)


if __name__ == "__main__":
    main()
