"""The Python package draws what the swell executable draws: for the same
scene, time and size, its colour frame is `swell render`'s PNG bit for bit
(the very file bytes, through the library's PNG writer), and its labels
are the executable's .npy arrays and JSON. Arrays have the documented
shapes and dtypes."""

import json
import os
import subprocess
import unittest

import numpy as np

import swell
import support

SIZE = (160, 120)
TIME_S = 20.0


class SameAsTheExecutable(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        app = support.needs_app(cls)
        cls.folder = support.output_folder(cls)
        # A spectral storm with foam, a boat and a buoy: every label class but terrain.
        cls.cli_png = os.path.join(cls.folder, "storm.png")
        subprocess.run([app, "render", "storm", "-o", cls.cli_png, "--size", "%dx%d" % SIZE, "--time", str(TIME_S),
                        "--labels"], check=True, stdout=subprocess.DEVNULL)
        cls.scene = swell.load("storm")
        cls.renderer = swell.Renderer(cls.scene)
        cls.camera = cls.scene.camera_at(TIME_S)
        cls.rgba = cls.renderer.render(cls.camera, TIME_S, SIZE)
        cls.labels = cls.renderer.render_labels(cls.camera, SIZE)

    @classmethod
    def tearDownClass(cls):
        cls.renderer = None

    def cli(self, suffix):
        return os.path.join(self.folder, "storm." + suffix)

    def test_the_colour_frame_is_the_executables_png_bit_for_bit(self):
        self.assertEqual(self.rgba.shape, (SIZE[1], SIZE[0], 4))
        self.assertEqual(self.rgba.dtype, np.uint8)
        ours = os.path.join(self.folder, "python.png")
        swell.write_png(self.rgba, ours)
        with open(ours, "rb") as a, open(self.cli_png, "rb") as b:
            self.assertTrue(a.read() == b.read(), "the PNG written from Python differs from swell render's")
        np.testing.assert_array_equal(swell.read_image(self.cli_png), self.rgba)
        # Not a blank frame: sky, sea and foam differ.
        self.assertGreater(len(np.unique(self.rgba.reshape(-1, 4), axis=0)), 100)

    def test_the_label_arrays_are_the_executables(self):
        h, w = SIZE[1], SIZE[0]
        expected = {"range_m": ("range", np.float32, (h, w)), "depth_m": ("depth", np.float32, (h, w)),
                    "normal": ("normal", np.float32, (h, w, 3)),
                    "semantic": ("semantic", np.uint16, (h, w)), "instance": ("instance", np.uint16, (h, w))}
        for name, (suffix, dtype, shape) in expected.items():
            ours = getattr(self.labels, name)
            self.assertEqual(ours.dtype, dtype, name)
            self.assertEqual(ours.shape, shape, name)
            np.testing.assert_array_equal(ours, np.load(self.cli(suffix + ".npy")), err_msg=name)
        # The amodal masks, one per object: each holds the object's visible pixels.
        amodal = self.labels.amodal
        self.assertEqual((amodal.dtype, amodal.shape), (np.uint8, (len(self.labels.objects), h, w)))
        np.testing.assert_array_equal(amodal, np.load(self.cli("amodal.npy")))
        for k, o in enumerate(self.labels.objects):
            self.assertEqual(int(amodal[k].sum()), o.amodal_pixels)
            self.assertTrue(np.all(amodal[k][self.labels.instance == o.instance] == 1), o.class_name)
        semantic = self.labels.semantic
        for cls in [swell.CLASS_SKY, swell.CLASS_WATER, swell.CLASS_FIRST_OBJECT]:
            self.assertIn(cls, semantic, "class %d not in the frame" % cls)
        sky = semantic == swell.CLASS_SKY
        self.assertTrue(np.all(np.isinf(self.labels.range_m[sky])))
        self.assertTrue(np.all(np.isfinite(self.labels.range_m[~sky])))
        lengths = np.linalg.norm(self.labels.normal[~sky], axis=-1)
        np.testing.assert_allclose(lengths, 1.0, atol=1e-3)

    def test_the_calibration_horizon_and_objects_are_the_executables_json(self):
        with open(self.cli("json")) as f:
            cli = json.load(f)
        camera = self.labels.camera
        self.assertEqual(camera.size, tuple(cli["size"]))
        for key in ["fx_px", "fy_px", "cx_px", "cy_px"]:
            self.assertEqual(getattr(camera, key), cli["camera"][key], key)
        np.testing.assert_array_equal(camera.camera_from_world, np.array(cli["camera"]["camera_from_world"]))
        np.testing.assert_array_equal(camera.world_from_camera, np.array(cli["camera"]["world_from_camera"]))
        np.testing.assert_array_equal(camera.intrinsics, [[camera.fx_px, 0, camera.cx_px], [0, camera.fy_px, camera.cy_px],
                                                          [0, 0, 1]])
        self.assertEqual(self.labels.horizon.line, tuple(cli["horizon"]["line"]))
        self.assertEqual(self.labels.horizon.visible, cli["horizon"]["visible"])
        classes = {str(i): name for i, name in enumerate(self.labels.classes) if name}
        self.assertEqual(classes, cli["classes"])
        self.assertEqual(len(self.labels.objects), len(cli["objects"]))
        for ours, theirs in zip(self.labels.objects, cli["objects"]):
            self.assertEqual((ours.instance, ours.class_name, ours.class_id, ours.visible_pixels, list(ours.box_px)),
                             (theirs["instance"], theirs["class"], theirs["class_id"], theirs["visible_pixels"],
                              theirs["box_px"]))
            np.testing.assert_array_equal(ours.box3d_m, np.array(theirs["box3d_m"]))
            # How much of it shows.
            self.assertEqual((ours.amodal_pixels, ours.occlusion, ours.truncation),
                             (theirs["amodal_pixels"], theirs["occlusion"], theirs["truncation"]))
            # The pose, in world axes and in the camera's.
            pose = theirs["pose"]
            np.testing.assert_array_equal(ours.world_from_object, np.array(pose["world_from_object"]))
            np.testing.assert_array_equal(ours.position_m, np.array(pose["position_m"]))
            self.assertEqual((ours.yaw_deg, ours.pitch_deg, ours.roll_deg, ours.heading_deg, ours.scale),
                             (pose["yaw_deg"], pose["pitch_deg"], pose["roll_deg"], pose["heading_deg"], pose["scale"]))
            camera_from_object = camera.camera_from_world @ ours.world_from_object
            np.testing.assert_allclose(np.array(pose["camera_from_object"]), camera_from_object, atol=1e-9)
            np.testing.assert_allclose(np.array(pose["camera_position_m"]), camera_from_object[:3, 3], atol=1e-9)
            # The velocity, in world axes and the camera's; null (None) for an object that rides the
            # water without being a rigid body.
            velocity = theirs["velocity"]
            if velocity is None:
                self.assertIsNone(ours.velocity_mps)
                self.assertIsNone(ours.angular_velocity_radps)
                continue
            np.testing.assert_array_equal(ours.velocity_mps, np.array(velocity["linear_mps"]))
            np.testing.assert_array_equal(ours.angular_velocity_radps, np.array(velocity["angular_radps"]))
            turn = camera.camera_from_world[:3, :3]
            np.testing.assert_allclose(np.array(velocity["camera_linear_mps"]), turn @ ours.velocity_mps, atol=1e-12)
            np.testing.assert_allclose(np.array(velocity["camera_angular_radps"]), turn @ ours.angular_velocity_radps,
                                       atol=1e-12)
        # The calibration computed on the CPU for the same camera is the frame's.
        cpu = swell.calibration_of(self.camera, SIZE)
        np.testing.assert_array_equal(cpu.camera_from_world, camera.camera_from_world)
        self.assertEqual(swell.horizon_of(cpu).line, self.labels.horizon.line)

    def test_the_optical_flow_is_the_executables(self):
        # The executable's still: its flow to labels drawn one frame (1/30 s) later.
        with open(self.cli("json")) as f:
            interval_s = json.load(f)["flow"]["interval_s"]
        self.assertEqual(interval_s, 1.0 / 30.0)
        renderer = swell.Renderer(self.scene)
        now_s, next_s = TIME_S, TIME_S + interval_s
        renderer.render(renderer.scene_camera_at(now_s), now_s, SIZE)
        labels = renderer.render_labels(renderer.scene_camera_at(now_s), SIZE)
        renderer.render(renderer.scene_camera_at(next_s), next_s, SIZE)
        later = renderer.render_labels(renderer.scene_camera_at(next_s), SIZE)
        flow, valid = renderer.optical_flow(labels, now_s, later, interval_s)
        self.assertEqual((flow.dtype, flow.shape), (np.float32, (SIZE[1], SIZE[0], 2)))
        self.assertEqual((valid.dtype, valid.shape), (np.uint8, (SIZE[1], SIZE[0])))
        np.testing.assert_array_equal(flow, np.load(self.cli("flow.npy")))
        np.testing.assert_array_equal(valid, np.load(self.cli("flow_valid.npy")))
        # The sky is never valid; most of the sea and the boats are.
        sky = labels.semantic == swell.CLASS_SKY
        self.assertFalse(np.any(valid[sky]))
        self.assertGreater(valid[~sky].mean(), 0.9)


class RenderArguments(support.SmallRendererCase):
    def test_bad_sizes_times_and_cameras_raise(self):
        camera = swell.Camera()
        for size in [(0, 10), (10, -1), (16385, 10), (10.5, 10), (10,), "10x10"]:
            with self.assertRaises((ValueError, TypeError), msg=repr(size)):
                self.renderer.render(camera, 0.0, size)
        with self.assertRaises(ValueError):
            self.renderer.render(camera, float("nan"), (8, 8))
        camera.near_m = 50.0
        camera.far_m = 10.0
        with self.assertRaises(ValueError) as caught:
            self.renderer.render(camera, 0.0, (8, 8))
        self.assertIn("near_m", str(caught.exception))

    def test_labels_follow_the_size_asked(self):
        camera = swell.Camera(position_m=(0.0, 4.0, 0.0), pitch_deg=-10.0)
        frame = self.renderer.render(camera, 1.0, (37, 23))
        self.assertEqual(frame.shape, (23, 37, 4))
        labels = self.renderer.render_labels(camera, (37, 23))
        self.assertEqual(labels.range_m.shape, (23, 37))
        self.assertEqual(labels.size, (37, 23))


if __name__ == "__main__":
    unittest.main()
