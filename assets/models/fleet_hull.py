"""Hull lines and solids shared by the fleet's models (fleet_model.py).

A hull is a set of half sections from the stern (u = 0) to the stem (u = 1),
each from the keel up to the sheer, in the same layout as boat_model.py's,
so its closed volume (skin, transom, lid) and its displacement come from the
same functions (boat_model.closed_hull, boat_model.volume_below).

Below the design waterline (y = 0) a section is a superellipse
|z / b|^n + |y / T|^n = 1 of half-breadth b and draft T (Lame's curve):
n = 1 is a V (a planing hull's deadrise), n = 2 an ellipse (a yacht's or a
kayak's round bilge), n of 6 or more a ship's box with a rounded bilge.
Above it the side runs straight to the sheer, with flare. The plan is a
parallel middle body between `mid`, a run aft to the transom (of half-breadth
`stern` times the greatest) and an entrance forward to the stem, each a
power curve; the stem is raked by `rake_m` at the sheer.

Axes as boat_model.py's: metres, +x forward, +y up, +z to starboard; the
origin on the design waterline, half way along the overall length.
"""

import math

import boat_model
from boat_model import box_tris, mirror, orient_outwards, quad_tris  # noqa: F401 (re-exported for fleet_model)


class Lines:
    def __init__(self, length_m, beam_m, draft_m, freeboard_aft_m, freeboard_bow_m, *, n=2.0, stern=0.7,
                 mid=(0.4, 0.55), run=2.0, entrance=1.8, flare=1.05, rake_m=0.0, forefoot=0.3, stern_draft=1.0,
                 stations=32, below_rows=4, above_rows=2):
        self.length_m, self.beam_m, self.draft_m = length_m, beam_m, draft_m
        self.freeboard = (freeboard_aft_m, freeboard_bow_m)
        self.n, self.stern, self.mid, self.run, self.entrance = n, stern, mid, run, entrance
        self.flare, self.rake_m, self.forefoot, self.stern_draft = flare, rake_m, forefoot, stern_draft
        self.stations, self.below_rows, self.above_rows = stations, below_rows, above_rows
        self.x_stern = -length_m / 2

    def plan(self, u):
        """Waterline half-breadth over the greatest, 0..1."""
        m0, m1 = self.mid
        if u < m0:
            return self.stern + (1.0 - self.stern) * (1.0 - ((m0 - u) / m0) ** self.run)
        if u <= m1:
            return 1.0
        return max(0.0, 1.0 - ((u - m1) / (1.0 - m1)) ** self.entrance)

    def half_breadth(self, u):
        return 0.5 * self.beam_m / self.flare * self.plan(u)

    def sheer_half_breadth(self, u):
        return self.half_breadth(u) * self.flare

    def keel_depth(self, u):
        """Draft of the keel line: full amidships, rising into the forefoot
        and, for a canoe stern, aft."""
        m0, m1 = self.mid
        if u > m1:
            t = (u - m1) / (1.0 - m1)
            return self.draft_m * (1.0 - (1.0 - self.forefoot) * t ** 2)
        if u < m0:
            t = (m0 - u) / m0
            return self.draft_m * (1.0 - (1.0 - self.stern_draft) * t ** 2)
        return self.draft_m

    def sheer(self, u):
        a, b = self.freeboard
        return a + (b - a) * u ** 2.0

    def x_at(self, u, y):
        """The stem is raked: at the sheer it lies rake_m ahead of its foot."""
        top = self.sheer(1.0)
        s = min(1.0, max(0.0, (y + self.draft_m) / (top + self.draft_m)))
        x_stem = self.x_stern + self.length_m - self.rake_m * (1.0 - s)
        return self.x_stern + u * (x_stem - self.x_stern)

    def section(self, u):
        b, t = self.half_breadth(u), self.keel_depth(u)
        points = []
        for k in range(self.below_rows + 1):
            phi = 0.5 * math.pi * k / self.below_rows
            z = b * math.sin(phi) ** (2.0 / self.n)
            y = -t * math.cos(phi) ** (2.0 / self.n)
            points.append((z, y))
        bs, ys = self.sheer_half_breadth(u), self.sheer(u)
        for k in range(1, self.above_rows + 1):
            f = k / self.above_rows
            points.append((b + f * (bs - b), f * ys))
        return [(self.x_at(u, y), y, z) for z, y in points]

    def grid(self):
        return [self.section(i / self.stations) for i in range(self.stations + 1)]

    def closed(self):
        return boat_model.closed_hull(self.grid())

    def skin(self):
        grid = self.grid()
        return boat_model.skin_tris(grid) + boat_model.transom_tris(grid)

    def deck(self):
        """The lid at the sheer, drawn as the deck."""
        return boat_model.lid_tris(self.grid())

    def u_of(self, x):
        return min(1.0, max(0.0, (x - self.x_stern) / self.length_m))

    def deck_at(self, x):
        """Sheer height and half-breadth at x, m."""
        u = self.u_of(x)
        return self.sheer(u), self.sheer_half_breadth(u)


def lathe_tris(profile, segments):
    """A closed solid of revolution about +y from (radius, height) points
    (the first and last at radius 0), wound outwards."""
    tris = []
    for (r0, y0), (r1, y1) in zip(profile, profile[1:]):
        for s in range(segments):
            a0, a1 = 2 * math.pi * s / segments, 2 * math.pi * (s + 1) / segments
            p = lambda r, y, a: (r * math.cos(a), y, r * math.sin(a))
            q = quad_tris(p(r0, y0, a0), p(r0, y0, a1), p(r1, y1, a1), p(r1, y1, a0))
            # Outward: away from the axis at the band's mid height.
            mid_a = 0.5 * (a0 + a1)
            for tri in q:
                n = boat_model.cross(boat_model.sub(tri[1], tri[0]), boat_model.sub(tri[2], tri[0]))
                c = tuple(sum(v[k] for v in tri) / 3 for k in range(3))
                axis = (0.0, c[1], 0.0)
                out = boat_model.sub(c, axis)
                if abs(r1 - r0) > 1e-12 and abs(y1 - y0) < 1e-12:  # a flat ring or cap: up or down
                    out = (0.0, 1.0 if r1 < r0 else -1.0, 0.0)
                elif math.hypot(out[0], out[2]) < 1e-9:
                    out = (math.cos(mid_a), 0.0, math.sin(mid_a))
                tris.append(tri if boat_model.dot(n, out) >= 0 else (tri[0], tri[2], tri[1]))
    return tris


def translated(tris, offset):
    return [tuple(tuple(p[k] + offset[k] for k in range(3)) for p in t) for t in tris]


def bar(p, q, half_width):
    return boat_model.bar_tris(p, q, half_width)


def displacement(tris):
    """Sea water displaced below the design waterline, kg, and the centre of
    buoyancy."""
    volume, centre = boat_model.volume_below(tris)
    return volume * boat_model.WATER_DENSITY_KG_PER_M3, centre


def metacentric_height(tris, center_of_mass_height_m, beam_scale=1.0):
    """GM = KB + BM - KG, m, heights from the waterline: the initial
    stability of a floating body (Bouguer's metacentre; Journee & Massie
    2001, Offshore Hydromechanics, sec. 2.4): BM is the waterplane's second
    moment about the centreline over the displaced volume. The waterplane is
    the loop where the hull's triangles cross y = 0; its second moment comes
    from Green's theorem over those segments. Stretching the beam by s
    multiplies the moment by s^3 and the volume by s: BM by s^2."""
    moment = 0.0
    for t in tris:
        cut = []
        for k in range(3):
            p, q = t[k], t[(k + 1) % 3]
            if (p[1] < 0) != (q[1] < 0):
                f = -p[1] / (q[1] - p[1])
                cut.append((p[0] + f * (q[0] - p[0]), p[2] + f * (q[2] - p[2])))
        if len(cut) == 2:
            (x0, z0), (x1, z1) = cut
            moment += (x0 * z1 - x1 * z0) * (z0 * z0 + z0 * z1 + z1 * z1) / 12.0
    volume, centre = boat_model.volume_below(tris)
    return centre[1] + abs(moment) / volume * beam_scale ** 2 - center_of_mass_height_m
