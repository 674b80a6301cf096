#!/usr/bin/env python3
"""Loads a Luz glTF scene into Mitsuba 3, for the benchmarks that compare Luz with Mitsuba's path
tracer on the same scene (docs/bench_path_mitsuba.py). A throwaway measurement tool, never a
build or test dependency; it needs numpy and mitsuba (pip, in a venv outside the repository).

Mapped as SCENES.md reads the file:
- triangles with node transforms (matrix or TRS) composed down the hierarchy, in world space;
  face normals from the counter-clockwise winding (glTF's front side);
- kd -> a two-sided `diffuse` (Luz shades both sides); kr alone -> `conductor` with
  specular_reflectance kr; kt -> `dielectric` (int_ior from extras.ior or KHR_materials_ior);
  other mixes fall back to the diffuse part, with a warning on stderr;
- emission x KHR_materials_emissive_strength -> an `area` emitter (front side only, as in Luz);
- KHR_lights_punctual point -> `point` (W/sr), directional -> `directional` (W/m^2), spot ->
  `spot` (Mitsuba's falloff between beam_width and cutoff_angle is not glTF's smooth ramp);
- scene.extras.background -> a `constant` emitter; ambient has no counterpart (Luz's path tracer
  ignores it too);
- the first camera: `perspective` with glTF's yfov, box pixel filter, independent sampler.
"""
import base64
import json
import math
import os
import sys

import numpy as np


def _node_matrix(node):
    if "matrix" in node:
        return np.array(node["matrix"], dtype=np.float64).reshape(4, 4).T  # column-major
    t = np.array(node.get("translation", [0, 0, 0]), dtype=np.float64)
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    s = np.array(node.get("scale", [1, 1, 1]), dtype=np.float64)
    m = np.eye(4)
    m[:3, :3] = r * s
    m[:3, 3] = t
    return m


def _buffers(gltf, folder):
    data = []
    for buffer in gltf["buffers"]:
        uri = buffer["uri"]
        if uri.startswith("data:"):
            data.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            with open(os.path.join(folder, uri), "rb") as f:
                data.append(f.read())
    return data


def _accessor(gltf, buffers, index):
    accessor = gltf["accessors"][index]
    view = gltf["bufferViews"][accessor["bufferView"]]
    dtype = {5126: np.float32, 5125: np.uint32, 5123: np.uint16, 5121: np.uint8}[accessor["componentType"]]
    width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[accessor["type"]]
    start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    count = accessor["count"] * width
    stride = view.get("byteStride", 0)
    raw = buffers[view["buffer"]]
    if stride and stride != width * np.dtype(dtype).itemsize:
        rows = [np.frombuffer(raw, dtype, width, start + i * stride) for i in range(accessor["count"])]
        return np.array(rows)
    return np.frombuffer(raw, dtype, count, start).reshape(-1, width) if width > 1 else np.frombuffer(raw, dtype, count, start)


def _material(gltf, index):
    """(kd, kr, kt, ior, Le) as SCENES.md maps them."""
    m = gltf["materials"][index] if index is not None else {}
    pbr = m.get("pbrMetallicRoughness", {})
    base = np.array(pbr.get("baseColorFactor", [0.8, 0.8, 0.8, 1])[:3])
    metallic = pbr.get("metallicFactor", 1.0)
    roughness = pbr.get("roughnessFactor", 1.0)
    extras = m.get("extras", {})
    ext = m.get("extensions", {})
    grey = lambda v: np.array(v if isinstance(v, list) else [v] * 3, dtype=np.float64)
    kd = base * (1 - metallic) if index is not None else np.array([0.8] * 3)
    kr = grey(extras["kr"]) if "kr" in extras else (base if metallic >= 0.5 and roughness <= 0.05 else np.zeros(3))
    kt = grey(extras.get("kt", ext.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)))
    ior = extras.get("ior", ext.get("KHR_materials_ior", {}).get("ior", 1.5))
    strength = ext.get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    Le = np.array(m.get("emissiveFactor", [0, 0, 0])) * strength
    return kd, kr, kt, ior, Le


def _rgb(v):
    return {"type": "rgb", "value": [float(c) for c in v]}


def load(path, width, height, spp=1, max_depth=16, rr_depth=4):
    """The scene as a Mitsuba scene object, its film width x height, the `path` integrator."""
    import mitsuba as mi

    with open(path) as f:
        gltf = json.load(f)
    buffers = _buffers(gltf, os.path.dirname(path))
    scene_index = gltf.get("scene", 0)
    scene_json = gltf["scenes"][scene_index]
    objects = {"type": "scene",
               "integrator": {"type": "path", "max_depth": max_depth, "rr_depth": rr_depth}}
    camera = None

    def visit(index, parent):
        nonlocal camera
        node = gltf["nodes"][index]
        world = parent @ _node_matrix(node)
        if "camera" in node and camera is None:
            camera = (gltf["cameras"][node["camera"]], world)
        if "mesh" in node:
            for p, primitive in enumerate(gltf["meshes"][node["mesh"]]["primitives"]):
                if primitive.get("mode", 4) != 4:
                    continue
                positions = _accessor(gltf, buffers, primitive["attributes"]["POSITION"]).astype(np.float64)
                positions = (world[:3, :3] @ positions.T).T + world[:3, 3]
                if "indices" in primitive:
                    faces = _accessor(gltf, buffers, primitive["indices"]).astype(np.uint32).reshape(-1, 3)
                else:
                    faces = np.arange(len(positions), dtype=np.uint32).reshape(-1, 3)
                if np.linalg.det(world[:3, :3]) < 0:
                    faces = faces[:, [0, 2, 1]]  # a mirroring transform turns the winding
                kd, kr, kt, ior, Le = _material(gltf, primitive.get("material"))
                if kt.max() > 0:
                    bsdf = {"type": "dielectric", "int_ior": float(ior), "ext_ior": 1.0}
                elif kr.max() > 0 and kd.max() == 0:
                    bsdf = {"type": "conductor", "material": "none", "specular_reflectance": _rgb(kr)}
                else:
                    if kr.max() > 0:
                        print(f"{path}: mesh {index}: kd with kr: only the diffuse part", file=sys.stderr)
                    bsdf = {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": _rgb(kd)}}
                props = mi.Properties()
                props["bsdf"] = mi.load_dict(bsdf)
                if Le.max() > 0:
                    props["emitter"] = mi.load_dict({"type": "area", "radiance": _rgb(Le)})
                mesh = mi.Mesh(f"mesh{index}_{p}", len(positions), len(faces), props=props)
                params = mi.traverse(mesh)
                params["vertex_positions"] = positions.astype(np.float32).ravel()
                params["faces"] = faces.ravel()
                params.update()
                objects[f"mesh{index}_{p}"] = mesh
        if "extensions" in node and "KHR_lights_punctual" in node["extensions"]:
            light = gltf["extensions"]["KHR_lights_punctual"]["lights"][node["extensions"]["KHR_lights_punctual"]["light"]]
            colour = np.array(light.get("color", [1, 1, 1])) * light.get("intensity", 1.0)
            position = world[:3, 3]
            direction = -world[:3, 2] / np.linalg.norm(world[:3, 2])  # lights shine down -Z
            key = f"light{index}"
            if light["type"] == "point":
                objects[key] = {"type": "point", "position": position.tolist(), "intensity": _rgb(colour)}
            elif light["type"] == "directional":
                objects[key] = {"type": "directional", "direction": direction.tolist(), "irradiance": _rgb(colour)}
            else:
                spot = light.get("spot", {})
                objects[key] = {"type": "spot", "intensity": _rgb(colour),
                                "cutoff_angle": math.degrees(spot.get("outerConeAngle", math.pi / 4)),
                                "beam_width": math.degrees(spot.get("innerConeAngle", 0.0)),
                                "to_world": mi.ScalarTransform4f().look_at(
                                    origin=position.tolist(), target=(position + direction).tolist(), up=[0, 1, 0])}
        for child in node.get("children", []):
            visit(child, world)

    for root in scene_json["nodes"]:
        visit(root, np.eye(4))

    background = scene_json.get("extras", {}).get("background", [0, 0, 0])
    if max(background) > 0:
        objects["background"] = {"type": "constant", "radiance": _rgb(background)}
    if camera is None:
        raise SystemExit(f"{path}: no camera (Luz frames one; this converter needs the file's)")
    cam, world = camera
    # glTF cameras look down -Z with +X to the right; Mitsuba's down +Z with +X to the left.
    flip = np.diag([-1.0, 1.0, -1.0, 1.0])
    objects["sensor"] = {
        "type": "perspective", "fov_axis": "y",
        "fov": math.degrees(cam["perspective"]["yfov"]),
        "near_clip": 0.01, "far_clip": 1000.0,
        "to_world": mi.ScalarTransform4f((world @ flip).tolist()),
        "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                 "pixel_format": "rgb"},
        "sampler": {"type": "independent", "sample_count": spp},
    }
    return mi.load_dict(objects)
