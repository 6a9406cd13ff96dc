"""Words and numbers as people read them in the workbench's messages and panels.

    text.counted(1, "cut")                -> "1 cut"
    text.counted(3, "vertex", "vertices") -> "3 vertices"
    text.number(80.00000000000001, 1e-5)  -> "80"   (the core's rule, see src/core/common/format.h)
    text.vector(FreeCAD.Vector(1, 2, 0))  -> "(1, 2, 0)"

Numbers come from the core (autoblock_native.format_number), so the CLI, the reports and the workbench
print them the same way: plain decimals rounded to a tolerance, scientific notation only for huge or tiny
values.
"""

import math

from . import native


def counted(n, singular, plural=None):
    """'1 cut', '0 cuts', '2 cuts'; plural: the plural form when it is not singular + 's'."""
    return "{} {}".format(n, singular if n == 1 else (plural or singular + "s"))


def number(value, tolerance=0.0):
    """`value` as text: a plain decimal rounded to `tolerance` (0: exact); noise below it reads '0'."""
    return native.load().format_number(float(value), float(tolerance))


def vector(v, tolerance=0.0):
    """A FreeCAD.Vector (or any x, y, z) as '(x, y, z)' with number()."""
    x, y, z = (v.x, v.y, v.z) if hasattr(v, "x") else tuple(v)
    return "({}, {}, {})".format(number(x, tolerance), number(y, tolerance), number(z, tolerance))


def point(x, y, tolerance=0.0):
    """'(x, y)' with number()."""
    return "({}, {})".format(number(x, tolerance), number(y, tolerance))


def significant(value, digits=4):
    """`value` rounded to `digits` significant digits, as number() prints it: (12345.6, 4) -> '12350'."""
    if value == 0:
        return number(0.0)
    leading = math.floor(math.log10(abs(value)))
    return number(value, 10.0 ** (leading - max(digits, 1) + 1))


def tolerance_of(size):
    """The tolerance of a face whose bounding box's longer side is `size` (the core's 1e-7 relative rule)."""
    return 1e-7 * abs(size)


def cut_direction(kind, direction):
    """How a general face's action reads: 'full cut at 30.0 degrees' (direction: (dx, dy) in the face's frame),
    'template (quads around its centre)'."""
    if kind == "template":
        return "template (quads around its centre)"
    return "{} cut at {:.1f} degrees".format(kind, math.degrees(math.atan2(direction[1], direction[0])))
