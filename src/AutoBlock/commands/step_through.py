"""Step through the cuts of the selected AutoBlock object (task panel)."""

import FreeCADGui

from .base import BaseCommand, selected_autoblocks


class StepThroughCommand(BaseCommand):
    NAME = "AutoBlock_StepThrough"
    ICON = "AutoBlock_StepThrough"
    MENU_TEXT = "Step through the cuts"
    TOOL_TIP = ("Show the selected AutoBlock object's decomposition cut by cut (an AutoBlock solid's: its cap's, on the "
                "cap): the parts at each step, the chosen vertex, the cut line, the reward and the return")

    def IsActive(self):
        return (FreeCADGui.ActiveDocument is not None and len(selected_autoblocks(solids=True)) == 1
                and not FreeCADGui.Control.activeDialog())

    def run(self):
        from ..gui_utils import echo

        obj = selected_autoblocks(solids=True)[0]
        echo("Gui.getDocument({!r}).setEdit({!r}, 0)".format(obj.Document.Name, obj.Name))
