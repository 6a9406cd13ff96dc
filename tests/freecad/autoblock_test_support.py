"""Shared helpers of the FreeCAD tests (TestAutoBlockApp, TestAutoBlockGui)."""

import os
import shutil
import tempfile

import FreeCAD
import Part

import AutoBlock.paths

SAMPLES = os.path.join(AutoBlock.paths.MODELS, "data", "test")
SAMPLE = os.path.join(SAMPLES, "shape_0003.brep")
HOLES_SAMPLE = os.path.join(AutoBlock.paths.MODELS, "data", "test-holes", "shape_0000.brep")


def read_face(path=SAMPLE):
    shape = Part.Shape()
    shape.read(path)
    return shape.Faces[0]


def temporary_folder():
    """A fresh folder under AUTOBLOCK_TEST_TMP (set by the test runner) or the system's."""
    base = os.environ.get("AUTOBLOCK_TEST_TMP")
    if base:
        os.makedirs(base, exist_ok=True)
    return tempfile.mkdtemp(prefix="autoblock-", dir=base)


def remove_folder(path):
    shutil.rmtree(path, ignore_errors=True)


def new_document(name, undo=True):
    doc = FreeCAD.newDocument(name)
    doc.UndoMode = 1 if undo else 0
    return doc


def close_document(doc):
    try:
        FreeCAD.closeDocument(doc.Name)
    except Exception:
        pass


def add_face(doc, face, name="Face"):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = face
    doc.recompute()
    return obj


def add_l_fusion(doc):
    """Part's Fusion (Refine off, its default) of a 10 x 4 x 3 box and a 4 x 6 x 3 one on its end: an L whose
    caps stay split where the boxes meet. Returns (fusion, long box, short box)."""
    long_box = doc.addObject("Part::Box", "LongBox")
    long_box.Length, long_box.Width, long_box.Height = 10, 4, 3
    short_box = doc.addObject("Part::Box", "ShortBox")
    short_box.Length, short_box.Width, short_box.Height = 4, 6, 3
    short_box.Placement.Base = FreeCAD.Vector(0, 4, 0)
    fusion = doc.addObject("Part::MultiFuse", "Fusion")
    fusion.Shapes = [long_box, short_box]
    doc.recompute()
    return fusion, long_box, short_box


def l_points(width=4.0, height=4.0, notch=2.0):
    """An L-shape's corners, counter-clockwise, in the XY plane."""
    V = FreeCAD.Vector
    return [V(0, 0, 0), V(width, 0, 0), V(width, height - notch, 0), V(width - notch, height - notch, 0),
            V(width - notch, height, 0), V(0, height, 0)]


def add_l_sketch(doc, placement=None, name="Sketch", **size):
    import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

    sketch = doc.addObject("Sketcher::SketchObject", name)
    if placement is not None:
        sketch.Placement = placement
    points = l_points(**size)
    for a, b in zip(points, points[1:] + points[:1]):
        sketch.addGeometry(Part.LineSegment(a, b))
    doc.recompute()
    return sketch


def l_face(**size):
    points = l_points(**size)
    return Part.Face(Part.makePolygon(points + points[:1]))


def is_rectangle(face, tolerance=1e-7):
    """Four corners and area = bounding-box area in the face's plane."""
    if len(face.Vertexes) != 4:
        return False
    a, b, c = (v.Point for v in face.OuterWire.OrderedVertexes[:3])
    return abs(face.Area - (a - b).Length * (c - b).Length) <= tolerance * max(face.Area, 1.0)


def add_slanted_sketch(doc, name="Slanted"):
    """A sketch of slanted lines: a hexagon with edges at several angles and a tilted quadrilateral hole."""
    import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

    V = FreeCAD.Vector
    sketch = doc.addObject("Sketcher::SketchObject", name)
    outer = [V(0, 0, 0), V(60, -8, 0), V(78, 18, 0), V(55, 47, 0), V(12, 40, 0), V(-6, 17, 0)]
    hole = [V(22, 12, 0), V(38, 9, 0), V(42, 24, 0), V(25, 28, 0)]
    for ring in (outer, hole):
        for a, b in zip(ring, ring[1:] + ring[:1]):
            sketch.addGeometry(Part.LineSegment(a, b))
    doc.recompute()
    return sketch


def add_l_pad(doc, length=3.0):
    """A PartDesign Body holding an L sketch padded by `length`: (body, pad), recomputed."""
    body = doc.addObject("PartDesign::Body", "Body")
    sketch = add_l_sketch(doc)
    body.addObject(sketch)
    pad = doc.addObject("PartDesign::Pad", "Pad")
    body.addObject(pad)
    pad.Profile = sketch
    pad.Length = length
    doc.recompute()
    return body, pad
