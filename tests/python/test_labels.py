"""Labels against geometry computed in NumPy from what the package returns:
on calm water every water pixel's range is the distance along its ray to
the sea's plane (from the returned calibration, within 1 cm below 100 km),
the sky and the water meet on the returned horizon line; an object's
pixels carry its instance and class, its 2D box lies within its projected
3D box, and every range on it lands inside that box, placed by the
returned object transform."""

import os
import tempfile
import unittest

import numpy as np

import swell

SIZE = (320, 240)


def open_sea():
    scene = swell.default_scene()
    scene["terrain"] = False
    while scene.list_size("objects"):
        scene.remove_object(0)
    return scene


def pixel_rays(calibration):
    """Unit world directions of every pixel centre's ray, (H, W, 3)."""
    w, h = calibration.size
    x, y = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
    camera = np.stack([(x - calibration.cx_px) / calibration.fx_px, (y - calibration.cy_px) / calibration.fy_px,
                       np.ones_like(x)], axis=-1)
    world = camera @ calibration.world_from_camera[:3, :3].T
    return world / np.linalg.norm(world, axis=-1, keepdims=True)


def eye_of(calibration):
    return calibration.world_from_camera[:3, 3]


class CalmWater(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.renderer = swell.Renderer(open_sea())
        cls.renderer.set_flat_water(True)

    @classmethod
    def tearDownClass(cls):
        cls.renderer = None

    def check(self, height_m, roll_deg, pitch_deg):
        camera = swell.Camera(position_m=(30.0, height_m, -12.0), yaw_deg=25.0, pitch_deg=pitch_deg, roll_deg=roll_deg)
        self.renderer.render(camera, 0.0, SIZE)
        labels = self.renderer.render_labels(camera, SIZE)
        calibration = labels.camera
        np.testing.assert_allclose(eye_of(calibration), camera.position_m, atol=1e-9)
        rays = pixel_rays(calibration)
        water = labels.semantic == swell.CLASS_WATER
        self.assertGreater(water.sum(), 0.2 * water.size)
        # The ray from the eye meets the plane y = 0 after height / -dy.
        with np.errstate(divide="ignore"):
            expected_m = np.where(rays[..., 1] < 0.0, height_m / -rays[..., 1], np.inf)
        near = water & (expected_m < 1.0e5)
        error_m = np.abs(labels.range_m[near].astype(np.float64) - expected_m[near])
        self.assertLess(error_m.max(), 0.01, "range off by %.4f m" % error_m.max())
        # Water below the horizon line, sky above it, beyond 1 px of it.
        a, b, c = labels.horizon.line
        w, h = SIZE
        x, y = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
        side_px = a * x + b * y + c
        self.assertTrue(np.all(labels.semantic[side_px < -1.0] == swell.CLASS_WATER))
        self.assertTrue(np.all(labels.semantic[side_px > 1.0] == swell.CLASS_SKY))
        # Flat water's normal is up.
        np.testing.assert_allclose(labels.normal[water], np.tile([0.0, 1.0, 0.0], (water.sum(), 1)), atol=1e-3)

    def test_low_level_camera(self):
        self.check(2.0, 0.0, -4.0)

    def test_high_rolled_camera(self):
        self.check(50.0, 15.0, -20.0)


class ObjectLabels(unittest.TestCase):
    def test_an_objects_pixels_lie_in_its_box(self):
        scene = open_sea()
        i = scene.add_object("builtin:boat")
        scene[f"objects[{i}].position_m"] = (2.0, 0.0, -30.0)
        scene[f"objects[{i}].yaw_deg"] = 30.0
        renderer = swell.Renderer(scene)
        renderer.set_flat_water(True)
        camera = swell.Camera(position_m=(0.0, 4.0, 0.0), pitch_deg=-6.0)
        renderer.render(camera, 0.0, SIZE)
        labels = renderer.render_labels(camera, SIZE)
        (boat,) = labels.objects
        self.assertEqual((boat.instance, boat.class_name, labels.classes[boat.class_id]), (1, "boat", "boat"))
        mine = labels.instance == boat.instance
        self.assertEqual(mine.sum(), boat.visible_pixels)
        self.assertGreater(boat.visible_pixels, 200)
        self.assertTrue(np.all(labels.semantic[mine] == boat.class_id))
        # The 2D box: the smallest one holding the pixels, within the 3D box's projection (1 px slack).
        ys, xs = np.nonzero(mine)
        self.assertEqual(boat.box_px, (xs.min(), ys.min(), xs.max() + 1, ys.max() + 1))
        projected = np.array([labels.camera.project(corner) for corner in boat.box3d_m])
        x0, y0, x1, y1 = boat.box_px
        self.assertGreaterEqual(x0, projected[:, 0].min() - 1.0)
        self.assertGreaterEqual(y0, projected[:, 1].min() - 1.0)
        self.assertLessEqual(x1, projected[:, 0].max() + 1.0)
        self.assertLessEqual(y1, projected[:, 1].max() + 1.0)
        # Every point the boat's pixels see lies in its 3D box: in the
        # boat's own axes (the inverse of its transform) the box is axis-aligned.
        (transform,) = renderer.object_transforms()
        local_from_world = np.linalg.inv(transform)
        corners = (np.c_[boat.box3d_m, np.ones(8)] @ local_from_world.T)[:, :3]
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        points = eye_of(labels.camera) + pixel_rays(labels.camera)[mine] * labels.range_m[mine][:, None]
        local = (np.c_[points, np.ones(len(points))] @ local_from_world.T)[:, :3]
        self.assertTrue(np.all(local >= lo - 0.01) and np.all(local <= hi + 0.01),
                        "a boat pixel's point lies %.3f m outside its box"
                        % max((lo - local).max(), (local - hi).max()))
        # The corners in its own axes take two values on each axis: the box is its mesh's, placed by the transform.
        for axis in range(3):
            self.assertEqual(len(np.unique(np.round(corners[:, axis], 6))), 2)


if __name__ == "__main__":
    unittest.main()


class Sensor(unittest.TestCase):
    """render_sensor: without a lens, render() and render_labels() as they are; through a lens, the
    calibration carries the coefficients and the labels' water lies below the written model's horizon."""

    def test_without_a_lens_it_is_render_and_render_labels(self):
        scene = open_sea()
        renderer = swell.Renderer(scene)
        camera = scene.camera_at(0.0)
        image, labels = renderer.render_sensor(camera, 1.0, (96, 64))
        np.testing.assert_array_equal(image, renderer.render(camera, 1.0, (96, 64)))
        np.testing.assert_array_equal(labels.semantic, renderer.render_labels(camera, (96, 64)).semantic)
        self.assertEqual(labels.camera.distortion, (0.0, 0.0, 0.0, 0.0, 0.0))

    def test_through_a_lens_the_calibration_carries_it(self):
        scene = open_sea()
        scene["camera.distortion_k1"] = -0.1
        renderer = swell.Renderer(scene)
        image, labels = renderer.render_sensor(scene.camera_at(0.0), 1.0, (96, 64))
        self.assertEqual(image.shape, (64, 96, 4))
        self.assertEqual(labels.camera.distortion[0], -0.1)
        self.assertTrue(labels.horizon.curve_px)
        self.assertFalse((labels.semantic == 0).any())

    def test_the_scenes_own_camera_moves_while_the_shutter_is_open(self):
        """camera=None: the scene's camera at each draw's time; a camera turning on its path blurs the sky's
        buoy, a camera held at the instant (the Camera given) does not move, and the labels are the instant's."""
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "turning.toml")
            with open(path, "w") as f:
                f.write(TURNING_PAST_A_BUOY)
            scene = swell.load(path)
        renderer = swell.Renderer(scene)
        moving, labels = renderer.render_sensor(None, 1.0, (96, 64))
        held, held_labels = renderer.render_sensor(renderer.scene_camera_at(1.0), 1.0, (96, 64))
        instant = renderer.render(renderer.scene_camera_at(1.0), 1.0, (96, 64))
        sky = slice(0, 30)
        self.assertGreater(np.abs(moving[sky].astype(int) - instant[sky].astype(int)).mean(), 1.0)
        self.assertLess(np.abs(held[sky].astype(int) - instant[sky].astype(int)).mean(), 0.1)
        np.testing.assert_array_equal(labels.instance, held_labels.instance)


# A camera turning at 30 degrees a second past a buoy standing in the sky, its shutter open 0.1 s.
TURNING_PAST_A_BUOY = """
terrain = false

[[objects]]
path = "builtin:buoy"
position_m = [0.0, 6.0, -20.0]
scale = 3.0

[camera]
shutter_s = 0.1
motion_samples = 8

[[camera.path]]
time_s = 0.0
position_m = [0.0, 2.0, 0.0]
yaw_deg = -30.0
pitch_deg = 0.0

[[camera.path]]
time_s = 2.0
position_m = [0.0, 2.0, 0.0]
yaw_deg = 30.0
pitch_deg = 0.0
"""


class Shoreline(unittest.TestCase):
    """The coast preset's shoreline: each chain's corners lie between a water (or foam, or surf) and a terrain
    (dry or wet) pixel, and each
    corner's water point is a touching water pixel's range along its ray."""

    def test_corners_lie_between_water_and_land(self):
        scene = swell.load("coast")
        renderer = swell.Renderer(scene)
        camera = renderer.scene_camera_at(0.0)
        renderer.render(camera, 20.0, SIZE)
        labels = renderer.render_labels(camera, SIZE)
        self.assertTrue(labels.shoreline)
        water = np.isin(labels.semantic,
                        [swell.CLASS_WATER, swell.CLASS_WHITECAP_FOAM, swell.CLASS_WAKE_FOAM, swell.CLASS_SURF])
        land = np.isin(labels.semantic, [swell.CLASS_TERRAIN, swell.CLASS_WET_SAND])
        self.assertTrue(np.any(labels.semantic == swell.CLASS_SURF))
        self.assertTrue(np.any(labels.semantic == swell.CLASS_WET_SAND))
        rays = pixel_rays(labels.camera)
        eye = eye_of(labels.camera)
        w, h = SIZE
        corners = 0
        for points_px, points_m in labels.shoreline:
            self.assertEqual(points_px.shape[1], 2)
            self.assertEqual(points_m.shape, (points_px.shape[0], 3))
            for (cx, cy), point in zip(points_px.astype(int), points_m):
                touching = [(x, y) for x in (cx - 1, cx) for y in (cy - 1, cy) if 0 <= x < w and 0 <= y < h]
                self.assertTrue(any(water[y, x] for x, y in touching))
                self.assertTrue(any(land[y, x] for x, y in touching))
                candidates = [eye + labels.range_m[y, x] * rays[y, x] for x, y in touching if water[y, x]]
                # float32 ranges of up to a few km: within a millimetre in a metre.
                self.assertLess(min(np.linalg.norm(c - point) / np.linalg.norm(c - eye) for c in candidates), 1e-6)
                corners += 1
        self.assertGreater(corners, 50)
