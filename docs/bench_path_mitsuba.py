#!/usr/bin/env python3
"""Luz's path tracer against Mitsuba 3's `path` integrator on the same scene, in the same run:
samples per second, and the time each needs to reach 3% mean relative error over lit pixels.
A throwaway measurement for docs/path_tracer.md, never part of the build or the tests:

    python3 -m venv /tmp/mitsuba && /tmp/mitsuba/bin/pip install mitsuba numpy
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
        /tmp/mitsuba/bin/python docs/bench_path_mitsuba.py build/luz [scenes/cornell_box.gltf]

The scene is converted by docs/mitsuba_scene.py (Luz's glTF reading, SCENES.md). Both render
max depth 16 in Luz's count (primary ray = depth 1; Mitsuba's max_depth is one more, it counts
the emitter seen as depth 1 too) with Russian roulette from the same depth, a box pixel filter
and independent samples. The error figures come from `luz compare --mask-emitters` against one
long Luz render (the reference), so both tracers are measured with the same code.
"""
import os
import re
import subprocess
import sys
import tempfile
import time

import drjit as dr
import mitsuba as mi

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_scene  # noqa: E402

mi.set_variant("llvm_ad_rgb")
luz = sys.argv[1] if len(sys.argv) > 1 else "build/luz"
scene_path = sys.argv[2] if len(sys.argv) > 2 else "scenes/cornell_box.gltf"
THROUGHPUT_SIZE, THROUGHPUT_SPP = 256, 64
ERROR_SIZE, REFERENCE_SPP = 64, 16384
SWEEP = [64, 128, 256, 512, 1024, 2048]
work = tempfile.mkdtemp(prefix="luz_bench_path_")


def luz_render(size, spp, out, seed=0):
    start = time.perf_counter()
    result = subprocess.run([luz, "render", scene_path, "--model", "path", "--size", f"{size}x{size}",
                             "--spp", str(spp), "--seed", str(seed), "--out", out],
                            capture_output=True, text=True, check=True)
    seconds = time.perf_counter() - start
    rate = float(re.search(r"([0-9.e+]+) samples/s", result.stdout).group(1))
    return seconds, rate


def mitsuba_render(scene, spp, out, seed=0):
    start = time.perf_counter()
    image = mi.render(scene, spp=spp, seed=seed)
    dr.eval(image)
    dr.sync_thread()
    seconds = time.perf_counter() - start
    mi.util.write_bitmap(out, image, write_async=False)  # luz compare reads it next
    return seconds


def relative_error(image, reference):
    out = subprocess.run([luz, "compare", image, reference, "--mask-emitters"],
                         capture_output=True, text=True, check=True).stdout
    return float(re.search(r"over lit pixels: ([0-9.]+)", out).group(1))


def time_to(target, sweep):
    """Seconds at which the error crosses `target`, interpolated in log-log between sweep points
    (error ~ 1/sqrt(time) for an unbiased estimator)."""
    import math
    for (t0, e0), (t1, e1) in zip(sweep, sweep[1:]):
        if e0 >= target >= e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0)))
    return float("nan")


print(f"Mitsuba {mi.__version__} (llvm_ad_rgb) against {luz} on {scene_path}; "
      f"machine: {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} at the start")

# ---- samples per second -------------------------------------------------------------------------
scene = mitsuba_scene.load(scene_path, THROUGHPUT_SIZE, THROUGHPUT_SIZE, max_depth=17, rr_depth=5)
first = mitsuba_render(scene, THROUGHPUT_SPP, os.path.join(work, "m_warm.exr"))
mitsuba_seconds = mitsuba_render(scene, THROUGHPUT_SPP, os.path.join(work, "m.exr"), seed=1)
luz_seconds, luz_rate = luz_render(THROUGHPUT_SIZE, THROUGHPUT_SPP, os.path.join(work, "l.exr"))
samples = THROUGHPUT_SIZE * THROUGHPUT_SIZE * THROUGHPUT_SPP
print(f"\n{THROUGHPUT_SIZE}x{THROUGHPUT_SIZE}, {THROUGHPUT_SPP} spp:")
print("| tracer | seconds | samples/s |\n| --- | --- | --- |")
print(f"| Luz path (render only) | {samples / luz_rate:.2f} | {luz_rate:.3g} |")
print(f"| Mitsuba path, llvm (first run with JIT: {first:.2f} s) | {mitsuba_seconds:.2f} | "
      f"{samples / mitsuba_seconds:.3g} |")
print(f"Mitsuba against Luz at equal spp: "
      f"{relative_error(os.path.join(work, 'm.exr'), os.path.join(work, 'l.exr')):.4f} mean relative error")

# ---- time to 3% ---------------------------------------------------------------------------------
reference = os.path.join(work, "reference.exr")
ref_seconds, _ = luz_render(ERROR_SIZE, REFERENCE_SPP, reference, seed=12345)
print(f"\nreference: Luz, {ERROR_SIZE}x{ERROR_SIZE}, {REFERENCE_SPP} spp, {ref_seconds:.1f} s")
scene = mitsuba_scene.load(scene_path, ERROR_SIZE, ERROR_SIZE, max_depth=17, rr_depth=5)
mitsuba_render(scene, SWEEP[0], os.path.join(work, "warm.exr"))  # compile the kernels first
rows, luz_sweep, mitsuba_sweep = [], [], []
for spp in SWEEP:
    out = os.path.join(work, f"l{spp}.exr")
    seconds, _ = luz_render(ERROR_SIZE, spp, out, seed=spp)
    luz_sweep.append((seconds, relative_error(out, reference)))
    out = os.path.join(work, f"m{spp}.exr")
    seconds = mitsuba_render(scene, spp, out, seed=spp)
    mitsuba_sweep.append((seconds, relative_error(out, reference)))
    rows.append(f"| {spp} | {luz_sweep[-1][0]:.2f} s, {100 * luz_sweep[-1][1]:.2f}% | "
                f"{mitsuba_sweep[-1][0]:.2f} s, {100 * mitsuba_sweep[-1][1]:.2f}% |")
print("| spp | Luz: time, mean relative error | Mitsuba: time, mean relative error |\n| --- | --- | --- |")
print("\n".join(rows))
print(f"time to 3%: Luz {time_to(0.03, luz_sweep):.2f} s, Mitsuba {time_to(0.03, mitsuba_sweep):.2f} s "
      f"(load average {os.getloadavg()[0]:.1f} at the end)")
