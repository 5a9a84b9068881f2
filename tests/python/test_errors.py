"""What goes wrong from Python becomes a Python exception with the
library's message, never a crash: calls out of order, scenes that fail
their checks (naming the key or the file), a renderer used from another
thread."""

import os
import threading
import unittest

import swell
import support


small_scene = support.small_scene


class Errors(support.SmallRendererCase):
    def test_labels_before_any_frame_raise_the_librarys_error(self):
        fresh = swell.Renderer(small_scene())
        with self.assertRaises(swell.Error) as caught:
            fresh.render_labels(swell.Camera(), (16, 16))
        self.assertIsInstance(caught.exception, RuntimeError)
        self.assertNotIsInstance(caught.exception, swell.InputError)

    def test_a_scene_that_fails_its_checks_is_refused_naming_the_key(self):
        scene = small_scene()
        scene["fog.start_m"] = 5000.0
        scene["fog.end_m"] = 100.0
        with self.assertRaises(swell.InputError) as caught:
            swell.Renderer(scene)
        self.assertIn("fog.end_m", str(caught.exception))
        # set_scene refuses it too, keeping the scene it had.
        with self.assertRaises(swell.InputError):
            self.renderer.set_scene(scene)
        self.assertEqual(self.renderer.scene["fog.end_m"], small_scene()["fog.end_m"])

    def test_a_missing_model_is_named_with_its_object(self):
        scene = small_scene()
        i = scene.add_object("no-such-model.glb")
        with self.assertRaises(swell.InputError) as caught:
            swell.Renderer(scene)
        self.assertIn("objects[%d].path" % i, str(caught.exception))
        self.assertIn("no-such-model.glb", str(caught.exception))

    def test_a_bad_model_file_is_named(self):
        folder = support.output_folder(self)
        path = os.path.join(folder, "scene.toml")
        with open(os.path.join(folder, "broken.glb"), "wb") as f:
            f.write(b"glTF\x02\x00\x00\x00")
        with open(path, "w") as f:
            f.write('[[objects]]\npath = "broken.glb"\n')
        with self.assertRaises(swell.InputError) as caught:
            swell.Renderer(swell.load_scene(path))
        self.assertTrue(str(caught.exception).startswith(path + ":2:"), str(caught.exception))

    def test_a_render_scale_out_of_range_raises(self):
        with self.assertRaises(swell.InputError):
            self.renderer.render_scale = 3.0
        self.assertEqual(self.renderer.render_scale, 1.0)

    def test_another_thread_gets_an_error_not_a_crash(self):
        errors = []

        def render():
            try:
                self.renderer.render(swell.Camera(), 0.0, (8, 8))
            except swell.Error as e:
                errors.append(str(e))

        thread = threading.Thread(target=render)
        thread.start()
        thread.join()
        self.assertEqual(len(errors), 1)
        self.assertIn("thread", errors[0])
        # The renderer still draws on its own thread.
        self.assertEqual(self.renderer.render(swell.Camera(), 0.0, (8, 8)).shape, (8, 8, 4))


if __name__ == "__main__":
    unittest.main()
