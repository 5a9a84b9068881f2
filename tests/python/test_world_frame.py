"""The labels' world frame (scene key labels.world_frame; docs/LABELS.md,
"World frames"): the same frame written in Swell's axes, ENU and NED. A
fixed boat at Swell's (3, 1, -20), its bow 30 degrees left of east
(yaw_deg = 30, so heading 060), is at ENU (3, 20, 1) and NED (20, 3, -1),
computed by hand from SCENE.md's axes (x east, y up, -z north); its
heading stays 60 degrees, its box, velocity and the camera's world
transforms turn with it, and what is in camera axes, pixels or the KITTI
files does not change. A frame name the key does not know is refused."""

import json
import os
import subprocess
import unittest

import numpy as np

import support

SCENE = """
history_start_s = 0.0

[sun]
direction = [0.3, 0.5, -0.8]

[[objects]]
path = "builtin:boat"
position_m = [3.0, 1.0, -20.0]
yaw_deg = 30.0

[camera]
position_m = [0.0, 5.0, 0.0]
pitch_deg = -10.0

[labels]
world_frame = "%s"
"""

FRAMES = ["swell", "enu", "ned"]


class WorldFrames(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.app = support.needs_app(cls)
        cls.folder = support.output_folder(cls)
        cls.json, cls.files = {}, {}
        for frame in FRAMES:
            scene = os.path.join(cls.folder, frame + ".toml")
            with open(scene, "w") as f:
                f.write(SCENE % frame)
            png = os.path.join(cls.folder, frame + ".png")
            subprocess.run([cls.app, "render", scene, "-o", png, "--size", "96x72", "--time", "1", "--labels"],
                           check=True, stdout=subprocess.DEVNULL)
            with open(os.path.join(cls.folder, frame + ".json")) as f:
                cls.json[frame] = json.load(f)
            cls.files[frame] = lambda suffix, frame=frame: os.path.join(cls.folder, frame + "." + suffix)

    def test_a_known_boats_position_and_heading(self):
        expected = {"swell": [3.0, 1.0, -20.0], "enu": [3.0, 20.0, 1.0], "ned": [20.0, 3.0, -1.0]}
        for frame in FRAMES:
            written = self.json[frame]
            self.assertEqual(written["world_frame"], frame)
            pose = written["objects"][0]["pose"]
            np.testing.assert_allclose(pose["position_m"], expected[frame], atol=1e-9, err_msg=frame)
            self.assertAlmostEqual(pose["heading_deg"], 60.0, places=9, msg=frame)
            np.testing.assert_allclose(np.array(pose["world_from_object"])[:3, 3], expected[frame], atol=1e-9)

    def test_world_quantities_turn_and_camera_ones_stay(self):
        swell_json = self.json["swell"]
        turns = {"swell": np.eye(3), "enu": np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]]),
                 "ned": np.array([[0, 0, -1], [1, 0, 0], [0, -1, 0]])}
        for frame in ["enu", "ned"]:
            turn, written = turns[frame], self.json[frame]
            ours, theirs = written["objects"][0], swell_json["objects"][0]
            np.testing.assert_allclose(ours["box3d_m"], (turn @ np.array(theirs["box3d_m"]).T).T, atol=1e-9)
            np.testing.assert_allclose(ours["pose"]["camera_from_object"], theirs["pose"]["camera_from_object"],
                                       atol=1e-9)
            np.testing.assert_allclose(ours["velocity"]["linear_mps"], [0, 0, 0])
            # A world point maps to the same camera point from either frame.
            point = np.array([3.0, 1.0, -20.0, 1.0])
            turned = np.append(turn @ point[:3], 1.0)
            np.testing.assert_allclose(np.array(written["camera"]["camera_from_world"]) @ turned,
                                       np.array(swell_json["camera"]["camera_from_world"]) @ point, atol=1e-9)
            sun = turn @ np.array(swell_json["sea"]["sun_direction"])
            np.testing.assert_allclose(written["sea"]["sun_direction"], sun, atol=1e-12)
            self.assertEqual(ours["box_px"], theirs["box_px"])
            # The normals turn: the sea's up is ENU's +z, NED's -z.
            normals = np.load(self.files[frame]("normal.npy"))
            reference = np.load(self.files["swell"]("normal.npy"))
            np.testing.assert_allclose(normals, reference @ turn.T.astype(np.float32), atol=1e-6)
            with open(self.files[frame]("kitti.txt")) as a, open(self.files["swell"]("kitti.txt")) as b:
                self.assertEqual(a.read(), b.read(), "the KITTI boxes stand in the camera's levelled axes")

    def test_an_unknown_frame_is_refused_at_its_place(self):
        scene = os.path.join(self.folder, "ecef.toml")
        with open(scene, "w") as f:
            f.write(SCENE % "ecef")
        png = os.path.join(self.folder, "ecef.png")
        result = subprocess.run([self.app, "render", scene, "-o", png, "--size", "32x24", "--labels"],
                                capture_output=True, text=True)
        self.assertEqual(result.returncode, 2)
        self.assertIn("ecef.toml:", result.stderr)
        self.assertIn("world_frame", result.stderr)
        self.assertFalse(os.path.exists(png))


if __name__ == "__main__":
    unittest.main()
