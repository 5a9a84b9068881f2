"""What the Python package's tests share: where CTest says the swell
executable and the test output folder are, and a fresh output folder per
test case."""

import os
import shutil
import unittest

SOURCE_DIR = os.environ.get("SWELL_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
SWELL_APP = os.environ.get("SWELL_APP", "")
OUTPUT_DIR = os.environ.get("SWELL_TEST_OUTPUT_DIR", "/tmp/swell-python-tests")


def scene_path(name):
    """A preset's file in the source tree (scenes/NAME.toml)."""
    return os.path.join(SOURCE_DIR, "scenes", name + ".toml")


def output_folder(test):
    """An empty folder for a test case's (or a test class's) files, named after it."""
    name = test.id() if isinstance(test, unittest.TestCase) else test.__module__ + "." + test.__qualname__
    folder = os.path.join(OUTPUT_DIR, "python", name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    return folder


def needs_app(test):
    """Skips a case that runs the swell executable when the build has none."""
    if not SWELL_APP or not os.path.exists(SWELL_APP):
        raise unittest.SkipTest("no swell executable (SWELL_APP) in this build")
    return SWELL_APP


def small_scene():
    """The default scene on a 32-vertex grid: quick to draw."""
    import swell
    scene = swell.default_scene()
    scene["grid.resolution"] = 32
    return scene


class SmallRendererCase(unittest.TestCase):
    """Cases sharing one renderer of small_scene(), made once for the class."""

    @classmethod
    def setUpClass(cls):
        import swell
        cls.renderer = swell.Renderer(small_scene())

    @classmethod
    def tearDownClass(cls):
        cls.renderer = None

