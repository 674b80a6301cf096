#!/usr/bin/env python3
"""The mutation check: does the suite notice when one line of a model breaks?

Each entry of mutations.txt (beside this file) is a small, realistic bug: a file, an exact
snippet of it and its replacement, and the test programs that should catch it. For each one this
script copies the tree into a scratch folder (once; later runs reuse it and its build), restores
every mutated file, applies the mutation, rebuilds incrementally (ninja + ccache) only the test
programs named, runs them, and reports

  caught          a test program failed (or ran past its time limit: 3x its unmutated time + 30 s)
  SURVIVED        every test program passed: a test is missing
  does not apply  the snippet is not in the file exactly once (the source moved on: update the
                  entry, do not count it either way)
  does not build  the mutant does not compile (a broken entry, not a caught bug)

A viewer test program (luz_viewer_test in tests/CMakeLists.txt) reads what its scripted viewer
saved: its script runs first, through ctest, and a script that fails catches the mutant too.

Usage: tests/mutations/run.py [--only NAME[,NAME...]] [--full] [--keep-going]
  --only  run these mutations only
  --full  run the whole ctest suite per mutation instead of the named test programs (slow)
  --list  print the mutations and exit
Exit status: 0 when every mutation that applies was caught, 1 otherwise.
"""
import argparse
import datetime
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parent.parent
LIST = HERE / "mutations.txt"
# A mutant that hangs (a solver that never converges) is caught by a time limit: three times
# what the program took on the unmutated tree, plus 30 s for a loaded machine.
TIME_LIMIT_FACTOR, TIME_LIMIT_SLACK = 3.0, 30.0


class Mutation:
    def __init__(self, name):
        self.name = name
        self.what = ""
        self.tests = []
        self.hunks = []  # (file, original, replacement)


def parse(path):
    """mutations.txt: blocks of '## key: value' lines and hunks

         ## name: fresnel-at-normal-incidence
         ## what: Fresnel always evaluated at normal incidence
         ## tests: test_whitted
         @@ src/raytracing/whitted.cpp
         <<<<
         exact original lines
         ====
         replacement lines
         >>>>
    """
    mutations, current, hunk, mode = [], None, None, None
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if mode in ("old", "new"):
            if line == "====" and mode == "old":
                mode = "new"
            elif line == ">>>>" and mode == "new":
                current.hunks.append((hunk[0], "\n".join(hunk[1]), "\n".join(hunk[2])))
                mode = None
            else:
                hunk[1 if mode == "old" else 2].append(line)
            continue
        if line.startswith("## name:"):
            current = Mutation(line.split(":", 1)[1].strip())
            mutations.append(current)
        elif line.startswith("## what:"):
            current.what = line.split(":", 1)[1].strip()
        elif line.startswith("## tests:"):
            current.tests = line.split(":", 1)[1].split()
        elif line.startswith("@@ "):
            hunk = [line[3:].strip(), [], []]
        elif line == "<<<<":
            mode = "old"
        elif line.strip() and not line.startswith("#"):
            sys.exit(f"{path}:{number}: cannot read {line!r}")
    for m in mutations:
        if not m.hunks or not m.tests:
            sys.exit(f"{path}: mutation {m.name} needs a hunk and a '## tests:' line")
    return mutations


def copy_tree(scratch):
    """Tracked and untracked-but-not-ignored files of the checkout, into scratch/tree."""
    tree = scratch / "tree"
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=REPO,
                           check=True, capture_output=True).stdout.decode().split("\0")
    for name in filter(None, files):
        source, target = REPO / name, tree / name
        if not source.is_file():
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        # Copy only what changed, so that ninja rebuilds only that (with a new modification
        # time: the checkout's may be older than an object built from a mutant).
        if not target.exists() or target.read_bytes() != source.read_bytes():
            shutil.copyfile(source, target)
            shutil.copymode(source, target)
    return tree


def viewer_scripts():
    """Viewer test programs and the ctest test that runs their scripted viewer before them
    (tests/CMakeLists.txt's luz_viewer_test, or a program given LUZ_VIEWER_SCRIPT_TEST by hand, as
    the lessons' are): a mutant is caught there too when its viewer fails."""
    text = (REPO / "tests" / "CMakeLists.txt").read_text()
    scripts = {m.group(1): f"viewer_{pathlib.Path(m.group(2)).stem}_script"
               for m in re.finditer(r"^luz_viewer_test\((\w+)\s+(\S+)", text, re.M)}
    for m in re.finditer(r"target_compile_definitions\((\w+)\s+PRIVATE[^)]*LUZ_VIEWER_SCRIPT_TEST=\"(\w+)\"", text):
        scripts.setdefault(m.group(1), m.group(2))
    return scripts


def run(command, cwd, log, timeout=None, env=None):
    with open(log, "a") as out:
        out.write(f"\n$ {' '.join(map(str, command))}\n")
        out.flush()
        try:
            return subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                                  timeout=timeout, env=env).returncode
        except subprocess.TimeoutExpired:
            out.write(f"\n(timed out after {timeout} s)\n")
            return "timeout"


def run_program(program, build, log, timeout, env, scripts, flags=()):
    """A test program's exit status, after its scripted viewer's where it has one."""
    if program in scripts:
        code = run(["ctest", "--test-dir", str(build), "-R", f"^{scripts[program]}$", "--output-on-failure"],
                   build, log, timeout, env)
        if code != 0:
            return code
    return run([str(build / "tests" / program), *flags], build / "tests", log, timeout, env)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--only", default="")
    parser.add_argument("--full", action="store_true")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--scratch", default=str(REPO / "build-mutants"),
                        help="scratch folder (default: build-mutants in the checkout, ignored "
                             "by git; under CCACHE_BASEDIR so the first build hits the cache)")
    args = parser.parse_args()

    mutations = parse(LIST)
    if args.list:
        for m in mutations:
            print(f"{m.name:<36} {' '.join(m.tests):<40} {m.what}")
        return 0
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - {m.name for m in mutations}
        if unknown:
            sys.exit(f"unknown mutation(s): {', '.join(sorted(unknown))}")
        mutations = [m for m in mutations if m.name in wanted]

    scratch = pathlib.Path(args.scratch).resolve()
    scratch.mkdir(parents=True, exist_ok=True)
    log = scratch / "mutations.log"
    log.write_text(f"mutation check of {REPO}, {datetime.datetime.now(datetime.timezone.utc)}\n")
    tree = copy_tree(scratch)
    build = tree / "build"
    env = dict(os.environ)
    # Relative to a common base, the scratch build's paths (../src/...) equal the checkout's.
    env.setdefault("CCACHE_BASEDIR", str(REPO.parent))
    if not (build / "build.ninja").exists():
        configure = ["cmake", "-S", str(tree), "-B", str(build), "-G", "Ninja",
                     "-DCMAKE_BUILD_TYPE=Release"]
        if shutil.which("ccache"):
            configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        if run(configure, tree, log, env=env) != 0:
            sys.exit(f"cmake failed: see {log}")
    jobs = os.environ.get("LUZ_MUTATION_JOBS", "2")

    # The pristine text of every file a mutation touches, to restore it after each mutant.
    pristine = {}
    for m in mutations:
        for file, _, _ in m.hunks:
            if file not in pristine and (REPO / file).is_file():
                pristine[file] = (REPO / file).read_text()

    # Baseline: the named test programs must pass on the unmutated tree, or nothing is measured.
    baseline = sorted({t for m in mutations for t in m.tests})
    print(f"baseline: building and running {' '.join(baseline)}", flush=True)
    if run(["nice", "ninja", "-j", jobs, *baseline], build, log, env=env) != 0:
        sys.exit(f"the unmutated tree does not build: see {log}")
    limit = {}
    scripts = viewer_scripts()
    for program in baseline:
        t0 = time.time()
        if run_program(program, build, log, None, env, scripts) != 0:
            sys.exit(f"{program} fails on the unmutated tree: see {log}")
        limit[program] = TIME_LIMIT_FACTOR * (time.time() - t0) + TIME_LIMIT_SLACK
        print(f"  {program}: {time.time() - t0:.0f} s, time limit {limit[program]:.0f} s", flush=True)

    results, started = [], time.time()
    for m in mutations:
        t0 = time.time()
        for file, text in pristine.items():
            if (tree / file).read_text() != text:
                (tree / file).write_text(text)
        status = None
        texts = {}
        for file, original, replacement in m.hunks:
            text = texts.get(file, pristine.get(file))
            if text is None or text.count(original) != 1:
                status = "does not apply"
                break
            texts[file] = text.replace(original, replacement)
        if status is None:
            for file, text in texts.items():
                (tree / file).write_text(text)
            with open(log, "a") as out:
                out.write(f"\n==== {m.name}: {m.what}\n")
            if run(["nice", "ninja", "-j", jobs, *m.tests], build, log, env=env) != 0:
                status = "does not build"
            elif args.full:
                code = run(["ctest", "--test-dir", str(build), "-j", jobs], build, log, env=env)
                status = "SURVIVED" if code == 0 else "caught"
            else:
                status = "SURVIVED"
                for program in m.tests:
                    code = run_program(program, build, log, limit[program], env, scripts,
                                       ("--gtest_brief=1", "--gtest_fail_fast"))
                    if code != 0:
                        status = f"caught by {program}" + (" (timeout)" if code == "timeout" else "")
                        break
        results.append((m, status))
        print(f"{m.name:<36} {status:<32} {time.time() - t0:6.0f} s   {m.what}", flush=True)

    for file, text in pristine.items():  # leave the scratch tree unmutated
        if (tree / file).read_text() != text:
            (tree / file).write_text(text)
    counts = {}
    for _, status in results:
        key = status.split(" by ")[0]
        counts[key] = counts.get(key, 0) + 1
    minutes = (time.time() - started) / 60
    print(f"\n{len(results)} mutations: " + ", ".join(f"{n} {k}" for k, n in sorted(counts.items()))
          + f"; {minutes:.1f} min. Log: {log}")
    return 0 if counts.get("SURVIVED", 0) == 0 and counts.get("does not build", 0) == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
