#!/usr/bin/env python3
"""Writes the fuzzers' seed corpora: small files that between them use every part of the format
their target reads, so that libFuzzer's mutations start from inputs that reach deep into it.
Small seeds keep each execution short: 10^6 of them fit in an hour.
- fuzz/seeds/ (glTF loader, a few hundred bytes to 2 kB): accessors, sparse accessors, materials,
  textures with KHR_texture_transform, vertex colours, the three light types, cameras, node
  transforms, GLB, KHR_mesh_quantization's integer attributes;
- fuzz/image_seeds/ (image decoder, under 1 kB): PNGs of every colour type the readers decode
  (grey, grey 16-bit, RGB, RGBA, palette) and, when Debian's cjpeg (libjpeg-turbo-progs) is on
  the PATH, baseline, greyscale and progressive JPEGs of a 2x2 picture.
  fuzz/make_seeds.py        (rewrites both)
"""
import base64
import json
import pathlib
import shutil
import struct
import subprocess
import zlib

OUT = pathlib.Path(__file__).resolve().parent / "seeds"
IMAGE_OUT = pathlib.Path(__file__).resolve().parent / "image_seeds"


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png_of(width, height, colour_type, bit_depth, rows, extra=b""):
    """A PNG of already filtered rows (a filter byte, 0, before each)."""
    header = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + extra + chunk(b"IDAT", zlib.compress(rows)) +
            chunk(b"IEND", b""))


def png(width, height, rgb):
    rows = b"".join(b"\0" + bytes(rgb[3 * width * y:3 * width * (y + 1)]) for y in range(height))
    return png_of(width, height, 2, 8, rows)


def write_image_seeds():
    IMAGE_OUT.mkdir(exist_ok=True)
    rgb = [255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255]
    (IMAGE_OUT / "rgb2x2.png").write_bytes(png(2, 2, rgb))
    (IMAGE_OUT / "rgb4x3.png").write_bytes(png(4, 3, list(range(36))))
    (IMAGE_OUT / "grey2x2.png").write_bytes(png_of(2, 2, 0, 8, b"\0\x10\x80\0\xff\x40"))
    (IMAGE_OUT / "grey16_1x1.png").write_bytes(png_of(1, 1, 0, 16, b"\0\x12\x34"))
    (IMAGE_OUT / "rgba1x2.png").write_bytes(png_of(1, 2, 6, 8, b"\0\xff\0\0\x80\0\0\xff\0\xff"))
    (IMAGE_OUT / "palette2x1.png").write_bytes(png_of(2, 1, 3, 8, b"\0\0\1", chunk(b"PLTE", b"\xff\0\0\0\0\xff")))
    cjpeg = shutil.which("cjpeg")
    if not cjpeg:
        print("cjpeg not found (apt-get install libjpeg-turbo-progs): no JPEG seeds")
        return
    ppm = b"P6\n2 2\n255\n" + bytes(rgb)
    for name, flags in (("rgb2x2.jpg", ["-quality", "90"]), ("grey2x2.jpg", ["-grayscale"]),
                        ("progressive2x2.jpg", ["-progressive"])):
        (IMAGE_OUT / name).write_bytes(subprocess.run([cjpeg, *flags], input=ppm, capture_output=True, check=True).stdout)


def data_uri(mime, data):
    return f"data:{mime};base64," + base64.b64encode(data).decode()


class Doc:
    def __init__(self):
        self.bin = bytearray()
        self.gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}], "nodes": [],
                     "meshes": [], "accessors": [], "bufferViews": [], "buffers": []}

    def view(self, data):
        while len(self.bin) % 4:
            self.bin += b"\0"
        self.gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.gltf["bufferViews"]) - 1

    def accessor(self, values, kind, component=5126, **extra):
        fmt = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}[component]
        flat = [x for v in values for x in (v if isinstance(v, (list, tuple)) else [v])]
        accessor = {"bufferView": self.view(struct.pack(f"<{len(flat)}{fmt}", *flat)), "componentType": component,
                    "count": len(values), "type": kind, **extra}
        if kind == "VEC3" and component == 5126:
            accessor["min"] = [min(v[i] for v in values) for i in range(3)]
            accessor["max"] = [max(v[i] for v in values) for i in range(3)]
        self.gltf["accessors"].append(accessor)
        return len(self.gltf["accessors"]) - 1

    def node(self, node, root=True):
        self.gltf["nodes"].append(node)
        if root:
            self.gltf["scenes"][0]["nodes"].append(len(self.gltf["nodes"]) - 1)
        return len(self.gltf["nodes"]) - 1

    def text(self):
        self.gltf["buffers"] = [{"byteLength": len(self.bin), "uri": data_uri("application/octet-stream", bytes(self.bin))}]
        return json.dumps(self.gltf, separators=(",", ":"))

    def glb(self):
        self.gltf["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(self.gltf, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.bin) + b"\0" * (-len(self.bin) % 4)
        body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
        return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def square(doc, material, colours=False, uvs=False):
    attributes = {"POSITION": doc.accessor([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], "VEC3"),
                  "NORMAL": doc.accessor([(0, 0, 1)] * 4, "VEC3")}
    if colours:
        attributes["COLOR_0"] = doc.accessor([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255,) * 4],
                                             "VEC4", 5121, normalized=True)
    if uvs:
        attributes["TEXCOORD_0"] = doc.accessor([(0, 1), (1, 1), (1, 0), (0, 0)], "VEC2")
    indices = doc.accessor([0, 1, 2, 0, 2, 3], "SCALAR", 5123)
    doc.gltf["meshes"].append({"primitives": [{"attributes": attributes, "indices": indices, "material": material}]})
    return len(doc.gltf["meshes"]) - 1


def lit_textured():
    doc = Doc()
    texture = png(2, 2, [255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255])
    doc.gltf["images"] = [{"uri": data_uri("image/png", texture)}]
    doc.gltf["samplers"] = [{"magFilter": 9729, "wrapS": 10497}]
    doc.gltf["textures"] = [{"source": 0, "sampler": 0}]
    doc.gltf["materials"] = [{"name": "checker", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0, "roughnessFactor": 0.4,
        "baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 2], "offset": [0.5, 0]}}}}}]
    doc.gltf["extensionsUsed"] = ["KHR_lights_punctual", "KHR_texture_transform"]
    doc.gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "point", "intensity": 20, "color": [1, 0.9, 0.8], "range": 10},
        {"type": "spot", "intensity": 40, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
        {"type": "directional", "intensity": 2}]}}
    doc.gltf["cameras"] = [{"type": "perspective", "name": "eye", "perspective": {"yfov": 0.7, "znear": 0.1, "zfar": 50, "aspectRatio": 1.5}}]
    mesh = square(doc, 0, colours=True, uvs=True)
    child = doc.node({"mesh": mesh, "rotation": [0, 0.38, 0, 0.92], "scale": [1, 2, 1]}, root=False)
    doc.node({"name": "group", "translation": [0, 0.5, 0], "children": [child]})
    for light, at in ((0, [0.5, 0.5, 2]), (1, [0, 2, 2]), (2, [0, 5, 0])):
        doc.node({"translation": at, "rotation": [-0.38, 0, 0, 0.92], "extensions": {"KHR_lights_punctual": {"light": light}}})
    doc.node({"camera": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 4, 1]})
    return doc


def emissive_sparse():
    doc = Doc()
    doc.gltf["materials"] = [
        {"name": "lamp", "emissiveFactor": [1, 1, 1], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}}},
        {"name": "glass", "pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.5}}}]
    doc.gltf["extensionsUsed"] = ["KHR_materials_emissive_strength", "KHR_materials_transmission", "KHR_materials_ior"]
    lamp = square(doc, 0)
    base = square(doc, 1)
    # The second square's positions moved by a sparse accessor (two of its corners).
    positions = doc.gltf["meshes"][base]["primitives"][0]["attributes"]["POSITION"]
    moved = doc.accessor([(-1, -1, 1), (1, -1, 1)], "VEC3")
    doc.gltf["accessors"][positions]["sparse"] = {
        "count": 2, "indices": {"bufferView": doc.view(struct.pack("<2H", 0, 1)), "componentType": 5123},
        "values": {"bufferView": doc.gltf["accessors"][moved]["bufferView"]}}
    doc.node({"mesh": lamp, "translation": [0, 3, 0], "rotation": [0.71, 0, 0, 0.71]})
    doc.node({"mesh": base})
    return doc


def quantized():
    """KHR_mesh_quantization as gltfpack writes it: shorts and bytes, padded to 4 bytes a vertex."""
    doc = Doc()

    def padded(values, fmt, stride, component, normalized):
        data = b"".join(struct.pack(f"<3{fmt}", *v) + b"\0" * (stride - 3 * struct.calcsize(fmt)) for v in values)
        view = doc.view(data)
        doc.gltf["bufferViews"][view]["byteStride"] = stride
        doc.gltf["accessors"].append({"bufferView": view, "componentType": component, "count": len(values),
                                      "type": "VEC3", "normalized": normalized})
        return len(doc.gltf["accessors"]) - 1

    attributes = {"POSITION": padded([(0, 0, 0), (1000, 0, 0), (1000, 1000, 0), (0, 1000, 0)], "h", 8, 5122, False),
                  "NORMAL": padded([(0, 0, 127)] * 3 + [(0, 0, -128)], "b", 4, 5120, True),
                  "TEXCOORD_0": doc.accessor([(0, 0), (2, 0), (2, 2), (0, 2)], "VEC2", 5123)}
    indices = doc.accessor([0, 1, 2, 0, 2, 3], "SCALAR", 5123)
    doc.gltf["meshes"].append({"primitives": [{"attributes": attributes, "indices": indices}]})
    doc.gltf["extensionsUsed"] = ["KHR_mesh_quantization"]
    doc.gltf["extensionsRequired"] = ["KHR_mesh_quantization"]
    doc.node({"mesh": 0, "scale": [0.001, 0.001, 0.001]})
    return doc


def main():
    OUT.mkdir(exist_ok=True)
    (OUT / "lit_textured.gltf").write_text(lit_textured().text())
    (OUT / "lit_textured.glb").write_bytes(lit_textured().glb())
    (OUT / "emissive_sparse.gltf").write_text(emissive_sparse().text())
    (OUT / "quantized.glb").write_bytes(quantized().glb())
    write_image_seeds()
    for path in sorted(OUT.iterdir()) + sorted(IMAGE_OUT.iterdir()):
        print(f"{path}: {path.stat().st_size} bytes")


if __name__ == "__main__":
    main()
