#!/usr/bin/env python3
"""Times Mitsuba 3's path tracer on scenes like Luz's, for the README's comparison with
`luz bench whitted --size 1024x1024`. A throwaway measurement, not part of the build or tests:

    python3 -m venv /tmp/mitsuba && /tmp/mitsuba/bin/pip install mitsuba
    /tmp/mitsuba/bin/python docs/bench_mitsuba.py [llvm_ad_rgb|scalar_rgb]

Prints, per scene, the first render (which includes Dr.Jit's kernel compilation) and the best
of five later ones (compiled kernels come from Dr.Jit's cache), 1024x1024, 1 spp, max_depth 5.
"""
import sys
import time

import drjit as dr
import mitsuba as mi

variant = sys.argv[1] if len(sys.argv) > 1 else "llvm_ad_rgb"
mi.set_variant(variant)


def cornell():
    scene = mi.cornell_box()  # Mitsuba's own Cornell box: walls, two blocks, an area light
    scene["sensor"]["film"]["width"] = 1024
    scene["sensor"]["film"]["height"] = 1024
    scene["integrator"] = {"type": "path", "max_depth": 5}
    return mi.load_dict(scene)


def whitted():
    # Whitted's composition: a red/yellow checkerboard, a mirror sphere, a glass sphere (ior 1.5),
    # a point light and a blue sky, as scenes/whitted.gltf.
    checker = {"type": "checkerboard", "color0": {"type": "rgb", "value": [0.75, 0.08, 0.05]},
               "color1": {"type": "rgb", "value": [0.8, 0.7, 0.08]},
               "to_uv": mi.ScalarTransform4f().scale([6, 8, 1])}
    return mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 5},
        "sensor": {"type": "perspective", "fov_axis": "y", "fov": 40,
                   "to_world": mi.ScalarTransform4f().look_at(origin=[0.2, 1.6, 4.2],
                                                              target=[0.2, 0.9, -3.8], up=[0, 1, 0]),
                   "film": {"type": "hdrfilm", "width": 1024, "height": 1024},
                   "sampler": {"type": "independent", "sample_count": 1}},
        "floor": {"type": "rectangle",
                  "to_world": mi.ScalarTransform4f().translate([0, 0, -2]).rotate([1, 0, 0], -90).scale([3, 4, 1]),
                  "bsdf": {"type": "diffuse", "reflectance": checker}},
        "mirror": {"type": "sphere", "center": [0.65, 0.75, -1.0], "radius": 0.6,
                   "bsdf": {"type": "conductor", "material": "none"}},
        "glass": {"type": "sphere", "center": [-0.45, 1.3, 0.4], "radius": 0.5,
                  "bsdf": {"type": "dielectric", "int_ior": 1.5, "ext_ior": 1.0}},
        "light": {"type": "point", "position": [2.0, 5.5, 3.0],
                  "intensity": {"type": "rgb", "value": [90, 90, 90]}},
        "sky": {"type": "constant", "radiance": {"type": "rgb", "value": [0.2, 0.35, 0.8]}},
    })


def timed(scene, seed):
    start = time.perf_counter()
    image = mi.render(scene, spp=1, seed=seed)
    dr.eval(image)
    dr.sync_thread()
    return time.perf_counter() - start


print(f"Mitsuba {mi.__version__}, variant {variant}, 1024x1024, 1 spp, path max_depth 5")
for name, make in (("cornell_box", cornell), ("whitted", whitted)):
    scene = make()
    first = timed(scene, 0)
    best = min(timed(scene, 0) for _ in range(5))  # same seed: the cached kernel is reused
    print(f"{name:<12} first {first:.3f} s (with kernel compilation), then best {best:.3f} s")
