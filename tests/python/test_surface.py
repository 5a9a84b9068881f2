"""Surface queries from Python: the exact surface of one listed sine wave
against its formula evaluated in NumPy (the level, the time and the axes
all count); the labels' water points lying on the drawn surface; the drawn
surface taken before a scene change refusing queries after it."""

import unittest

import numpy as np

import swell
from test_labels import eye_of, open_sea, pixel_rays

GRAVITY_MPS2 = 9.80665  # swell/constants.h's kGravity, standard gravity

ONE_WAVE = """
terrain = false
[waves]
depth_m = 12.0
[[waves.list]]
direction = [0.6, 0.8]
wavelength_m = 25.0
amplitude_m = 0.4
steepness = 0.0
phase_rad = 0.7
[water]
level_m = 3.5
"""


class ExactSurface(unittest.TestCase):
    def test_one_sine_wave_is_its_formula(self):
        scene = swell.parse_scene(ONE_WAVE, "one-wave.toml")
        renderer = swell.Renderer(scene)
        # A sine wave (steepness 0) moves nothing sideways: the height at
        # (x, z) is A cos(k d.x - omega t + phase) above the level, with
        # omega^2 = g k tanh(k depth) (Airy's dispersion relation).
        k = 2.0 * np.pi / 25.0
        omega = np.sqrt(GRAVITY_MPS2 * k * np.tanh(k * 12.0))
        x, z = np.meshgrid(np.linspace(-40.0, 60.0, 21), np.linspace(-30.0, 70.0, 17))
        for time_s in [0.0, 3.25, 100.0]:
            expected = 3.5 + 0.4 * np.cos(k * (0.6 * x + 0.8 * z) - omega * time_s + 0.7)
            heights = renderer.surface_height_m(x, z, time_s)
            self.assertEqual(heights.shape, x.shape)
            np.testing.assert_allclose(heights, expected, rtol=0.0, atol=1e-9, err_msg="t = %g s" % time_s)
        self.assertIsInstance(renderer.surface_height_m(1.0, 2.0, 0.0), float)
        # Broadcasting as NumPy does.
        self.assertEqual(renderer.surface_height_m(np.zeros((3, 1)), np.arange(4.0), 0.0).shape, (3, 4))

    def test_flat_water_is_the_level(self):
        scene = swell.parse_scene(ONE_WAVE, "one-wave.toml")
        renderer = swell.Renderer(scene)
        renderer.set_flat_water(True)
        np.testing.assert_array_equal(renderer.surface_height_m([0.0, 10.0, -7.0], 5.0, 2.0), [3.5, 3.5, 3.5])


class DrawnSurface(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.renderer = swell.Renderer(open_sea())

    @classmethod
    def tearDownClass(cls):
        cls.renderer = None

    def test_drawn_surface_before_any_step_raises(self):
        fresh = swell.Renderer(open_sea())
        with self.assertRaises(swell.Error):
            fresh.drawn_surface()

    def test_the_labels_water_lies_on_the_drawn_surface(self):
        camera = swell.Camera(position_m=(0.0, 5.0, 0.0), pitch_deg=-15.0)
        size = (160, 120)
        self.renderer.render(camera, 3.0, size)
        labels = self.renderer.render_labels(camera, size)
        drawn = self.renderer.drawn_surface()
        water = (labels.semantic == swell.CLASS_WATER) & (labels.range_m < 60.0)
        self.assertGreater(water.sum(), 5000)
        points = eye_of(labels.camera) + pixel_rays(labels.camera)[water] * labels.range_m[water][:, None]
        heights = drawn.height_m(points[:, 0], points[:, 2])
        # float32 ranges under 60 m are exact to 4 um; the rest is the depth buffer's.
        self.assertLess(np.abs(points[:, 1] - heights).max(), 0.01)
        # The drawn water is not flat (8 m/s of wind), and it is the waves: close to the exact surface.
        exact = self.renderer.surface_height_m(points[:, 0], points[:, 2], 3.0)
        self.assertGreater(np.std(exact), 0.1)
        self.assertLess(np.sqrt(np.mean((heights - exact) ** 2)), 0.1)
        position, normal = drawn.at(points[0, 0], points[0, 2])
        self.assertAlmostEqual(position[1], heights[0], places=9)
        self.assertAlmostEqual(np.linalg.norm(normal), 1.0, places=9)

    def test_a_drawn_surface_goes_stale_with_the_scene(self):
        self.renderer.advance_to(1.0, (0.0, 5.0, 0.0))
        drawn = self.renderer.drawn_surface()
        drawn.height_m(0.0, -10.0)
        self.renderer.set_flat_water(True)
        try:
            with self.assertRaises(swell.Error):
                drawn.height_m(0.0, -10.0)
        finally:
            self.renderer.set_flat_water(False)


if __name__ == "__main__":
    unittest.main()
