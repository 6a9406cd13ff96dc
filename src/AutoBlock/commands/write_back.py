"""Write the partitioned face (or a solid's prism blocks) back: a new Part feature, or replace the source's
shape."""

import FreeCADGui

from .base import BaseCommand, selected_autoblocks


def selected_targets():
    """The selected AutoBlock objects and AutoBlock solid objects."""
    return selected_autoblocks(solids=True)


def ask_mode(obj):
    """'new', 'replace' or None (cancelled)."""
    from PySide2 import QtWidgets

    from ..gui_utils import main_window

    box = QtWidgets.QMessageBox(main_window())
    box.setWindowTitle("AutoBlock: write back")
    box.setIcon(QtWidgets.QMessageBox.Question)
    from ..objects.solid_blocks import is_autoblock_solid

    solid = is_autoblock_solid(obj)
    source = (obj.Source.Label if solid else obj.Source[0].Label) if obj.Source else "the source"
    box.setText("Write the blocks of {} back into the document:".format(obj.Label))
    box.setInformativeText(
        "New Part feature: a compound of the {n} {kind}; {src} and {obj} stay as they are.\n\n"
        "Replace source shape: {src} gets {what} (plain Part features only); {obj} is then removed.\n\n"
        "Either can be undone.".format(n=obj.NumberOfBlocks, src=source, obj=obj.Label,
                                       kind="prism blocks" if solid else "block faces",
                                       what="the prism blocks in place of its solid" if solid else
                                       "the partitioned face in place of its face"))
    new = box.addButton("New Part feature", QtWidgets.QMessageBox.AcceptRole)
    replace = box.addButton("Replace source shape", QtWidgets.QMessageBox.AcceptRole)
    box.addButton(QtWidgets.QMessageBox.Cancel)
    box.setDefaultButton(new)
    box.exec_()
    clicked = box.clickedButton()
    if clicked is new:
        return "new"
    if clicked is replace:
        return "replace"
    return None


class WriteBackCommand(BaseCommand):
    NAME = "AutoBlock_WriteBack"
    ICON = "AutoBlock_WriteBack"
    MENU_TEXT = "Write back..."
    TOOL_TIP = ("Write the selected AutoBlock object's blocks into the document: as a new Part feature, or "
                "replacing the source object's shape")

    # Tests set this to a function(obj) -> mode to answer the question without a dialog.
    choose_mode = staticmethod(ask_mode)

    def IsActive(self):
        return FreeCADGui.ActiveDocument is not None and len(selected_targets()) >= 1

    def run(self):
        from ..gui_utils import echo, object_ref
        from ..transactions import transaction

        objects = selected_targets()
        mode = self.choose_mode(objects[0])
        if mode is None:
            return
        with transaction("Write back blocks"):
            echo("import AutoBlock")
            for obj in objects:
                echo("AutoBlock.write_back({}, mode={!r})".format(object_ref(obj), mode))
