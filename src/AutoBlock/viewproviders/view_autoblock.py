"""How an AutoBlock object looks: its blocks in distinct colours (the core's palette, as in the SVG
pictures), dark edges; double-click opens the step-through panel; the context menu offers stepping
and write-back."""

import FreeCAD
import FreeCADGui

from .. import paths


def block_colours(count):
    """(r, g, b, transparency) per block, from the core's palette; grey when the native module is missing."""
    try:
        from .. import native

        return [(r, g, b, 0.0) for r, g, b in native.load().block_colours(count)]
    except Exception:
        return [(0.8, 0.8, 0.8, 0.0)] * count


class ViewProviderAutoBlock:
    def __init__(self, vobj):
        vobj.Proxy = self
        self.ViewObject = vobj
        self.Object = vobj.Object
        vobj.LineWidth = 2.0
        vobj.LineColor = (0.15, 0.15, 0.15)
        vobj.PointSize = 4.0

    def attach(self, vobj):
        self.ViewObject = vobj
        self.Object = vobj.Object

    def getIcon(self):
        return paths.icon("AutoBlock_Object")

    def updateData(self, obj, prop):
        if prop == "Shape":
            # This runs before the Part view provider rebuilds its faces, which would drop the colours:
            # colour once it has.
            from PySide2 import QtCore

            QtCore.QTimer.singleShot(0, lambda: self.colour(obj))

    def colour(self, obj=None):
        obj = obj or self.Object
        try:
            if obj.Document.getObject(obj.Name) is None:
                return  # deleted meanwhile
            count = len(obj.Shape.Faces)
            if count:
                obj.ViewObject.DiffuseColor = block_colours(count)
        except Exception as error:  # never let colouring take anything down
            FreeCAD.Console.PrintWarning("AutoBlock: could not colour {}: {}\n".format(obj.Label, error))

    def onChanged(self, vobj, prop):
        pass

    def doubleClicked(self, vobj):
        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setupContextMenu(self, vobj, menu):
        from PySide2 import QtGui

        action = menu.addAction(QtGui.QIcon(paths.icon("AutoBlock_StepThrough")), "Step through the cuts")
        action.triggered.connect(lambda: FreeCADGui.runCommand("AutoBlock_StepThrough"))
        action = menu.addAction(QtGui.QIcon(paths.icon("AutoBlock_WriteBack")), "Write back...")
        action.triggered.connect(lambda: FreeCADGui.runCommand("AutoBlock_WriteBack"))

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # FreeCAD's own modes (transform, ...)
        from ..taskpanels.step_through import open_step_panel

        return open_step_panel(vobj.Object)

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        from ..taskpanels.step_through import close_step_panel

        close_step_panel(vobj.Object)
        return True

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


class ViewProviderAutoBlockSolid(ViewProviderAutoBlock):
    """An AutoBlock solid object: every face coloured by its prism block (a face shared by two blocks takes
    the first's). Double-click and the context menu step through its cap's cuts (drawn on the cap), as for a
    face; the context menu also offers write-back."""

    def colour(self, obj=None):
        obj = obj or self.Object
        try:
            if obj.Document.getObject(obj.Name) is None:
                return
            solids = obj.Shape.Solids
            palette = block_colours(len(solids))
            colours = []
            for face in obj.Shape.Faces:
                block = next((k for k, solid in enumerate(solids) if any(face.isSame(f) for f in solid.Faces)), 0)
                colours.append(palette[block] if palette else (0.8, 0.8, 0.8, 0.0))
            if colours:
                obj.ViewObject.DiffuseColor = colours
        except Exception as error:  # never let colouring take anything down
            FreeCAD.Console.PrintWarning("AutoBlock: could not colour {}: {}\n".format(obj.Label, error))
