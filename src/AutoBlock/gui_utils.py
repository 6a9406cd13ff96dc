"""Small GUI helpers: reporting errors (report view and a dialog), echoing console calls."""

import contextlib

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from . import native


def main_window():
    return FreeCADGui.getMainWindow()


def message_of(error):
    """A user-facing line for an exception: the message for ValueError and friends, the type otherwise."""
    if isinstance(error, (ValueError, NotImplementedError, native.NativeModuleMissing)):
        return str(error)
    return "{}: {}".format(type(error).__name__, error)


def report_error(title, message):
    """Print `message` to the report view and show it in a dialog."""
    FreeCAD.Console.PrintError("AutoBlock: {}: {}\n".format(title, message))
    QtWidgets.QMessageBox.warning(main_window(), "AutoBlock: " + title, message)


def ask_yes_no(title, message):
    """Ask a question in a dialog; True when the user answers Yes (No is the default)."""
    answer = QtWidgets.QMessageBox.question(main_window(), "AutoBlock: " + title, message,
                                            QtWidgets.QMessageBox.Yes | QtWidgets.QMessageBox.No,
                                            QtWidgets.QMessageBox.No)
    return answer == QtWidgets.QMessageBox.Yes


def report_exception(title, error):
    """Report an exception from a command; internal errors also get their traceback in the report view."""
    if not isinstance(error, (ValueError, NotImplementedError, native.NativeModuleMissing, TypeError)):
        import traceback

        FreeCAD.Console.PrintLog("".join(traceback.format_exception(type(error), error, error.__traceback__)))
    report_error(title, message_of(error))


@contextlib.contextmanager
def busy():
    """The wait cursor while the body runs (searching and meshing a face can take seconds), restored
    however it ends."""
    QtWidgets.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
    try:
        yield
    finally:
        QtWidgets.QApplication.restoreOverrideCursor()


def echo(code):
    """Run `code` in FreeCAD's Python console, echoed there (so users see the console call)."""
    FreeCADGui.doCommand(code)


def object_ref(obj):
    """Console text that designates `obj`."""
    return "App.getDocument({!r}).getObject({!r})".format(obj.Document.Name, obj.Name)
