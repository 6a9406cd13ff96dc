"""Export mesh: the selected AutoBlock object's quad mesh as a Gmsh .msh, VTK .vtu or Abaqus/CalculiX .inp
file, written by the core's exporters (one group per block, global coordinates)."""

import FreeCADGui

from .base import BaseCommand

FILTERS = "Gmsh mesh (*.msh);;VTK unstructured grid (*.vtu);;Abaqus/CalculiX input (*.inp)"


def selected_meshables():
    """Selected AutoBlock objects and AutoBlock mesh objects."""
    from ..objects.autoblock_feature import is_autoblock
    from ..objects.fem_mesh import is_autoblock_mesh

    return [o for o in FreeCADGui.Selection.getSelection() if is_autoblock(o) or is_autoblock_mesh(o)]


def ask_path(obj):
    """A file name chosen in a dialog, or None (cancelled)."""
    import os

    from PySide2 import QtWidgets

    from ..gui_utils import main_window

    start = os.path.join(os.path.expanduser("~"), "{}.msh".format(obj.Label.replace(" ", "_")))
    path, chosen = QtWidgets.QFileDialog.getSaveFileName(main_window(), "Export the quad mesh of {}".format(obj.Label),
                                                         start, FILTERS)
    if not path:
        return None
    if not os.path.splitext(path)[1]:
        path += {"VTK": ".vtu", "Abaqus": ".inp"}.get((chosen or "").split(" ")[0], ".msh")
    return path


class ExportMeshCommand(BaseCommand):
    NAME = "AutoBlock_ExportMesh"
    ICON = "AutoBlock_ExportMesh"
    MENU_TEXT = "Export mesh..."
    TOOL_TIP = ("Write the selected AutoBlock object's quad mesh to a file: Gmsh .msh, VTK .vtu or Abaqus/CalculiX "
                ".inp (one group per block)")

    # Tests set this to a function(obj) -> path to answer without a dialog.
    choose_path = staticmethod(ask_path)

    def IsActive(self):
        return FreeCADGui.ActiveDocument is not None and len(selected_meshables()) == 1

    def run(self):
        import FreeCAD

        from ..gui_utils import echo, object_ref

        obj = selected_meshables()[0]
        path = self.choose_path(obj)
        if not path:
            return
        echo("import AutoBlock")
        echo("_autoblock_mesh = AutoBlock.export_mesh({}, {!r})".format(object_ref(obj), path))
        import __main__

        result = getattr(__main__, "_autoblock_mesh", None)
        FreeCAD.Console.PrintMessage("AutoBlock: {}: {}\n".format(path, result.summary() if result else "written"))
