"""Train a policy (task panel)."""

import FreeCADGui

from .base import BaseCommand


class TrainCommand(BaseCommand):
    NAME = "AutoBlock_Train"
    ICON = "AutoBlock_Train"
    MENU_TEXT = "Train a policy..."
    TOOL_TIP = "Train a decomposition policy on folders of faces or generated shapes, in the background"

    def IsActive(self):
        return not FreeCADGui.Control.activeDialog()

    def run(self):
        from ..gui_utils import echo

        echo("import AutoBlock.taskpanels.train")
        echo("AutoBlock.taskpanels.train.show()")
