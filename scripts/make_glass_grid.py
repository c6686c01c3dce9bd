#!/usr/bin/env python3
"""Writes samples/assets/glass_grid.gltf: a test grid of glass objects, one property per object.

Two rows of four transmissive objects (transmissionFactor 1 throughout) stand on an opaque
checkered ground in front of an opaque striped backdrop, so that what each one does to the view
behind it (shift, inversion, blur, colour fringes) is visible against a regular pattern:

  row 1 (front), spheres of radius 0.4 with KHR_materials_volume thickness 0.8 (the diameter) and
  a light blue attenuation, roughness 0: IOR 1.1, 1.33, 1.5, 2.0 from left to right;
  row 2 (back), slabs 0.8 wide x 0.8 tall x 0.15 deep, IOR 1.5: thin-walled (no volume
  extension), thickness 0.15 with roughness 0.3, the same with roughness 0.6, and smooth with
  KHR_materials_dispersion 1.0.

A perspective camera looks at the grid from the front and slightly above; a KHR_lights_punctual
directional light comes from the front left. Buffers are embedded (base64 data: URI), and the
output is the same byte for byte on every run. Standard library only.
Run: python3 scripts/make_glass_grid.py
"""
import base64
import json
import math
import struct
from pathlib import Path

ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
FLOAT, UNSIGNED_SHORT = 5126, 5123

# Layout (metres, Y up, the camera looks down -Z). The back row stands far enough behind the front
# row that, seen from the camera, the slabs clear the spheres' tops: each object is seen against
# the backdrop and the ground, not through its neighbour.
COLUMNS_X = [-1.95, -0.65, 0.65, 1.95]
FRONT_Z, BACK_Z = 1.2, -1.6
WALL_Z = -2.9
SPHERE_RADIUS = 0.4
SLAB_SIZE = (0.8, 0.8, 0.15)
# The slabs turn 30 degrees about Y: a slab seen face-on shifts the view behind it by almost
# nothing, so thick against thin-walled and the dispersion fringes would hardly show.
SLAB_YAW_DEG = 30.0
# About 20 degrees above the grid: the least elevation at which the slabs clear the spheres in
# front of them. At 16:9 the grid spans about 83% of the frame's width, the backdrop fills the top
# (the frame's top corners meet it at y = 2.4, x = +-4.9) and the ground the bottom.
EYE = (0.0, 2.4, 5.2)
TARGET = (0.0, 0.4, -0.2)
YFOV = 0.7  # radians, about 40 degrees.


class Buffer:
    """One binary buffer with its bufferViews and accessors."""

    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def _view(self, payload: bytes, target: int) -> int:
        while len(self.data) % 4:
            self.data.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.data),
                           "byteLength": len(payload), "target": target})
        self.data.extend(payload)
        return len(self.views) - 1

    def floats(self, rows, typ: str, bounds: bool = False) -> int:
        """Accessor over float rows (VEC2/VEC3); min/max of POSITION from the stored float32s."""
        flat = [x for row in rows for x in row]
        payload = struct.pack(f"<{len(flat)}f", *flat)
        stored = struct.unpack(f"<{len(flat)}f", payload)
        n = len(rows[0])
        a = {"bufferView": self._view(payload, ARRAY_BUFFER), "componentType": FLOAT,
             "count": len(rows), "type": typ}
        if bounds:
            a["min"] = [min(stored[i::n]) for i in range(n)]
            a["max"] = [max(stored[i::n]) for i in range(n)]
        self.accessors.append(a)
        return len(self.accessors) - 1

    def indices(self, idx) -> int:
        assert max(idx) < 65536
        self.accessors.append({"bufferView": self._view(struct.pack(f"<{len(idx)}H", *idx),
                                                        ELEMENT_ARRAY_BUFFER),
                               "componentType": UNSIGNED_SHORT, "count": len(idx),
                               "type": "SCALAR"})
        return len(self.accessors) - 1

    def geometry(self, geo) -> dict:
        """The attributes and indices of one primitive (materials are added per mesh)."""
        pos, nrm, uv, idx = geo
        return {"attributes": {"POSITION": self.floats(pos, "VEC3", bounds=True),
                               "NORMAL": self.floats(nrm, "VEC3"),
                               "TEXCOORD_0": self.floats(uv, "VEC2")},
                "indices": self.indices(idx)}


class Geometry:
    """Positions, normals, uvs and triangle indices, grown one quad at a time."""

    def __init__(self):
        self.pos, self.nrm, self.uv, self.idx = [], [], [], []

    def quad(self, corners, normal):
        """corners counter-clockwise seen from the side `normal` points to (glTF front face)."""
        base = len(self.pos)
        self.pos += [list(c) for c in corners]
        self.nrm += [list(normal)] * 4
        self.uv += [[0, 1], [1, 1], [1, 0], [0, 0]]
        self.idx += [base, base + 1, base + 2, base, base + 2, base + 3]

    def parts(self):
        return self.pos, self.nrm, self.uv, self.idx


def box(hx, hy, hz):
    """A box centred at the origin, half extents hx, hy, hz, one flat normal per face."""
    g = Geometry()
    faces = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]
    h = (hx, hy, hz)
    for n, u, v in faces:
        g.quad([[h[i] * (n[i] + su * u[i] + sv * v[i]) for i in range(3)]
                for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))], n)
    return g.parts()


def sphere(radius, segments=32, rings=16):
    """A UV sphere centred at the origin; u runs around +Y, v from the top (0) to the bottom."""
    pos, nrm, uv, idx = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = [math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi)]
            pos.append([radius * c for c in n])
            nrm.append(n)
            uv.append([s / segments, r / rings])
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            # Counter-clockwise seen from outside; the degenerate triangles at the poles are
            # left out.
            if r != 0:
                idx += [a, b, a + 1]
            if r != rings - 1:
                idx += [a + 1, b, b + 1]
    return pos, nrm, uv, idx


def checker_ground(x0, x1, z0, z1, tile):
    """Two geometries of ground tiles facing +Y: the light and the dark squares of a checker."""
    light, dark = Geometry(), Geometry()
    nx, nz = round((x1 - x0) / tile), round((z1 - z0) / tile)
    for i in range(nx):
        for j in range(nz):
            a, b = x0 + i * tile, x0 + (i + 1) * tile
            c, d = z0 + j * tile, z0 + (j + 1) * tile
            (light if (i + j) % 2 == 0 else dark).quad(
                [[a, 0, d], [b, 0, d], [b, 0, c], [a, 0, c]], (0, 1, 0))
    return light.parts(), dark.parts()


def striped_wall(x0, x1, height, z, stripe):
    """Two geometries of vertical stripes facing +Z: vertical edges show sideways shifts best."""
    light, dark = Geometry(), Geometry()
    for i in range(round((x1 - x0) / stripe)):
        a, b = x0 + i * stripe, x0 + (i + 1) * stripe
        (light if i % 2 == 0 else dark).quad(
            [[a, 0, z], [b, 0, z], [b, height, z], [a, height, z]], (0, 0, 1))
    return light.parts(), dark.parts()


def quat_mul(p, q):
    px, py, pz, pw = p
    qx, qy, qz, qw = q
    return [pw * qx + px * qw + py * qz - pz * qy, pw * qy + py * qw + pz * qx - px * qz,
            pw * qz + pz * qw + px * qy - py * qx, pw * qw - px * qx - py * qy - pz * qz]


def yaw_pitch(yaw, pitch):
    """Rotation (x, y, z, w) turning -Z by `pitch` about X (up when positive), then `yaw` about
    Y (toward -X when positive): the orientation glTF cameras and lights point along."""
    return quat_mul([0, math.sin(yaw / 2), 0, math.cos(yaw / 2)],
                    [math.sin(pitch / 2), 0, 0, math.cos(pitch / 2)])


def look_from(eye, target):
    d = [t - e for t, e in zip(target, eye)]
    return yaw_pitch(math.atan2(-d[0], -d[2]), math.atan2(d[1], math.hypot(d[0], d[2])))


def clean(q):
    # Rounded so the file reads well; 12 digits are far below float precision.
    return [round(x, 12) + 0.0 for x in q]


def glass(name, ior, roughness=0.0, volume=None, dispersion=None):
    ext = {"KHR_materials_transmission": {"transmissionFactor": 1.0},
           "KHR_materials_ior": {"ior": ior}}
    if volume is not None:
        ext["KHR_materials_volume"] = volume
    if dispersion is not None:
        ext["KHR_materials_dispersion"] = {"dispersion": dispersion}
    # metallicFactor 0: glTF's default metallic 1 would make the glass a mirror in viewers that
    # follow the spec (transmission applies to the dielectric part only).
    return {"name": name,
            "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0,
                                     "roughnessFactor": roughness},
            "extensions": ext}


def opaque(name, color, roughness):
    return {"name": name,
            "pbrMetallicRoughness": {"baseColorFactor": color + [1], "metallicFactor": 0.0,
                                     "roughnessFactor": roughness}}


def main():
    buf = Buffer()
    materials, meshes, nodes = [], [], []

    def add_material(m):
        materials.append(m)
        return len(materials) - 1

    def add_mesh(name, primitive, material):
        meshes.append({"name": name, "primitives": [dict(primitive, material=material)]})
        return len(meshes) - 1

    def add_node(node):
        nodes.append(node)
        return len(nodes) - 1

    # The stage: checkered ground and striped backdrop, two opaque materials each.
    ground_light, ground_dark = checker_ground(-6.0, 6.0, WALL_Z, 3.6, 0.5)
    wall_light, wall_dark = striped_wall(-6.5, 6.5, 3.5, WALL_Z, 0.25)
    stage = []
    for name, geo, color, roughness in (
            ("ground_light", ground_light, [0.80, 0.80, 0.78], 0.8),
            ("ground_dark", ground_dark, [0.12, 0.12, 0.14], 0.8),
            ("backdrop_light", wall_light, [0.92, 0.86, 0.72], 0.9),
            ("backdrop_dark", wall_dark, [0.08, 0.16, 0.45], 0.9)):
        mesh = add_mesh(name, buf.geometry(geo), add_material(opaque(name, color, roughness)))
        stage.append(add_node({"name": name, "mesh": mesh}))

    # Row 1: spheres whose volume is their diameter, lightly attenuated, differing in IOR only.
    sphere_prim = buf.geometry(sphere(SPHERE_RADIUS))
    volume = {"thicknessFactor": 2 * SPHERE_RADIUS, "attenuationDistance": 2.0,
              "attenuationColor": [0.85, 0.93, 1.0]}
    row1 = []
    for x, ior in zip(COLUMNS_X, (1.1, 1.33, 1.5, 2.0)):
        name = f"ior_{ior}"
        mesh = add_mesh(f"sphere {name}", sphere_prim,
                        add_material(glass(name, ior, volume=volume)))
        row1.append(add_node({"name": f"sphere {name}", "mesh": mesh,
                              "translation": [x, SPHERE_RADIUS, 0.0]}))

    # Row 2: slabs, IOR 1.5, one of thin-walled / rough 0.3 / rough 0.6 / dispersion 1.0 each.
    hx, hy, hz = (s / 2 for s in SLAB_SIZE)
    slab_prim = buf.geometry(box(hx, hy, hz))
    slab_volume = {"thicknessFactor": SLAB_SIZE[2]}
    slabs = (glass("thin_walled", 1.5),
             glass("rough_0.3", 1.5, roughness=0.3, volume=slab_volume),
             glass("rough_0.6", 1.5, roughness=0.6, volume=slab_volume),
             glass("dispersion_1.0", 1.5, volume=slab_volume, dispersion=1.0))
    yaw = math.radians(SLAB_YAW_DEG)
    row2 = []
    for x, material in zip(COLUMNS_X, slabs):
        name = material["name"]
        mesh = add_mesh(f"slab {name}", slab_prim, add_material(material))
        row2.append(add_node({"name": f"slab {name}", "mesh": mesh,
                              "translation": [x, hy, 0.0],
                              "rotation": clean([0, math.sin(yaw / 2), 0, math.cos(yaw / 2)])}))

    rows = [add_node({"name": "row 1: spheres by IOR", "translation": [0, 0, FRONT_Z],
                      "children": row1}),
            add_node({"name": "row 2: slabs (thin, rough 0.3, rough 0.6, dispersion)",
                      "translation": [0, 0, BACK_Z], "children": row2})]
    camera = add_node({"name": "camera", "camera": 0, "translation": list(EYE),
                       "rotation": clean(look_from(EYE, TARGET))})
    # From the front left and above, so the objects' shadows and highlights fall to the back
    # right and do not hide the view through them.
    sun = add_node({"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 0}},
                    "rotation": clean(yaw_pitch(math.radians(-30), math.radians(-50)))})

    doc = {
        "asset": {"version": "2.0", "generator": "snell scripts/make_glass_grid.py"},
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior",
                           "KHR_materials_volume", "KHR_materials_dispersion",
                           "KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "sun", "type": "directional", "color": [1.0, 0.97, 0.92],
             "intensity": 1.0}]}},
        "scene": 0,
        "scenes": [{"name": "glass grid", "nodes": stage + rows + [camera, sun]}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"name": "front", "type": "perspective",
                     "perspective": {"yfov": YFOV, "aspectRatio": round(16 / 9, 6),
                                     "znear": 0.1, "zfar": 100.0}}],
    }
    write_gltf(doc, buf, "glass_grid.gltf")


def write_gltf(doc, buf, name):
    """Adds `buf` (accessors, views, the embedded buffer) to `doc` and writes samples/assets/name."""
    doc["accessors"] = buf.accessors
    doc["bufferViews"] = buf.views
    doc["buffers"] = [{"byteLength": len(buf.data),
                       "uri": "data:application/octet-stream;base64,"
                              + base64.b64encode(bytes(buf.data)).decode()}]
    out = Path(__file__).resolve().parent.parent / "samples" / "assets" / name
    out.write_text(json.dumps(doc, indent=1) + "\n")
    print(f"wrote {out} ({out.stat().st_size} bytes)")


if __name__ == "__main__":
    main()
