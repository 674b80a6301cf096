"""A shipped Luz scene (glTF 2.0, SCENES.md) as a Mitsuba 3 scene dictionary, for timing and
comparing Luz against Mitsuba on the same geometry, lights and camera. Importable:

    import mitsuba as mi; mi.set_variant("llvm_ad_rgb")
    from mitsuba_scene import scene_dict
    scene = mi.load_dict(scene_dict("scenes/whitted.gltf", 1024, 1024, {"type": "direct"}))

Only what the shipped scenes use is read: triangle meshes with POSITION and NORMAL (node
transforms as translation / rotation / scale or a matrix, composed down the hierarchy), the
material mapping of SCENES.md, KHR_lights_punctual, emissive triangles as area lights, the first
camera and the scene's background. Mitsuba has no Phong lobe and no ambient term, so a material's
ks and the scene's ambient are left out (they cost Luz a few multiplications per light, no ray);
textures and vertex colours are not read. Meshes go to binary PLY files in `folder` (a temporary
folder when not given), which the dictionary names.
"""
import json
import math
import os
import tempfile

import numpy as np

_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
_TYPES = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}


class _Gltf:
    def __init__(self, path):
        self.folder = os.path.dirname(os.path.abspath(path))
        with open(path) as f:
            self.json = json.load(f)
        self.buffers = []
        for buffer in self.json.get("buffers", []):
            uri = buffer["uri"]
            if uri.startswith("data:"):
                raise ValueError(f"{path}: data URIs are not read by this converter")
            with open(os.path.join(self.folder, uri), "rb") as f:
                self.buffers.append(f.read())

    def accessor(self, index):
        a = self.json["accessors"][index]
        view = self.json["bufferViews"][a["bufferView"]]
        dtype = np.dtype(_TYPES[a["componentType"]])
        n = _COMPONENTS[a["type"]]
        offset = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        stride = view.get("byteStride", dtype.itemsize * n)
        data = self.buffers[view["buffer"]]
        rows = [np.frombuffer(data, dtype, n, offset + i * stride) for i in range(a["count"])] \
            if stride != dtype.itemsize * n else \
            [np.frombuffer(data, dtype, n * a["count"], offset).reshape(a["count"], n)]
        return np.vstack(rows) if len(rows) > 1 else rows[0].reshape(a["count"], n)


def _quaternion_matrix(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0],
                     [0, 0, 0, 1]])


def _node_matrix(node):
    if "matrix" in node:
        return np.array(node["matrix"], dtype=float).reshape(4, 4).T  # glTF is column-major
    t = np.eye(4)
    t[:3, 3] = node.get("translation", [0, 0, 0])
    s = np.diag(list(node.get("scale", [1, 1, 1])) + [1])
    return t @ _quaternion_matrix(node.get("rotation", [0, 0, 0, 1])) @ s


def _world_nodes(g):
    """(node, world matrix) for every node reachable from the default scene."""
    scene = g.json["scenes"][g.json.get("scene", 0)]
    out = []

    def walk(index, parent):
        node = g.json["nodes"][index]
        world = parent @ _node_matrix(node)
        out.append((node, world))
        for child in node.get("children", []):
            walk(child, world)

    for root in scene["nodes"]:
        walk(root, np.eye(4))
    return out


def _material(m):
    """SCENES.md's coefficients of a glTF material: kd, kr, kt, ior, Le."""
    pbr = m.get("pbrMetallicRoughness", {})
    extras = m.get("extras", {})
    ext = m.get("extensions", {})
    base = np.array(pbr.get("baseColorFactor", [1, 1, 1, 1])[:3], dtype=float)
    metallic = pbr.get("metallicFactor", 1.0)
    roughness = pbr.get("roughnessFactor", 1.0)

    def rgb(value, default):
        if value is None:
            return np.array(default, dtype=float)
        return np.array([value] * 3 if np.isscalar(value) else value, dtype=float)

    transmission = ext.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)
    kd = base * (1 - metallic) * (1 - transmission)
    kr = rgb(extras.get("kr"), base if metallic >= 0.5 and roughness <= 0.05 else [0, 0, 0])
    kt = rgb(extras.get("kt"), base * (1 - metallic) * transmission)
    ior = extras.get("ior", ext.get("KHR_materials_ior", {}).get("ior", 1.5))
    le = np.array(m.get("emissiveFactor", [0, 0, 0]), dtype=float) * \
        ext.get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    return kd, kr, kt, ior, le


def _bsdf(kd, kr, kt, ior):
    spectrum = lambda c: {"type": "rgb", "value": [float(x) for x in c]}
    if kt.max() > 0:  # a dielectric: Fresnel between reflection and transmission
        return {"type": "dielectric", "int_ior": float(ior), "ext_ior": 1.0}
    mirror = {"type": "conductor", "material": "none", "specular_reflectance": spectrum(kr)}
    diffuse = {"type": "diffuse", "reflectance": spectrum(kd)}
    if kr.max() > 0 and kd.max() > 0:
        weight = float(kr.mean() / (kr.mean() + kd.mean()))
        return {"type": "blendbsdf", "weight": weight, "a": diffuse, "b": mirror}
    if kr.max() > 0:
        return mirror
    return diffuse


def _write_ply(path, positions, normals, indices):
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(positions)}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "property float nx\nproperty float ny\nproperty float nz\n"
                 f"element face {len(indices)}\nproperty list uchar int vertex_indices\nend_header\n").encode())
        f.write(np.hstack([positions, normals]).astype("<f4").tobytes())
        faces = np.empty(len(indices), dtype=[("n", "u1"), ("i", "<i4", 3)])
        faces["n"] = 3
        faces["i"] = indices
        f.write(faces.tobytes())


def scene_dict(path, width, height, integrator, spp=1, folder=None):
    """The Mitsuba dictionary of the glTF scene at `path`, seen by its first camera."""
    g = _Gltf(path)
    folder = folder or tempfile.mkdtemp(prefix="luz-mitsuba-")
    extras = g.json["scenes"][g.json.get("scene", 0)].get("extras", {})
    scene = {"type": "scene", "integrator": integrator}
    materials = [_material(m) for m in g.json.get("materials", [])]
    lights = g.json.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    camera = None
    for number, (node, world) in enumerate(_world_nodes(g)):
        if "camera" in node and camera is None:
            camera = (g.json["cameras"][node["camera"]], world)
        if "mesh" in node:
            normal_matrix = np.linalg.inv(world[:3, :3]).T
            for p, primitive in enumerate(g.json["meshes"][node["mesh"]]["primitives"]):
                if primitive.get("mode", 4) != 4:
                    continue
                positions = g.accessor(primitive["attributes"]["POSITION"]).astype(float)
                positions = positions @ world[:3, :3].T + world[:3, 3]
                normals = g.accessor(primitive["attributes"]["NORMAL"]).astype(float) @ normal_matrix.T
                normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
                indices = g.accessor(primitive["indices"]).reshape(-1, 3).astype(np.int32) \
                    if "indices" in primitive else np.arange(len(positions), dtype=np.int32).reshape(-1, 3)
                ply = os.path.join(folder, f"mesh{number}_{p}.ply")
                _write_ply(ply, positions, normals, indices)
                m = primitive.get("material")
                kd, kr, kt, ior, le = materials[m] if m is not None else \
                    (np.full(3, 0.8), np.zeros(3), np.zeros(3), 1.5, np.zeros(3))
                shape = {"type": "ply", "filename": ply, "face_normals": False,
                         "bsdf": _bsdf(kd, kr, kt, ior)}
                if le.max() > 0:
                    shape["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": [float(x) for x in le]}}
                scene[f"mesh{number}_{p}"] = shape
        light = node.get("extensions", {}).get("KHR_lights_punctual", {}).get("light")
        if light is not None:
            l = lights[light]
            power = [float(c) * l.get("intensity", 1.0) for c in l.get("color", [1, 1, 1])]
            position = world[:3, 3]
            direction = -world[:3, 2] / np.linalg.norm(world[:3, 2])  # lights shine down -Z
            value = {"type": "rgb", "value": power}
            if l["type"] == "point":
                scene[f"light{number}"] = {"type": "point", "position": [float(x) for x in position],
                                           "intensity": value}
            elif l["type"] == "spot":
                spot = l.get("spot", {})
                scene[f"light{number}"] = {
                    "type": "spot", "intensity": value,
                    "cutoff_angle": math.degrees(spot.get("outerConeAngle", math.pi / 4)),
                    "beam_width": math.degrees(spot.get("innerConeAngle", 0.0)),
                    "to_world": _look_at(position, position + direction)}
            else:
                scene[f"light{number}"] = {"type": "directional", "irradiance": value,
                                           "direction": [float(x) for x in direction]}
    background = extras.get("background", [0, 0, 0])
    if max(background) > 0:
        scene["background"] = {"type": "constant", "radiance": {"type": "rgb", "value": background}}
    if camera is None:
        raise ValueError(f"{path}: no camera (the converter takes the scene's first)")
    cam, world = camera
    import mitsuba as mi
    # glTF's camera looks down -Z with +X to the right; Mitsuba's down +Z with +X to the left.
    to_world = world @ np.diag([-1.0, 1.0, -1.0, 1.0])
    scene["sensor"] = {
        "type": "perspective", "fov_axis": "y", "fov": math.degrees(cam["perspective"]["yfov"]),
        "near_clip": cam["perspective"].get("znear", 0.01),
        "to_world": mi.ScalarTransform4f(to_world.tolist()),
        "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"}},
        "sampler": {"type": "independent", "sample_count": spp},
    }
    return scene



def load(path, width, height, spp=1, max_depth=16, rr_depth=4):
    """The scene as a loaded Mitsuba scene with the `path` integrator (docs/bench_path_mitsuba.py)."""
    import mitsuba as mi
    integrator = {"type": "path", "max_depth": max_depth, "rr_depth": rr_depth}
    return mi.load_dict(scene_dict(path, width, height, integrator, spp))


def _look_at(origin, target):
    import mitsuba as mi
    direction = target - origin
    up = [0, 1, 0] if abs(direction[1]) < 0.9 * np.linalg.norm(direction) else [1, 0, 0]
    return mi.ScalarTransform4f().look_at(origin=[float(x) for x in origin],
                                          target=[float(x) for x in target], up=up)
