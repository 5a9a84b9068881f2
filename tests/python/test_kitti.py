"""`swell render --labels` writes NAME.kitti.txt and NAME.kitti_calib.txt
(docs/LABELS.md, "KITTI boxes"): read back here by the conventions of
KITTI's object development kit (its readme.txt: the 15 columns; its
computeBox3D: a box's corners from h, w, l, the location of its bottom
centre and rotation_y, projected by P2), written from those definitions
alone. For objects that stand level, the corners are the JSON's box3d_m
(taken to the world by Tr_velo_to_cam) within 1e-4 m (the file's six
decimals), and their projection by P2 holds the 2D box (1 px) and is the
JSON calibration's projection of box3d_m (1e-3 px). The camera is pitched
and rolled, so the levelled camera is not the camera. The same frame's JSON
gives a rigid body's velocity in camera axes as the world's turned."""

import json
import math
import os
import subprocess
import unittest

import numpy as np

import support

SCENE = """
history_start_s = 0.0

[[objects]]
path = "builtin:boat"
position_m = [-3.0, 0.0, -22.0]
yaw_deg = 35.0

[[objects]]
path = "builtin:rock"
position_m = [6.0, -1.0, -30.0]
yaw_deg = -60.0
class = "reef rock"

[[objects]]
path = "builtin:boat"
position_m = [4.0, 0.0, -14.0]
yaw_deg = 150.0
floats = true
density_kg_per_m3 = 400.0
velocity_m_per_s = [-2.0, 0.0, 1.0]

[camera]
position_m = [0.0, 6.0, 0.0]
yaw_deg = 5.0
pitch_deg = -12.0
roll_deg = 8.0
fov_y_deg = 60.0

[wake]
enabled = false
"""

WIDTH, HEIGHT = 320, 240


def kitti_corners(h, w, l, location, ry):
    """The devkit's computeBox3D: corners in the label's camera axes, (8, 3)."""
    rotation = np.array([[math.cos(ry), 0.0, math.sin(ry)], [0.0, 1.0, 0.0], [-math.sin(ry), 0.0, math.cos(ry)]])
    x = [l / 2, l / 2, -l / 2, -l / 2, l / 2, l / 2, -l / 2, -l / 2]
    y = [0, 0, 0, 0, -h, -h, -h, -h]
    z = [w / 2, -w / 2, -w / 2, w / 2, w / 2, -w / 2, -w / 2, w / 2]
    return (rotation @ np.array([x, y, z])).T + np.array(location)


def read_calibration(path):
    """KITTI's calib file: `name: numbers` a line."""
    calibration = {}
    with open(path) as f:
        for line in f:
            name, numbers = line.split(":", 1)
            calibration[name] = np.array([float(v) for v in numbers.split()])
    return calibration


def project(p, points):
    """x = P [X; 1], divided by its third row."""
    h = p @ np.hstack([points, np.ones((len(points), 1))]).T
    return (h[:2] / h[2]).T


class KittiExport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        app = support.needs_app(cls)
        cls.folder = support.output_folder(cls)
        scene = os.path.join(cls.folder, "kitti.toml")
        with open(scene, "w") as f:
            f.write(SCENE)
        png = os.path.join(cls.folder, "frame.png")
        subprocess.run([app, "render", scene, "-o", png, "--size", "%dx%d" % (WIDTH, HEIGHT), "--time", "3",
                        "--labels"], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(cls.folder, "frame.json")) as f:
            cls.json = json.load(f)
        with open(os.path.join(cls.folder, "frame.kitti.txt")) as f:
            cls.lines = [line.split() for line in f if line.strip()]
        cls.calibration = read_calibration(os.path.join(cls.folder, "frame.kitti_calib.txt"))

    def objects_written(self):
        return [o for o in self.json["objects"] if o["amodal_pixels"] > 0]

    def test_every_object_in_view_has_a_line_of_fifteen_columns(self):
        written = self.objects_written()
        self.assertEqual(len(written), 3, "every object should be in view")
        self.assertEqual(len(self.lines), len(written))
        for line, o in zip(self.lines, written):
            self.assertEqual(len(line), 15)
            self.assertEqual(line[0], o["class"].replace(" ", "_"))
            self.assertAlmostEqual(float(line[1]), o["truncation"], places=6)
            occluded = 0 if o["occlusion"] < 0.01 else 1 if o["occlusion"] < 0.5 else 2
            self.assertEqual(int(line[2]), occluded)
            self.assertEqual([float(v) for v in line[4:8]], [float(v) for v in o["box_px"]])

    def test_the_boxes_corners_are_the_jsons_and_project_around_the_2d_box(self):
        p2 = self.calibration["P2"].reshape(3, 4)
        level_from_world = np.vstack([self.calibration["Tr_velo_to_cam"].reshape(3, 4), [0, 0, 0, 1]])
        world_from_level = np.linalg.inv(level_from_world)
        camera = self.json["camera"]
        k = np.array([[camera["fx_px"], 0, camera["cx_px"]], [0, camera["fy_px"], camera["cy_px"]], [0, 0, 1]])
        camera_p = k @ np.array(camera["camera_from_world"])[:3]
        level = 0
        for line, o in zip(self.lines, self.objects_written()):
            h, w, l = (float(v) for v in line[8:11])
            location = [float(v) for v in line[11:14]]
            ry = float(line[14])
            alpha = float(line[3])
            self.assertAlmostEqual(math.remainder(alpha - (ry - math.atan2(location[0], location[2])), 2 * math.pi),
                                   0.0, places=5)
            corners = kitti_corners(h, w, l, location, ry)
            pixels = project(p2, corners)
            x0, y0, x1, y1 = o["box_px"]
            self.assertLessEqual(pixels[:, 0].min(), x0 + 1.0, o["class"])
            self.assertLessEqual(pixels[:, 1].min(), y0 + 1.0, o["class"])
            self.assertGreaterEqual(pixels[:, 0].max(), x1 - 1.0, o["class"])
            self.assertGreaterEqual(pixels[:, 1].max(), y1 - 1.0, o["class"])
            if o["velocity"] is not None and np.any(o["velocity"]["angular_radps"]):
                continue  # a floating body: its box3d_m tilts with its pitch and roll, KITTI's box does not
            level += 1
            world = (world_from_level @ np.hstack([corners, np.ones((8, 1))]).T).T[:, :3]
            box3d = np.array(o["box3d_m"])
            # The same eight points, in another order.
            distances = np.linalg.norm(world[:, None, :] - box3d[None, :, :], axis=-1)
            self.assertLess(distances.min(axis=1).max(), 1e-4, o["class"])
            self.assertLess(distances.min(axis=0).max(), 1e-4, o["class"])
            # P2 on the corners is the JSON's calibration on box3d_m.
            theirs = project(camera_p, box3d)
            pairs = np.linalg.norm(pixels[:, None, :] - theirs[None, :, :], axis=-1)
            self.assertLess(pairs.min(axis=1).max(), 1e-3, o["class"])
        self.assertEqual(level, 2)

    def test_a_bodys_velocity_in_camera_axes_is_the_worlds_turned(self):
        body = self.json["objects"][2]["velocity"]
        self.assertIsNotNone(body)
        turn = np.array(self.json["camera"]["camera_from_world"])[:3, :3]
        np.testing.assert_allclose(body["camera_linear_mps"], turn @ np.array(body["linear_mps"]), atol=1e-12)
        np.testing.assert_allclose(body["camera_angular_radps"], turn @ np.array(body["angular_radps"]), atol=1e-12)
        self.assertAlmostEqual(body["linear_mps"][0], -2.0, delta=0.1)
        self.assertEqual(self.json["objects"][0]["velocity"], {"linear_mps": [0.0, 0.0, 0.0],
                                                               "angular_radps": [0.0, 0.0, 0.0],
                                                               "camera_linear_mps": [0.0, 0.0, 0.0],
                                                               "camera_angular_radps": [0.0, 0.0, 0.0]})


if __name__ == "__main__":
    unittest.main()
