#!/usr/bin/env python3
"""scripts/dataset-dask.py says what is missing and how to get it, exit 2,
before any Dask work, instead of a traceback: the swell executable (when it
is neither named, nor on PATH, nor in the build tree, where it is looked for
too), and Dask distributed (Debian's python3-distributed). Each case is a
second or less.

usage: test_dask_messages.py SWELL_EXECUTABLE DASK_RUNNER WORK_DIR
"""
import os
import shutil
import subprocess
import sys

swell, runner, work = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []
# A PATH without swell on it, and no $SWELL.
bare = {k: v for k, v in os.environ.items() if k != "SWELL"}
bare["PATH"] = "/usr/bin:/bin"
nowhere = os.path.join(work, "no-build")
sweep = os.path.join(work, "sweep.toml")
with open(sweep, "w") as f:
    f.write('scene = "storm"\ncount = 0\n')  # refused by swell itself: count 1..1000000


def run(args, env, prelude=""):
    code = (f"import sys, runpy; {prelude}sys.argv = {[runner, *args]!r}; "
            f"runpy.run_path({runner!r}, run_name='__main__')")
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120, cwd=work)


def expect(name, r, *needles):
    if r.returncode != 2 or "Traceback" in r.stderr or not all(n in r.stderr for n in needles):
        failures.append(f"{name}: exit {r.returncode}, stderr {r.stderr.strip()[-800:]!r}; wanted exit 2 with {needles}")


# No swell anywhere: named as missing, with the three ways to give it.
expect("no swell", run([sweep, "--out", os.path.join(work, "out")], dict(bare, SWELL_BUILD_DIR=nowhere)),
       "no swell executable", nowhere, "scripts/build.sh", "--swell PATH", "SWELL=PATH")
# A --swell that is not there.
expect("--swell missing", run([sweep, "--out", os.path.join(work, "out"), "--swell", os.path.join(work, "nope")], bare),
       "'" + os.path.join(work, "nope") + "' (--swell) is missing")
# $SWELL that is not there.
expect("$SWELL missing", run([sweep, "--out", os.path.join(work, "out")], dict(bare, SWELL=os.path.join(work, "nope"))),
       "($SWELL) is missing")
# In the build tree (here a folder laid out like one): found, and it is swell
# that refuses the sweep, at its line.
tree = os.path.join(work, "build")
os.makedirs(os.path.join(tree, "apps", "swell"))
os.symlink(os.path.abspath(swell), os.path.join(tree, "apps", "swell", "swell"))
expect("build tree", run([sweep, "--out", os.path.join(work, "out")], dict(bare, SWELL_BUILD_DIR=tree)),
       "sweep.toml:2:", "count")
# No Dask: named, with Debian's package.
expect("no dask", run([sweep, "--out", os.path.join(work, "out"), "--swell", swell], bare, "sys.modules['dask'] = None; "),
       "needs Dask distributed", "No module named 'dask", "apt-get install python3-distributed")

# Its interpreter is the one Debian's python3-distributed is for, said in its docstring.
with open(runner) as f:
    head = f.read(1200)
if not head.startswith("#!/usr/bin/python3\n") or "python3-distributed" not in head:
    failures.append(f"{runner}: its first line is not #!/usr/bin/python3, or its docstring does not say what it needs")

for f in failures:
    print("FAIL:", f)
print(f"{6 - len(failures)} of 6 cases as documented")
sys.exit(1 if failures else 0)
