"""The fleet: Swell's built-in vessels and navigation marks, each written by
make_models.py to fleet/NAME.gltf and compiled in as `builtin:NAME`.

Every model is drawn at its design size, its origin on its design waterline
(half way along a vessel's overall length, on a buoy's axis), with:

- a root node named after the class whose `extras` hold the design numbers:
  length_m and beam_m (of the hull volume), draft_m (its lowest point below
  the waterline: the keel, a yacht's fin, a buoy's float bottom),
  displacement_kg (the sea water the hull volume displaces below the
  waterline, computed here from the mesh) and center_of_mass_m (above the
  centre of buoyancy, at a height low enough that the metacentric height
  GM = KB + BM - KG stays positive down to 0.75 of the design beam, where BM,
  the waterplane's second moment over the volume, falls with the beam
  squared: a yacht's and a buoy's ballast low, the ships' 0.5 to 2 m under
  the waterline), so that a rigid body of that mass there floats level with
  its origin on the water;
- a node "hull": the closed hull volume (never drawn; the body's shape);
- materials named "hull" (the topsides' or a buoy's body's paint) and
  "superstructure", which a scene may recolour (hull_color,
  superstructure_color), and a node "superstructure" it may leave out
  (superstructure = false): a wheelhouse, deckhouse or coachroof, a
  kayak's paddler, a buoy's topmark.

The library stretches a model along its length and beam (length_m, beam_m)
keeping its draft; the mass that floats it at that draft then scales with
length times beam (docs/BODIES.md, "The fleet").

IALA marks are drawn for region A (IALA Maritime Buoyage System, 1980: port
hand red with a can topmark, starboard hand green with a cone point up; the
north cardinal black above yellow, two black cones points up).
"""

import math

from fleet_hull import Lines, bar, box_tris, displacement, lathe_tris, translated
import boat_model

# Linear RGB paints; each model uses some of them by name.
PAINT = {
    "antifouling red": (0.30, 0.035, 0.025),
    "antifouling blue": (0.02, 0.05, 0.16),
    "boot-top": (0.015, 0.015, 0.018),
    "white": (0.80, 0.80, 0.78),
    "deck grey": (0.30, 0.31, 0.30),
    "teak": (0.38, 0.24, 0.12),
    "glass": (0.015, 0.025, 0.035),
    "steel": (0.45, 0.46, 0.48),
    "black": (0.02, 0.02, 0.02),
    "rubber": (0.03, 0.03, 0.03),
    "red": (0.60, 0.03, 0.02),
    "green": (0.02, 0.30, 0.06),
    "yellow": (0.75, 0.55, 0.02),
    "orange": (0.80, 0.22, 0.02),
    "skin": (0.55, 0.32, 0.20),
}


class Model:
    """One class's parts as (node, [(material, triangles)]), its materials'
    colours, and its design centre of mass height."""

    def __init__(self, name, hull_tris, center_of_mass_height_m, colors):
        self.name = name
        self.hull_tris = hull_tris
        self.com_height_m = center_of_mass_height_m
        self.colors = dict(colors)  # material name -> rgb; "hull" and "superstructure" among them
        self.nodes = {}  # node name -> {material: triangles}, in insertion order

    def add(self, node, material, tris):
        self.colors.setdefault(material, PAINT.get(material, (0.5, 0.5, 0.5)))
        self.nodes.setdefault(node, {}).setdefault(material, []).extend(tris)

    def design(self):
        xs = [p[0] for t in self.hull_tris for p in t]
        ys = [p[1] for t in self.hull_tris for p in t]
        zs = [p[2] for t in self.hull_tris for p in t]
        mass, centre = displacement(self.hull_tris)
        return {
            "length_m": round(max(xs) - min(xs), 4),
            "beam_m": round(max(zs) - min(zs), 4),
            "draft_m": round(-min(ys), 4),
            "displacement_kg": round(mass, 2),
            "center_of_mass_m": [round(centre[0], 4), self.com_height_m, 0.0],
        }


def painted_hull(model, lines, boot_top_m, antifouling):
    """The hull's skin in bands: antifouling up to boot_top_m[0], the boot-top
    stripe, the topsides in "hull"; the deck."""
    below, stripe, topsides = boat_model.bands(lines.skin(), boot_top_m)
    model.add("hull skin", antifouling, below)
    model.add("hull skin", "boot-top", stripe)
    model.add("hull skin", "hull", topsides)


def deckhouse(x0, x1, floor, top, half_aft, half_fore, windows=0.0):
    """A box deckhouse from x0 to x1 (aft to fore), narrower forward; with a
    band of windows `windows` m deep under its roof. Returns (walls, glass)."""
    walls = []
    c = [((x0 if fx == 0 else x1), y, side * (half_aft if fx == 0 else half_fore))
         for fx in (0, 1) for y in (floor, top) for side in (-1, 1)]
    centre = ((x0 + x1) / 2, (floor + top) / 2, 0.0)
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    for f in faces:
        walls += boat_model.quad_tris(*(c[k] for k in f))
    walls = boat_model.orient_outwards(walls, centre)
    glass = []
    if windows > 0:
        lo, hi = top - windows - 0.15 * windows, top - 0.15 * windows
        for side in (-1, 1):
            q = [(x0 + 0.1 * (x1 - x0), lo, side * (half_aft + 0.01)), (x1 - 0.1 * (x1 - x0), lo, side * (half_fore + 0.01)),
                 (x1 - 0.1 * (x1 - x0), hi, side * (half_fore + 0.01)), (x0 + 0.1 * (x1 - x0), hi, side * (half_aft + 0.01))]
            glass += boat_model.facing(boat_model.quad_tris(*q), (0.0, 0.0, side))
        q = [(x1 + 0.01, lo, -0.85 * half_fore), (x1 + 0.01, lo, 0.85 * half_fore),
             (x1 + 0.01, hi, 0.85 * half_fore), (x1 + 0.01, hi, -0.85 * half_fore)]
        glass += boat_model.facing(boat_model.quad_tris(*q), (1.0, 0.0, 0.0))
    return walls, glass


def box(center, half):
    return box_tris(center, half)


# ---------------------------------------------------------------------------
# Vessels

def sailing_yacht():
    lines = Lines(11.0, 3.5, 0.50, 0.95, 1.20, n=2.2, stern=0.62, mid=(0.35, 0.45), run=1.6, entrance=1.5,
                  flare=1.08, rake_m=1.2, forefoot=0.05, stern_draft=0.25, stations=32)
    # The fin keel, a slab under the canoe body amidships, with a bulb: the
    # ballast that keeps its centre of mass low.
    fin = box((-0.3, -1.20, 0.0), (0.55, 0.70, 0.06))
    bulb = box((-0.4, -1.82, 0.0), (0.85, 0.12, 0.16))
    m = Model("sailing_yacht", lines.closed() + fin + bulb, -0.45, {"hull": PAINT["white"],
                                                                    "superstructure": PAINT["white"]})
    painted_hull(m, lines, (0.04, 0.10), "antifouling blue")
    m.add("hull skin", "antifouling blue", fin + bulb)
    m.add("deck", "teak", lines.deck())
    m.add("hull skin", "antifouling blue", box((-5.0, -0.45, 0.0), (0.25, 0.45, 0.03)))  # rudder
    deck_y, half = lines.deck_at(0.0)
    walls, glass = deckhouse(-2.2, 1.6, deck_y - 0.05, deck_y + 0.45, 1.15, 0.95, windows=0.18)
    m.add("superstructure", "superstructure", walls)
    m.add("superstructure", "glass", glass)
    # The rig: a 15 m mast stepped on the coachroof, a boom, forestay and backstay.
    top = deck_y + 15.0
    m.add("rig", "steel", bar((0.9, deck_y, 0.0), (0.9, top, 0.0), 0.08))
    m.add("rig", "steel", bar((0.9, deck_y + 1.6, 0.0), (-3.6, deck_y + 1.3, 0.0), 0.06))
    m.add("rig", "steel", bar((0.9, top - 0.3, 0.0), (lines.x_at(1.0, lines.sheer(1.0)), lines.sheer(1.0), 0.0), 0.012))
    m.add("rig", "steel", bar((0.9, top - 0.3, 0.0), (-5.4, lines.sheer(0.0), 0.0), 0.012))
    for side in (-1, 1):
        m.add("rig", "steel", bar((0.9, top - 4.0, 0.0), (0.7, deck_y, side * (half - 0.1)), 0.01))
    return m


def rib():
    lines = Lines(6.5, 2.0, 0.38, 0.55, 0.85, n=1.0, stern=0.92, mid=(0.2, 0.5), run=2.0, entrance=1.6, flare=1.04,
                  rake_m=0.5, forefoot=0.25, stations=28)
    m = Model("rib", lines.closed(), 0.05, {"hull": PAINT["white"], "superstructure": PAINT["deck grey"],
                                            "tube": (0.22, 0.23, 0.24)})
    painted_hull(m, lines, (0.02, 0.06), "antifouling blue")
    m.add("deck", "deck grey", translated(lines.deck(), (0.0, -0.30, 0.0)))
    # The tubes: round along each side at the sheer, joined round the bow,
    # open at the stern. Drawn only: they float the boat when it heels, which
    # the hull volume leaves out.
    r = 0.24
    path = []
    for i in range(0, lines.stations + 1):
        u = i / lines.stations
        if u > 0.93:
            break
        y = lines.sheer(u) - 0.05
        path.append((lines.x_at(u, y), y, lines.sheer_half_breadth(u) + 0.12))
    tip = (lines.x_at(1.0, lines.sheer(1.0)) - 0.1, lines.sheer(1.0) - 0.05, 0.0)
    for side in (-1, 1):
        pts = [(p[0], p[1], side * p[2]) for p in path] + [tip]
        for p, q in zip(pts, pts[1:]):
            m.add("tubes", "tube", tube(p, q, r, 8))
    deck_y, _ = lines.deck_at(0.0)
    walls, glass = deckhouse(-0.6, 0.2, deck_y - 0.3, deck_y + 0.65, 0.45, 0.40)
    m.add("superstructure", "superstructure", walls)
    m.add("superstructure", "glass", box((0.25, deck_y + 0.8, 0.0), (0.04, 0.18, 0.38)))  # windscreen
    # An A-frame aft with a radar on it.
    for side in (-1, 1):
        m.add("superstructure", "steel", bar((-2.7, deck_y - 0.3, side * 0.7), (-2.4, deck_y + 1.6, side * 0.6), 0.03))
    m.add("superstructure", "steel", bar((-2.4, deck_y + 1.6, -0.6), (-2.4, deck_y + 1.6, 0.6), 0.03))
    m.add("superstructure", "white", box((-2.4, deck_y + 1.72, 0.0), (0.2, 0.1, 0.2)))
    # An outboard on the transom.
    m.add("hull skin", "black", box((-3.45, 0.35, 0.0), (0.25, 0.45, 0.2)))
    return m


def tube(p, q, r, sides):
    """A closed tube of radius r from p to q (a RIB's side tube)."""
    d = boat_model.sub(q, p)
    axis = boat_model.normalize(d)
    side = boat_model.normalize(boat_model.cross(axis, (0.0, 1.0, 0.0)))
    up = boat_model.cross(side, axis)
    ring = lambda c: [tuple(c[k] + r * (math.cos(2 * math.pi * s / sides) * side[k] +
                                        math.sin(2 * math.pi * s / sides) * up[k]) for k in range(3))
                      for s in range(sides)]
    a, b = ring(p), ring(q)
    tris = []
    for s in range(sides):
        t = (s + 1) % sides
        tris += boat_model.quad_tris(a[s], a[t], b[t], b[s])
    tris += [(p, a[(s + 1) % sides], a[s]) for s in range(sides)] + [(q, b[s], b[(s + 1) % sides]) for s in range(sides)]
    return boat_model.orient_outwards(tris, tuple((p[k] + q[k]) / 2 for k in range(3)))


def fishing_trawler():
    lines = Lines(18.0, 6.0, 2.2, 1.5, 2.6, n=3.0, stern=0.75, mid=(0.35, 0.5), run=2.0, entrance=1.5, flare=1.06,
                  rake_m=1.5, forefoot=0.35, stations=32)
    m = Model("fishing_trawler", lines.closed(), -0.45, {"hull": (0.02, 0.09, 0.25),
                                                        "superstructure": PAINT["white"]})
    painted_hull(m, lines, (0.10, 0.30), "antifouling red")
    m.add("deck", "deck grey", lines.deck())
    deck_y, half = lines.deck_at(3.0)
    walls, glass = deckhouse(1.5, 5.0, deck_y, deck_y + 2.6, 2.0, 1.9, windows=0.8)
    m.add("superstructure", "superstructure", walls)
    m.add("superstructure", "glass", glass)
    m.add("superstructure", "superstructure", box((3.2, deck_y + 2.65, 0.0), (2.0, 0.06, 2.15)))  # roof
    m.add("superstructure", "steel", bar((2.5, deck_y + 2.7, 0.0), (2.5, deck_y + 6.5, 0.0), 0.08))  # mast
    # The gantry over the stern: two legs and a beam, with the trawl's blocks.
    aft_y, aft_half = lines.deck_at(-8.0)
    for side in (-1, 1):
        m.add("gantry", "orange", bar((-8.4, aft_y, side * (aft_half - 0.3)), (-8.2, aft_y + 5.0, side * (aft_half - 0.5)),
                                      0.15))
        m.add("gantry", "steel", box((-8.2, aft_y + 4.6, side * 1.2), (0.2, 0.3, 0.15)))
    m.add("gantry", "orange", bar((-8.2, aft_y + 5.0, -(aft_half - 0.5)), (-8.2, aft_y + 5.0, aft_half - 0.5), 0.15))
    # The net drum and winch forward of it.
    m.add("gantry", "green", box((-5.5, aft_y + 0.6, 0.0), (0.6, 0.6, 1.6)))
    m.add("hull skin", "hull", bulwark(lines, 0.8, 0.6))
    return m


def bulwark(lines, height_m, last_u):
    """A bulwark along each side at the sheer up to last_u of the length."""
    tris = []
    us = [i / lines.stations for i in range(lines.stations + 1) if i / lines.stations <= last_u]
    for u0, u1 in zip(us, us[1:]):
        a = (lines.x_at(u0, lines.sheer(u0)), lines.sheer(u0), lines.sheer_half_breadth(u0))
        b = (lines.x_at(u1, lines.sheer(u1)), lines.sheer(u1), lines.sheer_half_breadth(u1))
        q = [a, b, (b[0], b[1] + height_m, b[2]), (a[0], a[1] + height_m, a[2])]
        for side in (1, -1):
            f = (lambda p: p) if side > 0 else boat_model.mirror
            quad = boat_model.quad_tris(*(f(p) for p in q))
            tris += boat_model.facing(quad, (0.0, 0.0, side))
            tris += boat_model.facing([(t[0], t[2], t[1]) for t in quad], (0.0, 0.0, -side))
    return tris


def tug():
    lines = Lines(24.0, 9.0, 3.4, 1.4, 2.8, n=3.0, stern=0.85, mid=(0.3, 0.45), run=2.0, entrance=1.4, flare=1.08,
                  rake_m=1.2, forefoot=0.4, stations=32)
    m = Model("tug", lines.closed(), -0.7, {"hull": (0.01, 0.01, 0.012), "superstructure": PAINT["white"]})
    painted_hull(m, lines, (0.10, 0.45), "antifouling red")
    m.add("deck", "deck grey", lines.deck())
    m.add("hull skin", "red", bulwark(lines, 1.0, 1.0))
    # Fenders: a thick black rubbing band all round at the sheer.
    m.add("hull skin", "rubber", band(lines, lines.sheer(0.5) - 0.5, 0.45))
    deck_y, _ = lines.deck_at(3.0)
    walls, glass = deckhouse(-1.0, 7.5, deck_y, deck_y + 2.6, 3.2, 2.8)
    m.add("superstructure", "superstructure", walls)
    walls, glass = deckhouse(1.5, 6.0, deck_y + 2.6, deck_y + 5.2, 2.4, 2.4, windows=1.2)
    m.add("superstructure", "superstructure", walls)
    m.add("superstructure", "glass", glass)
    m.add("superstructure", "superstructure", box((3.75, deck_y + 5.25, 0.0), (2.6, 0.06, 2.9)))
    for side in (-1, 1):  # the funnels
        m.add("superstructure", "black", box((0.0, deck_y + 3.8, side * 1.8), (0.5, 1.2, 0.4)))
    m.add("superstructure", "steel", bar((4.5, deck_y + 5.3, 0.0), (4.5, deck_y + 9.0, 0.0), 0.1))
    # The towing hook aft.
    m.add("superstructure", "steel", box((-6.0, deck_y + 1.2, 0.0), (0.3, 1.2, 0.3)))
    return m


def band(lines, y, depth):
    """A rubbing band: the skin between y and y + depth, pushed out 0.15 m."""
    tris = []
    for tri in boat_model.bands(lines.skin(), (y, y + depth))[1]:
        tris.append(tuple((p[0], p[1], p[2] * 1.0 + math.copysign(0.15, p[2]) if abs(p[2]) > 1e-6 else p[2])
                          for p in tri))
    return tris


def container_ship():
    """A 180 m feeder container ship at full size: 28 m beam, 9 m draft."""
    lines = Lines(180.0, 28.0, 9.0, 7.0, 9.0, n=6.0, stern=0.55, mid=(0.3, 0.6), run=1.8, entrance=1.6, flare=1.02,
                  rake_m=8.0, forefoot=0.5, stations=40)
    m = Model("container_ship", lines.closed(), -1.0, {"hull": (0.02, 0.04, 0.09), "superstructure": PAINT["white"]})
    painted_hull(m, lines, (0.5, 2.0), "antifouling red")
    m.add("deck", "deck grey", lines.deck())
    # The accommodation block and bridge aft, with its wings.
    deck_y, half = lines.deck_at(-65.0)
    walls, glass = deckhouse(-76.0, -64.0, deck_y, deck_y + 18.0, 9.0, 9.0, windows=2.0)
    m.add("superstructure", "superstructure", walls)
    m.add("superstructure", "glass", glass)
    m.add("superstructure", "superstructure", box((-66.0, deck_y + 17.0, 0.0), (2.0, 0.8, half)))
    m.add("superstructure", "black", box((-73.0, deck_y + 21.0, 0.0), (2.5, 3.0, 2.0)))  # funnel
    # Containers: bays of 40 ft boxes (12.2 x 2.44 x 2.59 m), a stack each,
    # from the block to the bow, as high as the bridge's view allows.
    palette = [(0.45, 0.05, 0.03), (0.03, 0.12, 0.35), (0.50, 0.50, 0.48), (0.05, 0.25, 0.08),
               (0.55, 0.30, 0.03), (0.20, 0.20, 0.22)]
    for c, rgb in enumerate(palette):
        m.colors["container %d" % c] = rgb
    x, bay = -61.0, 0
    while x + 12.2 < 70.0:
        deck_y, half = lines.deck_at(x + 6.1)
        _, half_fore = lines.deck_at(x + 12.2)
        across = int((2 * min(half, half_fore) - 1.5) // 2.5)
        for k in range(across):
            z = (k - (across - 1) / 2) * 2.5
            tiers = 3 + (bay * 7 + k * 3) % 3
            colour = (bay * 5 + k * 11 + (k * k) % 7) % len(palette)
            m.add("cargo", "container %d" % colour,
                  box((x + 6.1, deck_y + 0.3 + tiers * 1.295, z), (6.05, tiers * 1.295, 1.2)))
        x += 12.8
        bay += 1
    return m


def tanker():
    """A 150 m product tanker at full size: 24 m beam, 9.5 m draft."""
    lines = Lines(150.0, 24.0, 9.5, 4.5, 7.0, n=8.0, stern=0.6, mid=(0.25, 0.65), run=1.8, entrance=1.8, flare=1.0,
                  rake_m=5.0, forefoot=0.55, stations=40)
    m = Model("tanker", lines.closed(), -2.2, {"hull": (0.03, 0.03, 0.035), "superstructure": PAINT["white"]})
    painted_hull(m, lines, (0.5, 1.6), "antifouling red")
    m.add("deck", "red", lines.deck())
    deck_y, half = lines.deck_at(-60.0)
    walls, glass = deckhouse(-70.0, -58.0, deck_y, deck_y + 15.0, 8.0, 8.0, windows=2.0)
    m.add("superstructure", "superstructure", walls)
    m.add("superstructure", "glass", glass)
    m.add("superstructure", "superstructure", box((-59.5, deck_y + 14.0, 0.0), (1.5, 0.6, half)))
    m.add("superstructure", "black", box((-67.0, deck_y + 17.0, 0.0), (2.0, 2.5, 1.6)))
    # The catwalk and cargo pipes along the centreline, the manifold
    # amidships, a mast forward.
    y = lines.deck_at(0.0)[0]
    m.add("pipes", "steel", box((5.0, y + 1.6, 0.0), (60.0, 0.15, 0.6)))
    for z in (-2.0, -1.4, 1.4, 2.0):
        m.add("pipes", "green", bar((-55.0, y + 0.6, z), (65.0, y + 0.6, z), 0.25))
    m.add("pipes", "green", box((0.0, y + 1.2, 0.0), (1.5, 1.2, 9.0)))
    m.add("pipes", "steel", bar((66.0, lines.deck_at(66.0)[0], 0.0), (66.0, lines.deck_at(66.0)[0] + 12.0, 0.0), 0.3))
    return m


def kayak():
    lines = Lines(4.8, 0.62, 0.12, 0.24, 0.30, n=2.0, stern=0.0, mid=(0.45, 0.5), run=1.6, entrance=1.5, flare=1.0,
                  rake_m=0.25, forefoot=0.35, stern_draft=0.35, stations=28, below_rows=4, above_rows=1)
    m = Model("kayak", lines.closed(), 0.03, {"hull": (0.85, 0.40, 0.01), "superstructure": (0.02, 0.10, 0.45)})
    painted_hull(m, lines, (-0.2, -0.19), "hull")  # one colour all over: no bands on a kayak
    m.add("deck", "hull", lines.deck())
    deck_y, _ = lines.deck_at(-0.2)
    m.add("deck", "black", box((-0.25, deck_y + 0.02, 0.0), (0.45, 0.03, 0.24)))  # cockpit coaming
    # The paddler: torso in a buoyancy aid, head, arms and a paddle.
    m.add("superstructure", "superstructure", box((-0.35, deck_y + 0.30, 0.0), (0.12, 0.28, 0.19)))
    m.add("superstructure", "skin", box((-0.33, deck_y + 0.70, 0.0), (0.09, 0.11, 0.08)))
    m.add("superstructure", "yellow", box((-0.33, deck_y + 0.82, 0.0), (0.10, 0.03, 0.09)))  # cap
    for side in (-1, 1):
        m.add("superstructure", "superstructure", bar((-0.35, deck_y + 0.50, side * 0.17),
                                                      (-0.05, deck_y + 0.38, side * 0.30), 0.04))
    m.add("superstructure", "black", bar((0.0, deck_y + 0.40, -1.05), (-0.1, deck_y + 0.34, 1.05), 0.015))
    for z in (-1.05, 1.05):
        m.add("superstructure", "yellow", box((0.0 if z < 0 else -0.1, deck_y + 0.40, z), (0.08, 0.01, 0.16)))
    return m


# ---------------------------------------------------------------------------
# IALA marks, region A

def buoy(name, body_rgb, com_height_m):
    """A float 1.8 m across, 0.7 m deep, with a ring fender at the waterline."""
    float_profile = [(0.0, -0.7), (0.8, -0.7), (0.9, -0.6), (0.9, 0.35), (0.0, 0.35)]
    m = Model(name, lathe_tris(float_profile, 20), com_height_m, {"hull": body_rgb, "superstructure": body_rgb})
    m.add("body", "hull", lathe_tris(float_profile, 20))
    m.add("body", "black", lathe_tris([(0.0, 0.05), (0.95, 0.05), (0.95, 0.25), (0.0, 0.25)], 20))
    return m


def lateral_port_buoy():
    """Port hand, region A: red, a can; its topmark a red can."""
    m = buoy("lateral_port_buoy", PAINT["red"], -0.5)
    m.add("body", "hull", lathe_tris([(0.0, 0.35), (0.6, 0.35), (0.6, 2.3), (0.0, 2.3)], 16))
    m.add("superstructure", "steel", bar((0.0, 2.3, 0.0), (0.0, 2.75, 0.0), 0.03))
    m.add("superstructure", "superstructure", lathe_tris([(0.0, 2.75), (0.22, 2.75), (0.22, 3.2), (0.0, 3.2)], 12))
    return m


def lateral_starboard_buoy():
    """Starboard hand, region A: green, a cone; its topmark a green cone point up."""
    m = buoy("lateral_starboard_buoy", PAINT["green"], -0.5)
    m.add("body", "hull", lathe_tris([(0.0, 0.35), (0.7, 0.35), (0.0, 2.5)], 16))
    m.add("superstructure", "steel", bar((0.0, 2.3, 0.0), (0.0, 2.8, 0.0), 0.03))
    m.add("superstructure", "superstructure", lathe_tris([(0.0, 2.75), (0.25, 2.75), (0.0, 3.25)], 12))
    return m


def cardinal_north_buoy():
    """North cardinal: a pillar, black above yellow; topmark two black cones,
    both points up."""
    m = buoy("cardinal_north_buoy", PAINT["yellow"], -0.55)
    m.colors["superstructure"] = PAINT["black"]
    m.add("body", "hull", lathe_tris([(0.0, 0.35), (0.5, 0.35), (0.42, 1.9), (0.0, 1.9)], 16))
    m.add("body", "black", lathe_tris([(0.0, 1.9), (0.42, 1.9), (0.32, 3.5), (0.0, 3.5)], 16))
    m.add("superstructure", "steel", bar((0.0, 3.5, 0.0), (0.0, 4.1, 0.0), 0.035))
    m.add("superstructure", "superstructure", lathe_tris([(0.0, 3.85), (0.28, 3.85), (0.0, 4.3)], 12))
    m.add("superstructure", "superstructure", lathe_tris([(0.0, 4.4), (0.28, 4.4), (0.0, 4.85)], 12))
    return m


CLASSES = [sailing_yacht, rib, fishing_trawler, tug, container_ship, tanker, kayak,
           lateral_port_buoy, lateral_starboard_buoy, cardinal_north_buoy]


def models():
    return [make() for make in CLASSES]
