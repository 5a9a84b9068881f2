#!/usr/bin/env python3
"""A fuzzer for the Python package's entry points (docs/FUZZING.md).

Every function of `swell` and every method and property of its objects is
called with arguments drawn from a pool of hostile values: numbers at and
past every edge (0, -0.0, denormals, 1e300, inf, nan, 2**63, 10**400, bools),
strings and paths (empty, huge, NUL bytes, folders, devices, a FIFO, files
that are not what they claim), sequences of the wrong length and type,
NumPy arrays of every dtype and shape, None, and objects made the wrong way
(`Class.__new__(Class)` without __init__, another class's instance). The
calls are not guided by coverage (the bindings are thin; what they must hold
is every argument's type and range), but drawn at random from a seed, so a
finding is reproduced by its seed.

A call may return or raise swell.Error (swell.InputError too), TypeError,
ValueError, KeyError or IndexError; anything else is a finding: another
exception, a crash (a signal), a hang past --timeout. The calls run in child
processes, a batch of --calls each, so that a crash ends one batch, not the
run; each child prints each call before making it, so the last line before a
crash names it, and on a crash every Python thread's stack (faulthandler).
A seed replays its batch against the same code only: the calls draw from the
package's keys and classes.

  fuzz/fuzz_python.py --max-total-time 600            # ten minutes, seeds from 1
  fuzz/fuzz_python.py --seed 17 --runs 1 -v           # one batch again, every call shown

Needs the package importable (PYTHONPATH=build/python) and Mesa's EGL for
the Renderer. Writes only in a private temporary folder, which is also the
children's working directory: paths outside it (`/dev/zero`, `/etc/passwd`)
are handed only to the calls that read.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

ALLOWED = ("Error", "TypeError", "ValueError", "KeyError", "IndexError")


def hostile_numbers():
    return [0, 1, -1, 2, 7, 0.0, -0.0, 0.5, -0.5, 1.0, 3.0, 59.0, 150.0, 1e-310, 5e-324, -5e-324, 1e-12, 1e300,
            -1e300, 1e308, float("inf"), float("-inf"), float("nan"), 2 ** 31, 2 ** 32, 2 ** 63 - 1, -2 ** 63,
            2 ** 64, 10 ** 400, -10 ** 400, True, False, 16384, 16385, 1e9, 1e9 + 1, 3600.0, -3600.0]


class World:
    """What a batch's calls are drawn from and act on."""

    def __init__(self, swell, np, folder, rng):
        self.swell, self.np, self.rng, self.folder = swell, np, rng, folder
        self.numbers = hostile_numbers() + [np.float32(2.5), np.int64(-3), np.float64("nan"), np.bool_(True)]
        with open(os.path.join(folder, "a_file"), "w") as f:
            f.write("not a folder, not a scene\n")
        with open(os.path.join(folder, "scene.toml"), "w") as f:
            f.write('[grid]\nresolution = 32\n[[objects]]\npath = "builtin:buoy"\nfloats = true\n'
                    'density_kg_per_m3 = 400.0\n[camera]\ndistortion_k1 = -0.05\n')
        with open(os.path.join(folder, "garbage.png"), "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4)
        fifo = os.path.join(folder, "fifo")
        if not os.path.exists(fifo):
            os.mkfifo(fifo)
        os.makedirs(os.path.join(folder, "a_folder"), exist_ok=True)
        # Paths outside the private folder are only ever read (load, read_image);
        # everything else, a method called with whatever value, gets the folder's own.
        self.system_paths = ["/dev/zero", "/dev/null", "/etc/passwd", "/proc/self/mem", "storm", "storm.toml", "calm"]
        self.read_paths = [os.path.join(folder, n) for n in ("scene.toml", "a_file", "garbage.png", "fifo", "a_folder",
                                                             "missing.toml", "a_file/below.toml")] + [
            "", "x" * 5000, "nul\x00byte", folder]
        self.write_paths = [os.path.join(folder, n) for n in ("out.png", "out.toml", "deeper/still/out.png",
                                                              "a_file/below.png", "a_folder", "x" * 300 + ".png",
                                                              "nul\x00byte.png")] + ["", folder]
        self.keys = list(swell.parameter_keys()) + [
            "", "fog", "fog.", ".fog", "fog..start_m", "objects[0].scale", "objects[1].scale", "objects[99].scale",
            "objects[-1].scale", "objects[0]", "objects[00000000000000000001].scale", "objects[0.5].scale",
            "camera.path[0].time_s", "waves.list[0].amplitude_m", "sky.clouds.coverage", "x" * 100000, "\x00",
            "fog.start_m\x00", "objects.scale"]
        self.classes = [c for c in vars(swell._swell).values() if isinstance(c, type) and not issubclass(c, BaseException)]
        scene = swell.default_scene()
        scene["grid.resolution"] = 32
        self.scenes = [scene, swell.load_scene(os.path.join(folder, "scene.toml")), swell.default_scene()]
        self.renderer = swell.Renderer(scene)
        self.cameras = [swell.Camera(), swell.Camera(position_m=(0.0, 4.0, 0.0), pitch_deg=-10.0, far_m=5000.0)]
        self.objects = []

    def pick(self, items):
        return items[self.rng.randrange(len(items))]

    def unconstructed(self):
        cls = self.pick(self.classes)
        return cls.__new__(cls)

    def number(self):
        return self.pick(self.numbers)

    def small_size(self):
        """A size that is cheap when valid, or one that is not valid at all."""
        r = self.rng.random()
        if r < 0.5:
            return (self.rng.randint(1, 48), self.rng.randint(1, 36))
        if r < 0.8:
            return self.pick([(0, 5), (5, 0), (-1, 8), (16385, 2), (2, 16385), (8.5, 8), (float("nan"), 8), (8,),
                              (8, 8, 8), "8x8", None, [8, 8], self.np.array([8, 8]), (True, 8), (10 ** 400, 8),
                              (1e300, 1), (2 ** 63, 1)])
        return self.value()

    def time(self):
        r = self.rng.random()
        if r < 0.5:
            return self.rng.uniform(0.0, 5.0)
        return self.pick([-1.0, -1e-300, float("nan"), float("inf"), 1e300, 1e9, 1e9 + 1.0, 3600.0, 1e6, "1",
                          None, 10 ** 400, True])

    def array(self):
        np = self.np
        dtype = self.pick([np.uint8, np.float64, np.float32, np.int64, np.uint16, np.bool_, np.complex64, object])
        shape = self.pick([(), (0,), (5,), (0, 4, 4), (4, 0, 4), (4, 4, 0), (4, 4, 3), (4, 4, 4), (3, 5, 4),
                           (2, 2, 4, 1), (1, 1, 4), (16385, 1, 4)])
        try:
            a = np.zeros(shape, dtype)
        except (ValueError, MemoryError):
            a = np.zeros((2, 2, 4), np.uint8)
        return a if self.rng.random() < 0.8 else a[..., ::-1] if a.ndim else a

    def vector(self, n=3):
        r = self.rng.random()
        if r < 0.6:
            return tuple(self.number() if self.rng.random() < 0.3 else self.rng.uniform(-50.0, 50.0) for _ in range(n))
        return self.pick([(), (1.0,), (1.0, 2.0, 3.0, 4.0), "abc", None, [1, "x", 2], self.np.zeros(n), {1: 2},
                          (float("nan"),) * n])

    def value(self):
        kind = self.rng.randrange(12)
        if kind < 3:
            return self.number()
        if kind == 3:
            return self.pick(["", "x", "fixed", "raymarch", "builtin:boat", "builtin:nothing", "\x00", "x" * 10000])
        if kind == 4:
            return self.vector(self.rng.choice([2, 3]))
        if kind == 5:
            return self.array()
        if kind == 6:
            return self.unconstructed()
        if kind == 7 and self.objects:
            return self.pick(self.objects)
        if kind == 8:
            return self.pick(self.cameras)
        if kind == 9:
            return self.pick(self.scenes)
        if kind == 10:
            return self.pick([None, [], {}, object(), b"bytes", (lambda: 0)])
        return self.pick(self.read_paths + self.write_paths)


def calls(world):
    """The entry points, each a function of the world drawing its arguments."""
    swell, w = world.swell, world
    renderer = lambda: w.renderer
    scene = lambda: w.pick(w.scenes)

    def keep(result):
        if result is not None and not isinstance(result, (int, float, str, bool, tuple, list)):
            w.objects.append(result)
            if len(w.objects) > 50:
                w.objects.pop(0)
        return result

    table = [
        ("swell.load", lambda: swell.load(w.pick(w.read_paths + w.system_paths + [w.value()]))),
        ("swell.load_scene", lambda: keep(swell.load_scene(w.pick(w.read_paths + w.system_paths)))),
        ("swell.parse_scene", lambda: keep(swell.parse_scene(w.pick(["", "[fog]\nstart_m = 1e300\n", "a = [[[[",
                                                                      "[[objects]]\npath = \"../x.glb\"\n", w.value()]),
                                                            w.pick(w.read_paths)))),
        ("swell.parameter", lambda: swell.parameter(w.pick(w.keys + [w.value()]))),
        ("swell.calibration_of", lambda: keep(swell.calibration_of(w.value() if w.rng.random() < 0.2 else w.pick(w.cameras),
                                                                   w.small_size()))),
        ("swell.horizon_of", lambda: keep(swell.horizon_of(w.value()))),
        ("swell.read_image", lambda: keep(swell.read_image(w.pick(w.read_paths + w.system_paths)))),
        ("swell.write_png", lambda: swell.write_png(w.array() if w.rng.random() < 0.7 else w.value(),
                                                     w.pick(w.write_paths))),
        ("Scene.__getitem__", lambda: scene()[w.pick(w.keys + [w.value()])]),
        ("Scene.__setitem__", lambda: scene().__setitem__(w.pick(w.keys), w.value())),
        ("Scene.keys", lambda: scene().keys()),
        ("Scene.list_size", lambda: scene().list_size(w.pick(["objects", "waves.list", "camera.path", "", w.value()]))),
        ("Scene.add_object", lambda: scene().add_object(w.pick(["builtin:buoy", "../out.glb", "", "x" * 5000,
                                                                "/dev/zero", w.value()]))),
        ("Scene.remove_object", lambda: scene().remove_object(w.number())),
        ("Scene.object_path", lambda: scene().object_path(w.number())),
        ("Scene.validate", lambda: scene().validate()),
        ("Scene.camera_at", lambda: keep(scene().camera_at(w.time()))),
        ("Scene.to_toml", lambda: scene().to_toml()),
        ("Scene.save", lambda: scene().save(w.pick(w.write_paths))),
        ("Scene.copy", lambda: keep(scene().copy())),
        ("Camera", lambda: keep(swell.Camera(w.vector(), w.number(), w.number(), w.number(), w.number(), w.number(),
                                             w.number()))),
        ("Camera.set", lambda: setattr(w.pick(w.cameras), w.pick(["position_m", "yaw_deg", "pitch_deg", "roll_deg",
                                                                   "fov_y_deg", "near_m", "far_m"]),
                                       w.value())),
        ("Renderer", lambda: keep(swell.Renderer(w.value() if w.rng.random() < 0.5 else w.scenes[1]))),
        ("Renderer.render", lambda: renderer().render(w.pick(w.cameras + [w.value()]), w.time(), w.small_size())),
        ("Renderer.render_sensor", lambda: renderer().render_sensor(w.pick(w.cameras), w.time(), w.small_size(),
                                                                   w.pick([True, False, w.value()]))),
        ("Renderer.render_labels", lambda: keep(renderer().render_labels(w.pick(w.cameras + [w.value()]),
                                                                        w.small_size()))),
        ("Renderer.advance_to", lambda: renderer().advance_to(w.time(), w.pick([None, w.vector()]))),
        ("Renderer.scene_camera_at", lambda: keep(renderer().scene_camera_at(w.time()))),
        ("Renderer.surface_height_m", lambda: renderer().surface_height_m(
            w.pick([0.0, w.number(), w.array(), [1.0, 2.0], w.value()]),
            w.pick([0.0, w.number(), w.array(), [1.0, 2.0], w.value()]), w.time())),
        ("Renderer.drawn_surface", lambda: keep(renderer().drawn_surface(w.pick([None, w.vector()])))),
        ("Renderer.object_transforms", lambda: renderer().object_transforms()),
        ("Renderer.set_scene", lambda: renderer().set_scene(w.scenes[0] if w.rng.random() < 0.7 else w.value())),
        ("Renderer.set_flat_water", lambda: renderer().set_flat_water(w.pick([True, False, w.value()]))),
        ("Renderer.render_scale", lambda: setattr(renderer(), "render_scale",
                                                  w.pick([0.5, 1.0, w.number(), w.value()]))),
        ("Renderer.scene", lambda: keep(renderer().scene)),
        ("any method of a kept object", lambda: call_any(w, w.pick(w.objects) if w.objects else w.unconstructed())),
        ("any method of an unconstructed object", lambda: call_any(w, w.unconstructed())),
    ]
    return table


def call_any(world, target):
    names = [n for n in dir(type(target)) if not n.startswith("_") or n in ("__getitem__", "__repr__", "__copy__")]
    if not names:
        return None
    name = world.pick(names)
    attribute = getattr(target, name)
    if callable(attribute):
        return attribute(*[world.value() for _ in range(world.rng.randrange(4))])
    return attribute


def child(seed, count, verbose):
    import faulthandler
    import random

    # A crash (SIGSEGV, SIGABRT, ...) prints every Python thread's stack to
    # stderr, which the parent keeps with the finding: the last call printed
    # says which call was in flight, this says where in it (or on which
    # other thread) it died.
    faulthandler.enable(all_threads=True)

    import numpy as np

    import swell
    rng = random.Random(seed)
    with tempfile.TemporaryDirectory(prefix="swell-fuzz-python-") as folder:
        # Relative paths (a scene's value saved as "builtin:boat") land here too.
        os.chdir(folder)
        world = World(swell, np, folder, rng)
        table = calls(world)
        for i in range(count):
            name, call = table[rng.randrange(len(table))]
            print(f"call {i}: {name}", flush=True)
            try:
                result = call()
                if verbose:
                    print(f"  -> {type(result).__name__}", flush=True)
            except Exception as e:  # noqa: BLE001 (sorting allowed from not)
                kind = type(e).__name__
                if kind not in ALLOWED and not isinstance(e, swell.Error):
                    print(f"FINDING: {name} raised {kind}: {str(e)[:500]}", flush=True)
                    return 3
                if verbose:
                    print(f"  -> {kind}: {str(e)[:200]}", flush=True)
    print("batch done", flush=True)
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, default=1, help="the first batch's seed; each next batch the next")
    parser.add_argument("--runs", type=int, default=0, help="batches to run (0: until --max-total-time)")
    parser.add_argument("--max-total-time", type=float, default=60.0, help="seconds to run when --runs is 0")
    parser.add_argument("--calls", type=int, default=200, help="calls a batch")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds a batch may take")
    parser.add_argument("--artifacts", default=".", help="where findings are written")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("-v", "--verbose", action="store_true", help="show each call's outcome")
    args = parser.parse_args()
    if args.child:
        return child(args.seed, args.calls, args.verbose)

    # The package must import here at all: a setup that cannot is no finding.
    setup = subprocess.run([sys.executable, "-c", "import numpy, swell"], capture_output=True, text=True)
    if setup.returncode != 0:
        sys.stderr.write(f"fuzz_python.py: cannot import swell and numpy (PYTHONPATH=build/python?):\n{setup.stderr}")
        return 2
    started = time.monotonic()
    seed, batches, calls_made, findings = args.seed, 0, 0, 0
    while (args.runs and batches < args.runs) or (not args.runs and time.monotonic() - started < args.max_total_time):
        command = [sys.executable, os.path.abspath(__file__), "--child", "--seed", str(seed), "--calls", str(args.calls)]
        if args.verbose:
            command.append("-v")
        stderr = ""  # what the child wrote there: on a crash, the stacks faulthandler printed
        try:
            r = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout, errors="replace")
            failed = r.returncode != 0
            why = f"exit {r.returncode}" if r.returncode >= 0 else f"signal {-r.returncode}"
            output, stderr = r.stdout, r.stderr
        except subprocess.TimeoutExpired as e:
            failed, why = True, f"no end after {args.timeout:.0f} s"
            output = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        if args.verbose:
            sys.stdout.write(output + stderr)
        batches += 1
        calls_made += args.calls
        if failed:
            findings += 1
            path = os.path.join(args.artifacts, f"crash-python-seed-{seed}.txt")
            with open(path, "w") as f:
                f.write(f"fuzz/fuzz_python.py --seed {seed} --runs 1 --calls {args.calls} -v\n{why}\n"
                        f"{output[-6000:]}{stderr[-6000:]}")
            # The last calls made, then the stacks (kept apart, so that
            # neither pushes the other out of CI's log).
            print(f"FINDING (seed {seed}, {why}): {path}\n{output[-1500:]}{stderr[-3000:]}", flush=True)
        seed += 1
    elapsed = time.monotonic() - started
    print(f"{batches} batches, {calls_made} calls in {elapsed:.0f} s ({calls_made / max(elapsed, 1e-9):.1f}/s), "
          f"{findings} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
