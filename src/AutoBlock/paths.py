"""Where AutoBlock's files are: the checkout, its resources and the built native module.

Everything is resolved from this file's location (Init.py and InitGui.py have no __file__).
Layout of a checkout: <root>/src/AutoBlock (this package), <root>/resources/{icons,ui},
<root>/build/python (the native module, built by ./setup.sh).
"""

import os

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(PACKAGE_DIR))
RESOURCES = os.path.join(ROOT, "resources")
ICONS = os.path.join(RESOURCES, "icons")
UI = os.path.join(RESOURCES, "ui")
MODELS = os.path.join(ROOT, "models")

# Environment variable naming the folder of autoblock_native*.so (the tests set it to their build).
NATIVE_DIR_VARIABLE = "AUTOBLOCK_NATIVE_DIR"


def icon(name):
    """The path of resources/icons/<name>.svg."""
    return os.path.join(ICONS, name + ".svg")


def ui(name):
    """The path of resources/ui/<name>.ui."""
    return os.path.join(UI, name + ".ui")


def native_dirs():
    """Folders searched for the native module, in order."""
    dirs = []
    if os.environ.get(NATIVE_DIR_VARIABLE):
        dirs.append(os.environ[NATIVE_DIR_VARIABLE])
    dirs += [PACKAGE_DIR, os.path.join(ROOT, "build", "python")]
    return dirs
