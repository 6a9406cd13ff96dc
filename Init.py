# AutoBlock workbench: App init (exec'd by FreeCAD at start-up, GUI or not).
#
# FreeCAD exec's this file without __file__; it has put this folder (the checkout, usually linked
# into the user's Mod folder) on sys.path. Find it there, make the Python package (src/AutoBlock)
# and the FreeCAD tests (tests/freecad) importable, and register the App tests. Nothing heavy is
# imported here: the native module loads on first use.
import os
import sys

import FreeCAD


def _autoblock_checkout():
    for entry in list(sys.path):
        if os.path.isfile(os.path.join(entry, "src", "AutoBlock", "__init__.py")) and os.path.isfile(
            os.path.join(entry, "InitGui.py")
        ):
            return entry
    return None


_root = _autoblock_checkout()
if _root is None:
    FreeCAD.Console.PrintWarning("AutoBlock: cannot find src/AutoBlock next to this Init.py; workbench not loaded\n")
else:
    for _entry in (os.path.join(_root, "src"), os.path.join(_root, "tests", "freecad")):
        if _entry not in sys.path:
            sys.path.append(_entry)
    FreeCAD.__unit_test__ += ["TestAutoBlockApp"]
del _autoblock_checkout, _root
