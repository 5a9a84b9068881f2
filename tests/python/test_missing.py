"""A Python without what the package needs gets an ImportError that names
what is missing, in which interpreter, and how to get it: NumPy, or the
compiled module (built for another Python). Each case runs in a fresh
interpreter with the piece blocked."""

import subprocess
import sys
import unittest


def import_with(blocked):
    """`import swell` in a fresh interpreter where importing `blocked` fails."""
    code = "import sys; sys.modules[%r] = None; import swell" % blocked
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)


class MissingPieces(unittest.TestCase):
    def test_no_numpy_says_so_and_how_to_get_it(self):
        r = import_with("numpy")
        self.assertNotEqual(r.returncode, 0)
        last = r.stderr.strip().splitlines()[-1]
        self.assertIn("ImportError: the swell package needs NumPy", last)
        self.assertIn("python3-numpy", last)
        self.assertIn(sys.executable, last)

    def test_a_module_built_for_another_python_says_which(self):
        r = import_with("swell._swell")
        self.assertNotEqual(r.returncode, 0)
        last = r.stderr.strip().splitlines()[-1]
        self.assertIn("its compiled module swell._swell, built for Python %d.%d" % sys.version_info[:2], last)
        self.assertIn("-DPython_EXECUTABLE=", last)


if __name__ == "__main__":
    unittest.main()
