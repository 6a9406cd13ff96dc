"""Undoable transactions: every change AutoBlock makes to a document is one of them."""

import contextlib

import FreeCAD


@contextlib.contextmanager
def transaction(name):
    """Run the block as one undoable transaction called `name`; abort it (undo its changes) when the block
    raises. When a transaction is already open (a GUI command's), the changes join it instead.

    Uses FreeCAD's application-level transaction: Document.openTransaction() followed by an abort or
    commit without changes leaves the transaction open in FreeCAD 0.20.
    """
    if FreeCAD.getActiveTransaction() is not None:
        yield
        return
    FreeCAD.setActiveTransaction(name)
    try:
        yield
    except BaseException:
        FreeCAD.closeActiveTransaction(True)
        raise
    FreeCAD.closeActiveTransaction()
