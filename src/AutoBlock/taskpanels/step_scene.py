"""The step-through panel's picture in the 3-D view: Coin nodes added to the view's scene graph (not to
the document), removed when the panel closes.

It draws the pieces at a step (blocks in their final colours, parts still to cut in grey, the part
being cut highlighted), the outlines, the current part's vertices, the chosen vertex, the cut line
(on a face with edges at other angles: the cut's chords at any angle, a partial cut ending where it
meets the boundary, and its origin ringed in red also when it lies on an edge), and, when a learned
policy gives them, value scores at the vertices.

The vertex marks are screen-space images (SoImage): a disc in the score's colour with a dark outline, the
score as white text on a dark label, and a red ring around the chosen vertex. They keep their size in
pixels whatever the zoom or the model's size, and read on FreeCAD's dark-blue gradient as on a light
background.
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
        self.labels = []  # the score labels drawn now
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

    @staticmethod
    def _translation(offset):
        translation = coin.SoTranslation()
        translation.translation.setValue(offset.x, offset.y, offset.z)
        return translation

    def _badge(self, point, colour, label, chosen, lift, side=(1, 1)):
        """A vertex mark drawn in screen space at `point` (see badge_image); label: the score's text or ""."""
        node = coin.SoSeparator()
        translation = coin.SoTranslation()
        translation.translation.setValue(point.x + lift.x, point.y + lift.y, point.z + lift.z)
        node.addChild(translation)
        width, height, pixels = badge_image(colour, label, chosen, side)
        image = coin.SoImage()
        image.image.setValue(coin.SbVec2s(width, height), 4, pixels)
        image.horAlignment = coin.SoImage.CENTER
        image.vertAlignment = coin.SoImage.HALF
        node.addChild(image)
        if label:
            self.labels.append(label)
        return node

    def _label_sides(self, view, cut):
        """Per vertex of the cut part, the screen quadrant (sx, sy), each +1 or -1, for its label: opposite the
        quadrant its two boundary edges open into (away from the part at a convex corner, into it at a
        re-entrant one), so that neighbouring labels do not fall on each other."""
        piece = next((p for p in view.pieces if p.id == cut.part), None)
        arms = {}
        for ring in ([piece.outer] + list(piece.holes)) if piece is not None else []:
            count = len(ring)
            for k, (x, y) in enumerate(ring):
                (px, py), (nx, ny) = ring[k - 1], ring[(k + 1) % count]
                arms[(x, y)] = ((px > x) - (px < x) + (nx > x) - (nx < x), (py > y) - (py < y) + (ny > y) - (ny < y))
        try:
            orientation = self.view.getCameraNode().orientation.getValue()
            right = FreeCAD.Vector(*orientation.multVec(coin.SbVec3f(1, 0, 0)).getValue())
            up = FreeCAD.Vector(*orientation.multVec(coin.SbVec3f(0, 1, 0)).getValue())
        except Exception:  # no camera to ask: the model's X and Y
            right, up = FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(0, 1, 0)
        sides = []
        for local in cut.local_vertices:
            ax, ay = arms.get(tuple(local), (-1, -1))
            away = view.frame.Rotation.multVec(FreeCAD.Vector(-ax, -ay, 0))
            sides.append((1 if away.dot(right) >= 0 else -1, 1 if away.dot(up) >= 0 else -1))
        return sides

    # -- the picture --------------------------------------------------------------------------------
    def show(self, view, colours):
        """Draw `view` (a stepping.StepView); colours: (r, g, b) per block, in the order set aside."""
        self.content.removeAllChildren()
        self.labels = []
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
        self.content.addChild(self._lines([[a, b] for a, b in cut.line], CUT_COLOUR, 5, lift * 2))
        # The vertex marks are drawn last and on top of everything (an annotation), in screen space.
        marks = coin.SoAnnotation()
        scores = cut.scores or []
        scored = [score for score in scores if score is not None]
        low, high = (min(scored), max(scored)) if scored else (0.0, 1.0)
        span = (high - low) or 1.0
        sides = self._label_sides(view, cut)
        for index, point in enumerate(cut.vertices):
            score = scores[index] if index < len(scores) else None
            chosen = index == cut.chosen
            if score is not None:
                marks.addChild(self._badge(point, score_colour((score - low) / span), "{:.2f}".format(score), chosen,
                                           lift * 3, sides[index]))
            elif chosen:  # no score: a dark dot, ringed in red
                marks.addChild(self._badge(point, VERTEX_COLOUR, "", True, lift * 3))
            else:
                marks.addChild(self._markers([point], VERTEX_COLOUR, _marker("CIRCLE_FILLED", 7), lift * 3))
        if cut.chosen < 0 and cut.vertex is not None:  # a general cut from a point on an edge
            marks.addChild(self._badge(cut.vertex, VERTEX_COLOUR, "", True, lift * 3))
        self.content.addChild(marks)


BADGE_RADIUS = 7       # px: the disc at a vertex
RING_WIDTH = 3.5       # px: the red ring around the chosen vertex
LABEL_FONT_PIXELS = 13


def badge_image(colour, label, chosen, side=(1, 1)):
    """(width, height, RGBA bytes, rows bottom-up as SoImage wants them) of a vertex mark centred on the vertex:
    a disc of `colour` with a dark outline; a red ring around it when `chosen`; `label` (may be empty) as white
    text on a dark, slightly transparent rounded box, beside the disc in the screen quadrant `side` ((1, 1):
    right and up). The image is symmetric about the vertex (the rest stays transparent), so that SoImage can
    centre it there."""
    from PySide2 import QtCore, QtGui

    font = QtGui.QFont()
    font.setPixelSize(LABEL_FONT_PIXELS)
    font.setBold(True)
    metrics = QtGui.QFontMetrics(font)
    ring = BADGE_RADIUS + 2 + RING_WIDTH
    pad_x, pad_y, gap = 4, 1, 3
    label_w = metrics.horizontalAdvance(label) + 2 * pad_x if label else 0
    label_h = metrics.height() + 2 * pad_y if label else 0
    half_w = int(ring + 1 + (gap + label_w if label else 0))
    half_h = int(max(ring + 1, label_h))
    width, height = 2 * half_w + 1, 2 * half_h + 1  # odd: the vertex falls on a pixel's centre
    image = QtGui.QImage(width, height, QtGui.QImage.Format_RGBA8888)
    image.fill(QtCore.Qt.transparent)
    painter = QtGui.QPainter(image)
    painter.setRenderHint(QtGui.QPainter.Antialiasing)
    centre = QtCore.QPointF(width / 2.0, height / 2.0)
    if chosen:
        painter.setPen(QtGui.QPen(QtGui.QColor.fromRgbF(*CUT_COLOUR), RING_WIDTH))
        painter.setBrush(QtCore.Qt.NoBrush)
        radius = BADGE_RADIUS + 2 + RING_WIDTH / 2.0
        painter.drawEllipse(centre, radius, radius)
    painter.setPen(QtGui.QPen(QtGui.QColor(25, 25, 25), 1.5))
    painter.setBrush(QtGui.QColor.fromRgbF(*colour[:3]))
    painter.drawEllipse(centre, BADGE_RADIUS, BADGE_RADIUS)
    if label:
        # Beside the disc, level with its upper (or lower) half: x away by the ring, y by half the label.
        left = centre.x() + ring + gap if side[0] > 0 else centre.x() - ring - gap - label_w
        top = centre.y() - label_h + 2 if side[1] > 0 else centre.y() - 2
        box = QtCore.QRectF(left, top, label_w, label_h)
        painter.setPen(QtCore.Qt.NoPen)
        painter.setBrush(QtGui.QColor(20, 20, 28, 215))
        painter.drawRoundedRect(box, 4, 4)
        painter.setFont(font)
        painter.setPen(QtGui.QColor(255, 255, 255))
        painter.drawText(box, QtCore.Qt.AlignCenter, label)
    painter.end()
    flipped = image.mirrored(False, True)
    pixels = bytes(flipped.constBits())[: width * height * 4] if flipped.bytesPerLine() == 4 * width else b"".join(
        bytes(flipped.constScanLine(row))[: 4 * width] for row in range(height))
    return width, height, pixels
