"""Which face to cut, and the face's own frame.

A face can be given as a Part.Face, any Part.Shape holding one face (or closed planar wires, as a
sketch holds), a document object with such a shape, or an object with a sub-element name
((obj, "Face3")). The core cuts faces parallel to the XY plane; a face in any other plane (a sketch on
XZ, the side of a box) or turned within its plane is carried into its own frame first (face_frame,
computed by the core, src/core/geometry/occt_face.h), cut there, and the blocks carried back. In that
frame a face whose edges run along two perpendicular directions has them along X and Y (the grid
engine); a face with edges at other angles (the general engine) keeps the model's coordinates when
it is parallel to XY, as in the CLI.
"""

import FreeCAD
import Part

from . import text

IDENTITY = FreeCAD.Placement()


def _is_document_object(target):
    return hasattr(target, "TypeId") and hasattr(target, "Document") and hasattr(target, "Name")


def face_of(target, sub=None):
    """Returns (face, label): the face `target` designates (global coordinates) and a name for messages.

    Raises ValueError when it designates no face or several, and TypeError for other objects.
    """
    if isinstance(target, tuple) and len(target) == 2 and sub is None:
        target, sub = target
    if isinstance(sub, (list, tuple)):
        if len(sub) > 1:
            raise ValueError("one face at a time: got the sub-elements {}".format(", ".join(sub)))
        sub = sub[0] if sub else None
    if sub == "":
        sub = None
    if isinstance(target, Part.Shape):
        if sub:
            return _single_face(target.getElement(sub), sub), sub
        return _single_face(target, "the shape"), "the shape"
    if _is_document_object(target):
        label = target.Label
        if not hasattr(target, "Shape") and not sub:
            raise ValueError("{} ({}) has no shape".format(label, target.TypeId))
        if sub:
            # A sub-element ("Face6"), a path to one through containers ("Pad.Face6" of a Body), or a path
            # to a whole object inside a container ("Sketch." of a Body).
            element = sub.split(".")[-1]
            if element and not element.startswith("Face"):
                raise ValueError("{}.{} is not a face: select a face (Face1, Face2, ...)".format(label, sub))
            label = "{}.{}".format(label, sub.rstrip("."))
            try:
                shape = Part.getShape(target, sub, needSubElement=bool(element))
            except Exception as error:
                raise ValueError("{}: no such face ({})".format(label, error)) from error
        else:
            shape = Part.getShape(target)
        return _single_face(shape, label), label
    raise TypeError("expected a Part.Face, a Part.Shape, a document object or (object, 'FaceN'), got {}".format(
        type(target).__name__))


def selection_target(obj, sub):
    """(object, sub or None) that AutoBlock should cut for a selected `obj` with sub-element path `sub`
    (FreeCADGui.Selection.getSelectionEx("", 0): obj is the top-level object, sub a full path), and the
    object to hide once it is cut. A face or a path to one is kept; an edge or vertex stands for its
    whole object."""
    element = sub.split(".")[-1] if sub else ""
    if element.startswith("Face"):
        path = sub
    elif sub and "." in sub:
        path = sub[: sub.rindex(".") + 1]  # "Sketch.Edge3" -> "Sketch."
    else:
        path = None
    leaf = obj
    if path:
        try:
            leaf = obj.getSubObject(path, retType=1) or obj
        except Exception:
            leaf = obj
    return obj, path, leaf


def _single_face(shape, label):
    if shape is None or shape.isNull():
        raise ValueError("{} is empty (a null shape)".format(label))
    faces = shape.Faces
    if len(faces) == 1:
        return faces[0]
    if len(faces) > 1:
        raise ValueError("{} has {} faces: choose one (select a face, or pass (object, 'Face1'))".format(
            label, len(faces)))
    wires = shape.Wires
    if not wires:
        raise ValueError("{} holds no face and no closed wire".format(label))
    if not all(w.isClosed() for w in wires):
        if len(wires) == 1:
            raise ValueError("{} holds no face, and its wire is not closed".format(label))
        raise ValueError("{} holds no face, and not all of its {} are closed".format(label, text.counted(len(wires), "wire")))
    try:
        made = Part.makeFace(wires, "Part::FaceMakerBullseye")
    except Exception as error:
        raise ValueError("{}: its closed wires do not make a planar face ({})".format(label, error)) from error
    if len(made.Faces) != 1:
        raise ValueError("{}: its closed wires make {} faces, expected one".format(label, len(made.Faces)))
    return made.Faces[0]


def face_frame(face):
    """The placement of the face's own frame, by the core's rule (src/core/geometry/occt_face.h, face_frame, the
    one the CLI uses): identity when the face lies parallel to XY with an edge along X or Y, or with no frame
    in which its edges run along two perpendicular directions (coordinates stay the model's); otherwise origin
    at the start of its longest straight edge, X along that edge, Z along the face's normal. Faces the core
    cannot read keep the identity (the core then says what is wrong)."""
    from . import native

    return placement_of(native.load().face_frame(face.exportBrepToString()))


def placement_of(m):
    """The placement of 12 numbers as the core gives a frame: the row-major rotation, then the translation."""
    return FreeCAD.Placement(FreeCAD.Matrix(m[0], m[1], m[2], m[9], m[3], m[4], m[5], m[10], m[6], m[7], m[8], m[11],
                                            0, 0, 0, 1))


def is_identity(placement):
    return placement.isIdentity() if hasattr(placement, "isIdentity") else placement == FreeCAD.Placement()


def into_frame(shape, frame):
    """A copy of `shape` (global coordinates) in `frame`'s coordinates."""
    copy = shape.copy()
    if not is_identity(frame):
        copy.transformShape(frame.inverse().toMatrix(), True)  # True: move the geometry, not the location
    return copy


def out_of_frame(shape, frame):
    """A copy of `shape` (in `frame`'s coordinates) in global coordinates."""
    copy = shape.copy()
    if not is_identity(frame):
        # Move the geometry itself: a Part feature replaces its shape's location by its Placement.
        copy.transformShape(frame.toMatrix(), True)
    return copy


def point_out_of_frame(x, y, z, frame):
    """The global point of (x, y, z) in `frame`."""
    return frame.multVec(FreeCAD.Vector(x, y, z))


def polygon_face(outer, holes, z):
    """A planar face at height z bounded by `outer` and `holes` (lists of (x, y) corners)."""
    def wire(ring):
        points = [FreeCAD.Vector(x, y, z) for x, y in ring]
        return Part.makePolygon(points + points[:1])

    wires = [wire(outer)] + [wire(h) for h in holes]
    return Part.makeFace(wires, "Part::FaceMakerBullseye").Faces[0]
