#!/usr/bin/env python3
"""The viewer's frame against `luz bench local`'s, on the same machine in the same minutes. A
measurement, never part of the build or the tests; needs Xvfb (setup.sh installs it):

    python3 docs/bench_viewer.py [--luz build/luz] [--rounds 5] [--scene cornell_box]
                                 [--window 1280x720] [--models flat phong]

Each round runs `luz bench local` (the scene, each model without effects, 40 frames, 1280x720)
and then the viewer under Xvfb, one window per model: a script that waits 60 frames and dumps
the state seven times, 30 frames apart (`frame_ms` is smoothed over about ten frames; the
round's figure is the median dump, printed with its phases). Rounds interleave the two, so a
machine whose speed drifts slows both alike; the ratio is taken round by round and its median
reported, with the load average (uptime) seen around the rounds.

Each viewer runs on an Xvfb of its own, whose CPU time (/proc) from the first dump to the last,
divided by the frames between them, is the X server's share of every frame: presenting copies the
picture into the server, which makes the copy on the same processors as the drawing.

The bench draws 1280x720 pictures. In a 1280x720 window the panel takes the left part of it and
the picture is smaller; `--window 1720x752` gives the picture itself 1280x720 at the default UI
scale (`dump-windows` tells the picture's rectangle).
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DUMPS = 7
DUMP_FRAMES = 30  # frames between dumps


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def bench_medians(luz, scene, models):
    """The bench's median ms per frame of each model, without effects."""
    out = subprocess.run([luz, "bench", "local", "--scenes", scene, "--shadings", *models,
                          "--effects", "none", "--frames", "40"],
                         check=True, capture_output=True, text=True).stdout
    medians = {}
    for line in out.splitlines():
        fields = line.split()
        if len(fields) > 4 and fields[0] == scene and fields[1] in models:
            medians[fields[1]] = float(fields[4])
    missing = set(models) - set(medians)
    if missing:
        raise RuntimeError(f"no bench figure for {sorted(missing)} in:\n{out}")
    return medians


def cpu_seconds(pid):
    """User and system CPU time of process pid so far."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()  # after the command's name, which may hold spaces
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def start_xvfb():
    """An Xvfb on a free display: the process and its DISPLAY. -noreset: a server resets when its
    last client leaves, and `luz` checks for a display (a connection it closes) before it opens its
    window, whose connection could fall into the reset."""
    read_end, write_end = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1920x1080x24",
                             "-nolisten", "tcp", "-noreset"], pass_fds=(write_end,),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    with os.fdopen(read_end) as f:
        number = f.readline().strip()
    if not number:
        xvfb.kill()
        raise RuntimeError("Xvfb did not start")
    return xvfb, f":{number}"


def viewer_frame(luz, scene_path, model, window, folder):
    """The median of the dumps' frame_ms, that dump's phases, and the X server's ms of CPU a frame."""
    lines = [f"model {model}", "wait 60"]
    for i in range(DUMPS):
        lines += [f"dump-state state{i}.json", f"wait {DUMP_FRAMES}"]
    lines.append("quit")
    script = os.path.join(folder, "frames.txt")
    with open(script, "w") as f:
        f.write("\n".join(lines) + "\n")
    dumps = [os.path.join(folder, f"state{i}.json") for i in range(DUMPS)]
    for dump in dumps:
        if os.path.exists(dump):
            os.remove(dump)
    xvfb, display = start_xvfb()
    try:
        # Its messages to a file, not a pipe: nothing reads a pipe while the dumps are awaited.
        with tempfile.TemporaryFile(mode="w+") as errors:
            viewer = subprocess.Popen([luz, "--script", script, "--size", window, scene_path], cwd=folder,
                                      env=dict(os.environ, DISPLAY=display),
                                      stdout=subprocess.DEVNULL, stderr=errors)
            # The server's CPU time when the first dump and the last appear (polled every 2 ms).
            server = []
            for dump in (dumps[0], dumps[-1]):
                while not os.path.exists(dump) and viewer.poll() is None:
                    time.sleep(0.002)
                server.append(cpu_seconds(xvfb.pid))
            if viewer.wait(timeout=600) != 0:
                errors.seek(0)
                raise RuntimeError(f"the viewer failed ({viewer.returncode}):\n{errors.read()}")
    finally:
        xvfb.terminate()
        xvfb.wait()
    server_ms = 1000.0 * (server[1] - server[0]) / (DUMP_FRAMES * (DUMPS - 1))
    states = []
    for dump in dumps:
        with open(dump) as f:
            states.append(json.load(f))
    states.sort(key=lambda s: s["frame_ms"])
    median = states[DUMPS // 2]
    return median["frame_ms"], median["frame_phases_ms"], server_ms


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--luz", default=os.path.join(ROOT, "build", "luz"))
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--scene", default="cornell_box", help="a shipped scene's name")
    parser.add_argument("--window", default="1280x720", help="the viewer's window, WxH")
    parser.add_argument("--models", nargs="+", default=["flat", "phong"],
                        choices=["flat", "gouraud", "phong"])
    args = parser.parse_args()
    if not shutil.which("Xvfb"):
        sys.exit("bench_viewer.py: needs Xvfb (the xvfb package, which setup.sh installs)")
    scene_path = os.path.join(ROOT, "scenes", f"{args.scene}.gltf")
    if not os.path.exists(scene_path):
        sys.exit(f"bench_viewer.py: no shipped scene {args.scene} ({scene_path})")

    ratios = {m: [] for m in args.models}
    loads = [load_average()]
    print(f"{args.scene}, window {args.window}, bench 1280x720; ms per frame (viewer phases: models,"
          " panel, present; the X server's CPU)")
    with tempfile.TemporaryDirectory() as folder:
        for r in range(args.rounds):
            bench = bench_medians(args.luz, args.scene, args.models)
            for model in args.models:
                frame, phases, server = viewer_frame(args.luz, scene_path, model, args.window, folder)
                ratio = frame / bench[model]
                ratios[model].append(ratio)
                print(f"round {r + 1} {model:7} bench {bench[model]:6.2f}  viewer {frame:6.2f}"
                      f" ({phases.get('models', 0):.2f}, {phases.get('panel', 0):.2f},"
                      f" {phases.get('present', 0):.2f}; {server:.2f})  viewer / bench {ratio:.2f}", flush=True)
            loads.append(load_average())
    print(f"load average {min(loads):.1f}-{max(loads):.1f}")
    for model in args.models:
        values = ratios[model]
        print(f"{model:7} viewer / bench: median {statistics.median(values):.2f}"
              f" ({min(values):.2f}-{max(values):.2f}) over {len(values)} rounds")


if __name__ == "__main__":
    main()
