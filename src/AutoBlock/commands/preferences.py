"""Open AutoBlock's preferences page."""

from .base import BaseCommand


class PreferencesCommand(BaseCommand):
    NAME = "AutoBlock_Preferences"
    ICON = "AutoBlock_Preferences"
    MENU_TEXT = "Preferences..."
    TOOL_TIP = "AutoBlock's preferences: default policy, reward preset, mesh size, threads"

    def IsActive(self):
        return True

    def run(self):
        from ..gui_utils import echo

        echo('Gui.showPreferences("AutoBlock")')
