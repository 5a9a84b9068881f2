"""Hostile calls into the package (issue 48): every object made by any route
either works or raises, never crashes; every numeric argument is held to the
range `swell render` holds it to, refused with the same words; a frame whose
bodies would be stepped for longer than a still may take is refused as the
executable refuses it; write_png names what is wrong with its array; and
every error of the library's reaches Python as swell.Error."""

import os
import subprocess
import sys
import textwrap
import time
import unittest

import numpy as np

import swell
import support


def tail(message):
    """A message without the name of what it is about: 'time_s: X' and '--time: X' both give 'X'."""
    return message.split(": ", 1)[1]


def cli_error(*args):
    """The message `swell` prints for arguments it refuses (exit 2)."""
    app = support.SWELL_APP
    result = subprocess.run([app, *args], capture_output=True, text=True, timeout=120)
    assert result.returncode == 2, (args, result.returncode, result.stderr)
    line = result.stderr.strip().splitlines()[0]
    return line.removeprefix("swell: error: ")


FLOATING = """[waves.wind]
speed_mps = 8.0

[[objects]]
path = "builtin:buoy"
position_m = [0.0, 0.0, -20.0]
floats = true
density_kg_per_m3 = 400.0
center_of_mass_offset_m = [0.0, -0.9, 0.0]

[grid]
resolution = 32
"""


class ObjectsMadeWithoutTheirConstructor(unittest.TestCase):
    def test_every_attribute_of_every_class_raises_instead_of_crashing(self):
        # In a child: a crash there fails this test instead of ending the run.
        child = textwrap.dedent("""
            import inspect, sys, swell
            classes = [c for c in vars(swell._swell).values() if inspect.isclass(c) and not issubclass(c, BaseException)]
            assert len(classes) >= 8, classes
            arguments = {"render": (swell.Camera(), 0.0, (8, 8)), "render_labels": (swell.Camera(), (8, 8)),
                         "render_sensor": (swell.Camera(), 0.0, (8, 8)), "advance_to": (1.0,),
                         "scene_camera_at": (1.0,), "surface_height_m": (0.0, 0.0, 0.0), "set_scene": (swell.Scene(),),
                         "set_flat_water": (True,), "at": (0.0, 0.0), "height_m": (0.0, 0.0), "get": ("fog.start_m",),
                         "set": ("fog.start_m", 1.0), "__getitem__": ("fog.start_m",),
                         "__setitem__": ("fog.start_m", 1.0), "list_size": ("objects",), "add_object": ("builtin:buoy",),
                         "remove_object": (0,), "object_path": (0,), "camera_at": (0.0,), "save": ("/nonexistent/x",),
                         "project": ((0.0, 0.0, -5.0),), "__deepcopy__": ({},),
                         "optical_flow": (swell.Labels.__new__(swell.Labels), 0.0, swell.Labels.__new__(swell.Labels), 0.1)}
            for cls in classes:
                for name in sorted(vars(cls)):
                    if name.startswith("__") and name not in ("__getitem__", "__setitem__", "__copy__", "__deepcopy__", "__repr__"):
                        continue
                    bare = cls.__new__(cls)
                    print(cls.__name__, name, flush=True)
                    try:
                        attribute = getattr(bare, name)
                        if callable(attribute):
                            attribute(*arguments.get(name, ()))
                    except TypeError as e:
                        assert "__new__" in str(e), (cls.__name__, name, str(e))
                    else:
                        if name != "__repr__":
                            raise AssertionError(f"{cls.__name__}.{name} of an unconstructed object did not raise")
                # And as an argument to another's method.
            bare_camera = swell.Camera.__new__(swell.Camera)
            try:
                swell.calibration_of(bare_camera, (8, 8))
            except TypeError as e:
                assert "Camera.__new__" in str(e), str(e)
            else:
                raise AssertionError("an unconstructed camera was taken")
            print("ok")
            """)
        result = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True, timeout=300)
        self.assertEqual(result.returncode, 0, result.stdout[-2000:] + result.stderr[-3000:])
        self.assertTrue(result.stdout.strip().endswith("ok"))

    def test_a_renderer_made_by_new_then_init_works(self):
        renderer = swell.Renderer.__new__(swell.Renderer)
        with self.assertRaises(TypeError):
            renderer.scene
        renderer.__init__(support.small_scene())
        self.assertEqual(renderer.scene["grid.resolution"], 32)


class RangesAsTheExecutableHoldsThem(support.SmallRendererCase):
    def test_times_outside_0_to_1e9_are_refused_with_the_executables_words(self):
        support.needs_app(self)
        camera = swell.Camera()
        for bad, shown in [(-1.0, "-1"), (1e300, "1e300"), (float("nan"), "nan"), (float("inf"), "inf")]:
            expected = tail(cli_error("render", "-o", "x.png", "--time", shown)).split(", got")[0]
            for call in (lambda: self.renderer.render(camera, bad, (8, 8)),
                         lambda: self.renderer.render_sensor(camera, bad, (8, 8)),
                         lambda: self.renderer.advance_to(bad),
                         lambda: self.renderer.scene_camera_at(bad),
                         lambda: self.renderer.surface_height_m(0.0, 0.0, bad),
                         lambda: self.renderer.scene.camera_at(bad)):
                with self.assertRaises(ValueError, msg=repr(bad)) as caught:
                    call()
                self.assertTrue(str(caught.exception).startswith("time_s: " + expected), str(caught.exception))

    def test_sizes_and_the_render_scale_are_refused_with_the_executables_words(self):
        support.needs_app(self)
        size_words = tail(cli_error("render", "-o", "x.png", "--size", "0x5")).split(", got")[0]
        with self.assertRaises(ValueError) as caught:
            self.renderer.render(swell.Camera(), 0.0, (0, 5))
        self.assertTrue(str(caught.exception).startswith("size: " + size_words), str(caught.exception))
        scale_words = tail(cli_error("render", "-o", "x.png", "--scale", "9")).split(", got")[0]
        with self.assertRaises(swell.InputError) as caught:
            self.renderer.render_scale = 9.0
        self.assertEqual(caught.exception.message.split(", got")[0], scale_words)


class HistoryBound(unittest.TestCase):
    def test_a_floating_body_a_billion_seconds_on_is_refused_at_once_as_the_executable_refuses_it(self):
        app = support.needs_app(self)
        folder = support.output_folder(self)
        path = os.path.join(folder, "floating.toml")
        with open(path, "w") as f:
            f.write(FLOATING)
        renderer = swell.Renderer(swell.load_scene(path))
        started = time.monotonic()
        for call in (lambda: renderer.advance_to(1e9), lambda: renderer.render(swell.Camera(), 1e9, (8, 8))):
            with self.assertRaises(ValueError) as caught:
                call()
            self.assertIn("floating body", str(caught.exception))
            self.assertIn("history_start_s", str(caught.exception))
        self.assertLess(time.monotonic() - started, 5.0, "the refusal stepped the bodies first")
        self.assertIsNone(renderer.simulated_time_s)
        expected = tail(cli_error("render", path, "-o", os.path.join(folder, "x.png"), "--time", "1000000000"))
        self.assertEqual(tail(str(caught.exception)), expected)
        del app


class WritePng(unittest.TestCase):
    def test_arrays_that_are_not_uint8_rgba_are_refused_naming_rgba(self):
        path = os.path.join(support.output_folder(self), "x.png")
        for bad in [np.zeros((4, 4, 4), np.float64), np.zeros((0,), np.uint8), np.zeros((5,), np.uint8),
                    np.zeros((4, 4, 3), np.uint8), np.zeros((0, 4, 4), np.uint8), [[1, 2, 3, 4]], "pixels"]:
            with self.assertRaises(TypeError, msg=repr(bad)) as caught:
                swell.write_png(bad, path)
            self.assertIn("rgba", str(caught.exception))
            self.assertNotIn("Unregistered", str(caught.exception))
        self.assertFalse(os.path.exists(path))

    def test_a_path_under_a_file_raises_swell_error(self):
        folder = support.output_folder(self)
        with open(os.path.join(folder, "a_file"), "w") as f:
            f.write("x")
        with self.assertRaises(swell.Error) as caught:
            swell.write_png(np.zeros((2, 2, 4), np.uint8), os.path.join(folder, "a_file", "x.png"))
        self.assertIn("a_file", str(caught.exception))

    def test_a_strided_uint8_view_is_written_as_its_pixels(self):
        path = os.path.join(support.output_folder(self), "view.png")
        rgba = np.arange(8 * 6 * 4, dtype=np.uint8).reshape(8, 6, 4)[::2, ::-1]
        swell.write_png(rgba, path)
        np.testing.assert_array_equal(swell.read_image(path), rgba)


class LensFolds(unittest.TestCase):
    def test_a_folding_lens_is_refused_at_its_line_naming_the_coefficients_set(self):
        folder = support.output_folder(self)
        path = os.path.join(folder, "lens.toml")
        with open(path, "w") as f:
            f.write("[grid]\nresolution = 32\n\n[camera]\nfov_y_deg = 120.0\ndistortion_p1 = 0.1\ndistortion_p2 = 0.1\n")
        renderer = swell.Renderer(swell.load_scene(path))
        with self.assertRaises(swell.InputError) as caught:
            renderer.render_sensor(renderer.scene_camera_at(0.0), 0.0, (64, 36))
        error = caught.exception
        self.assertEqual((error.path, error.line), (path, 6))
        self.assertIn("camera.distortion_p1 = 0.1 and camera.distortion_p2 = 0.1", error.message)
        self.assertNotIn("distortion_k1", error.message)
        self.assertIsNone(renderer.simulated_time_s, "the lens was checked after rendering")


class SequencesThatMakeTheirItems(unittest.TestCase):
    """A NumPy array makes a new scalar (or a view) each time one of its
    elements is taken, owned by whoever took it. The vectors and sizes read
    from a sequence held that item by a borrowed handle only, so it was freed
    before it was read: a use after free, and a double free when reading it
    took and dropped a reference (the Python fuzzer's seed 86 died of SIGSEGV
    many calls later). Here the items are counted: each must be read before
    it is let go."""

    def read_and_let_go(self, convert, n):
        events, kept = [], []

        class Number:
            def __init__(self, i):
                self.i = i

            def __float__(self):
                events.append(("read", self.i))
                return float(self.i + 1)

            def __del__(self):
                # Kept alive from here on (resurrected), so that a binding
                # that lets go too early reads a live object, and this test
                # fails on the order instead of on freed memory.
                kept.append(self)
                events.append(("let go", self.i))

        class MadeOnEachAccess:
            def __len__(self):
                return n

            def __getitem__(self, i):
                if not 0 <= i < n:
                    raise IndexError(i)
                return Number(i)

        result = convert(MadeOnEachAccess())
        for i in range(n):
            self.assertIn(("read", i), events)
            self.assertIn(("let go", i), events)
            self.assertLess(events.index(("read", i)), events.index(("let go", i)), events)
        return result

    def test_a_position_holds_each_item_while_reading_it(self):
        camera = self.read_and_let_go(lambda v: swell.Camera(position_m=v), 3)
        self.assertEqual(camera.position_m, (1.0, 2.0, 3.0))

    def test_a_size_holds_each_item_while_reading_it(self):
        calibration = self.read_and_let_go(lambda v: swell.calibration_of(swell.Camera(), v), 2)
        self.assertIsNotNone(calibration)

    def test_numpy_arrays_as_positions_and_sizes(self):
        self.assertEqual(swell.Camera(position_m=np.array([1, 2, 3])).position_m, (1.0, 2.0, 3.0))
        self.assertEqual(swell.Camera(position_m=np.arange(3.0, dtype=np.float32)).position_m, (0.0, 1.0, 2.0))
        self.assertIsNotNone(swell.calibration_of(swell.Camera(), np.array([8, 6])))
        with self.assertRaisesRegex(TypeError, "Camera.position_m: expected a number"):
            swell.Camera(position_m=np.zeros((3, 2)))


if __name__ == "__main__":
    unittest.main()
