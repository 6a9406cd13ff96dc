"""The base of AutoBlock's commands."""

import FreeCADGui

from .. import paths


class BaseCommand:
    NAME = ""
    ICON = ""
    MENU_TEXT = ""
    TOOL_TIP = ""
    ACCEL = ""

    def GetResources(self):
        return {"Pixmap": paths.icon(self.ICON), "MenuText": self.MENU_TEXT, "ToolTip": self.TOOL_TIP,
                "Accel": self.ACCEL}

    def IsActive(self):
        return FreeCADGui.ActiveDocument is not None

    def Activated(self):
        from ..gui_utils import report_exception

        try:
            self.run()
        except Exception as error:  # a command must never take FreeCAD down
            report_exception(self.MENU_TEXT.replace("...", ""), error)

    def run(self):
        raise NotImplementedError


def selected_autoblocks(solids=False):
    """The selected AutoBlock objects (solids: and AutoBlock solid objects)."""
    from ..objects.autoblock_feature import is_autoblock
    from ..objects.solid_blocks import is_autoblock_solid

    return [o for o in FreeCADGui.Selection.getSelection() if is_autoblock(o) or (solids and is_autoblock_solid(o))]
