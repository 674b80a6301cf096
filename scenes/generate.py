#!/usr/bin/env python3
"""Writes the scenes that ship with Luz as glTF 2.0 (.gltf JSON + .bin), and checks them.

    python3 scenes/generate.py [--out DIR]     write the scenes into DIR (default: this folder),
                                               then check what was written
    python3 scenes/generate.py --check [DIR]   only check the scenes already in DIR

Python 3 standard library only. The output is deterministic, byte for byte: keys are sorted,
every float written to JSON is rounded to a fixed number of significant digits first, every
float written to the .bin is rounded before it is packed as float32, and nothing depends on
the time or the machine. tests/check_generated_scenes.sh regenerates into a temporary folder
and byte-compares with the committed files.

Conventions are those of /SCENES.md (the scene contract): right-handed, +Y up, metres, radiance
in the program's linear units (W/(m^2 sr)), point-light intensity in candela read as W/sr.

Sections
  [VECTORS]   tiny 3-vector helpers
  [NUMBERS]   fixed float formatting (why the bytes are reproducible)
  [BUILDER]   GltfBuilder: buffers, accessors, materials, meshes, nodes, cameras, lights
  [GEOMETRY]  quads oriented by a wanted normal, UV spheres
  [CORNELL]   cornell_box.gltf   (Cornell Program of Computer Graphics, measured data)
  [CORNELL SPHERES] cornell_spheres.gltf (the box with a mirror and a glass sphere: the hybrid)
  [SPHERES]   phong_spheres.gltf (ks along the columns, Phong exponent n along the rows)
  [WHITTED]   whitted.gltf       (Whitted 1980, "An Improved Illumination Model for Shaded Display")
  [EFFECTS]   local_effects.gltf (slide 19's other possibilities of the local models, one each)
  [CHECK]     validation of written files against SCENES.md's rules
  [MAIN]
"""

import argparse
import json
import math
import os
import struct
import sys

GENERATOR = "luz scenes/generate.py"
SCENE_FILES = ("cornell_box", "phong_spheres", "whitted", "local_effects", "cornell_spheres")


# ==== [VECTORS] ================================================================================

def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    return scale(a, 1.0 / length(a))


def luminance(rgb):
    """Rec. 709 luminance of a linear RGB triple (the program's primaries, SCENES.md)."""
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


# ==== [NUMBERS] ================================================================================
# json.dumps prints a float as the shortest decimal that reads back as the same double. Values
# that come out of atan/sin/cos could differ in their last bit between C libraries, so every
# float is rounded to fewer digits than a double holds before it is written: the files are then
# the same on every machine (barring a value sitting exactly on a rounding boundary).

def num(x, digits=6):
    """A JSON float: `digits` significant digits; -0.0 becomes 0.0 so no '-0.0' appears."""
    if not math.isfinite(x):
        raise ValueError("non-finite value %r" % x)
    return float("%.*g" % (digits, x)) + 0.0


def nums(values, digits=6):
    return [num(v, digits) for v in values]


def f32(x):
    """x as the float32 the .bin stores (rounded to 9 decimals first, see above)."""
    return struct.unpack("<f", struct.pack("<f", round(x, 9)))[0]


def f32_text(x):
    """The shortest decimal that reads back as float32 x: for accessor min/max, which must equal
    the stored data exactly (glTF 2.0, 3.6.2.5)."""
    for digits in range(1, 10):
        candidate = float("%.*g" % (digits, x))
        if f32(candidate) == x:
            return candidate + 0.0
    return x + 0.0


# ==== [BUILDER] ================================================================================

ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963
FLOAT = 5126
UNSIGNED_SHORT = 5123
UNSIGNED_INT = 5125
TRIANGLES = 4


class GltfBuilder:
    """Collects one glTF document and its single binary buffer."""

    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.extensions_used = set()
        self.doc = {
            "asset": {"version": "2.0", "generator": GENERATOR},
            "scene": 0,
            "scenes": [{"name": name, "nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }

    # -- binary data ---------------------------------------------------------------------------
    def _buffer_view(self, data, target):
        # Every view starts on a 4-byte boundary (glTF: offsets must be multiples of the
        # component size; 4 covers float32 and uint32).
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data), "target": target}
        self.bin.extend(data)
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, view, component_type, count, type_, **extra):
        accessor = {"bufferView": view, "componentType": component_type, "count": count,
                    "type": type_}
        accessor.update(extra)
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def vec3_accessor(self, vectors, with_bounds):
        flat = [f32(c) for v in vectors for c in v]
        view = self._buffer_view(struct.pack("<%df" % len(flat), *flat), ARRAY_BUFFER)
        extra = {}
        if with_bounds:  # required for POSITION (glTF 2.0, 3.7.2.1)
            extra["min"] = [f32_text(min(flat[i::3])) for i in range(3)]
            extra["max"] = [f32_text(max(flat[i::3])) for i in range(3)]
        return self._accessor(view, FLOAT, len(vectors), "VEC3", **extra)

    def index_accessor(self, indices, vertex_count):
        # uint16 while it can address every vertex, uint32 beyond.
        if vertex_count <= 65535:
            data, component = struct.pack("<%dH" % len(indices), *indices), UNSIGNED_SHORT
        else:
            data, component = struct.pack("<%dI" % len(indices), *indices), UNSIGNED_INT
        view = self._buffer_view(data, ELEMENT_ARRAY_BUFFER)
        return self._accessor(view, component, len(indices), "SCALAR")

    def geometry(self, positions, normals, indices):
        """Accessors of one triangle list: returns the attributes and indices of a primitive."""
        assert len(positions) == len(normals) and len(indices) % 3 == 0
        return {"attributes": {"POSITION": self.vec3_accessor(positions, True),
                               "NORMAL": self.vec3_accessor(normals, False)},
                "indices": self.index_accessor(indices, len(positions)),
                "mode": TRIANGLES}

    # -- materials -----------------------------------------------------------------------------
    def material(self, name, kd, ks=0.0, shininess=None, roughness=1.0, kr=None, kt=None,
                 ior=None, emission=None, transmission_extension=False):
        """A material in SCENES.md's mapping: kd is baseColorFactor (metallicFactor 0), the
        lecture's coefficients go in extras. `emission` is a radiance RGB in W/(m^2 sr): it is
        written as emissiveFactor normalised to max 1 times KHR_materials_emissive_strength."""
        extras = {"ks": num(ks) if isinstance(ks, (int, float)) else nums(ks)}
        if shininess is not None:
            extras["shininess"] = num(shininess)
        if kr is not None:
            extras["kr"] = num(kr) if isinstance(kr, (int, float)) else nums(kr)
        if kt is not None:
            extras["kt"] = num(kt) if isinstance(kt, (int, float)) else nums(kt)
        if ior is not None:
            extras["ior"] = num(ior)
        base = list(kd)
        transmission = None
        if transmission_extension:
            # glTF's glass: kd = base x (1 - t), kt = base x t (SCENES.md Materials). So that
            # glTF viewers and Luz read the same kd and kt, base = kd + kt and t = kt / base
            # (one t for all channels: kd grey, kt a number).
            assert isinstance(kt, (int, float)) and kd[0] == kd[1] == kd[2], name
            base = [kd[0] + kt] * 3
            transmission = kt / base[0]
        mat = {"name": name,
               "pbrMetallicRoughness": {"baseColorFactor": nums(base + [1.0]),
                                        "metallicFactor": 0.0,
                                        "roughnessFactor": num(roughness)},
               "extras": extras}
        if emission is not None:
            strength = max(emission)
            mat["emissiveFactor"] = nums([c / strength for c in emission])
            if strength != 1.0:
                mat.setdefault("extensions", {})["KHR_materials_emissive_strength"] = {
                    "emissiveStrength": num(strength)}
                self.extensions_used.add("KHR_materials_emissive_strength")
        if transmission_extension:
            # The same kd, kt and ior for glTF viewers that do not read Luz's extras.
            exts = mat.setdefault("extensions", {})
            exts["KHR_materials_transmission"] = {"transmissionFactor": num(transmission)}
            exts["KHR_materials_ior"] = {"ior": extras["ior"]}
            self.extensions_used.update(("KHR_materials_transmission", "KHR_materials_ior"))
        self.doc["materials"].append(mat)
        return len(self.doc["materials"]) - 1

    # -- meshes and nodes ----------------------------------------------------------------------
    def mesh(self, name, primitives):
        """primitives: list of (geometry dict from geometry(), material index)."""
        prims = []
        for geometry, material in primitives:
            prim = dict(geometry)
            prim["material"] = material
            prims.append(prim)
        self.doc["meshes"].append({"name": name, "primitives": prims})
        return len(self.doc["meshes"]) - 1

    def node(self, name, translation=None, rotation=None, **fields):
        node = {"name": name}
        if translation is not None:
            node["translation"] = nums(translation)
        if rotation is not None:
            node["rotation"] = nums(rotation)
        node.update(fields)
        self.doc["nodes"].append(node)
        index = len(self.doc["nodes"]) - 1
        self.doc["scenes"][0]["nodes"].append(index)
        return index

    def mesh_node(self, name, mesh, translation=None):
        return self.node(name, translation, mesh=mesh)

    def camera(self, name, eye, target, yfov, aspect, znear, zfar):
        """A perspective camera at `eye` looking at `target` with +Y up. glTF cameras look down
        their node's -Z, so the node's rotation takes -Z to the viewing direction."""
        self.doc.setdefault("cameras", []).append({
            "name": name, "type": "perspective",
            "perspective": {"yfov": num(yfov), "aspectRatio": num(aspect),
                            "znear": num(znear), "zfar": num(zfar)}})
        return self.node(name, eye, look_rotation(eye, target), camera=len(self.doc["cameras"]) - 1)

    def point_light(self, name, position, intensity, color=(1.0, 1.0, 1.0)):
        """KHR_lights_punctual point light; intensity in candela, read as W/sr (SCENES.md)."""
        lights = self.doc.setdefault("extensions", {}).setdefault(
            "KHR_lights_punctual", {"lights": []})["lights"]
        lights.append({"name": name, "type": "point", "intensity": num(intensity),
                       "color": nums(color)})
        self.extensions_used.add("KHR_lights_punctual")
        return self.node(name, position,
                         extensions={"KHR_lights_punctual": {"light": len(lights) - 1}})

    def light(self, name, type_, position, target, intensity, color=(1.0, 1.0, 1.0), spot=None,
              extras=None):
        """A KHR_lights_punctual light of any type aimed from `position` at `target` (lights shine
        down their node's -Z, as cameras look). `spot`: (inner, outer) cone angles in radians.
        `extras`: Luz's light extras (attenuation, warn_exponent; SCENES.md)."""
        lights = self.doc.setdefault("extensions", {}).setdefault(
            "KHR_lights_punctual", {"lights": []})["lights"]
        light = {"name": name, "type": type_, "intensity": num(intensity), "color": nums(color)}
        if spot is not None:
            light["spot"] = {"innerConeAngle": num(spot[0]), "outerConeAngle": num(spot[1])}
        if extras:
            light["extras"] = {k: (nums(v) if isinstance(v, (list, tuple)) else num(v))
                               for k, v in extras.items()}
        lights.append(light)
        self.extensions_used.add("KHR_lights_punctual")
        direction = sub(target, position)
        # look_rotation needs an up vector off the aiming direction: straight down aims use -Z.
        up = (0.0, 1.0, 0.0) if abs(normalize(direction)[1]) < 0.99 else (0.0, 0.0, -1.0)
        return self.node(name, position, look_rotation(position, target, up),
                         extensions={"KHR_lights_punctual": {"light": len(lights) - 1}})

    def scene_extras(self, ambient, background, exposure):
        self.doc["scenes"][0]["extras"] = {"ambient": nums(ambient),
                                           "background": nums(background),
                                           "exposure": num(exposure)}

    # -- output --------------------------------------------------------------------------------
    def write(self, folder):
        while len(self.bin) % 4:
            self.bin.append(0)
        bin_name = self.name + ".bin"
        self.doc["buffers"] = [{"uri": bin_name, "byteLength": len(self.bin)}]
        if self.extensions_used:
            self.doc["extensionsUsed"] = sorted(self.extensions_used)
        text = json.dumps(self.doc, indent=1, sort_keys=True, ensure_ascii=True,
                          allow_nan=False) + "\n"
        with open(os.path.join(folder, self.name + ".gltf"), "w", encoding="ascii",
                  newline="\n") as f:
            f.write(text)
        with open(os.path.join(folder, bin_name), "wb") as f:
            f.write(bytes(self.bin))


def look_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """Unit quaternion [x, y, z, w] turning the node's axes so that -Z points from eye to target
    and +Y is as close to `up` as possible."""
    z = normalize(sub(eye, target))  # the camera looks down -Z
    x = normalize(cross(up, z))
    y = cross(z, x)
    # Rotation matrix with columns x, y, z -> quaternion (Shoemake's method).
    m00, m11, m22 = x[0], y[1], z[2]
    trace = m00 + m11 + m22
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s, 0.25 * s)
    elif m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        q = (0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s)
    elif m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        q = ((y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s, (z[0] - x[2]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
        q = ((z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s, (x[1] - y[0]) / s)
    if q[3] < 0:  # one of the two equal quaternions, always the same one
        q = tuple(-c for c in q)
    return q


# ==== [GEOMETRY] ===============================================================================

def newell_normal(points):
    """Unit normal of a polygon by Newell's method: exact for planar polygons, the best-fit plane
    for slightly non-planar ones (the measured Cornell walls are out of plane by a few mm)."""
    n = (0.0, 0.0, 0.0)
    for i, p in enumerate(points):
        q = points[(i + 1) % len(points)]
        n = add(n, ((p[1] - q[1]) * (p[2] + q[2]),
                    (p[2] - q[2]) * (p[0] + q[0]),
                    (p[0] - q[0]) * (p[1] + q[1])))
    return normalize(n)


def oriented_quad(points, towards):
    """A flat-shaded quad as two triangles, wound counter-clockwise seen from the side its normal
    points to; `towards` is a direction the normal must have a positive component along (the
    data's vertex order is not consistent, so the winding is decided here, not copied)."""
    points = list(points)
    n = newell_normal(points)
    if dot(n, towards) < 0:
        points.reverse()
        n = scale(n, -1.0)
    return points, [n] * 4, [0, 1, 2, 0, 2, 3]


def uv_sphere(radius, segments, rings):
    """A smooth UV sphere with shared vertices: one vertex at each pole (fans, so no degenerate
    triangles), `rings - 1` latitude circles of `segments` vertices (the seam is closed by index,
    not duplicated: there are no texture coordinates to split). Normals are the exact radial
    directions. Counter-clockwise seen from outside."""
    positions, normals = [], []

    def vertex(n):
        normals.append(n)
        positions.append(scale(n, radius))

    vertex((0.0, 1.0, 0.0))  # north pole, index 0
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2.0 * math.pi * j / segments
            # phi runs from +X towards -Z, i.e. counter-clockwise seen from +Y.
            vertex((math.sin(theta) * math.cos(phi), math.cos(theta),
                    -math.sin(theta) * math.sin(phi)))
    vertex((0.0, -1.0, 0.0))  # south pole, last index
    south = len(positions) - 1

    def ring(i, j):  # vertex j (mod segments) of latitude circle i (1 .. rings-1)
        return 1 + (i - 1) * segments + j % segments

    indices = []
    for j in range(segments):
        indices += [0, ring(1, j), ring(1, j + 1)]
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b = ring(i, j), ring(i, j + 1)
            c, d = ring(i + 1, j), ring(i + 1, j + 1)
            indices += [a, c, d, a, d, b]
    for j in range(segments):
        indices += [south, ring(rings - 1, j + 1), ring(rings - 1, j)]
    return positions, normals, indices


def roughness_for_shininess(n):
    """Inverse of SCENES.md's default n = 2/r^4 - 2, so that a glTF viewer reading only the
    roughness shows a highlight of about the same width as the Phong exponent in extras."""
    return (2.0 / (n + 2.0)) ** 0.25


# ==== [CORNELL] ================================================================================
# Source: Cornell Program of Computer Graphics, "Cornell Box Data",
# www.graphics.cornell.edu/online/box/data.html. Coordinates there are millimetres in a
# right-handed frame with +Y up; the camera stands at z = -800 looking along +Z. Looking along +Z
# with +Y up in a right-handed frame, +X points to the viewer's LEFT, so the red wall (x ~ 552.8)
# is on the left and the green wall (x = 0) on the right, as in the photographs. The data is
# used as-is, only scaled to metres (no mirroring needed).

MM = 0.001  # millimetres -> metres

CORNELL_WHITE = (0.73, 0.73, 0.73)
# Red and green as in the RGB renditions of the measured spectra widely used by renderers'
# Cornell-box scenes; white kept neutral (the measured white is slightly warm).
CORNELL_RED = (0.63, 0.065, 0.05)
CORNELL_GREEN = (0.14, 0.45, 0.091)
# Radiance of the light, W/(m^2 sr): the usual RGB rendition of the measured (warm) lamp.
CORNELL_LIGHT_RADIANCE = (17.0, 12.0, 4.0)

# The light quad of the data sits at the ceiling's height (548.8 mm, in a hole of the ceiling).
# The ceiling here is one quad without a hole, so the light hangs 1 mm below it: coplanar faces
# would fight in depth buffers and self-intersect rays.
CORNELL_LIGHT_Y = 548.8 - 1.0

CORNELL_FACES = {
    # name: (material, [4 corners in mm, as listed on the data page])
    "floor": ("white", [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2),
                        (549.6, 0.0, 559.2)]),
    "ceiling": ("white", [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2),
                          (0.0, 548.8, 0.0)]),
    "back_wall": ("white", [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2),
                            (556.0, 548.8, 559.2)]),
    "right_wall_green": ("green", [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0),
                                   (0.0, 548.8, 559.2)]),
    "left_wall_red": ("red", [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2),
                              (556.0, 548.8, 0.0)]),
}

CORNELL_LIGHT = [(343.0, CORNELL_LIGHT_Y, 227.0), (343.0, CORNELL_LIGHT_Y, 332.0),
                 (213.0, CORNELL_LIGHT_Y, 332.0), (213.0, CORNELL_LIGHT_Y, 227.0)]

# Blocks: the top and four sides of each, as on the data page (no bottom: it rests on the floor).
CORNELL_SHORT_BLOCK = [
    ("top", [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0),
             (290.0, 165.0, 114.0)]),
    ("side_a", [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0),
                (240.0, 0.0, 272.0)]),
    ("side_b", [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0),
                (290.0, 0.0, 114.0)]),
    ("side_c", [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0),
                (130.0, 0.0, 65.0)]),
    ("side_d", [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0),
                (82.0, 0.0, 225.0)]),
]
CORNELL_TALL_BLOCK = [
    ("top", [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0),
             (472.0, 330.0, 406.0)]),
    ("side_a", [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0),
                (472.0, 0.0, 406.0)]),
    ("side_b", [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0),
                (314.0, 0.0, 456.0)]),
    ("side_c", [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0),
                (265.0, 0.0, 296.0)]),
    ("side_d", [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0),
                (423.0, 0.0, 247.0)]),
]

# Camera of the data page: at (278, 273, -800) mm, looking along +Z, up +Y, focal length 35 mm,
# film 25 mm x 25 mm, so yfov = 2 atan(12.5 / 35) (about 39.3 degrees) and a square picture.
CORNELL_EYE = (278.0, 273.0, -800.0)
CORNELL_YFOV = 2.0 * math.atan(12.5 / 35.0)


def centroid(points):
    return scale(tuple(map(sum, zip(*points))), 1.0 / len(points))


def cornell_exposure():
    """EV that makes the floor under the light mid-grey in the local models (direct light only,
    the light sampled once at its centroid, SCENES.md): E = Le * A * cos_e * cos_r / d^2 with
    both cosines 1 straight below, radiance L = kd/pi * E. Mid-grey = 0.214 linear, which the sRGB
    curve writes as 50 %; the EV is rounded to half a stop."""
    width = (343.0 - 213.0) * MM
    depth = (332.0 - 227.0) * MM
    d = CORNELL_LIGHT_Y * MM  # light above the floor
    irradiance = [le * width * depth / (d * d) for le in CORNELL_LIGHT_RADIANCE]  # ~(0.77, 0.55, 0.18)
    radiance = [kd / math.pi * e for kd, e in zip(CORNELL_WHITE, irradiance)]     # ~(0.18, 0.13, 0.04)
    ev = math.log2(0.214 / luminance(radiance))                                     # ~0.70
    return round(ev * 2.0) / 2.0                                                    # 0.5


def unwelded_quad(points, towards):
    """The quad as a triangle soup, as converters write the published data: two triangles with
    their own three vertices each and each its own face normal, so a quad that is out of plane
    (the measured walls) is two faces at a slight angle sharing no vertex."""
    points, _, _ = oriented_quad(points, towards)
    indices = [0, 1, 3, 1, 2, 3]  # the other diagonal from the shipped box's
    corners, normals = [], []
    for t in range(0, len(indices), 3):
        a, b, c = (points[i] for i in indices[t:t + 3])
        n = normalize(cross(sub(b, a), sub(c, a)))
        corners += [a, b, c]
        normals += [n, n, n]
    return corners, normals, list(range(len(corners)))


def cornell_box(name="cornell_box", blocks=True, unwelded=False):
    g = GltfBuilder(name)
    materials = {
        "white": g.material("white", CORNELL_WHITE, ks=0.0),
        "red": g.material("red", CORNELL_RED, ks=0.0),
        "green": g.material("green", CORNELL_GREEN, ks=0.0),
        # The light's diffuser reflects like the white walls.
        "light": g.material("light", CORNELL_WHITE, ks=0.0, emission=CORNELL_LIGHT_RADIANCE),
    }
    room_centre = (278.0, 274.4, 279.6)

    def quad_geometry(corners_mm, towards):
        make = unwelded_quad if unwelded else oriented_quad
        points, normals, indices = make([scale(p, MM) for p in corners_mm], towards)
        return g.geometry(points, normals, indices)

    # Walls, floor and ceiling: normals into the room (towards its centre).
    for name, (material, corners) in CORNELL_FACES.items():
        towards = sub(room_centre, centroid(corners))
        mesh = g.mesh(name, [(quad_geometry(corners, towards), materials[material])])
        g.mesh_node(name, mesh)

    # Blocks: one primitive per face, normals out of the block.
    for name, faces in (("short_block", CORNELL_SHORT_BLOCK), ("tall_block", CORNELL_TALL_BLOCK)):
        if not blocks:
            break
        block_centre = centroid([p for _, corners in faces for p in corners])
        primitives = [(quad_geometry(corners, sub(centroid(corners), block_centre)),
                       materials["white"]) for _, corners in faces]
        g.mesh_node(name, g.mesh(name, primitives))

    # The light faces down, into the room.
    mesh = g.mesh("light", [(quad_geometry(CORNELL_LIGHT, (0.0, -1.0, 0.0)), materials["light"])])
    g.mesh_node("light", mesh)

    eye = scale(CORNELL_EYE, MM)
    g.camera("cornell_camera", eye, add(eye, (0.0, 0.0, 1.0)), CORNELL_YFOV, 1.0, 0.1, 10.0)

    # Ambient: the local models have no interreflection. A rough estimate of the indirect light
    # in the box (power pi*Le*A ~ 0.73 W red over ~1.9 m^2 of surface, mean reflectance ~0.6,
    # open front) gives an indirect radiance of ~0.1; a fifth of it, 0.02 grey, keeps the
    # shadows dark (~15 % of the lit floor) but not holes. Radiosity and hybrid ignore it.
    g.scene_extras(ambient=(0.02, 0.02, 0.02), background=(0.0, 0.0, 0.0),
                   exposure=cornell_exposure())
    return g


def cornell_unwelded():
    """Not shipped: the Cornell box as a file from outside brings it (unwelded_quad), for
    measuring radiosity against the path tracer on geometry the team did not mesh
    (docs/radiosity.md); written by --unwelded."""
    return cornell_box("cornell_unwelded", unwelded=True)


# ==== [CORNELL SPHERES] ========================================================================
# The Cornell box without its blocks, a mirror sphere at the back on the left (red) side and a
# glass sphere in front on the right, resting on the floor: the placement of H. W. Jensen's
# classic pictures ("Global Illumination using Photon Maps", 1996), the standard demonstration of
# why diffuse interreflection (radiosity) and mirror and glass (rays) are combined: radiosity
# alone shows two dull spheres, Whitted alone a black ceiling and mirrored walls without their
# colour bleeding; the hybrid shows both.

SPHERES_RADIUS_MM = 110.0
MIRROR_SPHERE_MM = (390.0, SPHERES_RADIUS_MM, 370.0)
GLASS_SPHERE_MM = (175.0, SPHERES_RADIUS_MM, 190.0)
# Few enough triangles that radiosity (at least one patch per triangle) stays quick to solve.
CORNELL_SPHERE_SEGMENTS, CORNELL_SPHERE_RINGS = 32, 20


def cornell_spheres():
    g = cornell_box("cornell_spheres", blocks=False)
    # Mirror: kd + ks + kr = 1, a tight highlight of the lamp.
    mirror = g.material("mirror", (0.05, 0.05, 0.05), ks=0.15, shininess=300.0,
                        roughness=roughness_for_shininess(300.0), kr=0.8)
    # Glass: kd + ks + kr + kt = 1, eta 1.5 (the --fresnel switch splits kt further).
    glass = g.material("glass", (0.0, 0.0, 0.0), ks=0.1, shininess=400.0,
                       roughness=roughness_for_shininess(400.0), kr=0.05, kt=0.85, ior=1.5,
                       transmission_extension=True)
    radius = SPHERES_RADIUS_MM * MM
    for name, centre, material in (("mirror_sphere", MIRROR_SPHERE_MM, mirror),
                                   ("glass_sphere", GLASS_SPHERE_MM, glass)):
        sphere = g.geometry(*uv_sphere(radius, CORNELL_SPHERE_SEGMENTS, CORNELL_SPHERE_RINGS))
        g.mesh_node(name, g.mesh(name, [(sphere, material)]), scale(centre, MM))
    return g


# ==== [SPHERES] ================================================================================
# The classic teaching plate of the Phong model: one diffuse colour, the specular coefficient ks
# rising from left to right, the exponent n rising from top to bottom. kd = (1 - ks) * base, so
# kd + ks <= 1 in every channel; ks stops at 0.8 so the last column still shows its colour.

SPHERE_KS = (0.0, 0.2, 0.4, 0.6, 0.8)            # columns, left to right
SPHERE_N = (5.0, 20.0, 80.0, 320.0)              # rows, top to bottom
SPHERE_BASE = (0.85, 0.3, 0.1)                   # a red-orange
SPHERE_RADIUS = 0.4                              # m
SPHERE_SPACING = 1.0                             # m between centres
SPHERE_SEGMENTS, SPHERE_RINGS = 48, 32


def phong_spheres():
    g = GltfBuilder("phong_spheres")
    # One sphere geometry in the buffer, shared by the twenty meshes (each with its material)
    # and placed by the nodes' translations.
    sphere = g.geometry(*uv_sphere(SPHERE_RADIUS, SPHERE_SEGMENTS, SPHERE_RINGS))
    columns, rows = len(SPHERE_KS), len(SPHERE_N)
    for row, n in enumerate(SPHERE_N):
        for column, ks in enumerate(SPHERE_KS):
            name = "ks%.2f_n%d" % (ks, n)
            kd = tuple((1.0 - ks) * c for c in SPHERE_BASE)
            material = g.material(name, kd, ks=ks, shininess=n,
                                  roughness=roughness_for_shininess(n))
            centre = ((column - (columns - 1) / 2.0) * SPHERE_SPACING,
                      ((rows - 1) / 2.0 - row) * SPHERE_SPACING, 0.0)
            g.mesh_node(name, g.mesh(name, [(sphere, material)]), centre)

    # Key light up, left and in front, so every sphere shows its highlight on the upper left of
    # the side facing the camera; a weaker fill from the lower right keeps the shadow side from
    # being pure black and adds a second, smaller highlight. At ~7.8 m the key gives
    # IL = I / (pi d^2) ~ 0.52: diffuse radiance kd * IL ~ 0.44 (red) facing it in the first
    # column, a highlight peak ks * IL ~ 0.42 in the last; nothing clips at exposure 0.
    g.point_light("key_light", (-3.0, 4.0, 6.0), 100.0)
    g.point_light("fill_light", (4.0, -1.5, 5.0), 20.0)

    # Camera on +Z framing the 5 x 4 grid (4.8 m x 3.8 m with the radii) with a margin:
    # yfov 30 degrees at 8.5 m sees 4.6 m vertically, 6.1 m horizontally at aspect 4:3.
    g.camera("spheres_camera", (0.0, 0.0, 8.5), (0.0, 0.0, 0.0), math.radians(30.0),
             4.0 / 3.0, 0.1, 100.0)
    # Ambient so the ambient term shows when a student switches it on; dark grey background.
    g.scene_extras(ambient=(0.03, 0.03, 0.03), background=(0.01, 0.01, 0.01), exposure=0.0)
    return g


# ==== [WHITTED] ================================================================================
# After the picture in T. Whitted, "An Improved Illumination Model for Shaded Display",
# Communications of the ACM 23(6), 1980: a red and yellow checkerboard, a mirror sphere and a
# glass sphere in front of it, a blue sky. The positions are not published; these reproduce the
# composition (glass sphere in front, upper left; mirror sphere behind it to the right).

CHECK_SIZE = 0.5                                 # m, side of one square
CHECK_COLUMNS, CHECK_ROWS = 12, 16               # x from -3 to 3, z from -6 to 2
CHECK_X0, CHECK_Z0 = -3.0, -6.0
CHECK_RED = (0.75, 0.08, 0.05)
CHECK_YELLOW = (0.8, 0.7, 0.08)

MIRROR_CENTRE, MIRROR_RADIUS = (0.65, 0.75, -1.0), 0.6
GLASS_CENTRE, GLASS_RADIUS = (-0.45, 1.3, 0.4), 0.5


def whitted():
    g = GltfBuilder("whitted")
    red = g.material("checker_red", CHECK_RED, ks=0.0)
    yellow = g.material("checker_yellow", CHECK_YELLOW, ks=0.0)
    # Mirror: kd + ks + kr = 1; a highlight from ks.
    mirror = g.material("mirror", (0.1, 0.1, 0.1), ks=0.15, shininess=100.0,
                        roughness=roughness_for_shininess(100.0), kr=0.75)
    # Glass: kd + ks + kr + kt = 1; eta 1.5. With the Fresnel switch, kt's share splits further.
    glass = g.material("glass", (0.0, 0.0, 0.0), ks=0.1, shininess=200.0,
                       roughness=roughness_for_shininess(200.0), kr=0.05, kt=0.85, ior=1.5,
                       transmission_extension=True)

    # The checkerboard as geometry, one primitive per colour: every model sees the squares,
    # radiosity included, without textures. Squares of one colour touch only at corners, so
    # each keeps its own four vertices.
    squares = {0: ([], [], []), 1: ([], [], [])}
    for row in range(CHECK_ROWS):
        for column in range(CHECK_COLUMNS):
            x0, z0 = CHECK_X0 + column * CHECK_SIZE, CHECK_Z0 + row * CHECK_SIZE
            x1, z1 = x0 + CHECK_SIZE, z0 + CHECK_SIZE
            points, normals, indices = oriented_quad(
                [(x0, 0.0, z0), (x1, 0.0, z0), (x1, 0.0, z1), (x0, 0.0, z1)], (0.0, 1.0, 0.0))
            positions, all_normals, all_indices = squares[(row + column) % 2]
            all_indices += [len(positions) + i for i in indices]
            positions += points
            all_normals += normals
    floor = g.mesh("checkerboard", [(g.geometry(*squares[0]), red),
                                    (g.geometry(*squares[1]), yellow)])
    g.mesh_node("checkerboard", floor)

    # Each sphere built at its own radius (no node scale: normals stay exactly unit) and placed
    # by its node's translation. Finer than the plate's spheres: they are large in the picture
    # and their silhouettes refract and reflect the board.
    for name, centre, radius, material in (("mirror_sphere", MIRROR_CENTRE, MIRROR_RADIUS, mirror),
                                           ("glass_sphere", GLASS_CENTRE, GLASS_RADIUS, glass)):
        sphere = g.geometry(*uv_sphere(radius, 64, 48))
        g.mesh_node(name, g.mesh(name, [(sphere, material)]), centre)

    # The light above and behind the camera, to the right: shadows fall forward-left of the
    # spheres onto the board. At ~6 m it gives the board ~2 W/m^2, diffuse radiance ~0.4.
    g.point_light("light", (2.0, 5.5, 3.0), 90.0)

    g.camera("whitted_camera", (0.2, 1.6, 4.2), (0.1, 0.8, -0.4), math.radians(40.0),
             4.0 / 3.0, 0.1, 100.0)
    # Blue sky; a little ambient as in Whitted's model, so shadows are not pure black.
    g.scene_extras(ambient=(0.05, 0.05, 0.05), background=(0.2, 0.35, 0.8), exposure=0.0)
    return g


# ==== [EFFECTS] ================================================================================
# Slide 19's "other possibilities" of the local models on one plate, each where the camera sees it
# plainly (the README's table names the switch and the flag of each):
#   front row, left to right: distance attenuation (two low point lights, physical 1/d^2 and the
#     classroom 1/(0.35 d), equal straight below them), and non-uniform lights (a spot with a
#     smooth cone edge, a spot with Warn's cos^p);
#   middle row: blocking by occlusion (a box in the key spot's and the sun's light), a
#     non-refractive pane (kt 0.6) in front of a red box and a yellow ball, a mirror ball (kr 0.8)
#     before a green panel;
#   behind: the floor recedes 16 m between coloured pillars, for the atmospheric attenuation.

EFFECTS_FLOOR = (-4.0, 4.0, -16.0, 3.0)  # x0, x1, z0, z1, m
EFFECTS_CELL = 0.25                      # m: fine enough for Gouraud to show the light pools
EFFECTS_GREY = (0.55, 0.55, 0.55)


def grid_floor(x0, x1, z0, z1, cell):
    """A flat floor at y = 0 facing +Y, tessellated into cells with shared vertices."""
    columns, rows = int(round((x1 - x0) / cell)), int(round((z1 - z0) / cell))
    positions, normals, indices = [], [], []
    for j in range(rows + 1):
        for i in range(columns + 1):
            positions.append((x0 + i * cell, 0.0, z0 + j * cell))
            normals.append((0.0, 1.0, 0.0))
    for j in range(rows):
        for i in range(columns):
            a = j * (columns + 1) + i
            b, c, d = a + 1, a + columns + 2, a + columns + 1
            # Counter-clockwise seen from +Y: a (x0, z0), d (x0, z0 + cell), c, b.
            indices += [a, d, c, a, c, b]
    return positions, normals, indices


def box(centre, size):
    """An axis-aligned box, flat faces wound counter-clockwise seen from outside."""
    hx, hy, hz = (s / 2.0 for s in size)
    cx, cy, cz = centre
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u, v = (axis + 1) % 3, (axis + 2) % 3
            corners = []
            for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis] = sign
                p[u], p[v] = du, dv
                corners.append((cx + p[0] * hx, cy + p[1] * hy, cz + p[2] * hz))
            points, face_normals, face_indices = oriented_quad(corners, tuple(n))
            indices += [len(positions) + k for k in face_indices]
            positions += points
            normals += face_normals
    return positions, normals, indices


def local_effects():
    g = GltfBuilder("local_effects")
    floor = g.material("floor", EFFECTS_GREY, ks=0.0)
    white = g.material("white", (0.75, 0.75, 0.75), ks=0.0)
    red = g.material("red", (0.7, 0.08, 0.06), ks=0.2, shininess=40.0,
                     roughness=roughness_for_shininess(40.0))
    yellow = g.material("yellow", (0.7, 0.56, 0.075), ks=0.3, shininess=60.0,
                        roughness=roughness_for_shininess(60.0))
    green = g.material("green", (0.1, 0.5, 0.12), ks=0.0)
    blue = g.material("pillar_blue", (0.12, 0.25, 0.7), ks=0.0)
    orange = g.material("pillar_orange", (0.8, 0.4, 0.08), ks=0.0)
    # kd + ks + kt and kd + ks + kr at most 1: within the budget of 1 (see check_scene).
    pane = g.material("pane", (0.05, 0.08, 0.1), ks=0.3, shininess=200.0,
                      roughness=roughness_for_shininess(200.0), kt=0.6)
    mirror = g.material("mirror", (0.05, 0.05, 0.05), ks=0.15, shininess=200.0,
                        roughness=roughness_for_shininess(200.0), kr=0.8)

    g.mesh_node("floor", g.mesh("floor", [(g.geometry(*grid_floor(*EFFECTS_FLOOR, EFFECTS_CELL)), floor)]))
    # Pillars along the receding floor: the fog takes their colour away with distance.
    for k, z in enumerate((-4.0, -7.0, -10.0, -13.0)):
        for side, x in (("left", -3.0), ("right", 3.0)):
            name = "pillar_%s_%d" % (side, k)
            material = blue if (k + (side == "right")) % 2 == 0 else orange
            g.mesh_node(name, g.mesh(name, [(g.geometry(*box((x, 1.0, z), (0.4, 2.0, 0.4))), material)]))
    # Middle row. Occlusion: a box in the key spot's and the sun's light.
    g.mesh_node("shadow_box", g.mesh("shadow_box", [(g.geometry(*box((-2.6, 0.35, -1.6), (0.7, 0.7, 0.7))), white)]))
    # Transparency: a thin pane, and what lies behind it.
    g.mesh_node("pane", g.mesh("pane", [(g.geometry(*box((0.0, 0.65, -1.0), (1.6, 1.2, 0.02))), pane)]))
    g.mesh_node("red_box", g.mesh("red_box", [(g.geometry(*box((-0.4, 0.3, -2.0), (0.5, 0.6, 0.5))), red)]))
    g.mesh_node("yellow_ball", g.mesh("yellow_ball", [(g.geometry(*uv_sphere(0.3, 48, 32)), yellow)]),
                (0.45, 0.3, -2.0))
    # Reflection map: a mirror ball before a green panel (and the rest of the plate around it).
    g.mesh_node("mirror_ball", g.mesh("mirror_ball", [(g.geometry(*uv_sphere(0.5, 64, 48)), mirror)]),
                (2.6, 0.5, -1.6))
    g.mesh_node("green_panel", g.mesh("green_panel", [(g.geometry(*box((2.6, 0.8, -2.6), (1.8, 1.6, 0.05))), green)]))

    # Front row: distance attenuation. Both lamps 0.35 m over the floor, equal straight below them
    # (1/d^2 = 1/(0.35 d) at d = 0.35); away from there the classroom lamp falls as 1/d only.
    g.light("lamp_physical", "point", (-2.4, 0.35, 0.8), (-2.4, 0.0, 0.8), 0.3)
    g.light("lamp_classroom", "point", (-0.8, 0.35, 0.8), (-0.8, 0.0, 0.8), 0.3,
            extras={"attenuation": [0.0, 0.35, 0.0]})
    # Non-uniform lights: the same spot twice, 1.6 m up, with a smooth cone edge and with Warn's
    # cos^30 (half its axis intensity at 12 degrees off the axis).
    g.light("spot_smooth", "spot", (0.8, 1.6, 0.8), (0.8, 0.0, 0.8), 6.0,
            spot=(math.radians(12.0), math.radians(22.0)))
    g.light("spot_warn", "spot", (2.4, 1.6, 0.8), (2.4, 0.0, 0.8), 6.0,
            spot=(0.0, math.radians(40.0)), extras={"warn_exponent": 30.0})
    # The key light of the middle row (a spot: its shadows come from a perspective map) and a
    # weak sun over everything (an orthographic map), so the far floor is lit for the fog.
    g.light("key_spot", "spot", (-0.5, 4.5, 0.5), (0.0, 0.0, -1.8), 25.0,
            spot=(math.radians(30.0), math.radians(40.0)))
    g.light("sun", "directional", (0.0, 10.0, 0.0), (3.0, 0.0, -4.0), 0.2)

    g.camera("effects_camera", (0.0, 3.0, 5.6), (0.0, 0.2, -1.8), math.radians(50.0), 4.0 / 3.0,
             0.1, 100.0)
    g.scene_extras(ambient=(0.02, 0.02, 0.02), background=(0.05, 0.06, 0.08), exposure=0.0)
    return g


# ==== [CHECK] ==================================================================================
# Independent of the builder above: reads the files back and applies the rules of SCENES.md
# and of the glTF 2.0 specification that matter to Luz's loader.

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}
COMPONENT_FORMATS = {FLOAT: "f", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I", 5121: "B"}


def check_scene(path):
    """Returns a list of problems (empty when the scene is fine)."""
    problems = []

    def problem(where, what):
        problems.append("%s: %s: %s" % (os.path.basename(path), where, what))

    with open(path, encoding="ascii") as f:
        doc = json.load(f)

    def walk_numbers(value, where):
        if isinstance(value, float) and not math.isfinite(value):
            problem(where, "non-finite number")
        elif isinstance(value, dict):
            for k, v in value.items():
                walk_numbers(v, where + "." + k)
        elif isinstance(value, list):
            for i, v in enumerate(value):
                walk_numbers(v, "%s[%d]" % (where, i))
    walk_numbers(doc, "document")

    if doc.get("asset", {}).get("version") != "2.0":
        problem("asset", "version is not 2.0")
    if doc.get("asset", {}).get("generator") != GENERATOR:
        problem("asset", "generator is not %r" % GENERATOR)

    # Buffers: only the scene's own .bin, beside it.
    buffers = []
    for i, buf in enumerate(doc.get("buffers", [])):
        uri = buf.get("uri", "")
        if (not uri or "/" in uri or "\\" in uri or ":" in uri or uri.startswith(".")
                or uri != os.path.splitext(os.path.basename(path))[0] + ".bin"):
            problem("buffer %d" % i, "uri %r is not the scene's own .bin" % uri)
            buffers.append(b"")
            continue
        with open(os.path.join(os.path.dirname(path), uri), "rb") as f:
            data = f.read()
        if len(data) != buf.get("byteLength"):
            problem("buffer %d" % i, "byteLength %s but file has %d bytes"
                    % (buf.get("byteLength"), len(data)))
        buffers.append(data)

    views = doc.get("bufferViews", [])
    for i, view in enumerate(views):
        b = view.get("buffer", -1)
        if not 0 <= b < len(buffers):
            problem("bufferView %d" % i, "no buffer %s" % b)
        elif view.get("byteOffset", 0) + view["byteLength"] > len(buffers[b]):
            problem("bufferView %d" % i, "runs past the end of its buffer")

    def read_accessor(index, where):
        accessors = doc.get("accessors", [])
        if not 0 <= index < len(accessors):
            problem(where, "no accessor %s" % index)
            return None
        acc = accessors[index]
        fmt = COMPONENT_FORMATS.get(acc["componentType"])
        n = COMPONENTS[acc["type"]]
        view = views[acc["bufferView"]]
        size = struct.calcsize("<" + fmt) * n
        stride = view.get("byteStride", size)
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        if start % struct.calcsize("<" + fmt):
            problem(where, "accessor %d is not aligned" % index)
        if acc.get("byteOffset", 0) + stride * (acc["count"] - 1) + size > view["byteLength"]:
            problem(where, "accessor %d runs past its bufferView" % index)
            return None
        data = buffers[view["buffer"]]
        out = []
        for k in range(acc["count"]):
            values = struct.unpack_from("<%d%s" % (n, fmt), data, start + k * stride)
            out.append(values if n > 1 else values[0])
        return acc, out

    meshes = doc.get("meshes", [])
    materials = doc.get("materials", [])
    for m, mesh in enumerate(meshes):
        for p, prim in enumerate(mesh.get("primitives", [])):
            where = "mesh %d %r primitive %d" % (m, mesh.get("name"), p)
            if prim.get("mode", TRIANGLES) != TRIANGLES:
                problem(where, "not a triangle primitive")
            if "material" in prim and not 0 <= prim["material"] < len(materials):
                problem(where, "no material %s" % prim["material"])
            attrs = prim.get("attributes", {})
            pos = read_accessor(attrs.get("POSITION", -1), where + " POSITION")
            nor = read_accessor(attrs.get("NORMAL", -1), where + " NORMAL")
            idx = read_accessor(prim.get("indices", -1), where + " indices")
            if not (pos and nor and idx):
                continue
            (pacc, positions), (_, normals), (_, indices) = pos, nor, idx
            for axis in range(3):
                lo = min(v[axis] for v in positions)
                hi = max(v[axis] for v in positions)
                if "min" not in pacc or "max" not in pacc:
                    problem(where, "POSITION without min/max")
                    break
                if f32(pacc["min"][axis]) != lo or f32(pacc["max"][axis]) != hi:
                    problem(where, "POSITION min/max do not match the data on axis %d" % axis)
            if len(normals) != len(positions):
                problem(where, "NORMAL and POSITION counts differ")
                continue
            for v in positions + normals:
                if not all(math.isfinite(c) for c in v):
                    problem(where, "non-finite vertex data")
                    break
            for k, nrm in enumerate(normals):
                if abs(length(nrm) - 1.0) > 1e-5:
                    problem(where, "normal %d is not unit (%g)" % (k, length(nrm)))
                    break
            if len(indices) % 3:
                problem(where, "index count is not a multiple of 3")
                continue
            if indices and max(indices) >= len(positions):
                problem(where, "index %d >= vertex count %d" % (max(indices), len(positions)))
                continue
            for t in range(0, len(indices), 3):
                a, b, c = (positions[i] for i in indices[t:t + 3])
                face = cross(sub(b, a), sub(c, a))
                longest = max(length(sub(b, a)), length(sub(c, b)), length(sub(a, c)))
                if length(face) <= 1e-6 * longest * longest:
                    problem(where, "degenerate triangle %d" % (t // 3))
                    break
                # Winding: counter-clockwise seen from the side the normals point to.
                mean_normal = add(add(normals[indices[t]], normals[indices[t + 1]]),
                                  normals[indices[t + 2]])
                if dot(face, mean_normal) <= 0:
                    problem(where, "triangle %d is wound against its normals" % (t // 3))
                    break

    # Materials: kd + ks + kr + kt <= 1 per channel, with SCENES.md's defaults. The path tracer's
    # normalised Phong lobe ks (n + 2)/(2 pi) cos^n reflects at most ks of the light arriving
    # (all of it at normal incidence; Lafortune and Willems 1994, "Using the modified Phong
    # reflectance model for physically based rendering"), so this sum bounds what a surface
    # gives back and the reference picture stays energy-conserving.
    for i, mat in enumerate(materials):
        where = "material %d %r" % (i, mat.get("name"))
        pbr = mat.get("pbrMetallicRoughness", {})
        base = pbr.get("baseColorFactor", [1.0, 1.0, 1.0, 1.0])[:3]
        metallic = pbr.get("metallicFactor", 1.0)
        roughness = pbr.get("roughnessFactor", 1.0)
        extras = mat.get("extras", {})
        exts = mat.get("extensions", {})

        def rgb(value):
            return [float(value)] * 3 if isinstance(value, (int, float)) else list(value)
        transmission = exts.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)
        kd = [c * (1.0 - metallic) * (1.0 - transmission) for c in base]
        if "kr" in extras:
            kr = rgb(extras["kr"])
        elif metallic >= 0.5 and roughness <= 0.05:
            kr = base
        else:
            kr = [0.0] * 3
        if "kt" in extras:
            kt = rgb(extras["kt"])
        else:
            kt = [c * (1.0 - metallic) * transmission for c in base]
        ks = rgb(extras["ks"]) if "ks" in extras else [0.0] * 3
        for ch in range(3):
            total = kd[ch] + ks[ch] + kr[ch] + kt[ch]
            if total > 1.0 + 1e-9:
                problem(where, "kd + ks + kr + kt = %g > 1 in channel %d" % (total, ch))
        for key in ("ks", "ka", "kr", "kt"):
            if key in extras and any(c < 0 for c in rgb(extras[key])):
                problem(where, "negative extras.%s" % key)

    # Nodes, cameras, lights, scene.
    cameras = doc.get("cameras", [])
    lights = doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    nodes = doc.get("nodes", [])
    for i, node in enumerate(nodes):
        where = "node %d %r" % (i, node.get("name"))
        if "mesh" in node and not 0 <= node["mesh"] < len(meshes):
            problem(where, "no mesh %s" % node["mesh"])
        if "camera" in node and not 0 <= node["camera"] < len(cameras):
            problem(where, "no camera %s" % node["camera"])
        light = node.get("extensions", {}).get("KHR_lights_punctual", {}).get("light")
        if light is not None and not 0 <= light < len(lights):
            problem(where, "no light %s" % light)
        if "rotation" in node and abs(length(node["rotation"][:3]) ** 2
                                      + node["rotation"][3] ** 2 - 1.0) > 1e-5:
            problem(where, "rotation is not a unit quaternion")
    if not cameras:
        problem("cameras", "the scene has no camera")
    for i, cam in enumerate(cameras):
        persp = cam.get("perspective", {})
        if cam.get("type") != "perspective" or not 0 < persp.get("yfov", 0) < math.pi:
            problem("camera %d" % i, "not a perspective camera with 0 < yfov < pi")
    for i, light in enumerate(lights):
        if light.get("intensity", 1.0) < 0:
            problem("light %d" % i, "negative intensity")
    scene = doc.get("scenes", [{}])[doc.get("scene", 0)]
    for n in scene.get("nodes", []):
        if not 0 <= n < len(nodes):
            problem("scene", "no node %s" % n)
    for key in ("ambient", "background", "exposure"):
        if key not in scene.get("extras", {}):
            problem("scene.extras", "no %s" % key)
    used = set(doc.get("extensionsUsed", []))
    for ext in ("KHR_lights_punctual",) if lights else ():
        if ext not in used:
            problem("extensionsUsed", "%s missing" % ext)
    return problems


# ==== [MAIN] ===================================================================================

def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=here, help="folder to write into (default: %(default)s)")
    parser.add_argument("--check", nargs="?", const=here, metavar="DIR",
                        help="only check the scenes in DIR (default: this folder)")
    parser.add_argument("--unwelded", metavar="DIR",
                        help="only write cornell_unwelded.gltf (a triangle soup of the box) into DIR")
    args = parser.parse_args(argv)
    if args.unwelded is not None:
        os.makedirs(args.unwelded, exist_ok=True)
        cornell_unwelded().write(args.unwelded)
        return 0

    if args.check is None:
        os.makedirs(args.out, exist_ok=True)
        for build in (cornell_box, phong_spheres, whitted, local_effects, cornell_spheres):
            build().write(args.out)
        folder = args.out
    else:
        folder = args.check

    problems = []
    for name in SCENE_FILES:
        problems += check_scene(os.path.join(folder, name + ".gltf"))
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        return 1
    print("%s: %d scenes written and checked" % (folder, len(SCENE_FILES))
          if args.check is None else "%s: %d scenes checked" % (folder, len(SCENE_FILES)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
