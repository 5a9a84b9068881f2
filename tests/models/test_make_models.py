"""assets/models/make_models.py: the committed models are its output, byte for
byte, and the boat's hull is fitted to its design numbers (boat_model.DESIGN)
and closed. The C++ side checks the same file as Swell loads it
(tests/cpu/test_boat_model.cpp).

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
import make_models  # noqa: E402


class MakeModels(unittest.TestCase):
    def test_committed_models_are_the_scripts_output(self):
        with tempfile.TemporaryDirectory() as folder:
            make_models.main(folder)
            for name in ("lighthouse.gltf", "crate.glb", "boat.gltf"):
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


if __name__ == "__main__":
    unittest.main()
