#!/usr/bin/env python3
"""Luz's Whitted tracer against Mitsuba 3 on the SAME scenes: the shipped glTF files, converted by
docs/mitsuba_scene.py. A throwaway measurement, never part of the build or the tests; Mitsuba
lives in a venv outside the repository (needs Debian's libllvm19 for the llvm variant):

    python3 -m venv /work/venv-mitsuba && /work/venv-mitsuba/bin/pip install mitsuba
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
        /work/venv-mitsuba/bin/python docs/bench_mitsuba.py [--luz build/luz] [--runs 5]

Two pairs per scene, 1024x1024, 1 spp:
  Luz Whitted depth 1 (local model + shadow rays)   vs  Mitsuba `direct`
  Luz Whitted depth 5                                vs  Mitsuba `path`, max_depth 5
The runs interleave (Luz, Mitsuba, Luz, Mitsuba, ...) in one invocation, so both see the same
load; each line reports the best and the median of the runs and the load average (uptime) seen
around them. Luz's figure is the render time `luz bench whitted` prints (the trace of every
pixel, on TBB's threads); Mitsuba's is mi.render() to a synchronised result, after one untimed
render that compiles its kernels.
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402

from mitsuba_scene import scene_dict  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def luz_seconds(luz, scene, depth, size):
    out = subprocess.run([luz, "bench", "whitted", "--size", f"{size}x{size}", "--depth", str(depth),
                          "--spp", "1", "--repeats", "1", "--scenes", scene],
                         check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        fields = line.split()
        if fields and fields[0] == scene:
            return float(fields[1])
    raise RuntimeError(f"no timing for {scene} in:\n{out}")


def mitsuba_seconds(scene):
    start = time.perf_counter()
    image = mi.render(scene, spp=1, seed=0)
    dr.eval(image)
    dr.sync_thread()
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--luz", default=os.path.join(ROOT, "build", "luz"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--scenes", default="whitted,cornell_box")
    parser.add_argument("--variant", default="llvm_ad_rgb")
    args = parser.parse_args()
    mi.set_variant(args.variant)

    print(f"Luz ({args.luz}) vs Mitsuba {mi.__version__} {args.variant}, {args.size}x{args.size}, "
          f"1 spp, {args.runs} interleaved runs each; {os.cpu_count()} CPUs")
    print(f"{'scene':<14} {'pair':<28} {'Luz best':>9} {'median':>8} {'Mitsuba best':>13} "
          f"{'median':>8} {'ratio Luz/Mi':>13} {'load':>10}")
    for name in args.scenes.split(","):
        path = os.path.join(ROOT, "scenes", name + ".gltf")
        pairs = [("Whitted d1 / direct", 1, {"type": "direct"}),
                 ("Whitted d5 / path d5", 5, {"type": "path", "max_depth": 5})]
        for label, depth, integrator in pairs:
            scene = mi.load_dict(scene_dict(path, args.size, args.size, integrator))
            mitsuba_seconds(scene)  # compiles the kernels
            luz, mitsuba, loads = [], [], []
            for _ in range(args.runs):
                loads.append(load_average())
                luz.append(luz_seconds(args.luz, name, depth, args.size))
                mitsuba.append(mitsuba_seconds(scene))
            loads.append(load_average())
            ratio_best = min(luz) / min(mitsuba)
            ratio_median = statistics.median(luz) / statistics.median(mitsuba)
            print(f"{name:<14} {label:<28} {min(luz):>9.3f} {statistics.median(luz):>8.3f} "
                  f"{min(mitsuba):>13.3f} {statistics.median(mitsuba):>8.3f} "
                  f"{ratio_best:>6.2f}/{ratio_median:<6.2f} {min(loads):>4.1f}-{max(loads):<4.1f}",
                  flush=True)
    print("ratio: best/best and median/median (below 1: Luz is faster); load: 1-minute load average")


if __name__ == "__main__":
    main()
