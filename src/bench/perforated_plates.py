# Perforated plates for `autoblock_bench_mesh --files`: faces unlike the arc generator's (which has
# one to four holes), with scores of round holes as tube sheets, filters and flanges have them.
#
#   freecadcmd -c "import sys; sys.argv = ['perforated_plates.py', 'OUT.brep', 'SEED', 'COUNT']; \
#                  exec(open('src/bench/perforated_plates.py').read())"
#
# Writes one compound of COUNT planar faces (default 40, seed 20261205), five kinds in turn:
#   0  a rectangular plate with a grid of holes;
#   1  a staggered (60-degree) grid;
#   2  holes of mixed sizes scattered at random, none nearer another than the ligament;
#   3  a disk with a polar pattern (4, 6 or 8 holes on each of one to four rings);
#   4  a disk with concentric rings of holes, as many on a ring as its pitch allows.
# With a fourth argument `flanges`, every face is a flange instead (kind 5): a disk with a bore
# (0.2-0.55 of its radius) and a bolt circle of 3-24 holes, a third of them with a second bolt circle
# (as many holes or twice as many, in line or half a pitch turned), a quarter with a flat (the disk
# cut by a chord outside the holes).
# Hole diameters 2-10, ligaments (the plate left between two holes) 0.35-2.5 diameters, margins
# 0.6-2 diameters; half the rectangular plates turned by a random angle. Faces that OpenCASCADE
# does not make valid with every hole are left out (the script prints what it kept).
import math
import random
import sys

import FreeCAD as App
import Part

V = App.Vector


def turned(p, angle, c):
    x, y = p.x - c.x, p.y - c.y
    return V(c.x + x * math.cos(angle) - y * math.sin(angle), c.y + x * math.sin(angle) + y * math.cos(angle), 0)


def plate(kind, rng):
    angle = rng.uniform(0, math.pi) if rng.random() < 0.5 else 0.0
    d = rng.uniform(2.0, 10.0)
    ligament = d * rng.choice([0.35, 0.6, 1.0, 1.5, 2.5])
    pitch = d + ligament
    margin = rng.choice([0.6, 1.0, 2.0]) * d
    holes = []
    if kind in (0, 1, 2):
        nx, ny = rng.randint(2, 10), rng.randint(2, 9)
        if kind == 0:
            holes = [(V(margin + d / 2 + i * pitch, margin + d / 2 + j * pitch, 0), d / 2) for i in range(nx) for j in range(ny)]
            w, h = 2 * margin + d + (nx - 1) * pitch, 2 * margin + d + (ny - 1) * pitch
        elif kind == 1:
            dy = pitch * math.sqrt(3) / 2
            holes = [(V(margin + d / 2 + i * pitch + (j % 2) * pitch / 2, margin + d / 2 + j * dy, 0), d / 2)
                     for j in range(ny) for i in range(nx - (j % 2))]
            w, h = 2 * margin + d + (nx - 1) * pitch, 2 * margin + d + (ny - 1) * dy
        else:
            w, h = rng.uniform(40, 200), rng.uniform(30, 120)
            wanted = rng.randint(5, 40)
            for _ in range(5000):
                if len(holes) == wanted:
                    break
                r = rng.uniform(0.5, 1.5) * d / 2
                c = V(rng.uniform(margin + r, w - margin - r), rng.uniform(margin + r, h - margin - r), 0)
                if all((c - c2).Length > r + r2 + ligament for c2, r2 in holes):
                    holes.append((c, r))
            if len(holes) < 3:
                return None
        centre = V(w / 2, h / 2, 0)
        corners = [turned(p, angle, centre) for p in (V(0, 0, 0), V(w, 0, 0), V(w, h, 0), V(0, h, 0))]
        holes = [(turned(c, angle, centre), r) for c, r in holes]
        outer = Part.makePolygon(corners + [corners[0]])
    else:
        rings = rng.randint(1, 4)
        if rng.random() < 0.5:
            holes.append((V(0, 0, 0), d / 2))
        for ring in range(1, rings + 1):
            radius = ring * pitch
            count = max(3, int(2 * math.pi * radius / pitch)) if kind == 4 else rng.choice([4, 6, 8])
            phase = rng.uniform(0, math.pi)
            holes += [(V(radius * math.cos(phase + 2 * math.pi * i / count), radius * math.sin(phase + 2 * math.pi * i / count), 0), d / 2)
                      for i in range(count)]
        outer = Part.Wire(Part.makeCircle(rings * pitch + d / 2 + margin, V(0, 0, 0)))
    face = Part.Face(outer)
    for c, r in holes:
        face = face.cut(Part.Face(Part.Wire(Part.makeCircle(r, c))))
    face = face.Faces[0]
    if not face.isValid() or len(face.Wires) != len(holes) + 1:
        return None
    print("kind %d: %d holes, diameter %.2f, ligament %.2f diameters" % (kind, len(holes), d, ligament / d))
    return face


def flange(rng):
    R = rng.uniform(30.0, 150.0)
    rb = rng.uniform(0.2, 0.55) * R
    width = R - rb
    n = rng.choice([3, 4, 5, 6, 8, 10, 12, 16, 24])
    two = rng.random() < 1.0 / 3.0
    circles = [rb + width * (rng.uniform(0.3, 0.4) if two else rng.uniform(0.4, 0.6))]
    if two:
        circles.append(rb + width * rng.uniform(0.65, 0.75))
    # The bolt diameter: at most a third of the ring's width per circle, and a ligament of at least
    # 0.4 diameters between neighbours on the crowdest circle.
    counts = [n] + ([n * rng.choice([1, 2])] if two else [])
    d_max = min(width / (3.0 * len(circles)), min(2.0 * r * math.sin(math.pi / c) / 1.4 for r, c in zip(circles, counts)))
    d = rng.uniform(0.4, 1.0) * d_max
    phase = rng.uniform(0, 2 * math.pi)
    holes = [(V(0, 0, 0), rb)]
    for ring, (r, c) in enumerate(zip(circles, counts)):
        offset = (math.pi / c) * (1 if ring == 1 and rng.random() < 0.5 else 0)
        holes += [(V(r * math.cos(phase + offset + 2 * math.pi * i / c), r * math.sin(phase + offset + 2 * math.pi * i / c), 0), d / 2)
                  for i in range(c)]
    face = Part.Face(Part.Wire(Part.makeCircle(R, V(0, 0, 0))))
    if rng.random() < 0.25:
        # A flat: the chord at a distance past the outer bolt circle.
        a = rng.uniform(0, 2 * math.pi)
        at = circles[-1] + d / 2 + rng.uniform(0.3, 0.7) * (R - circles[-1] - d / 2)
        u, t = V(math.cos(a), math.sin(a), 0), V(-math.sin(a), math.cos(a), 0)
        box = Part.makePolygon([u * at + t * 2 * R, u * 2 * R + t * 2 * R, u * 2 * R - t * 2 * R, u * at - t * 2 * R, u * at + t * 2 * R])
        face = face.cut(Part.Face(box)).Faces[0]
    for c, r in holes:
        face = face.cut(Part.Face(Part.Wire(Part.makeCircle(r, c))))
    face = face.Faces[0]
    if not face.isValid() or len(face.Wires) != len(holes) + 1:
        return None
    print("flange: %d bolt holes on %d circles, bore %.2f of the radius" % (len(holes) - 1, len(circles), rb / R))
    return face


def main(argv):
    out = argv[1] if len(argv) > 1 else "perforated.brep"
    seed = int(argv[2]) if len(argv) > 2 else 20261205
    count = int(argv[3]) if len(argv) > 3 else 40
    flanges = len(argv) > 4 and argv[4] == "flanges"
    rng = random.Random(seed)
    faces = []
    for k in range(count):
        face = flange(rng) if flanges else plate(k % 5, rng)
        if face is not None:
            faces.append(face)
    Part.makeCompound(faces).exportBrep(out)
    print("%d faces written to %s" % (len(faces), out))


main(sys.argv)
