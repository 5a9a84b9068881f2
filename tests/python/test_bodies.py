"""Floating bodies stepped from Python: advance_to() gives the same
transforms in two renderers and in any order of times, a boat under way is
carried at its velocity, and the transforms place the 3D boxes the
executable writes for the same scene and time."""

import json
import os
import subprocess
import unittest

import numpy as np

import swell
import support


def under_way():
    """The under-way preset (a boat at 4 m/s and a buoy, both rigid bodies),
    its history starting at 0 s and without the wake: a few seconds of
    steps, not the minute before t = 0 the preset simulates."""
    scene = swell.load("under-way")
    scene["history_start_s"] = 0.0
    scene["wake.enabled"] = False
    return scene


class Bodies(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = under_way()
        cls.first = swell.Renderer(cls.scene)
        cls.second = swell.Renderer(cls.scene)

    @classmethod
    def tearDownClass(cls):
        cls.first = cls.second = None

    def test_transforms_before_any_step_raise(self):
        fresh = swell.Renderer(self.scene)
        with self.assertRaises(swell.Error):
            fresh.object_transforms()

    def test_the_same_time_gives_the_same_transforms_in_any_order(self):
        self.first.advance_to(6.0)
        at6 = self.first.object_transforms()
        self.assertEqual(at6.shape, (2, 4, 4))
        self.assertEqual(self.first.simulated_time_s, 6.0)
        # Another renderer, reaching 6 s after going past it.
        self.second.advance_to(9.0)
        self.assertFalse(np.array_equal(self.second.object_transforms(), at6))
        self.second.advance_to(6.0)
        np.testing.assert_array_equal(self.second.object_transforms(), at6)
        np.testing.assert_array_equal(at6[:, 3], np.tile([0.0, 0.0, 0.0, 1.0], (2, 1)))

    def test_a_boat_under_way_is_carried_at_its_velocity(self):
        self.first.advance_to(2.0)
        before = self.first.object_transforms()[0]
        self.first.advance_to(7.0)
        after = self.first.object_transforms()[0]
        # 4 m/s towards -z for 5 s; its tilt moves its origin by centimetres.
        moved = after[:3, 3] - before[:3, 3]
        self.assertAlmostEqual(moved[2], -20.0, delta=0.3)
        self.assertAlmostEqual(moved[0], 0.0, delta=0.3)
        # Its rotation stays a rotation.
        rotation = after[:3, :3]
        np.testing.assert_allclose(rotation @ rotation.T, np.eye(3), atol=1e-9)

    def test_the_transforms_place_the_executables_3d_boxes(self):
        app = support.needs_app(self)
        folder = support.output_folder(self)
        path = os.path.join(folder, "bodies.toml")
        self.scene.save(path)
        time_s, size = 4.0, (96, 64)
        subprocess.run([app, "render", path, "-o", os.path.join(folder, "bodies.png"), "--size", "%dx%d" % size,
                        "--time", str(time_s), "--labels"], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(folder, "bodies.json")) as f:
            cli = json.load(f)
        renderer = swell.Renderer(swell.load_scene(path))
        camera = renderer.scene.camera_at(time_s)
        renderer.render(camera, time_s, size)
        labels = renderer.render_labels(camera, size)
        transforms = renderer.object_transforms()
        for i, (ours, theirs) in enumerate(zip(labels.objects, cli["objects"])):
            np.testing.assert_array_equal(ours.box3d_m, np.array(theirs["box3d_m"]))
            # In the body's own axes its box is axis-aligned: the transform is the one that placed it.
            local = (np.c_[ours.box3d_m, np.ones(8)] @ np.linalg.inv(transforms[i]).T)[:, :3]
            for axis in range(3):
                self.assertEqual(len(np.unique(np.round(local[:, axis], 6))), 2, "object %d, axis %d" % (i, axis))


if __name__ == "__main__":
    unittest.main()
