# What a FreeCAD user waits for: `import AutoBlock`, then the first and a second decomposition of a
# face (the first loads the native module; a learned policy also loads the learned-policy runtime
# with LibTorch), each policy in a fresh freecadcmd process.
#   freecadcmd src/bench/bench_freecad_start.py FACE_FILE [POLICY ...]
# (run from the checkout; AUTOBLOCK_NATIVE_DIR may name the native module's folder). Prints Markdown.
import os
import subprocess
import sys
import time

# freecadcmd passes its own arguments too: find this script and what follows it.
script = os.path.abspath(next(a for a in sys.argv if a.endswith("bench_freecad_start.py")))
here = os.path.dirname(script)
args = sys.argv[sys.argv.index(next(a for a in sys.argv if a.endswith("bench_freecad_start.py"))) + 1:]

if os.environ.get("AUTOBLOCK_BENCH_CHILD"):
    face_file, policy = args[0], args[1]
    start = time.perf_counter()
    import FreeCAD  # noqa: F401
    import Part

    sys.path.insert(0, os.path.join(here, "..", ".."))
    sys.path.insert(0, os.path.join(here, ".."))
    shape = Part.read(face_file)
    t0 = time.perf_counter()
    import AutoBlock

    t1 = time.perf_counter()
    first = AutoBlock.decompose(shape.Faces[0], policy=policy or None)
    t2 = time.perf_counter()
    AutoBlock.decompose(shape.Faces[0], policy=policy or None)
    t3 = time.perf_counter()
    print("RESULT {} {:.3f} {:.3f} {:.3f} {}".format(policy or "default", t1 - t0, t2 - t1, t3 - t2, first.policy),
          flush=True)
    sys.exit(0)

face_file = args[0]
policies = args[1:] or [""]
print("| policy | `import AutoBlock` s | first decomposition s (loads the native module) | second s |")
print("|---|---:|---:|---:|")
for policy in policies:
    env = dict(os.environ, AUTOBLOCK_BENCH_CHILD="1")
    out = subprocess.run(["freecadcmd", script, face_file, policy], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout
    line = [ln for ln in out.splitlines() if ln.startswith("RESULT ")]
    if not line:
        print("| {} | failed: {} | | |".format(policy, out.strip().splitlines()[-1:] or ""))
        continue
    _, name, imp, first, second, used = line[0].split()
    print("| {} ({}) | {} | {} | {} |".format(name, used, imp, first, second), flush=True)
