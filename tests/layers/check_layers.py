#!/usr/bin/env python3
"""Holds src/app's #include lines to the layers of tests/layers/layers.txt.

Usage: check_layers.py LAYERS.txt APP_DIR
Prints every include that crosses an edge the file does not list, and every folder that holds
more than MAX_FILES files, and exits 1 when there is one.
"""
import pathlib
import re
import sys

MAX_FILES = 40  # a folder a reader takes in at a glance


def unit_of(relative: pathlib.PurePosixPath) -> str:
    """The unit a file of src/app belongs to (see layers.txt)."""
    parts = relative.parts
    if len(parts) == 1:
        return "main"
    if parts[0] == "models":
        if len(parts) == 2:
            return "models"
        model = parts[1]
        headless = (f"render_{model}", f"{model}_options")  # its render and its options table
        return model if relative.stem in headless else f"{model}_view"
    if parts[0] == "cli" and len(parts) > 2:
        return parts[1]  # cli/bench
    return parts[0]


def read_layers(path: pathlib.Path):
    allowed, never = {}, {}
    for number, line in enumerate(path.read_text().splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        head, _, rest = line.partition(":")
        if not _:
            sys.exit(f"{path}:{number}: expected 'UNIT: UNITS' or 'UNIT never: HEADERS'")
        if head.endswith(" never"):
            never[head[: -len(" never")].strip()] = rest.split()
        else:
            allowed[head.strip()] = set(rest.split())
    return allowed, never


def model_rules(unit: str, allowed, never) -> None:
    """A model folder that layers.txt does not name takes its MODEL and MODEL_view rules."""
    if unit in allowed:
        return
    view = unit.endswith("_view")
    model = unit[: -len("_view")] if view else unit
    template = "MODEL_view" if view else "MODEL"
    if template in allowed:
        allowed[unit] = {u.replace("MODEL", model) for u in allowed[template]}
        never[unit] = never.get(template, [])


def main() -> int:
    layers, app = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    allowed, never = read_layers(layers)
    problems = []
    files = sorted(p for p in app.rglob("*") if p.suffix in (".h", ".cpp"))
    if not files:
        problems.append(f"{app}: no sources")
    for path in files:
        relative = pathlib.PurePosixPath(path.relative_to(app).as_posix())
        unit = unit_of(relative)
        if relative.parts[0] == "models" and len(relative.parts) > 2:
            model_rules(unit, allowed, never)
        if unit not in allowed:
            problems.append(f"{relative}: its unit '{unit}' is not in {layers.name}")
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            found = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
            if not found:
                continue
            bracket, header = found.groups()
            spelled = ("<" if bracket == "<" else "") + header
            for banned in never.get(unit, []):
                if spelled.startswith(banned):
                    problems.append(f"{relative}:{number}: {unit} never includes {line.strip()[len('#include '):]}")
            if bracket == '"' and header.startswith("app/"):
                included = pathlib.PurePosixPath(header[len("app/"):])
                target = unit_of(included)
                any_model = "EVERY_MODEL" in allowed[unit] and included.parts[0] == "models" and len(included.parts) > 2
                if target != unit and target not in allowed[unit] and not any_model:
                    problems.append(f"{relative}:{number}: {unit} may not include {header} ({target})")
    for folder in sorted({app, *(p for p in app.rglob("*") if p.is_dir())}):
        count = sum(1 for p in folder.iterdir() if p.is_file())
        if count > MAX_FILES:
            problems.append(f"{folder.relative_to(app.parent)}/: {count} files (at most {MAX_FILES})")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
