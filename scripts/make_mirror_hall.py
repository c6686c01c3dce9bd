#!/usr/bin/env python3
"""Writes samples/assets/mirror_hall.gltf: a wall mirror given as a glTF node, for the mirror effect.

A checkered ground and a striped backdrop (z = -3) with, standing against the backdrop, a flat
2.4 x 1.6 m quad named "Mirror" (facing +Z, centre (0, 1.1, -2.9)) and, beside it, "Bent": two
1 x 1 m quads meeting at 30 degrees (not planar: the mirror effect refuses it, naming how far a
vertex lies off the best plane). A red box and a blue ball stand in front of the mirror; the
camera looks at the mirror from the front right, so the objects and the room behind the camera
show in it:

  snell render --scene samples/assets/mirror_hall.gltf --effect mirror --set mirror.node=Mirror

The geometry helpers are those of make_glass_grid.py. Buffers are embedded (base64 data: URI);
the output is the same byte for byte on every run. Standard library only.
Run: python3 scripts/make_mirror_hall.py
"""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from make_glass_grid import (Buffer, Geometry, box, checker_ground, clean, look_from,  # noqa: E402
                             opaque, sphere, striped_wall, write_gltf)

WALL_Z = -3.0
EYE = (2.6, 1.6, 4.2)
TARGET = (0.0, 1.0, -2.9)
YFOV = 0.75


def mirror_quad(half_w, half_h):
    """A quad in the plane z = 0 facing +Z (counter-clockwise seen from +Z)."""
    g = Geometry()
    g.quad([[-half_w, -half_h, 0], [half_w, -half_h, 0], [half_w, half_h, 0], [-half_w, half_h, 0]],
           (0, 0, 1))
    return g.parts()


def bent_sheet():
    """Two unit quads facing +Z, the right one turned 30 degrees about the shared edge x = 0."""
    g = Geometry()
    g.quad([[-1, -0.5, 0], [0, -0.5, 0], [0, 0.5, 0], [-1, 0.5, 0]], (0, 0, 1))
    a = math.radians(30)
    x, z = math.cos(a), math.sin(a)
    n = (-math.sin(a), 0, math.cos(a))
    g.quad([[0, -0.5, 0], [x, -0.5, z], [x, 0.5, z], [0, 0.5, 0]], n)
    return g.parts()


def main():
    buf = Buffer()
    materials, meshes, nodes = [], [], []

    def add(kind, item):
        kind.append(item)
        return len(kind) - 1

    def mesh(name, geo, material):
        return add(meshes, {"name": name,
                            "primitives": [dict(buf.geometry(geo), material=material)]})

    ground_light, ground_dark = checker_ground(-5.0, 5.0, WALL_Z, 5.0, 0.5)
    wall_light, wall_dark = striped_wall(-5.0, 5.0, 3.5, WALL_Z, 0.25)
    top = []
    for name, geo, color, roughness in (
            ("ground_light", ground_light, [0.80, 0.80, 0.78], 0.8),
            ("ground_dark", ground_dark, [0.12, 0.12, 0.14], 0.8),
            ("backdrop_light", wall_light, [0.92, 0.86, 0.72], 0.9),
            ("backdrop_dark", wall_dark, [0.08, 0.16, 0.45], 0.9)):
        top.append(add(nodes, {"name": name,
                               "mesh": mesh(name, geo, add(materials,
                                                           opaque(name, color, roughness)))}))
    steel = add(materials, opaque("steel", [0.55, 0.56, 0.58], 0.2))
    top.append(add(nodes, {"name": "Mirror", "mesh": mesh("Mirror", mirror_quad(1.2, 0.8), steel),
                           "translation": [0.0, 1.1, WALL_Z + 0.1]}))
    top.append(add(nodes, {"name": "Bent", "mesh": mesh("Bent", bent_sheet(), steel),
                           "translation": [2.2, 1.1, WALL_Z + 0.1]}))
    red = add(materials, opaque("red", [0.85, 0.10, 0.08], 0.4))
    top.append(add(nodes, {"name": "red box", "mesh": mesh("red box", box(0.3, 0.3, 0.3), red),
                           "translation": [-0.5, 0.3, -1.2],
                           "rotation": clean([0, math.sin(0.3), 0, math.cos(0.3)])}))
    blue = add(materials, opaque("blue", [0.12, 0.25, 0.85], 0.3))
    top.append(add(nodes, {"name": "blue ball", "mesh": mesh("blue ball", sphere(0.35), blue),
                           "translation": [0.7, 0.35, -0.6]}))
    yellow = add(materials, opaque("yellow", [0.92, 0.78, 0.12], 0.4))
    # Behind the camera's side of the room: only the mirror shows it.
    top.append(add(nodes, {"name": "yellow column",
                           "mesh": mesh("yellow column", box(0.25, 1.0, 0.25), yellow),
                           "translation": [-1.8, 1.0, 3.0]}))
    top.append(add(nodes, {"name": "camera", "camera": 0, "translation": list(EYE),
                           "rotation": clean(look_from(EYE, TARGET))}))
    doc = {
        "asset": {"version": "2.0", "generator": "snell scripts/make_mirror_hall.py"},
        "scene": 0,
        "scenes": [{"name": "mirror hall", "nodes": top}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"name": "front right", "type": "perspective",
                     "perspective": {"yfov": YFOV, "aspectRatio": round(16 / 9, 6),
                                     "znear": 0.1, "zfar": 100.0}}],
    }
    write_gltf(doc, buf, "mirror_hall.gltf")


if __name__ == "__main__":
    main()
