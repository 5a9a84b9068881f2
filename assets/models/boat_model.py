"""The 7 m motor workboat (boat.gltf), which is also Swell's `builtin:boat`.

The hull is a hard-chine V-bottom with a flat transom: each half section is
two straight panels, keel to chine and chine to sheer, so the chine is a
crisp line along the side. Stations run from the transom (u = 0) to the stem
(u = 1); at each height the stem lies at x_stem(y), raked forward, so the bow
is sharp and its flare (the sheer half-breadth past the chine's) grows
forward. The sheer rises from the transom to the stem head.

The design numbers are DESIGN below; the script is given them and the hull
is fitted to them: the deadrise aft (how high the chine lies) is found by
bisection so that the hull below the design waterline displaces exactly
DESIGN["displacement_kg"] of sea water. The file carries DESIGN, and the
centre of mass that trims the boat level at that waterline, in the root
node's `extras`, so tests check the mesh against the numbers it was made
from (tests/cpu/test_boat_model.cpp).

Axes: metres, +x forward (the bow), +y up, +z to starboard; the origin lies
on the design waterline, half way along the overall length. A rider
(`floats = true`, no mass) sits with its origin on the water, at this
waterline; a rigid body floats there when its mass is the displacement and
its centre of mass is the one in `extras`.

Nodes: "boat" (the root, with `extras`), and under it "hull" (the closed
hull volume: the outer skin from the keel to the sheer, the transom and a lid
at the sheer; Swell's hull_node, never drawn), "hull skin" (the outer skin
and transom, painted in bands: antifouling up to just above the waterline, a
boot-top stripe, topsides), "deck" (deck, bulwarks and the gunwale cap),
"wheelhouse" (walls, roof, windows and a radar scanner) and "rail" (the
bow rail and the mast).
"""

import math

WATER_DENSITY_KG_PER_M3 = 1025.0  # sea water, as src/objects uses

DESIGN = {
    "length_m": 7.0,           # overall, transom to stem head
    "beam_m": 2.4,             # at the sheer, widest
    "draft_m": 0.48,           # keel below the design waterline
    "freeboard_aft_m": 0.78,   # sheer above the waterline at the transom
    "freeboard_bow_m": 1.25,   # at the stem head
    "displacement_kg": 2500.0, # sea water displaced at the design waterline
    "center_of_mass_height_m": 0.15,  # above the waterline: engine low, wheelhouse high
}

STATIONS = 40
BOTTOM_ROWS = 3   # rows across the bottom panel (it is twisted: deadrise changes along the hull)
SIDE_ROWS = 3     # rows across the topsides (flare changes along the hull)
BOOT_TOP_M = (0.05, 0.14)  # antifouling below the first height, boot-top between

COLORS = {  # linear RGB
    "antifouling": (0.30, 0.045, 0.03),
    "boot-top": (0.015, 0.015, 0.018),
    "topsides": (0.03, 0.09, 0.20),
    "rubbing strake": (0.60, 0.58, 0.52),
    "deck": (0.42, 0.40, 0.34),
    "gunwale": (0.28, 0.15, 0.06),
    "wheelhouse": (0.78, 0.77, 0.72),
    "roof": (0.85, 0.85, 0.82),
    "glass": (0.015, 0.025, 0.035),
    "rail": (0.55, 0.56, 0.58),
}


def smoothstep(a, b, x):
    t = min(1.0, max(0.0, (x - a) / (b - a)))
    return t * t * (3 - 2 * t)


class Hull:
    """The hull's lines for one aft chine height (the fitted parameter)."""

    def __init__(self, chine_aft_m):
        self.chine_aft_m = chine_aft_m
        d = DESIGN
        self.x_transom = -d["length_m"] / 2
        self.x_stem_head = d["length_m"] / 2

    def sheer(self, u):
        d = DESIGN
        return d["freeboard_aft_m"] + (d["freeboard_bow_m"] - d["freeboard_aft_m"]) * u ** 2.2

    def keel(self, u):
        """Keel (bottom centreline) height: straight aft, sweeping up forward
        into the forefoot, where it meets the stem 0.1 m under the waterline."""
        t = max(0.0, (u - 0.5) / 0.5)
        return -DESIGN["draft_m"] + (DESIGN["draft_m"] - 0.1) * t ** 2.2

    def chine(self, u):
        """Chine height: near the waterline aft, rising to meet the stem."""
        return self.chine_aft_m + (0.42 - self.chine_aft_m) * u ** 2.5

    def sheer_half_breadth(self, u):
        half = DESIGN["beam_m"] / 2
        if u < 0.5:
            return half * (0.90 + 0.10 * math.sin(0.5 * math.pi * u / 0.5))
        v = (u - 0.5) / 0.5
        return half * (1.0 - v ** 2.1)

    def chine_half_breadth(self, u):
        """Narrower than the sheer, and more so forward: the flare."""
        return self.sheer_half_breadth(u) * (0.90 - 0.22 * u ** 2)

    def x_stem(self, y):
        """The stem, raked: the head at the sheer, the forefoot further aft."""
        top, foot = DESIGN["freeboard_bow_m"], -0.1
        s = min(1.0, max(0.0, (top - y) / (top - foot)))
        return self.x_stem_head - 0.75 * s ** 1.4

    def x_at(self, u, y):
        """Stations are fractions of the way from the flat transom to the stem
        at each height, so the raked stem is a station line of its own."""
        return self.x_transom + u * (self.x_stem(y) - self.x_transom)

    def section(self, u):
        """Starboard half section, keel to sheer: rows of (x, y, z) points;
        index BOTTOM_ROWS is the chine."""
        keel = (0.0, self.keel(u))
        chine = (self.chine_half_breadth(u), self.chine(u))
        sheer = (self.sheer_half_breadth(u), self.sheer(u))
        points = []
        for k in range(BOTTOM_ROWS + 1):
            t = k / BOTTOM_ROWS
            # A little convexity across the bottom, as a planked V-bottom has.
            z = keel[0] + t * (chine[0] - keel[0])
            y = keel[1] + t * (chine[1] - keel[1]) - 0.03 * math.sin(math.pi * t) * (chine[0] > 0)
            points.append((z, y))
        for k in range(1, SIDE_ROWS + 1):
            t = k / SIDE_ROWS
            points.append((chine[0] + t * (sheer[0] - chine[0]), chine[1] + t * (sheer[1] - chine[1])))
        return [(self.x_at(u, y), y, z) for z, y in points]

    def grid(self):
        return [self.section(i / STATIONS) for i in range(STATIONS + 1)]


# ---------------------------------------------------------------------------
# Geometry helpers: triangles are (p0, p1, p2) position triples, wound
# counter-clockwise seen from outside.

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalize(v):
    n = math.sqrt(dot(v, v))
    return (v[0] / n, v[1] / n, v[2] / n) if n > 0 else (0.0, 1.0, 0.0)


def mirror(p):
    return (p[0], p[1], -p[2])


def quad_tris(a, b, c, d):
    """Quad a b c d, counter-clockwise from outside; degenerate halves dropped."""
    out = []
    for t in ((a, b, c), (a, c, d)):
        n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
        if dot(n, n) > 1e-14:
            out.append(t)
    return out


def skin_tris(grid):
    """The starboard and port outer skin, keel to sheer."""
    tris = []
    for i in range(len(grid) - 1):
        for j in range(len(grid[i]) - 1):
            a, b, c, d = grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]
            # At the stem a, b and c may all lie on the centreline: a flat
            # triangle there would meet its mirror image face to face, so
            # split such a quad along its other diagonal.
            on_centreline = all(p[2] == 0.0 for p in (a, b, c))
            starboard = quad_tris(b, c, d, a) if on_centreline else quad_tris(a, b, c, d)
            tris += starboard
            tris += [(mirror(p0), mirror(p2), mirror(p1)) for p0, p1, p2 in starboard]
    return tris


def transom_tris(grid):
    """The flat transom: the section at u = 0, port and starboard, facing aft."""
    section = grid[0]
    tris = []
    for j in range(len(section) - 1):
        a, b = section[j], section[j + 1]
        # Fan from the centreline: keel point and the points across.
        ca, cb = (a[0], a[1], 0.0), (b[0], b[1], 0.0)
        for t in quad_tris(ca, cb, b, a):
            # Seen from aft (-x) these must be counter-clockwise: check and flip.
            n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
            tris.append(t if n[0] < 0 else (t[0], t[2], t[1]))
    # The port half, mirrored.
    tris += [(mirror(p0), mirror(p2), mirror(p1)) for p0, p1, p2 in tris]
    return tris


def lid_tris(grid):
    """The lid at the sheer, facing up: from the centreline to each side at
    every station, so that it meets the transom's top edge vertex for vertex."""
    tris = []
    for i in range(len(grid) - 1):
        a, b = grid[i][-1], grid[i + 1][-1]
        ca, cb = (a[0], a[1], 0.0), (b[0], b[1], 0.0)
        for side in (a, b), (mirror(a), mirror(b)):
            tris += up_facing(quad_tris(ca, cb, side[1], side[0]))
    return tris


def volume_below(tris, level=0.0):
    """Volume of the closed surface below y = level, and its centroid: each
    triangle clipped to the part below, summed as signed tetrahedra with an
    apex on the plane (the waterplane that closes the cut adds nothing)."""
    apex = (0.0, level, 0.0)
    vol, moment = 0.0, [0.0, 0.0, 0.0]
    for tri in tris:
        for poly in clip_below(list(tri), level):
            for k in range(1, len(poly) - 1):
                a, b, c = (sub(p, apex) for p in (poly[0], poly[k], poly[k + 1]))
                v = dot(a, cross(b, c)) / 6.0
                vol += v
                for axis in range(3):
                    moment[axis] += v * (a[axis] + b[axis] + c[axis]) / 4.0
    centroid = tuple(moment[axis] / vol + apex[axis] for axis in range(3)) if vol else (0.0, 0.0, 0.0)
    return vol, centroid


def clip_below(poly, level):
    """The part of a polygon below y = level (Sutherland-Hodgman, one plane)."""
    out = []
    for k, p in enumerate(poly):
        q = poly[(k + 1) % len(poly)]
        if p[1] <= level:
            out.append(p)
        if (p[1] < level) != (q[1] < level) and p[1] != q[1]:
            t = (level - p[1]) / (q[1] - p[1])
            out.append(tuple(p[a] + t * (q[a] - p[a]) for a in range(3)))
    return [out] if len(out) >= 3 else []


def clip_above(poly, level):
    flipped = [(p[0], -p[1], p[2]) for p in poly]
    return [[(p[0], -p[1], p[2]) for p in part] for part in clip_below(flipped, -level)]


def closed_hull(grid):
    return skin_tris(grid) + transom_tris(grid) + lid_tris(grid)


def fit_hull():
    """The aft chine height whose hull displaces the design displacement at
    the design waterline: bisection (the displacement falls as the chine,
    and with it the deadrise, rises)."""
    target = DESIGN["displacement_kg"] / WATER_DENSITY_KG_PER_M3
    lo, hi = -DESIGN["draft_m"] + 0.05, 0.30
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        vol, _ = volume_below(closed_hull(Hull(mid).grid()))
        lo, hi = (mid, hi) if vol > target else (lo, mid)
    return Hull(0.5 * (lo + hi))


# ---------------------------------------------------------------------------
# Drawn parts.

def bands(tris, heights):
    """Triangles cut at each height into len(heights) + 1 bands, lowest first."""
    out = [[] for _ in range(len(heights) + 1)]
    for tri in tris:
        rest = [list(tri)]
        for k, h in enumerate(heights):
            below, above = [], []
            for poly in rest:
                below += clip_below(poly, h)
                above += clip_above(poly, h)
            out[k] += fan(below)
            rest = above
        out[-1] += fan(rest)
    return out


def fan(polys):
    tris = []
    for poly in polys:
        for k in range(1, len(poly) - 1):
            t = (poly[0], poly[k], poly[k + 1])
            n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
            if dot(n, n) > 1e-14:
                tris.append(t)
    return tris


def box_tris(center, half, yaw=0.0):
    """An axis-aligned (then yawed about y) box, wound outwards."""
    cx, cy, cz = center
    hx, hy, hz = half
    c, s = math.cos(yaw), math.sin(yaw)

    def p(x, y, z):
        return (cx + c * x - s * z, cy + y, cz + s * x + c * z)

    corners = [p(sx * hx, sy * hy, sz * hz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = []
    for f in faces:
        tris += quad_tris(*(corners[k] for k in f))
    return orient_outwards(tris, (cx, cy, cz))


def orient_outwards(tris, center):
    out = []
    for t in tris:
        n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
        m = tuple((t[0][a] + t[1][a] + t[2][a]) / 3 - center[a] for a in range(3))
        out.append(t if dot(n, m) >= 0 else (t[0], t[2], t[1]))
    return out


def bar_tris(p, q, half_width):
    """A square bar from p to q (a rail tube or a stanchion)."""
    d = sub(q, p)
    length = math.sqrt(dot(d, d))
    axis = normalize(d)
    side = normalize(cross(axis, (0.0, 1.0, 0.0)) if abs(axis[1]) < 0.9 else cross(axis, (1.0, 0.0, 0.0)))
    up = cross(side, axis)
    w = half_width
    ring = lambda base: [tuple(base[a] + w * (sx * side[a] + sy * up[a]) for a in range(3))
                         for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    r0, r1 = ring(p), ring(q)
    tris = []
    for k in range(4):
        tris += quad_tris(r0[k], r0[(k + 1) % 4], r1[(k + 1) % 4], r1[k])
    tris += quad_tris(r0[3], r0[2], r0[1], r0[0]) + quad_tris(*r1)
    center = tuple((p[a] + q[a]) / 2 for a in range(3))
    del length
    return orient_outwards(tris, center)


class Decks:
    """Deck, bulwarks and gunwale: the deck lies inside the hull, low in the
    open cockpit aft and nearly flush with the sheer on the foredeck."""

    BULWARK_M = 0.05  # thickness of the hull side at the sheer

    def __init__(self, hull):
        self.hull = hull

    def deck(self, u):
        aft = 0.30
        fore = self.hull.sheer(u) - 0.10
        return aft + (fore - aft) * smoothstep(0.52, 0.60, u)

    def side_half_breadth(self, u, y):
        """The outer side's half-breadth at height y (chine to sheer)."""
        h = self.hull
        yc, ys = h.chine(u), h.sheer(u)
        bc, bs = h.chine_half_breadth(u), h.sheer_half_breadth(u)
        t = min(1.0, max(0.0, (y - yc) / (ys - yc)))
        return bc + t * (bs - bc)

    def tris(self, last_u=0.985):
        h = self.hull
        deck, walls, cap = [], [], []
        us = [i / STATIONS for i in range(STATIONS + 1) if i / STATIONS <= last_u] + [last_u]
        rows = []
        for u in us:
            ys, yd = h.sheer(u), self.deck(u)
            bs = h.sheer_half_breadth(u)
            t = min(self.BULWARK_M, 0.45 * bs)
            inner_top = max(0.0, bs - t)
            inner_deck = max(0.0, self.side_half_breadth(u, yd) - t)
            rows.append({
                "outer": (h.x_at(u, ys), ys, bs),
                "inner_top": (h.x_at(u, ys), ys, inner_top),
                "inner_deck": (h.x_at(u, yd), yd, inner_deck),
            })
        for r0, r1 in zip(rows, rows[1:]):
            # Deck, facing up, port to starboard.
            a, b = r0["inner_deck"], r1["inner_deck"]
            deck += up_facing(quad_tris(mirror(a), mirror(b), b, a))
            # Bulwark's inner face (facing inboard) and the gunwale cap (up).
            for side in (1, -1):
                f = (lambda p: p) if side > 0 else mirror
                q = [f(r0["inner_deck"]), f(r1["inner_deck"]), f(r1["inner_top"]), f(r0["inner_top"])]
                walls += facing(quad_tris(*q), (0.0, 0.0, -side))
                q = [f(r0["inner_top"]), f(r1["inner_top"]), f(r1["outer"]), f(r0["outer"])]
                cap += up_facing(quad_tris(*q))
        # Forward end: close the deck to the bow with the cap.
        r = rows[-1]
        stem = (h.x_stem(h.sheer(1.0)), h.sheer(1.0), 0.0)
        for side in (1, -1):
            f = (lambda p: p) if side > 0 else mirror
            cap += up_facing(quad_tris(f(r["outer"]), stem, stem, f(r["inner_top"])) +
                             [(f(r["inner_top"]), f(r["outer"]), stem)])
        cap += up_facing([(mirror(r["inner_top"]), r["inner_top"], stem)])
        walls += facing(quad_tris(mirror(r["inner_deck"]), r["inner_deck"], r["inner_top"], mirror(r["inner_top"])),
                        (-1.0, 0.0, 0.0))
        # Aft end: the transom's inner face and its cap.
        r = rows[0]
        x_in = r["inner_deck"][0] + self.BULWARK_M
        a, b = r["inner_deck"], r["inner_top"]
        ia, ib = (x_in, a[1], a[2]), (x_in, b[1], b[2])
        walls += facing(quad_tris(mirror(ia), ia, ib, mirror(ib)), (1.0, 0.0, 0.0))
        deck += up_facing(quad_tris(mirror(a), mirror(ia), ia, a))
        for side in (1, -1):
            f = (lambda p: p) if side > 0 else mirror
            walls += facing(quad_tris(f(a), f(ia), f(ib), f(b)), (0.0, 0.0, -side))
        o = r["outer"]
        cap += up_facing(quad_tris(mirror(o), mirror((x_in, o[1], o[2])), (x_in, o[1], o[2]), o))
        return deck, walls, cap

    def rubbing_strake(self):
        """A proud band just under the sheer, along each side."""
        h = self.hull
        tris = []
        us = [i / STATIONS for i in range(STATIONS + 1) if i / STATIONS <= 0.97]
        for u0, u1 in zip(us, us[1:]):
            pts = []
            for u in (u0, u1):
                ys = h.sheer(u)
                top, bottom = ys - 0.02, ys - 0.11
                bt, bb = self.side_half_breadth(u, top), self.side_half_breadth(u, bottom)
                pts.append([(h.x_at(u, bottom), bottom, bb), (h.x_at(u, bottom), bottom, bb + 0.035),
                            (h.x_at(u, top), top, bt + 0.035), (h.x_at(u, top), top, bt)])
            for k in range(3):
                q = quad_tris(pts[0][k], pts[1][k], pts[1][k + 1], pts[0][k + 1])
                tris += facing(q, (0.0, -1.0, 0.0) if k == 0 else (0.0, 0.0, 1.0) if k == 1 else (0.0, 1.0, 0.0))
        return tris + [(mirror(a), mirror(c), mirror(b)) for a, b, c in tris]


def facing(tris, direction):
    out = []
    for t in tris:
        n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
        out.append(t if dot(n, direction) >= 0 else (t[0], t[2], t[1]))
    return out


def up_facing(tris):
    return facing(tris, (0.0, 1.0, 0.0))


def wheelhouse(hull, decks):
    """A wheelhouse amidships with a raked front, windows all round and a
    roof that overhangs, and a mast on it; returns (walls, roof, glass,
    mast) triangles."""
    x0, x1 = hull.x_at(0.36, 0.3), hull.x_at(0.60, 0.3)   # aft and forward faces at the deck
    floor = decks.deck(0.36) - 0.02
    top = 2.05
    half_aft, half_fore = 0.78, 0.70
    rake = 0.30   # the front leans aft by this much at the roof

    def corner(x_frac, y, side):
        x = x0 + x_frac * (x1 - x0)
        half = half_aft + x_frac * (half_fore - half_aft)
        if x_frac >= 1.0:
            x -= rake * (y - floor) / (top - floor)
        return (x, y, side * half)

    walls = []
    aft = [corner(0, floor, -1), corner(0, floor, 1), corner(0, top, 1), corner(0, top, -1)]
    fore = [corner(1, floor, 1), corner(1, floor, -1), corner(1, top, -1), corner(1, top, 1)]
    stbd = [corner(0, floor, 1), corner(1, floor, 1), corner(1, top, 1), corner(0, top, 1)]
    port = [corner(1, floor, -1), corner(0, floor, -1), corner(0, top, -1), corner(1, top, -1)]
    walls += facing(quad_tris(*aft), (-1, 0, 0)) + facing(quad_tris(*fore), (1, 0, 0))
    walls += facing(quad_tris(*stbd), (0, 0, 1)) + facing(quad_tris(*port), (0, 0, -1))

    # The roof: a slab a little larger than the walls, its edge 6 cm thick.
    xr0, xr1 = x0 - 0.15, x1 - rake + 0.12
    roof = box_tris(((xr0 + xr1) / 2, top + 0.03, 0.0), ((xr1 - xr0) / 2, 0.03, half_aft + 0.08))

    # Windows: dark panes 1 cm proud of the walls.
    glass = []
    sill, head = 1.25, 1.85

    def pane(face, x_frac0, x_frac1, side, direction, lo=sill, hi=head):
        a, b = (corner(x_frac0, lo, side), corner(x_frac1, lo, side))
        c, d = (corner(x_frac1, hi, side), corner(x_frac0, hi, side))
        off = tuple(0.01 * k for k in direction)
        q = [tuple(p[i] + off[i] for i in range(3)) for p in (a, b, c, d)]
        return facing(quad_tris(*q), direction)

    for side in (1, -1):
        glass += pane("side", 0.12, 0.45, side, (0, 0, side))
        glass += pane("side", 0.55, 0.92, side, (0, 0, side))
    # Front: two panes across the raked face.
    n_front = normalize((top - floor, rake, 0.0))
    for z0, z1 in ((-0.62, -0.05), (0.05, 0.62)):
        q = []
        for z, y in ((z0, sill), (z1, sill), (z1, head), (z0, head)):
            x = x1 - rake * (y - floor) / (top - floor)
            q.append((x + 0.01 * n_front[0], y, z))
        glass += facing(quad_tris(*q), n_front)
    # Aft: a door with a window, on the centreline.
    q = [(x0 - 0.01, 1.10, -0.28), (x0 - 0.01, 1.10, 0.28), (x0 - 0.01, 1.80, 0.28), (x0 - 0.01, 1.80, -0.28)]
    glass += facing(quad_tris(*q), (-1, 0, 0))
    # A short mast on the roof, with a yard for the lights and a radar scanner.
    xm = x0 + 0.25
    mast = bar_tris((xm, top + 0.06, 0.0), (xm, top + 0.95, 0.0), 0.025)
    mast += bar_tris((xm, top + 0.70, -0.35), (xm, top + 0.70, 0.35), 0.015)
    mast += box_tris((xm + 0.05, top + 0.99, 0.0), (0.10, 0.04, 0.04))
    radar = box_tris(((xr0 + xr1) / 2 + 0.1, top + 0.14, 0.0), (0.09, 0.05, 0.09))
    radar += box_tris(((xr0 + xr1) / 2 + 0.1, top + 0.23, 0.0), (0.08, 0.04, 0.38))
    return walls, roof + radar, glass, mast


def bow_rail(hull, decks):
    """Stanchions along the foredeck's edge and a rail on them to the stem."""
    tris = []
    height = 0.45
    us = [0.62 + k * (0.97 - 0.62) / 5 for k in range(6)]
    for side in (1, -1):
        top_points = []
        for u in us:
            ys = hull.sheer(u)
            z = side * max(0.02, hull.sheer_half_breadth(u) - 0.06)
            base = (hull.x_at(u, ys), ys, z)
            top = (base[0], ys + height, z)
            tris += bar_tris(base, top, 0.014)
            top_points.append(top)
        # The rail meets its twin ahead of the stem head (the pulpit).
        tip = (hull.x_stem(hull.sheer(1.0)) + 0.05, hull.sheer(1.0) + height, 0.0)
        top_points.append(tip)
        for p, q in zip(top_points, top_points[1:]):
            tris += bar_tris(p, q, 0.016)
    return tris


def level_trim_center_of_mass(hull):
    """Where the centre of mass must lie for the boat to float level at its
    design waterline when it weighs its displacement: above the centre of
    buoyancy (Archimedes: the weight and the buoyancy on one vertical), at
    the design height."""
    _, center_of_buoyancy = volume_below(closed_hull(hull.grid()))
    return (center_of_buoyancy[0], DESIGN["center_of_mass_height_m"], 0.0)


def scene_keys(hull):
    """The [[objects]] keys that float builtin:boat level at its design
    waterline: its displacement as its mass, and its centre of mass as an
    offset from the hull volume's centroid (where Swell puts it by default)."""
    _, centroid = volume_below(closed_hull(hull.grid()), level=10.0)  # above it all: the whole volume
    com = level_trim_center_of_mass(hull)
    return DESIGN["displacement_kg"], [round(com[k] - centroid[k], 3) + 0.0 for k in range(3)]


def parts():
    """Every part of the boat as (node, [(material, triangles)]), and the
    fitted hull."""
    hull = fit_hull()
    grid = hull.grid()
    decks = Decks(hull)
    skin = skin_tris(grid) + transom_tris(grid)
    antifouling, boot_top, topsides = bands(skin, BOOT_TOP_M)
    deck, walls, cap = decks.tris()
    wh_walls, roof, glass, mast = wheelhouse(hull, decks)
    return hull, [
        ("hull", [("hull volume", closed_hull(grid))]),
        ("hull skin", [("antifouling", antifouling), ("boot-top", boot_top), ("topsides", topsides),
                       ("rubbing strake", decks.rubbing_strake())]),
        ("deck", [("deck", deck), ("topsides", walls), ("gunwale", cap)]),
        ("wheelhouse", [("wheelhouse", wh_walls), ("roof", roof), ("glass", glass)]),
        ("rail", [("rail", bow_rail(hull, decks) + mast)]),
    ]
