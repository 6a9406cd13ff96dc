"""The workbench's commands (GUI only). Each one echoes its console call and reports errors in the report
view and a dialog; none can take FreeCAD down."""

TOOLBAR = ["AutoBlock_AutoBlock", "AutoBlock_StepThrough", "AutoBlock_ExportMesh", "AutoBlock_WriteBack",
           "AutoBlock_Train"]
MENU = TOOLBAR + ["Separator", "AutoBlock_Preferences"]

_registered = False


def register():
    """Register the commands with FreeCADGui (once)."""
    global _registered
    if _registered:
        return
    import FreeCADGui

    from .auto_block import AutoBlockCommand
    from .export_mesh import ExportMeshCommand
    from .preferences import PreferencesCommand
    from .step_through import StepThroughCommand
    from .train import TrainCommand
    from .write_back import WriteBackCommand

    for command in (AutoBlockCommand, StepThroughCommand, ExportMeshCommand, WriteBackCommand, TrainCommand,
                    PreferencesCommand):
        FreeCADGui.addCommand(command.NAME, command())
    _registered = True
