"""assets/models/make_models.py: the committed models are its output, byte for
byte, and the boat's hull is fitted to its design numbers (boat_model.DESIGN)
and closed; the fleet's hulls (fleet_model.py) are closed and their design
numbers are their meshes'. The C++ side checks the same files as Swell loads
them (tests/cpu/test_boat_model.cpp, tests/cpu/test_fleet.cpp).

    python3 tests/models/test_make_models.py
"""

import pathlib
import sys
import tempfile
import unittest

MODELS = pathlib.Path(__file__).resolve().parents[2] / "assets" / "models"
sys.path.insert(0, str(MODELS))
sys.dont_write_bytecode = True  # the models' folder is installed as it is

import boat_model  # noqa: E402
import fleet_hull  # noqa: E402
import fleet_model  # noqa: E402
import make_models  # noqa: E402


def open_edges(tris):
    """Edges not walked once each way, corners compared by position."""
    key = lambda p: tuple(round(c, 5) + 0.0 for c in p)
    edges = {}
    for t in tris:
        for k in range(3):
            edge = (key(t[k]), key(t[(k + 1) % 3]))
            edges[edge] = edges.get(edge, 0) + 1
    return [(a, b) for (a, b), count in edges.items() if (count, edges.get((b, a), 0)) != (1, 1)]


class MakeModels(unittest.TestCase):
    def test_committed_models_are_the_scripts_output(self):
        with tempfile.TemporaryDirectory() as folder:
            make_models.main(folder)
            names = ["lighthouse.gltf", "crate.glb", "boat.gltf"]
            names += ["fleet/%s.gltf" % m.__name__ for m in fleet_model.CLASSES]
            self.assertEqual(sorted(p.name for p in (MODELS / "fleet").iterdir()),
                             sorted(n[len("fleet/"):] for n in names[3:]), "fleet/ holds what the script writes")
            for name in names:
                written = (pathlib.Path(folder) / name).read_bytes()
                self.assertEqual(written, (MODELS / name).read_bytes(),
                                 "%s differs from the script's output: run make_models.py" % name)

    def test_hull_displaces_the_design_displacement(self):
        hull = boat_model.fit_hull()
        volume, _ = boat_model.volume_below(boat_model.closed_hull(hull.grid()))
        displaced = volume * boat_model.WATER_DENSITY_KG_PER_M3
        self.assertAlmostEqual(displaced / boat_model.DESIGN["displacement_kg"], 1.0, delta=1e-3)

    def test_hull_volume_is_closed(self):
        # Every edge walked once each way, corners compared by position.
        tris = boat_model.closed_hull(boat_model.fit_hull().grid())
        key = lambda p: tuple(round(c, 5) + 0.0 for c in p)
        edges = {}
        for t in tris:
            for k in range(3):
                edge = (key(t[k]), key(t[(k + 1) % 3]))
                edges[edge] = edges.get(edge, 0) + 1
        for (a, b), count in edges.items():
            self.assertEqual((count, edges.get((b, a), 0)), (1, 1), "edge %s-%s" % (a, b))


    def test_fleet_hulls_are_closed_and_their_design(self):
        models = fleet_model.models()
        self.assertGreaterEqual(len(models), 8)
        for model in models:
            with self.subTest(model.name):
                self.assertEqual(open_edges(model.hull_tris), [])
                design = model.design()
                volume, centre = boat_model.volume_below(model.hull_tris)
                self.assertGreater(volume, 0.0)
                self.assertAlmostEqual(design["displacement_kg"] / (volume * boat_model.WATER_DENSITY_KG_PER_M3),
                                       1.0, delta=1e-4)
                ys = [p[1] for t in model.hull_tris for p in t]
                self.assertAlmostEqual(design["draft_m"], -min(ys), delta=1e-4)
                self.assertIn("hull", model.colors)
                self.assertIn("superstructure", model.nodes, "a superstructure a scene can leave out")
                # Upright: positive initial stability at the design beam and
                # at the narrowest a scene may ask for (0.75 of it).
                for beam_scale in (1.0, 0.75):
                    self.assertGreater(fleet_hull.metacentric_height(model.hull_tris, model.com_height_m, beam_scale),
                                       0.05, "GM at %.2f of the beam" % beam_scale)

    def test_metacentric_height_of_a_box(self):
        # A box barge of beam B and draft T, its centre of mass on the
        # waterline: KB = -T/2, BM = B^2 / (12 T), so GM = B^2/(12 T) - T/2.
        tris = boat_model.box_tris((0.0, 0.0, 0.0), (5.0, 1.0, 2.0))  # 10 m long, 4 m beam, 1 m draft
        self.assertAlmostEqual(fleet_hull.metacentric_height(tris, 0.0), 16.0 / 12.0 - 0.5, places=9)
        self.assertAlmostEqual(fleet_hull.metacentric_height(tris, 0.0, 0.5), 4.0 / 12.0 - 0.5, places=9)


if __name__ == "__main__":
    unittest.main()
