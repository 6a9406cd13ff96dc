# AutoBlock workbench: GUI init (exec'd by FreeCAD after Init.py when the GUI is up).
#
# Defines and registers the workbench. Loading stays cheap: commands, task panels and the native
# module are imported when the workbench is first activated or a command first runs.
import FreeCAD
import FreeCADGui


class AutoBlockWorkbench(FreeCADGui.Workbench):
    """Cut planar rectilinear faces into rectangular blocks for structured quad meshing."""

    MenuText = "AutoBlock"
    ToolTip = "Cut planar rectilinear faces into rectangular blocks (block decomposition for mapped quad meshing)"

    def __init__(self):
        import AutoBlock.paths

        self.__class__.Icon = AutoBlock.paths.icon("AutoBlock_Workbench")

    def Initialize(self):
        import AutoBlock.commands

        AutoBlock.commands.register()
        self.appendToolbar("AutoBlock", AutoBlock.commands.TOOLBAR)
        self.appendMenu("AutoBlock", AutoBlock.commands.MENU)
        import AutoBlock.preferences_page

        AutoBlock.preferences_page.register()

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


try:
    import AutoBlock  # noqa: F401  (Init.py put it on sys.path)
except ImportError as error:
    FreeCAD.Console.PrintWarning("AutoBlock: workbench not loaded ({})\n".format(error))
else:
    FreeCADGui.addWorkbench(AutoBlockWorkbench())
    FreeCAD.__unit_test__ += ["TestAutoBlockGui"]
