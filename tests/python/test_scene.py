"""Scenes from Python without GL: loading files and presets, every value
read and written through the parameter table with its range checked, and
the errors a user gets for a bad key, value or file."""

import os
import tempfile
import unittest

import swell
import support


class SceneValues(unittest.TestCase):
    def test_every_key_reads_back_what_the_table_holds(self):
        scene = swell.default_scene()
        keys = scene.keys()
        self.assertIn("waves.wind.speed_mps", keys)
        self.assertIn("objects[1].position_m", keys)
        for key in keys:
            info = swell.parameter(key)
            value = scene[key]
            # Every key set to what it holds is accepted and changes nothing.
            scene[key] = value
            self.assertEqual(scene[key], value, key)
            if info["kind"] == "choice":
                self.assertIn(value, info["choices"], key)

    def test_a_set_value_is_what_the_scene_file_holds(self):
        scene = swell.default_scene()
        scene["waves.wind.speed_mps"] = 12.5
        scene["fog.color"] = (0.5, 0.25, 0.125)
        scene["objects[1].scale"] = 2.0
        scene["antialiasing"] = "msaa4"
        scene["grid.resolution"] = 64
        scene["terrain"] = False
        again = swell.parse_scene(scene.to_toml(), "again.toml")
        self.assertEqual(again["waves.wind.speed_mps"], 12.5)
        self.assertEqual(again["fog.color"], (0.5, 0.25, 0.125))
        self.assertEqual(again["objects[1].scale"], 2.0)
        self.assertEqual(again["antialiasing"], "msaa4")
        self.assertEqual(again["grid.resolution"], 64)
        self.assertIs(again["terrain"], False)

    def test_the_sun_by_its_angles_as_sweeps_vary_it(self):
        # The keys a sweep varies are the scene's: setting one gives the sun
        # by its angles, which the saved scene writes back.
        scene = swell.default_scene()
        scene["sun.elevation_deg"] = 10.0
        scene["sun.azimuth_deg"] = 90.0
        self.assertNotIn("sun.direction", scene.keys())
        again = swell.parse_scene(scene.to_toml(), "again.toml")
        self.assertEqual((again["sun.elevation_deg"], again["sun.azimuth_deg"]), (10.0, 90.0))
        with self.assertRaises(KeyError):
            again["sun.direction"]

    def test_a_copy_is_independent(self):
        scene = swell.default_scene()
        copy = scene.copy()
        copy["fog.start_m"] = 10.0
        self.assertNotEqual(scene["fog.start_m"], 10.0)

    def test_objects_are_added_and_removed(self):
        scene = swell.default_scene()
        n = scene.list_size("objects")
        i = scene.add_object("builtin:buoy")
        self.assertEqual(i, n)
        scene[f"objects[{i}].position_m"] = (5.0, 0.0, -20.0)
        self.assertEqual(scene.object_path(i), "builtin:buoy")
        self.assertEqual(scene[f"objects[{i}].position_m"], (5.0, 0.0, -20.0))
        scene.validate()
        scene.remove_object(i)
        self.assertEqual(scene.list_size("objects"), n)


class BadValues(unittest.TestCase):
    def test_an_unknown_key_is_named_with_a_suggestion(self):
        scene = swell.default_scene()
        with self.assertRaises(KeyError) as caught:
            scene["fog.strat_m"] = 1.0
        self.assertIn("fog.strat_m", str(caught.exception))
        self.assertIn("did you mean fog.start_m", str(caught.exception))
        with self.assertRaises(KeyError):
            scene["no.such.key"]

    def test_a_value_out_of_range_names_the_key_and_the_range(self):
        scene = swell.default_scene()
        with self.assertRaises(ValueError) as caught:
            scene["fog.start_m"] = -5.0
        self.assertEqual(str(caught.exception), "fog.start_m = -5 is out of range; allowed 0..1000000 m")
        with self.assertRaises(ValueError) as caught:
            scene["objects[0].position_m"] = (0.0, float("nan"), 0.0)
        self.assertIn("objects[0].position_m", str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            scene["antialiasing"] = "msaa8"
        self.assertIn('"off", "msaa4" or "fxaa"', str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            scene["grid.resolution"] = 4
        self.assertIn("grid.resolution", str(caught.exception))
        # Nothing was changed by a refused value.
        self.assertEqual(scene["fog.start_m"], swell.default_scene()["fog.start_m"])

    def test_a_value_of_the_wrong_type_names_the_key(self):
        scene = swell.default_scene()
        for key, value in [("fog.start_m", "far"), ("terrain", 1), ("grid.resolution", 64.5),
                           ("fog.color", (1.0, 1.0)), ("antialiasing", 2)]:
            with self.assertRaises(TypeError, msg=key) as caught:
                scene[key] = value
            self.assertIn(key, str(caught.exception))

    def test_list_items_are_checked(self):
        scene = swell.default_scene()
        with self.assertRaises(IndexError) as caught:
            scene["objects[9].scale"] = 1.0
        self.assertIn("objects[9].scale", str(caught.exception))
        with self.assertRaises(KeyError) as caught:
            scene["objects.scale"]
        self.assertIn("objects[0].scale", str(caught.exception))

    def test_cross_field_rules_are_checked_by_validate(self):
        scene = swell.default_scene()
        scene["fog.start_m"] = 5000.0
        scene["fog.end_m"] = 100.0
        with self.assertRaises(swell.InputError) as caught:
            scene.validate()
        self.assertIn("fog.end_m", str(caught.exception))

    def test_camera_fields_take_the_scene_keys_ranges(self):
        camera = swell.Camera(position_m=(0.0, 3.0, 0.0), pitch_deg=-5.0)
        with self.assertRaises(ValueError) as caught:
            camera.pitch_deg = 95.0
        self.assertEqual(str(caught.exception), "Camera.pitch_deg = 95 is out of range; allowed -89..89 deg")
        with self.assertRaises(ValueError):
            swell.Camera(fov_y_deg=200.0)
        with self.assertRaises(TypeError):
            camera.position_m = (1.0, 2.0)
        self.assertEqual(camera.pitch_deg, -5.0)


class SceneFiles(unittest.TestCase):
    def test_a_bad_scene_file_raises_at_its_line(self):
        folder = support.output_folder(self)
        path = os.path.join(folder, "bad.toml")
        with open(path, "w") as f:
            f.write("[fog]\nstart_m = 100.0\nend_m = -3.0\n")
        with self.assertRaises(swell.InputError) as caught:
            swell.load_scene(path)
        error = caught.exception
        self.assertTrue(str(error).startswith(path + ":3:"), str(error))
        self.assertIn("fog.end_m", str(error))
        self.assertEqual((error.path, error.line), (path, 3))

    def test_presets_are_found_by_name(self):
        names = swell.preset_names()
        for name in ["storm", "calm", "under-way"]:
            self.assertIn(name, names)
        storm = swell.load("storm")
        self.assertEqual(os.path.realpath(storm.file), os.path.realpath(support.scene_path("storm")))
        self.assertEqual(swell.load("storm.toml")["waves.wind.speed_mps"], storm["waves.wind.speed_mps"])
        with self.assertRaises(swell.InputError) as caught:
            swell.load("stromy")
        self.assertIn("storm", str(caught.exception))
        self.assertIn("no preset of that name", str(caught.exception))

    def test_a_saved_scene_loads_back_equal(self):
        scene = swell.load(support.scene_path("sunset"))
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "saved.toml")
            scene.save(path)
            again = swell.load_scene(path)
        for key in scene.keys():
            self.assertEqual(again[key], scene[key], key)


if __name__ == "__main__":
    unittest.main()
