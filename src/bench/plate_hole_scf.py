#!/usr/bin/env python3
"""Stress concentration at a round hole (issue 13, "a real analysis"): a plate of width W and length
L with a central hole of diameter d in uniaxial tension, meshed by `autoblock mesh` (CPS4, plane
stress) and by gmsh 4.8's all-quad mesher, solved with CalculiX, its K_t compared with the published
finite-width value.

Published values, net section (sigma_nom = F / ((W - d) t), F the total end load):
  - Peterson's fit of Howland's (1930) series solution for a long plate (Pilkey & Pilkey,
    "Peterson's Stress Concentration Factors", 3rd ed., 2008, Chart 4.1), the reference for --check:
        K_tn = 2 + 0.284 (1 - d/W) - 0.600 (1 - d/W)^2 + 1.32 (1 - d/W)^3
  - Heywood's formula ("Designing by Photoelasticity", 1952), shown beside it:
        K_tn = 2 + (1 - d/W)^3
The two agree within 1.5 % for d/W <= 0.5 and both tend to 3 (Kirsch) as d/W -> 0.

The plate: W = 20, L = 4 W by default (--length), hole at the centre, written here as BREP text
(one planar face: four lines and a circle, no other tool needed). Both ends carry a uniform traction
sigma as consistent nodal loads (each boundary edge of length l gives sigma t l / 2 to its two
nodes; 1/6, 4/6, 1/6 of sigma t l on an 8-node quad's side; total sigma W t), so the plate is free; rigid motion is removed by
the bottom corners (left: x and y, right: y), whose reactions are zero by equilibrium. Steel-like
E = 210000, nu = 0.3, thickness t = 1 (*SOLID SECTION). ccx writes nodal stresses (*NODE FILE,
S: extrapolated from the integration points and averaged between elements) into the .frd; the hoop
stress at the hole's boundary nodes is interpolated (quadratic in angle through the three nodes
nearest) to the two points on the section through the centre perpendicular to the load (angles 90
and 270 degrees), and their mean is sigma_max.

gmsh runs as in autoblock_bench_mesh and bench_process.py: Frontal-Delaunay for quads
(Mesh.Algorithm 8, Mesh.CrossFieldClosestPoint = 0), Blossom full-quad recombination
(Mesh.RecombinationAlgorithm 3), Mesh.MeshSizeMin = Mesh.MeshSizeMax = its size; the size is scaled
(two rounds of h' = h sqrt(gmsh's count / AutoBlock's), as in autoblock_bench_mesh) to bring its
quad count close to AutoBlock's. It writes the mesh as .inp (-format inp); its CPS4 quads go into the
same deck as AutoBlock's (re-ordered counter-clockwise if gmsh wrote them clockwise).

--reference adds a row: gmsh's mesh again with 8-node quads (CPS8, mid-side nodes on the circle),
whose nodal stresses are much nearer convergence: it tells the first-order meshes' error from the
published formula's own distance to this plate.

    python3 src/bench/plate_hole_scf.py --autoblock build/bin/autoblock [--ratio 0.3 | --ratios 0.2,0.3,0.4,0.5]
        [--size H] [--length 4] [--gmsh gmsh] [--no-gmsh] [--reference] [--check] [--json OUT] [--keep DIR]

--size is the element size in units of W (default 1/80: 0.25 for W = 20; at 1/40, 30-60 nodes on
the hole, the CPS4 nodal stress at the hole moves by several per cent with the local layout of the
quads, for either mesher). --check exits 1 if AutoBlock's K_t is more than 5 % from Peterson's
(Howland's) value, or AutoBlock gave no mesh, at any ratio (a failed `autoblock mesh` is a row of the
table). Prints Markdown. Exit 2 with one line `error: ...` if ccx, gmsh or autoblock is missing or
ccx or gmsh fails.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

WIDTH = 20.0
YOUNG, POISSON, THICKNESS, TRACTION = 210000.0, 0.3, 1.0, 100.0
TOLERANCE = 0.05  # --check: relative error allowed against the published value

GMSH_SETTINGS = ("Mesh.Algorithm = 8;\nMesh.CrossFieldClosestPoint = 0;\nMesh.RecombineAll = 1;\n"
                 "Mesh.RecombinationAlgorithm = 3;\nMesh.MeshSizeFromPoints = 0;\n"
                 "Mesh.MeshSizeMin = {h:.17g};\nMesh.MeshSizeMax = {h:.17g};\n")


class Failure(Exception):
    """A tool is missing or failed: one line, exit 2."""


class MeshFailure(Failure):
    """`autoblock mesh` refused or failed on the plate: reported in the table."""


def peterson(ratio):
    u = 1.0 - ratio
    return 2.0 + 0.284 * u - 0.600 * u * u + 1.32 * u ** 3


def heywood(ratio):
    return 2.0 + (1.0 - ratio) ** 3


def plate_brep(length, width, diameter):
    """One planar face in z = 0: the rectangle [0, length] x [0, width] (counter-clockwise wire) with
    a circular hole of the given diameter at its centre (clockwise wire), as OpenCASCADE BREP text
    (the layout FreeCAD's Part module writes for such a face)."""
    g = lambda v: repr(float(v))
    cx, cy, r = length / 2, width / 2, diameter / 2
    L, W = g(length), g(width)
    two_pi = g(2 * math.pi)
    vertex = lambda x, y: "Ve\n1e-07\n{} {} 0\n0 0\n\n0101101\n*\n".format(g(x), g(y))
    edge = lambda k, last, ends: ("Ed\n 1e-07 1 1 0\n1  {k} 0 0 {e}\n2  {k} 1 0 0 {e}\n0\n\n0101000\n{v} *\n"
                                  .format(k=k, e=last, v=ends))
    # Curves 1-4: left, bottom, top, right (parameter = arc length from the lower/left end); 5: the hole.
    return "".join([
        "DBRep_DrawableShape\n\nCASCADE Topology V1, (c) Matra-Datavision\nLocations 0\nCurve2ds 5\n",
        "1 0 0 0 1 \n1 0 0 1 0 \n1 0 {W} 1 0 \n1 {L} 0 0 1 \n".format(L=L, W=W),
        "2 {} {} 1 0 -0 1 {}\n".format(g(cx), g(cy), g(r)),
        "Curves 5\n1 0 0 0 -0 1 0 \n1 0 0 0 1 0 -0 \n1 0 {W} 0 1 0 -0 \n1 {L} 0 0 -0 1 0 \n".format(L=L, W=W),
        "2 {} {} 0 0 0 1 1 0 -0 -0 1 0 {}\n".format(g(cx), g(cy), g(r)),
        "Polygon3D 0\nPolygonOnTriangulations 0\nSurfaces 1\n1 0 0 0 0 0 1 1 0 -0 -0 1 0 \nTriangulations 0\n\n",
        "TShapes 13\n",
        vertex(0, 0),                       # 13
        vertex(0, width),                   # 12
        edge(1, W, "+13 0 -12 0"),          # 11 left
        vertex(length, 0),                  # 10
        edge(2, L, "+13 0 -10 0"),          # 9 bottom
        vertex(length, width),              # 8
        edge(3, L, "+12 0 -8 0"),           # 7 top
        edge(4, W, "+10 0 -8 0"),           # 6 right
        "Wi\n\n0101100\n-11 0 +9 0 -7 0 +6 0 *\n",  # 5 outer wire
        vertex(cx + r, cy),                 # 4
        "Ed\n 1e-07 1 1 0\n1  5 0 0 {e}\n2  5 1 0 0 {e}\n0\n\n0101000\n+4 0 -4 0 *\n".format(e=two_pi),  # 3 hole
        "Wi\n\n0101100\n-3 0 *\n",          # 2 hole wire
        "Fa\n0  1e-07 1 0\n\n0101000\n+5 0 +2 0 *\n\n+1 0 \n",  # 1 the face
    ])


def run(command, what, cwd=None, env=None):
    try:
        done = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True)
    except OSError as e:
        raise Failure("{}: cannot run {}: {}".format(what, command[0], e.strerror))
    if done.returncode != 0:
        message = (done.stderr.strip() or done.stdout.strip()).splitlines()
        raise Failure("{} failed (exit {}): {}".format(what, done.returncode, message[-1] if message else "no output"))
    return done.stdout


def read_inp_mesh(path, element="CPS4"):
    """Nodes {id: (x, y)} and the quads [(id, n1, n2, n3, n4)] (CPS8: and their four mid-side nodes)
    of an Abaqus .inp (AutoBlock's or gmsh's). Any other surface element (a triangle) is an error;
    gmsh's line and point elements are skipped."""
    nodes, quads = {}, []
    section = None
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                words = [w.strip().upper() for w in line.split(",")]
                keyword = words[0]
                kind = next((w.split("=", 1)[1] for w in words[1:] if w.startswith("TYPE=")), "")
                if keyword == "*NODE":
                    section = "node"
                elif keyword == "*ELEMENT" and kind == element:
                    section = "quad"
                elif keyword == "*ELEMENT" and kind.startswith(("CPS", "CPE", "S3", "S4", "CAX")):
                    raise Failure("{}: {} elements, not all-quad {}".format(path, kind, element))
                else:
                    section = None
                continue
            items = [v for v in line.split(",") if v.strip()]
            if section == "node":
                nodes[int(items[0])] = (float(items[1]), float(items[2]))
            elif section == "quad":
                quads.append(tuple(int(v) for v in items[:9 if element == "CPS8" else 5]))
    if not quads:
        raise Failure("{}: no {} elements".format(path, element))
    return nodes, quads


def signed_area(nodes, quad):
    p = [nodes[n] for n in quad[1:5]]
    return 0.5 * sum(p[i][0] * p[(i + 1) % 4][1] - p[(i + 1) % 4][0] * p[i][1] for i in range(4))


def scaled_jacobian(nodes, quad):
    """The quad's minimum over its corners of the normalised cross product of the corner's edges."""
    p = [nodes[n] for n in quad[1:5]]
    worst = 1.0
    for i in range(4):
        (x0, y0), (x1, y1), (x2, y2) = p[i], p[(i + 1) % 4], p[i - 1]
        ax, ay, bx, by = x1 - x0, y1 - y0, x2 - x0, y2 - y0
        worst = min(worst, (ax * by - ay * bx) / (math.hypot(ax, ay) * math.hypot(bx, by)))
    return worst


def write_inp_mesh(path, nodes, quads):
    """The mesh in the sets AutoBlock's .inp defines (NALL, EALL), CPS4 or CPS8."""
    with open(path, "w") as f:
        f.write("*NODE, NSET=NALL\n")
        for n in sorted(nodes):
            f.write("{}, {:.17g}, {:.17g}, 0\n".format(n, *nodes[n]))
        f.write("*ELEMENT, TYPE={}, ELSET=EALL\n".format("CPS8" if len(quads[0]) == 9 else "CPS4"))
        for q in quads:
            f.write(", ".join(str(n) for n in q) + "\n")


def boundary_edges(quads):
    """The sides used by one quad: (a, b, mid-side node or None)."""
    count = {}
    for q in quads:
        for i in range(4):
            a, b = q[1 + i], q[1 + (i + 1) % 4]
            key = (min(a, b), max(a, b), q[5 + i] if len(q) == 9 else None)
            count[key] = count.get(key, 0) + 1
    return [e for e, c in count.items() if c == 1]


def nearest_node(nodes, x, y):
    return min(nodes, key=lambda n: (nodes[n][0] - x) ** 2 + (nodes[n][1] - y) ** 2)


def deck(mesh_file, nodes, quads, length):
    """The analysis around the mesh: material, section, supports, end loads, nodal stress output."""
    tol = 1e-6 * length  # AutoBlock snaps coordinates to a lattice of 1e-7 of the face's longer side
    loads = {}
    for a, b, mid in boundary_edges(quads):
        (xa, ya), (xb, yb) = nodes[a], nodes[b]
        for x_end, sign in ((0.0, -1.0), (length, 1.0)):
            if abs(xa - x_end) < tol and abs(xb - x_end) < tol:
                force = sign * TRACTION * THICKNESS * abs(yb - ya)
                # Consistent loads: 1/2, 1/2 on a linear side; 1/6, 1/6 and 4/6 (mid-side) on a quadratic one.
                shares = ((a, 0.5), (b, 0.5)) if mid is None else ((a, 1 / 6), (b, 1 / 6), (mid, 4 / 6))
                for n, w in shares:
                    loads[n] = loads.get(n, 0.0) + w * force
    left, right = nearest_node(nodes, 0, 0), nearest_node(nodes, length, 0)
    lines = ["*INCLUDE, INPUT={}".format(mesh_file),
             "*MATERIAL, NAME=STEEL", "*ELASTIC", "{:g}, {:g}".format(YOUNG, POISSON),
             "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL", "{:g}".format(THICKNESS),
             "*BOUNDARY", "{}, 1, 2, 0".format(left), "{}, 2, 2, 0".format(right),
             "*STEP", "*STATIC", "*CLOAD"]
    lines += ["{}, 1, {:.17g}".format(n, loads[n]) for n in sorted(loads)]
    lines += ["*NODE FILE", "U, S", "*END STEP", ""]
    total = sum(v for v in loads.values() if v > 0)
    return "\n".join(lines), total


def read_frd_stress(path):
    """Nodal stresses {node: (sxx, syy, szz, sxy, syz, szx)} of the last STRESS block of a .frd."""
    stress, block = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith(" -4"):
                block = {} if line.split()[1] == "STRESS" else None
                if block is not None:
                    stress = block
            elif line.startswith(" -3"):
                block = None
            elif block is not None and line.startswith(" -1"):
                # Fixed columns: node I10, then 12-character values (may touch: -1.2E+02-3.4E+01).
                node = int(line[3:13])
                block[node] = tuple(float(line[13 + 12 * i:25 + 12 * i]) for i in range(6))
    if not stress:
        raise Failure("{}: no STRESS results".format(path))
    return stress


def hoop_at(on_hole, target):
    """The hoop stress at angle target, interpolated (quadratic in angle) through the three nodes of
    on_hole [(angle, hoop stress, node)] nearest it; and the angle from target to the nearest."""
    near = sorted(on_hole, key=lambda p: abs(math.remainder(p[0] - target, 2 * math.pi)))[:3]
    ts = [target + math.remainder(t - target, 2 * math.pi) for t, _, _ in near]
    value = 0.0
    for i, (_, s, _) in enumerate(near):
        weight = 1.0
        for j in range(3):
            if j != i:
                weight *= (target - ts[j]) / (ts[i] - ts[j])
        value += weight * s
    return value, min(abs(t - target) for t in ts)


def solve(work, name, mesh_path, ratio, length, ccx, as_is, element="CPS4"):
    """Runs ccx on the mesh (AutoBlock's file included as it is when as_is, else rewritten in its
    sets); returns elements, nodes, K_t and the details."""
    nodes, quads = read_inp_mesh(mesh_path, element)
    clockwise = [q for q in quads if signed_area(nodes, q) < 0]
    if clockwise and len(clockwise) < len(quads):
        raise Failure("{}: {} of {} quads clockwise, the others not".format(mesh_path, len(clockwise), len(quads)))
    folder = os.path.join(work, "ccx-" + name)  # the deck, its mesh and ccx's results
    os.makedirs(folder, exist_ok=True)
    if clockwise or not as_is:
        # gmsh's mesh (or a clockwise one): rewritten with AutoBlock's sets, quads counter-clockwise.
        flip = (0, 1, 4, 3, 2, 8, 7, 6, 5) if element == "CPS8" else (0, 1, 4, 3, 2)
        quads = [tuple(q[i] for i in flip) if clockwise else q for q in quads]
        write_inp_mesh(os.path.join(folder, "mesh.inp"), nodes, quads)
    else:
        shutil.copyfile(mesh_path, os.path.join(folder, "mesh.inp"))  # AutoBlock's file as it is
    text, total = deck("mesh.inp", nodes, quads, length)
    with open(os.path.join(folder, "job.inp"), "w") as f:
        f.write(text)
    if abs(total - TRACTION * THICKNESS * WIDTH) > 1e-6 * total:
        raise Failure("{}: the end loads add up to {:.9g}, not sigma W t (the ends are not meshed as lines?)"
                      .format(name, total))
    env = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.perf_counter()
    out = run([ccx, "-i", "job"], "ccx on the {} mesh".format(name), cwd=folder, env=env)
    seconds = time.perf_counter() - start
    if "*ERROR" in out:
        raise Failure("ccx on the {} mesh: {}".format(name, next(l for l in out.splitlines() if "*ERROR" in l)))
    stress = read_frd_stress(os.path.join(folder, "job.frd"))

    d = ratio * WIDTH
    cx, cy, r = length / 2, WIDTH / 2, d / 2
    on_hole = []  # (angle, hoop stress, node) at the nodes on the hole's circle
    for n, (x, y) in nodes.items():
        if abs(math.hypot(x - cx, y - cy) - r) < 1e-6 * WIDTH:
            if n not in stress:
                raise Failure("{}: ccx wrote no stress at node {}".format(name, n))
            t = math.atan2(y - cy, x - cx)
            sxx, syy, _, sxy, _, _ = stress[n]
            s, c = math.sin(t), math.cos(t)
            on_hole.append((t, sxx * s * s + syy * c * c - 2 * sxy * s * c, n))  # along the tangent
    if len(on_hole) < 8:
        raise Failure("{}: only {} nodes on the hole".format(name, len(on_hole)))
    top, off_top = hoop_at(on_hole, math.pi / 2)
    bottom, off_bottom = hoop_at(on_hole, -math.pi / 2)
    nominal = TRACTION * WIDTH / (WIDTH - d)  # net section
    sigma_max = (top + bottom) / 2
    # Far field: sigma_xx at the loaded ends' nodes should be the traction.
    ends = [stress[n][0] for n, (x, _) in nodes.items() if min(abs(x), abs(x - length)) < 1e-6 * length]
    hole = {n for _, _, n in on_hole}
    jacobians = [(scaled_jacobian(nodes, q), any(n in hole for n in q[1:5])) for q in quads]
    return {"elements": len(quads), "nodes": len(nodes), "hole_nodes": len(on_hole),
            "min_scaled_jacobian": min(j for j, _ in jacobians),
            "min_scaled_jacobian_at_hole": min(j for j, at in jacobians if at),
            "kt": sigma_max / nominal, "kt_top": top / nominal, "kt_bottom": bottom / nominal,
            "kt_max_node": max(s for _, s, _ in on_hole) / nominal,
            "nearest_node_degrees": math.degrees(max(off_top, off_bottom)),
            "end_stress_over_traction": sum(ends) / len(ends) / TRACTION,
            "clockwise_reordered": len(clockwise), "ccx_seconds": seconds}


def autoblock_mesh(work, args, size, tag):
    folder = os.path.join(work, tag)
    os.makedirs(folder, exist_ok=True)
    mesh, report = os.path.join(folder, "mesh.inp"), os.path.join(folder, "report.json")
    try:
        run([args.autoblock, "mesh", os.path.join(work, "plate.brep"), "--size", repr(size), "--out", mesh,
             "--json", report], "autoblock mesh")
    except Failure as e:
        raise MeshFailure(str(e))
    with open(report) as f:
        return mesh, json.load(f)


def gmsh_mesh(work, gmsh, size, tag, element="CPS4"):
    folder = os.path.join(work, tag)
    os.makedirs(folder, exist_ok=True)
    geo, mesh = os.path.join(folder, "plate.geo"), os.path.join(folder, "gmsh.inp")
    with open(geo, "w") as f:
        f.write('SetFactory("OpenCASCADE");\nMerge "{}";\n'.format(os.path.join(work, "plate.brep")))
        f.write(GMSH_SETTINGS.format(h=size))
        if element == "CPS8":  # the same quads with mid-side nodes (on the hole's circle there)
            f.write("Mesh.ElementOrder = 2;\nMesh.SecondOrderIncomplete = 1;\n")
    run([gmsh, geo, "-2", "-format", "inp", "-o", mesh], "gmsh")
    return mesh, len(read_inp_mesh(mesh, element)[1])


def analyse(ratio, args, ccx):
    length = args.length * WIDTH
    size = args.size * WIDTH
    work = tempfile.mkdtemp(prefix="plate-hole-scf-", dir=args.keep)
    try:
        with open(os.path.join(work, "plate.brep"), "w") as f:
            f.write(plate_brep(length, WIDTH, ratio * WIDTH))
        rows = []
        try:
            mesh, report = autoblock_mesh(work, args, size, "autoblock")
        except MeshFailure as e:  # a row of the table (and a failed --check), not the end of the run
            row = {"mesher": "AutoBlock", "size": size, "failed": str(e)}
        else:
            row = solve(work, "autoblock", mesh, ratio, length, ccx, True)
            row.update(mesher="AutoBlock", size=size, blocks=report["blocks"], conformal=report["conformal"],
                       reported_min_scaled_jacobian=report["quality"]["min_scaled_jacobian"])
        rows.append(row)
        if args.gmsh:
            # Gmsh's size scaled towards AutoBlock's element count (two rounds, as autoblock_bench_mesh);
            # size h as it is if AutoBlock failed.
            h = size
            gmesh, count = gmsh_mesh(work, args.gmsh, h, "gmsh")
            for _ in range(2 if "elements" in row else 0):
                h *= math.sqrt(count / row["elements"])
                gmesh, count = gmsh_mesh(work, args.gmsh, h, "gmsh")
            grow = solve(work, "gmsh", gmesh, ratio, length, ccx, False)
            grow.update(mesher="gmsh 4.8", size=h)
            rows.append(grow)
            if args.reference:
                qmesh, _ = gmsh_mesh(work, args.gmsh, h, "gmsh-cps8", "CPS8")
                qrow = solve(work, "gmsh-cps8", qmesh, ratio, length, ccx, False, "CPS8")
                qrow.update(mesher="gmsh 4.8, CPS8 (reference)", size=h)
                rows.append(qrow)
        for r in rows:
            r.update(ratio=ratio, width=WIDTH, length=length, diameter=ratio * WIDTH,
                     peterson=peterson(ratio), heywood=heywood(ratio))
            if "kt" in r:
                r.update(error_percent=100 * (r["kt"] / peterson(ratio) - 1),
                         error_heywood_percent=100 * (r["kt"] / heywood(ratio) - 1))
        return rows
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--autoblock", default="build/bin/autoblock", help="the autoblock binary")
    parser.add_argument("--gmsh", default="gmsh", help="gmsh binary (skipped with a note if absent)")
    parser.add_argument("--no-gmsh", action="store_true", help="AutoBlock only")
    parser.add_argument("--ccx", default="ccx", help="CalculiX binary")
    parser.add_argument("--reference", action="store_true",
                        help="also gmsh's mesh with 8-node quads (CPS8): the FE answer nearer convergence")
    parser.add_argument("--ratio", type=float, default=0.3, help="d/W (default 0.3)")
    parser.add_argument("--ratios", help="several d/W, comma-separated (overrides --ratio)")
    parser.add_argument("--size", type=float, default=1 / 80, help="element size in units of W (default 1/80)")
    parser.add_argument("--length", type=float, default=4.0, help="plate length in units of W (default 4)")
    parser.add_argument("--check", action="store_true", help="exit 1 if AutoBlock's K_t is > 5 %% off Peterson's")
    parser.add_argument("--json", help="write every row to this file")
    parser.add_argument("--keep", help="keep the meshes, decks and results in a folder under this one")
    args = parser.parse_args()
    ratios = [float(v) for v in args.ratios.split(",")] if args.ratios else [args.ratio]
    try:
        if any(not 0 < r < 0.9 for r in ratios) or args.length < 2 or not 0 < args.size < 0.5:
            raise Failure("want 0 < d/W < 0.9, --length >= 2 (in W), 0 < --size < 0.5 (in W)")
        ccx = shutil.which(args.ccx)
        if not ccx:
            raise Failure("CalculiX ({}) not found: install the Debian package calculix-ccx".format(args.ccx))
        if not shutil.which(args.autoblock):
            raise Failure("autoblock binary {} not found".format(args.autoblock))
        args.gmsh = None if args.no_gmsh else shutil.which(args.gmsh)
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
        rows = []
        for ratio in ratios:
            rows += analyse(ratio, args, ccx)
    except Failure as e:
        print("error: {}".format(e), file=sys.stderr)
        return 2

    print("Plate W = {:g}, L = {:g} W, element size {:g} W, CPS4 plane stress, CalculiX; K_t on the net section\n"
          .format(WIDTH, args.length, args.size))
    if not args.gmsh and not args.no_gmsh:
        print("(gmsh not found: AutoBlock only)\n")
    print("| d/W | L/W | mesher | size | elements | nodes | nodes on hole | K_t | Peterson (Howland) | error % | "
          "Heywood | error % | min scaled Jacobian (at the hole) |")
    print("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        if "failed" in r:
            print("| {:.2f} | {:g} | {} | {:.3g} | {} | | | | {:.4f} | | {:.4f} | | |".format(
                r["ratio"], r["length"] / WIDTH, r["mesher"], r["size"], r["failed"].replace("|", "/"), r["peterson"],
                r["heywood"]))
            continue
        print("| {:.2f} | {:g} | {} | {:.3g} | {} | {} | {} | {:.4f} | {:.4f} | {:+.2f} | {:.4f} | {:+.2f} | {} |".format(
            r["ratio"], r["length"] / WIDTH, r["mesher"], r["size"], r["elements"], r["nodes"], r["hole_nodes"], r["kt"], r["peterson"],
            r["error_percent"], r["heywood"], r["error_heywood_percent"],
            "{:.3f} ({:.3f})".format(r["min_scaled_jacobian"], r["min_scaled_jacobian_at_hole"])))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"width": WIDTH, "length_over_width": args.length, "size_over_width": args.size,
                       "young": YOUNG, "poisson": POISSON, "thickness": THICKNESS, "traction": TRACTION,
                       "rows": rows}, f, indent=1)
    bad = [r for r in rows if r["mesher"] == "AutoBlock" and ("failed" in r or abs(r["error_percent"]) > 100 * TOLERANCE)]
    if args.check and bad:
        print("check failed: AutoBlock's K_t is more than {:g} % from Peterson's (or no mesh) at d/W = {}".format(
            100 * TOLERANCE, ", ".join("{:g}".format(r["ratio"]) for r in bad)), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
