#!/usr/bin/env python3
"""Writes the project's own glTF models next to this script.

  lighthouse.gltf  a 20 m lighthouse: a grey rock base, a white tower and a red
                   top with a lit lantern; origin at the centre of its base.
                   One embedded base64 buffer, a material per part, and nodes
                   that place the tower and the top (interleaved tower data).
  crate.glb        a 1 m floating wooden crate, origin at its centre: planked
                   faces and edge battens coloured by COLOR_0 (normalised
                   unsigned bytes), no normals (loaders compute them).
  boat.gltf        a 7 m motor workboat, origin on its design waterline:
                   a hard-chine hull fitted to its design displacement, a
                   deck, a wheelhouse with windows and a bow rail; a material
                   per paint, and a "hull" node holding the closed hull
                   volume (boat_model.py has its lines and design numbers).
                   Swell compiles this file in as `builtin:boat`.

Units are metres, +y is up, colours are linear RGB. Deterministic: running it
again gives the same bytes (tests/models/test_make_models.py checks that the
committed files are its output). Needs only the Python standard library:

    python3 assets/models/make_models.py [OUTPUT_FOLDER]

writes them next to this script, or into OUTPUT_FOLDER. After changing
boat.gltf rebuild Swell, which compiles it in as builtin:boat.
"""

import base64
import json
import math
import pathlib
import struct
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the models: the folder is installed as it is
import boat_model  # noqa: E402
import fleet_model  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent

FLOAT, UNSIGNED_BYTE, UNSIGNED_SHORT = 5126, 5121, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


class Gltf:
    """A glTF document being built, with all binary data in one buffer."""

    def __init__(self):
        self.doc = {
            "asset": {"version": "2.0", "generator": "Swell make_models.py"},
            "scene": 0,
            "scenes": [{"nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }
        self.data = bytearray()

    def view(self, payload, target=None, stride=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if target:
            view["target"] = target
        if stride:
            view["byteStride"] = stride
        self.data += payload
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, view, component_type, count, kind, offset=0, normalized=False, bounds=None):
        a = {"bufferView": view, "componentType": component_type, "count": count, "type": kind}
        if offset:
            a["byteOffset"] = offset
        if normalized:
            a["normalized"] = True
        if bounds:
            a["min"], a["max"] = bounds
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def material(self, name, rgb):
        self.doc["materials"].append({
            "name": name,
            "pbrMetallicRoughness": {"baseColorFactor": [round(c, 4) for c in rgb] + [1.0],
                                     "metallicFactor": 0.0, "roughnessFactor": 0.8},
        })
        return len(self.doc["materials"]) - 1

    def node(self, name, mesh=None, translation=None, children=None, extras=None):
        n = {"name": name}
        if extras:
            n["extras"] = extras
        if mesh is not None:
            n["mesh"] = mesh
        if translation:
            n["translation"] = translation
        if children:
            n["children"] = children
        self.doc["nodes"].append(n)
        return len(self.doc["nodes"]) - 1

    def mesh(self, name, primitives):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        return len(self.doc["meshes"]) - 1

    def positions_normals(self, verts, interleaved=False):
        """Accessors for POSITION and NORMAL of (position, normal) pairs."""
        bounds = bounds_of([p for p, _ in verts])
        if interleaved:
            view = self.view(b"".join(struct.pack("<6f", *p, *n) for p, n in verts), ARRAY_BUFFER, 24)
            return (self.accessor(view, FLOAT, len(verts), "VEC3", bounds=bounds),
                    self.accessor(view, FLOAT, len(verts), "VEC3", offset=12))
        pv = self.view(b"".join(struct.pack("<3f", *p) for p, _ in verts), ARRAY_BUFFER)
        nv = self.view(b"".join(struct.pack("<3f", *n) for _, n in verts), ARRAY_BUFFER)
        return (self.accessor(pv, FLOAT, len(verts), "VEC3", bounds=bounds),
                self.accessor(nv, FLOAT, len(verts), "VEC3"))

    def indices(self, tris):
        flat = [i for t in tris for i in t]
        view = self.view(struct.pack("<%dH" % len(flat), *flat), ELEMENT_ARRAY_BUFFER)
        return self.accessor(view, UNSIGNED_SHORT, len(flat), "SCALAR")


def bounds_of(points):
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    return [round(v, 5) for v in lo], [round(v, 5) for v in hi]


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v) if length > 0 else (0.0, 1.0, 0.0)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def lathe(profile, segments, wobble=None):
    """A surface of revolution about +y from (radius, height) profile points.
    Each profile segment is its own band, so edges between bands stay sharp;
    normals are smooth around each band. wobble(angle, height) scales the
    radius, for rough shapes."""
    verts, tris = [], []
    for (r0, y0), (r1, y1) in zip(profile, profile[1:]):
        # Outward direction of the band in the profile plane, to orient faces.
        length = math.hypot(r1 - r0, y1 - y0)
        radial, up = (y1 - y0) / length, -(r1 - r0) / length
        base = len(verts)
        points = []
        for r, y in ((r0, y0), (r1, y1)):
            for s in range(segments):
                a = 2 * math.pi * s / segments
                k = wobble(a, y) if wobble else 1.0
                points.append((r * k * math.cos(a), y, r * k * math.sin(a)))
        band = []
        for s in range(segments):
            t = (s + 1) % segments
            a, b, c, d = s, t, segments + s, segments + t
            if r0 > 0:
                band.append((a, c, b))
            if r1 > 0:
                band.append((b, c, d))
        angle = lambda i: 2 * math.pi * (i % segments) / segments
        oriented = []
        for tri in band:
            p0, p1, p2 = (points[i] for i in tri)
            mid = angle(tri[0])
            expected = (radial * math.cos(mid), up, radial * math.sin(mid))
            oriented.append(tri if dot(cross(sub(p1, p0), sub(p2, p0)), expected) >= 0 else (tri[0], tri[2], tri[1]))
        # Area-weighted normals; a ring at radius 0 is one point, so share it.
        sums = [[0.0, 0.0, 0.0] for _ in points]
        key = lambda i: (i // segments) * segments if (r0, r1)[i // segments] == 0 else i
        for tri in oriented:
            p0, p1, p2 = (points[i] for i in tri)
            n = cross(sub(p1, p0), sub(p2, p0))
            for i in tri:
                for k in range(3):
                    sums[key(i)][k] += n[k]
        for i, p in enumerate(points):
            verts.append((tuple(round(c, 5) for c in p), normalize(sums[key(i)])))
        tris += [tuple(base + i for i in tri) for tri in oriented]
    return verts, tris


def rock_wobble(angle, y):
    """Deterministic lumps: a few sines around, fading towards the top."""
    bumps = 0.10 * math.sin(3 * angle + 0.7) + 0.06 * math.sin(7 * angle + 2.1) + 0.04 * math.sin(11 * angle)
    return 1.0 + bumps * (1.0 - 0.3 * y / 2.0)


def lighthouse():
    g = Gltf()
    rock_mat = g.material("rock", (0.30, 0.28, 0.26))
    white_mat = g.material("whitewash", (0.85, 0.85, 0.82))
    red_mat = g.material("red paint", (0.60, 0.04, 0.03))
    lamp_mat = g.material("lantern glass", (0.95, 0.85, 0.45))

    def primitive(profile, segments, material, wobble=None, interleaved=False):
        verts, tris = lathe(profile, segments, wobble)
        pos, nrm = g.positions_normals(verts, interleaved)
        return {"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": g.indices(tris), "material": material}

    # Rock base, 0..2 m: a rough flat-topped mound.
    rock = g.mesh("rock", [primitive([(0.0, 0.0), (4.6, 0.0), (4.3, 0.7), (3.6, 1.5), (2.6, 2.0), (0.0, 2.0)],
                                     20, rock_mat, rock_wobble)])
    # Tower, 13 m from the rock's top; a slight taper and a plinth ring.
    tower = g.mesh("tower", [primitive([(2.1, 0.0), (2.1, 0.4), (1.9, 0.5), (1.6, 7.0), (1.35, 13.0)],
                                       24, white_mat, interleaved=True)])
    # The top, 5 m: a red gallery deck, the lantern room, a red roof and vent.
    top = g.mesh("top", [
        primitive([(0.0, 0.0), (2.0, 0.0), (2.0, 0.3), (1.05, 0.3)], 24, red_mat),
        primitive([(1.05, 0.3), (1.05, 2.3)], 16, lamp_mat),
        primitive([(1.3, 2.3), (1.3, 2.5), (0.25, 4.4), (0.3, 4.6), (0.0, 5.0)], 16, red_mat),
    ])
    rock_node = g.node("rock", mesh=rock)
    tower_node = g.node("tower", mesh=tower, translation=[0.0, 2.0, 0.0])
    top_node = g.node("top", mesh=top, translation=[0.0, 15.0, 0.0])
    root = g.node("lighthouse", children=[rock_node, tower_node, top_node])
    g.doc["scenes"][0]["nodes"] = [root]
    g.doc["buffers"].append({
        "byteLength": len(g.data),
        "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(g.data)).decode("ascii"),
    })
    return json.dumps(g.doc, indent=1).encode("utf-8") + b"\n"


def quad(axis, sign, lo, hi, color):
    """The face of box lo..hi facing sign along axis: 4 vertices, 2 triangles,
    counter-clockwise seen from outside."""
    u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
    verts = []
    for u, v in ((0, 0), (1, 0), (1, 1), (0, 1)):
        p = [0.0, 0.0, 0.0]
        p[axis] = hi[axis] if sign > 0 else lo[axis]
        p[u_axis] = hi[u_axis] if u else lo[u_axis]
        p[v_axis] = hi[v_axis] if v else lo[v_axis]
        verts.append(tuple(p))
    # u_axis x v_axis points along +axis.
    tris = [(0, 1, 2), (0, 2, 3)] if sign > 0 else [(0, 2, 1), (0, 3, 2)]
    return verts, [color] * 4, tris


def crate():
    planks = [(0.42, 0.27, 0.13), (0.36, 0.22, 0.10), (0.45, 0.30, 0.15), (0.38, 0.24, 0.11)]
    batten = (0.26, 0.16, 0.07)
    verts, colors, tris = [], [], []

    def add(part):
        v, c, t = part
        base = len(verts)
        verts.extend(v)
        colors.extend(c)
        tris.extend(tuple(base + i for i in tri) for tri in t)

    # The body, 94 cm, just inside the battens: each face is 4 planks.
    h = 0.47
    for axis in range(3):
        for sign in (-1, 1):
            v_axis = (axis + 2) % 3
            for k in range(4):
                lo, hi = [-h] * 3, [h] * 3
                lo[v_axis], hi[v_axis] = -h + 2 * h * k / 4, -h + 2 * h * (k + 1) / 4
                add(quad(axis, sign, lo, hi, planks[(k + axis) % 4]))
    # Battens along the 12 edges, 8 cm square, flush with the 1 m outline.
    w = 0.08
    for axis in range(3):
        a1, a2 = (axis + 1) % 3, (axis + 2) % 3
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                lo, hi = [0.0] * 3, [0.0] * 3
                lo[axis], hi[axis] = -0.5, 0.5
                lo[a1], hi[a1] = (0.5 - w, 0.5) if s1 > 0 else (-0.5, -0.5 + w)
                lo[a2], hi[a2] = (0.5 - w, 0.5) if s2 > 0 else (-0.5, -0.5 + w)
                for face_axis in range(3):
                    for sign in (-1, 1):
                        add(quad(face_axis, sign, lo, hi, batten))

    g = Gltf()
    pos_view = g.view(b"".join(struct.pack("<3f", *p) for p in verts), ARRAY_BUFFER)
    pos = g.accessor(pos_view, FLOAT, len(verts), "VEC3", bounds=bounds_of(verts))
    col_view = g.view(b"".join(bytes(round(255 * x) for x in c) + b"\xff" for c in colors), ARRAY_BUFFER)
    col = g.accessor(col_view, UNSIGNED_BYTE, len(colors), "VEC4", normalized=True)
    mesh = g.mesh("crate", [{"attributes": {"POSITION": pos, "COLOR_0": col}, "indices": g.indices(tris)}])
    g.doc["scenes"][0]["nodes"] = [g.node("crate", mesh=mesh)]
    del g.doc["materials"]
    g.doc["buffers"].append({"byteLength": len(g.data)})

    text = json.dumps(g.doc, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    data = bytes(g.data) + b"\0" * (-len(g.data) % 4)
    total = 12 + 8 + len(text) + 8 + len(data)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text +
            struct.pack("<I4s", len(data), b"BIN\0") + data)


def creased_normals(tris, crease_deg=30.0):
    """Indexed vertices with normals for a triangle soup: each corner's
    normal is the area-weighted sum of the faces at its position that turn
    less than crease_deg from its own face, so panels stay smooth along
    their length and a chine or a box's edge stays sharp."""
    key = lambda p: tuple(round(c, 5) + 0.0 for c in p)
    faces = [cross(sub(t[1], t[0]), sub(t[2], t[0])) for t in tris]
    at = {}
    for f, t in zip(faces, tris):
        for p in t:
            at.setdefault(key(p), []).append(f)
    limit = math.cos(math.radians(crease_deg))
    verts, index, out = [], {}, []
    for f, t in zip(faces, tris):
        unit = normalize(f)
        corners = []
        for p in t:
            total = [0.0, 0.0, 0.0]
            for g in at[key(p)]:
                if dot(normalize(g), unit) >= limit:
                    total = [total[k] + g[k] for k in range(3)]
            n = tuple(round(c, 5) + 0.0 for c in normalize(total))
            v = (key(p), n)
            if v not in index:
                index[v] = len(verts)
                verts.append(v)
            corners.append(index[v])
        out.append(tuple(corners))
    return verts, out


def welded(tris):
    """Indexed vertices for a closed surface: corners at one position share
    one vertex, so its edges are shared as indices too."""
    key = lambda p: tuple(round(c, 5) + 0.0 for c in p)
    verts, index, out = [], {}, []
    for t in tris:
        corners = []
        for p in t:
            k = key(p)
            if k not in index:
                index[k] = len(verts)
                verts.append(k)
            corners.append(index[k])
        out.append(tuple(corners))
    return verts, out


def boat():
    hull, parts = boat_model.parts()
    g = Gltf()
    materials = {name: g.material(name, rgb) for name, rgb in boat_model.COLORS.items()}
    children = []
    for node_name, prims in parts:
        primitives = []
        for material, tris in prims:
            if node_name == "hull":
                # The hull volume: never drawn, only positions (welded) matter.
                points, indices = welded(tris)
                view = g.view(b"".join(struct.pack("<3f", *p) for p in points), ARRAY_BUFFER)
                pos = g.accessor(view, FLOAT, len(points), "VEC3", bounds=bounds_of(points))
                primitives.append({"attributes": {"POSITION": pos}, "indices": g.indices(indices)})
                continue
            verts, indices = creased_normals(tris)
            pos, nrm = g.positions_normals(verts)
            primitives.append({"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": g.indices(indices),
                               "material": materials[material]})
        children.append(g.node(node_name, mesh=g.mesh(node_name, primitives)))
    design = dict(boat_model.DESIGN)
    design["center_of_mass_m"] = [round(c, 4) for c in boat_model.level_trim_center_of_mass(hull)]
    root = g.node("boat", children=children, extras=design)
    g.doc["scenes"][0]["nodes"] = [root]
    g.doc["buffers"].append({
        "byteLength": len(g.data),
        "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(g.data)).decode("ascii"),
    })
    return json.dumps(g.doc, indent=1).encode("utf-8") + b"\n"


def fleet_file(model):
    """One of the fleet (fleet_model.py): its root named after its class,
    with its design numbers in extras, the node "hull" its closed volume, a
    node per part, a material per paint."""
    g = Gltf()
    materials = {name: g.material(name, rgb) for name, rgb in model.colors.items()}
    children = []
    points, indices = welded(model.hull_tris)
    view = g.view(b"".join(struct.pack("<3f", *p) for p in points), ARRAY_BUFFER)
    pos = g.accessor(view, FLOAT, len(points), "VEC3", bounds=bounds_of(points))
    children.append(g.node("hull", mesh=g.mesh("hull", [{"attributes": {"POSITION": pos},
                                                         "indices": g.indices(indices)}])))
    drawn = 0
    for node_name, parts in model.nodes.items():
        primitives = []
        for material, tris in parts.items():
            if not tris:
                continue
            verts, idx = creased_normals(tris)
            pos, nrm = g.positions_normals(verts)
            primitives.append({"attributes": {"POSITION": pos, "NORMAL": nrm}, "indices": g.indices(idx),
                               "material": materials[material]})
            drawn += len(idx)
        children.append(g.node(node_name, mesh=g.mesh(node_name, primitives)))
    design = model.design()
    design["drawn_triangles"] = drawn
    root = g.node(model.name, children=children, extras=design)
    g.doc["scenes"][0]["nodes"] = [root]
    g.doc["buffers"].append({
        "byteLength": len(g.data),
        "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(g.data)).decode("ascii"),
    })
    return json.dumps(g.doc, separators=(",", ":")).encode("utf-8") + b"\n", design


def main(folder=HERE):
    folder = pathlib.Path(folder)
    for name, content in (("lighthouse.gltf", lighthouse()), ("crate.glb", crate()), ("boat.gltf", boat())):
        (folder / name).write_bytes(content)
        print("%s: %d bytes" % (name, len(content)))
    (folder / "fleet").mkdir(exist_ok=True)
    for model in fleet_model.models():
        content, design = fleet_file(model)
        (folder / "fleet" / (model.name + ".gltf")).write_bytes(content)
        print("fleet/%s.gltf: %d bytes, %d drawn triangles, %.2f m x %.2f m, draft %.2f m, %.0f kg"
              % (model.name, len(content), design["drawn_triangles"], design["length_m"], design["beam_m"],
                 design["draft_m"], design["displacement_kg"]))
    mass, offset = boat_model.scene_keys(boat_model.fit_hull())
    print("boat.gltf floats level at its waterline with mass_kg = %.1f, center_of_mass_offset_m = %s"
          % (mass, offset))


if __name__ == "__main__":
    main(*sys.argv[1:2])
