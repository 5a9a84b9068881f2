#!/usr/bin/env python3
"""Checks what a shared libswell exports (its dynamic symbol table): Swell's
own API, and nothing of the libraries it is built with (stb, tinygltf,
toml++, fmt, GLM) that a user might link their own copy of.

  check_exports.py LIBSWELL.so

Allowed: symbols in namespace swell, and the C++ standard library's templates
instantiated for Swell's types (std:: and __gnu_cxx:: templates are declared
with default visibility by libstdc++, so GCC exports their instantiations).
"""
import re
import subprocess
import sys

library = sys.argv[1]
out = subprocess.run(["nm", "-D", "--defined-only", "-C", library], check=True, capture_output=True, text=True).stdout
symbols = [line.split(" ", 2)[2] for line in out.splitlines() if line.count(" ") >= 2]
foreign = ("stb", "tinygltf", "toml", "fmt::", "glm::", "nlohmann", "epoxy", "Json", "base64")
swell = [s for s in symbols if "swell::" in s]
bad = []
for s in symbols:
    owner = s.replace("typeinfo for ", "").replace("typeinfo name for ", "").replace("vtable for ", "")
    owner = owner.replace("guard variable for ", "").replace("non-virtual thunk to ", "")
    # What a virtual base brings (swell::WaveModel's SurfaceQuery): the
    # table of its vtables, the vtables used while a base is built, and the
    # thunks that reach the base's functions.
    owner = owner.replace("VTT for ", "").replace("construction vtable for ", "").replace("virtual thunk to ", "")
    is_swell = owner.startswith("swell::")
    # (a function template's name starts with its return type: "bool std::...")
    is_std_for_swell = re.match(r"^(?:[A-Za-z_][\w:]*\s+)?(?:std|__gnu_cxx)::", owner) is not None
    if any(f in owner.split("(")[0] for f in foreign) and not is_swell:
        bad.append(s)
    elif not (is_swell or is_std_for_swell or s.startswith(("swell::", "operator"))):
        bad.append(s)
if len(swell) < 50:
    print(f"{library}: only {len(swell)} swell:: symbols exported; is the public API marked SWELL_API?")
    sys.exit(1)
if bad:
    print(f"{library}: exports {len(bad)} symbols that are not Swell's:")
    for s in bad[:40]:
        print("  " + s)
    sys.exit(1)
print(f"{library}: {len(swell)} swell:: symbols exported, {len(symbols) - len(swell)} standard-library "
      f"instantiations, nothing else")
