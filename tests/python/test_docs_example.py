"""The examples of docs/PYTHON.md run as printed: its first Python block,
run in a fresh folder, renders the labelled frame and writes its PNG; its
second sets and saves scene keys."""

import contextlib
import io
import os
import re
import unittest

import numpy as np

import swell
import support


class DocsExample(unittest.TestCase):
    def test_the_labelled_frame_example_runs(self):
        with open(os.path.join(support.SOURCE_DIR, "docs", "PYTHON.md")) as f:
            blocks = re.findall(r"```python\n(.*?)```", f.read(), re.S)
        self.assertTrue(blocks, "docs/PYTHON.md has no python block")
        folder = support.output_folder(self)
        here = os.getcwd()
        os.chdir(folder)
        try:
            printed = io.StringIO()
            namespace = {}
            with contextlib.redirect_stdout(printed):
                exec(compile(blocks[0], "docs/PYTHON.md", "exec"), namespace)
        finally:
            os.chdir(here)
        labels = namespace["labels"]
        self.assertEqual(labels.range_m.shape, (480, 640))
        np.testing.assert_array_equal(swell.read_image(os.path.join(folder, "storm.png")), namespace["rgba"])
        # It prints a line for each of the storm's two objects.
        self.assertEqual(len(printed.getvalue().splitlines()), 2)

    def test_the_scene_keys_example_runs_as_printed(self):
        # The second block, alone in a fresh interpreter's namespace: what it
        # uses it imports, and the keys it sets are the scene's.
        with open(os.path.join(support.SOURCE_DIR, "docs", "PYTHON.md")) as f:
            blocks = re.findall(r"```python\n(.*?)```", f.read(), re.S)
        self.assertGreaterEqual(len(blocks), 2, "docs/PYTHON.md has no second python block")
        folder = support.output_folder(self)
        here = os.getcwd()
        os.chdir(folder)
        try:
            namespace = {}
            exec(compile(blocks[1], "docs/PYTHON.md", "exec"), namespace)
        finally:
            os.chdir(here)
        scene = namespace["scene"]
        self.assertEqual(scene["fog.start_m"], 800.0)
        self.assertTrue(scene[f"objects[{namespace['i']}].floats"])
        self.assertEqual(swell.load_scene(os.path.join(folder, "edited.toml"))["antialiasing"], "msaa4")


if __name__ == "__main__":
    unittest.main()
