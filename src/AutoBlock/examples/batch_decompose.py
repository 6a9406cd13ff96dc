# Decompose and mesh every .brep/.step face of a folder with AutoBlock, writing the blocks, the quad mesh
# and a summary.
#   freecadcmd batch_decompose.py INPUT_FOLDER OUTPUT_FOLDER [POLICY]
import json
import os
import sys

import FreeCAD  # noqa: F401  (before Part)
import Part

import AutoBlock


def main(folder, out, policy=None):
    names = sorted(n for n in os.listdir(folder) if n.lower().endswith((".brep", ".brp", ".step", ".stp")))
    os.makedirs(out, exist_ok=True)
    summary, failed = [], 0
    for i, name in enumerate(names, 1):
        stem = os.path.join(out, os.path.splitext(name)[0])
        try:
            result = AutoBlock.decompose(Part.read(os.path.join(folder, name)), policy=policy)
        except Exception as error:  # unreadable file or unsupported face: report it and go on
            failed += 1
            print("[{}/{}] {}: skipped: {}".format(i, len(names), name, error), flush=True)
            continue
        result.shape.exportBrep(stem + "-blocks.brep")
        entry = dict(result.to_dict(), file=name)
        try:
            mesh = AutoBlock.mesh(result)  # element size: 1/20 of the face's longer side
            mesh.export(stem + "-mesh.msh")
            entry.update(mesh=os.path.basename(stem) + "-mesh.msh", nodes=len(mesh.nodes), quads=len(mesh.quads))
            meshed = "; " + mesh.summary()
        except ValueError as error:  # an incomplete decomposition cannot be meshed: say so and go on
            meshed = "; not meshed: {}".format(error)
        summary.append(entry)
        print("[{}/{}] {}: {}{}".format(i, len(names), name, result.summary(), meshed), flush=True)
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print("{} decomposed, {} skipped; results in {}".format(len(summary), failed, out), flush=True)
    return 1 if failed else 0


if len(sys.argv) < 3:
    print("usage: freecadcmd batch_decompose.py INPUT_FOLDER OUTPUT_FOLDER [POLICY]", flush=True)
    sys.exit(2)
sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else None))
