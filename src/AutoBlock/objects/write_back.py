"""Writing an AutoBlock object's partitioned face back into the document:

    AutoBlock.write_back(obj, mode="new")       # a new Part feature holding the blocks (a compound)
    AutoBlock.write_back(obj, mode="replace")   # the source object's shape, with its face partitioned

An AutoBlock solid object's prism blocks (solid_blocks.py) are written back the same way: a new Part feature
holding them, or, with "replace", the source solid made the compound of its prisms.

"replace" works on plain Part features (Part::Feature, e.g. an imported STEP face or solid): a
parametric source (a sketch, an extrusion, a PartDesign feature) recomputes its shape from its own
inputs, so replacing it would not last; such sources get a clear ValueError. When the source holds
just the face, its new shape is the compound of the blocks; when the face belongs to a solid or a
shell, the face is split into the blocks in place (OpenCASCADE's general fuse). The AutoBlock object
has then done its job and is removed, with its FEM mesh object (the mesh of a face that no longer has a
parametric source). Either mode is one undoable transaction.

A new Part feature lies exactly where the AutoBlock object is, so the AutoBlock object (now redundant) is
hidden, as Auto-Block hides the source. Either mode says in the report view what it created, hid or
removed.
"""

import FreeCAD

from .. import text
from ..transactions import transaction
from .autoblock_feature import is_autoblock

MODES = ("new", "replace")


def report(message):
    """Say `message` in the report view (tests replace this to read it)."""
    FreeCAD.Console.PrintMessage("AutoBlock: {}\n".format(message))


def write_back(obj, mode="new", name=None):
    """Write `obj`'s blocks back. Returns the Part feature that holds them (new, or the source). obj: an AutoBlock
    object, or an AutoBlock solid object (solid_blocks.py), whose prism blocks become the new feature's shape
    or replace its source solid."""
    from .solid_blocks import is_autoblock_solid

    if not is_autoblock(obj) and not is_autoblock_solid(obj):
        raise ValueError("{} is not an AutoBlock object".format(getattr(obj, "Label", obj)))
    if mode not in MODES:
        raise ValueError("mode must be 'new' or 'replace', not {!r}".format(mode))
    if "Invalid" in obj.State or "Touched" in obj.State or obj.Shape.isNull():
        raise ValueError("{} is out of date or has no result: recompute it first".format(obj.Label))
    with transaction("Write back blocks"):
        return _new(obj, name) if mode == "new" else _replace(obj)


def _copy_colours(obj, target):
    if not FreeCAD.GuiUp:
        return
    try:
        colours = list(obj.ViewObject.DiffuseColor)
        if len(colours) == len(target.Shape.Faces):
            target.ViewObject.DiffuseColor = colours
    except Exception:  # colours are a nicety; never fail the write-back over them
        pass


def _new(obj, name):
    doc = obj.Document
    feature = doc.addObject("Part::Feature", name or "Blocks")
    feature.Label = name or "{} blocks".format(obj.Label)
    feature.Shape = obj.Shape.copy()
    _copy_colours(obj, feature)
    blocks = text.counted(len(_blocks_of(feature.Shape)), "block")
    if obj.Visibility:
        obj.Visibility = False
        hidden = "; hid {}, which shows the same blocks in the same place".format(obj.Label)
    else:
        hidden = ""
    doc.recompute()
    report("wrote the {} of {} to the new Part feature {}{}".format(blocks, obj.Label, feature.Label, hidden))
    return feature


def _blocks_of(shape):
    """The blocks of an AutoBlock object's shape: its solids (prisms of a solid object), else its faces."""
    return shape.Solids or shape.Faces


def _replace(obj):
    import Part

    from .solid_blocks import hex_mesh_objects_of, is_autoblock_solid

    doc = obj.Document
    if not obj.Source:
        raise ValueError("{}: no source to replace".format(obj.Label))
    solid = is_autoblock_solid(obj)
    source = obj.Source if solid else obj.Source[0]
    if source.TypeId != "Part::Feature":
        raise ValueError(
            "{} is a {}: its shape is recomputed from its own inputs, so replacing it would not last; write the "
            "blocks to a new Part feature instead".format(source.Label, source.TypeId))
    blocks = obj.Shape.copy()
    old = source.Shape
    if solid or (len(old.Faces) == 1 and not old.Solids and not old.Shells):
        new = blocks  # a solid object's prisms fill its whole source solid
    else:
        # Split the source's face into the blocks: the general fuse makes the blocks and the face share
        # their pieces, so the solid (or shell) comes out with the partitioned face in place.
        fused, _ = old.generalFuse([blocks])
        if old.Solids:
            parts = fused.Solids
        elif old.Shells:
            parts = fused.Shells
        else:
            parts = []
        if len(parts) != len(old.Solids or old.Shells):
            raise ValueError("{}: could not split its face into the blocks in place; write the blocks to a new "
                             "Part feature instead".format(source.Label))
        new = parts[0] if len(parts) == 1 else Part.makeCompound(parts)
        if not new.isValid():
            raise ValueError("{}: splitting its face in place gave an invalid shape; write the blocks to a new "
                             "Part feature instead".format(source.Label))
    # Keep the source's placement: a Part feature's shape is its geometry relative to its placement.
    placement = source.Placement
    local = new.copy()
    local.transformShape(placement.inverse().toMatrix(), True)  # True: move the geometry itself
    local.Placement = placement
    from .fem_mesh import mesh_objects_of

    meshes = hex_mesh_objects_of(obj) if solid else mesh_objects_of(obj)
    blocks = text.counted(len(_blocks_of(blocks)), "block")
    removed = [obj.Label] + [mesh.Label for mesh in meshes]
    for mesh in meshes:
        doc.removeObject(mesh.Name)
    doc.removeObject(obj.Name)
    source.Shape = local
    source.Visibility = True
    doc.recompute()
    report("{} now holds the {} in place of its {}, and is shown; removed {}, no longer needed".format(
        source.Label, blocks, "solid" if solid else "face", " and ".join(removed)))
    return source
