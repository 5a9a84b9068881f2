"""Swell, a real-time ocean renderer, from Python (docs/PYTHON.md).

Scenes are loaded from files or presets, or built from the default, and
read and written by their scene-file keys through the parameter table;
a headless Renderer draws colour frames and their labels into NumPy
arrays, steps the simulation and answers surface queries::

    import swell
    scene = swell.load("storm")                    # a preset, or a path to a .toml
    scene["waves.wind.speed_mps"] = 15.0           # checked against its range
    renderer = swell.Renderer(scene)
    camera = scene.camera_at(20.0)
    rgba = renderer.render(camera, 20.0, (640, 480))   # uint8 (480, 640, 4)
    labels = renderer.render_labels(camera, (640, 480))
    labels.range_m, labels.semantic, labels.camera.intrinsics
"""

import os
import sys

from . import _paths


def _missing(what, how):
    """The ImportError for a Python without what the package needs: what is
    missing, in which interpreter, and how to get it."""
    here = "Python %d.%d at %s" % (sys.version_info[0], sys.version_info[1], sys.executable)
    return ImportError("the swell package needs %s, which this Python (%s) lacks: %s (docs/PYTHON.md)"
                       % (what, here, how))


# NumPy: every frame and label comes back as a NumPy array.
try:
    import numpy as _numpy  # noqa: F401
except ImportError:
    raise _missing("NumPy", "on Debian `apt-get install python3-numpy` (scripts/install-deps.sh installs it) and "
                   "run %s, the Python swell was built for, or `%s -m pip install numpy` for this one"
                   % (_paths.BUILT_FOR_EXECUTABLE, sys.executable)) from None

# The compiled module, built for one Python version.
try:
    from . import _swell  # noqa: F401
except ImportError as error:
    raise _missing("its compiled module swell._swell, built for Python %s (%s)"
                   % (_paths.BUILT_FOR_VERSION, _paths.BUILT_FOR_EXECUTABLE),
                   "run that Python (`%s`), or build swell for this one with "
                   "`cmake -B build -DPython_EXECUTABLE=%s` (%s)"
                   % (_paths.BUILT_FOR_EXECUTABLE, sys.executable, error)) from None

from ._swell import (
    CLASS_FIRST_OBJECT,
    CLASS_NONE,
    CLASS_SKY,
    CLASS_SURF,
    CLASS_TERRAIN,
    CLASS_WAKE_FOAM,
    CLASS_WATER,
    CLASS_WET_SAND,
    CLASS_WHITECAP_FOAM,
    Calibration,
    Camera,
    DrawnSurface,
    Error,
    Horizon,
    InputError,
    Labels,
    ObjectLabel,
    Renderer,
    Scene,
    calibration_of,
    default_scene,
    horizon_of,
    load_scene,
    parameter,
    parameter_keys,
    parse_scene,
    read_image,
    write_png,
)

__all__ = [
    "CLASS_FIRST_OBJECT", "CLASS_NONE", "CLASS_SKY", "CLASS_SURF", "CLASS_TERRAIN", "CLASS_WAKE_FOAM",
    "CLASS_WATER", "CLASS_WET_SAND", "CLASS_WHITECAP_FOAM",
    "Calibration", "Camera", "DrawnSurface", "Error", "Horizon", "InputError", "Labels", "ObjectLabel",
    "Renderer", "Scene", "calibration_of", "default_scene", "horizon_of", "load", "load_scene", "parameter",
    "parameter_keys", "parse_scene", "preset_names", "presets_folder", "read_image", "write_png",
]

def presets_folder():
    """The folder of the preset scenes: share/swell/scenes where the package is
    installed, the source tree's scenes/ in a build tree."""
    return _paths.presets_folder()


def preset_names():
    """The presets' names (their file names without .toml), sorted."""
    try:
        return sorted(name[:-5] for name in os.listdir(presets_folder()) if name.endswith(".toml"))
    except OSError:
        return []


def load(scene):
    """A scene file's path, or a preset's name ("storm" or "storm.toml"), as
    `swell render` takes it: a path that exists, or has a folder in it, is
    read as a file; a bare name that is neither is looked up among the
    presets. Raises swell.InputError naming the file and line of anything
    wrong in it, or listing the presets for an unknown name."""
    path = os.fspath(scene)
    if not path or os.path.lexists(path) or os.path.dirname(path):
        return load_scene(path)
    name = path if path.endswith(".toml") else path + ".toml"
    preset = os.path.join(presets_folder(), name)
    if os.path.isfile(preset):
        return load_scene(preset)
    names = preset_names()
    if not names:
        raise _input_error(path, "no such scene file, and no presets in '%s'" % presets_folder())
    raise _input_error(path, "no such scene file, and no preset of that name; the presets (in '%s') are: %s"
                       % (presets_folder(), ", ".join(names)))


def _input_error(path, message):
    error = InputError("%s: %s" % (path, message))
    error.path, error.line, error.column, error.message = path, 0, 0, message
    return error
