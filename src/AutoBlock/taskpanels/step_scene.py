"""The step-through panel's picture in the 3-D view: Coin nodes added to the view's scene graph (not to
the document), removed when the panel closes.

It draws the pieces at a step (blocks in their final colours, parts still to cut in grey, the part
being cut highlighted), the outlines, the current part's vertices, the chosen vertex, the cut line,
and, when a learned policy gives them, value scores at the vertices.
"""

import FreeCAD
import FreeCADGui
from pivy import coin

from .. import faces

PART_COLOUR = (0.86, 0.87, 0.90)
CURRENT_COLOUR = (1.0, 0.85, 0.35)
CURRENT_OUTLINE = (0.85, 0.42, 0.0)
OUTLINE = (0.12, 0.12, 0.12)
CUT_COLOUR = (0.85, 0.0, 0.05)
VERTEX_COLOUR = (0.1, 0.1, 0.1)


def _marker(name, size):
    try:
        return FreeCADGui.getMarkerIndex(name, size)
    except Exception:
        return coin.SoMarkerSet.CIRCLE_FILLED_9_9


def score_colour(t):
    """Blue (0) to red (1) through white."""
    t = min(max(t, 0.0), 1.0)
    if t < 0.5:
        s = t / 0.5
        return (0.2 + 0.8 * s, 0.35 + 0.65 * s, 1.0)
    s = (t - 0.5) / 0.5
    return (1.0, 1.0 - 0.8 * s, 1.0 - 0.8 * s)


class StepScene:
    def __init__(self, view):
        self.view = view
        self.root = coin.SoSeparator()
        self.root.setName("AutoBlockStepScene")
        light = coin.SoLightModel()
        light.model = coin.SoLightModel.BASE_COLOR
        self.root.addChild(light)
        self.content = coin.SoSeparator()
        self.root.addChild(self.content)
        self.view.getSceneGraph().addChild(self.root)

    def remove(self):
        try:
            graph = self.view.getSceneGraph()
            if graph.findChild(self.root) >= 0:
                graph.removeChild(self.root)
        except Exception:  # the view may be gone already
            pass

    # -- building blocks ------------------------------------------------------------------------
    @staticmethod
    def _material(colour, transparency=0.0):
        material = coin.SoMaterial()
        material.diffuseColor.setValue(*colour)
        material.transparency.setValue(transparency)
        return material

    def _face(self, face, colour):
        node = coin.SoSeparator()
        node.addChild(self._material(colour))
        points, triangles = face.tessellate(max(face.BoundBox.DiagonalLength * 1e-3, 1e-9))
        coordinates = coin.SoCoordinate3()
        coordinates.point.setValues(0, len(points), [(p.x, p.y, p.z) for p in points])
        node.addChild(coordinates)
        face_set = coin.SoIndexedFaceSet()
        indices = []
        for a, b, c in triangles:
            indices += [a, b, c, -1]
        face_set.coordIndex.setValues(0, len(indices), indices)
        node.addChild(face_set)
        return node

    def _lines(self, polylines, colour, width, lift):
        node = coin.SoSeparator()
        node.addChild(self._material(colour))
        style = coin.SoDrawStyle()
        style.lineWidth = width
        node.addChild(style)
        points, counts = [], []
        for line in polylines:
            points += [(p.x + lift.x, p.y + lift.y, p.z + lift.z) for p in line]
            counts.append(len(line))
        coordinates = coin.SoCoordinate3()
        coordinates.point.setValues(0, len(points), points)
        node.addChild(coordinates)
        line_set = coin.SoLineSet()
        line_set.numVertices.setValues(0, len(counts), counts)
        node.addChild(line_set)
        return node

    def _markers(self, points, colour, marker, lift):
        node = coin.SoSeparator()
        node.addChild(self._material(colour))
        coordinates = coin.SoCoordinate3()
        coordinates.point.setValues(0, len(points), [(p.x + lift.x, p.y + lift.y, p.z + lift.z) for p in points])
        node.addChild(coordinates)
        markers = coin.SoMarkerSet()
        markers.markerIndex = marker
        node.addChild(markers)
        return node

    def _disc(self, centre, radius, colour, axes, lift, ring=(1.0, 1.0, 1.0)):
        """A filled disc in the face's plane (axes: its in-plane unit vectors) with a thin ring around it."""
        import math

        u, v = axes
        points = []
        for k in range(24):
            a = 2 * math.pi * k / 24
            p = centre + u * (radius * math.cos(a)) + v * (radius * math.sin(a)) + lift
            points.append((p.x, p.y, p.z))
        node = coin.SoSeparator()
        node.addChild(self._material(colour))
        coordinates = coin.SoCoordinate3()
        coordinates.point.setValues(0, len(points), points)
        node.addChild(coordinates)
        face_set = coin.SoFaceSet()
        face_set.numVertices.setValue(len(points))
        node.addChild(face_set)
        outline = [FreeCAD.Vector(*p) for p in points + points[:1]]
        node.addChild(self._lines([outline], ring, 2, lift * 0.1))
        return node

    @staticmethod
    def _translation(offset):
        translation = coin.SoTranslation()
        translation.translation.setValue(offset.x, offset.y, offset.z)
        return translation

    def _text(self, point, text, colour, lift):
        node = coin.SoSeparator()
        node.addChild(self._material(colour))
        translation = coin.SoTranslation()
        translation.translation.setValue(point.x + lift.x, point.y + lift.y, point.z + lift.z)
        node.addChild(translation)
        label = coin.SoText2()
        label.string = text
        node.addChild(label)
        return node

    # -- the picture --------------------------------------------------------------------------------
    def show(self, view, colours):
        """Draw `view` (a stepping.StepView); colours: (r, g, b) per block, in the order set aside."""
        self.content.removeAllChildren()
        # Everything is drawn a little above the face (on the side its normal points to), layer by layer, so
        # that the source face or a solid's face in the same place cannot hide it.
        lift = view.normal * (1e-3 * max(view.size, 1e-9))
        current = view.next.part if view.next is not None else None

        faces_node = coin.SoSeparator()
        faces_node.addChild(self._translation(lift * 0.5))
        faces_node.addChild(coin.SoPolygonOffset())
        outlines, current_outline = [], []
        for piece in view.pieces:
            if piece.block:
                colour = colours[piece.index % len(colours)] if colours else PART_COLOUR
            else:
                colour = CURRENT_COLOUR if piece.id == current else PART_COLOUR
            faces_node.addChild(self._face(piece.face, colour))
            for ring in [piece.outer] + list(piece.holes):
                loop = [faces.point_out_of_frame(x, y, view.z, view.frame) for x, y in list(ring) + [ring[0]]]
                (current_outline if piece.id == current else outlines).append(loop)
        self.content.addChild(faces_node)
        if outlines:
            self.content.addChild(self._lines(outlines, OUTLINE, 2, lift))
        if current_outline:
            self.content.addChild(self._lines(current_outline, CURRENT_OUTLINE, 4, lift * 1.5))
        if view.next is None:
            return
        cut = view.next
        axes = (view.frame.Rotation.multVec(FreeCAD.Vector(1, 0, 0)), view.frame.Rotation.multVec(FreeCAD.Vector(0, 1, 0)))
        radius = 0.012 * max(view.size, 1e-9)
        self.content.addChild(self._lines([[a, b] for a, b in cut.line], CUT_COLOUR, 5, lift * 2))
        scored = [(point, score) for point, score in zip(cut.vertices, cut.scores or []) if score is not None]
        if scored:
            low, high = min(s for _, s in scored), max(s for _, s in scored)
            span = (high - low) or 1.0
            for point, score in scored:
                self.content.addChild(self._disc(point, radius, score_colour((score - low) / span), axes, lift * 3,
                                                 ring=OUTLINE))
                self.content.addChild(self._text(point + axes[0] * (1.5 * radius) + axes[1] * (1.5 * radius),
                                                 "{:.2f}".format(score), OUTLINE, lift * 4))
            unscored = [point for point, score in zip(cut.vertices, cut.scores) if score is None]
            if unscored:
                self.content.addChild(self._markers(unscored, VERTEX_COLOUR, _marker("CIRCLE_FILLED", 7), lift * 3))
        else:
            self.content.addChild(self._markers(cut.vertices, VERTEX_COLOUR, _marker("CIRCLE_FILLED", 7), lift * 3))
        # The chosen vertex: a red disc, under its score marker (a red ring around it) when there is one.
        self.content.addChild(self._disc(cut.vertex, radius * (1.4 if scored else 1.0), CUT_COLOUR, axes,
                                         lift * (2.5 if scored else 5)))
