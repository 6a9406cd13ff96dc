"""The native module (autoblock_native, built from src/python), loaded on first use.

Importing AutoBlock, or loading the workbench, does not load it: only the first decomposition
does. When it is missing, every action says how to build it instead of failing obscurely.
"""

import importlib
import os
import sys

from . import paths

_module = None


class NativeModuleMissing(RuntimeError):
    """The native module is not built (or not built for this Python)."""


def load():
    """The native module. Raises NativeModuleMissing with what to do when it cannot be loaded."""
    global _module
    if _module is not None:
        return _module
    searched = paths.native_dirs()
    for folder in searched:
        if not os.path.isdir(folder):
            continue
        if any(name.startswith("autoblock_native.") for name in os.listdir(folder)):
            if folder not in sys.path:
                sys.path.insert(0, folder)
            break
    try:
        # FreeCAD's Part module must come first in a plain Python (see the platform notes).
        import FreeCAD  # noqa: F401
        import Part  # noqa: F401

        _module = importlib.import_module("autoblock_native")
    except ImportError as error:
        raise NativeModuleMissing(
            "the AutoBlock native module is not available ({}). Build it with `./setup.sh build` in {} "
            "(it must be built for this Python, {}.{}); searched: {}".format(
                error, paths.ROOT, sys.version_info.major, sys.version_info.minor, ", ".join(searched)
            )
        ) from error
    return _module


def capabilities():
    """What the core can do beyond the baselines: dict with learned_policies, training, vertex_scores, meshing."""
    return dict(load().capabilities())


def has(capability):
    """True when the core offers `capability` (see capabilities())."""
    return bool(capabilities().get(capability, False))
