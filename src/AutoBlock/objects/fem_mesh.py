"""FEM mesh objects of AutoBlock's quads, so that FreeCAD's FEM workbench can use them.

An AutoBlock object's mesh is a Fem::FemMeshObjectPython linked to it (property AutoBlock): on every
recompute it meshes the object's blocks with the core's mapped quad mesher (conformal merge, interval
assignment, transfinite blocks) at the object's MeshSize, so it follows the source face, the policy and
the mesh size. Its FemMesh holds 4-node quads in global coordinates (the exported files, export_mesh,
also keep the blocks: one group per block).

    mesh = AutoBlock.mesh(autoblock_object)     # its mesh object (made when it has none)
"""

import FreeCAD

from .. import paths
from . import properties

TYPE = "AutoBlock::Mesh"


def fem_mesh(nodes, quads):
    """A Fem.FemMesh of 4-node quads. nodes: [(x, y, z)]; quads: [(a, b, c, d)] of 0-based node indices,
    counter-clockwise. Raises ValueError for a bad index or a degenerate quad."""
    import Fem

    count = len(nodes)
    mesh = Fem.FemMesh()
    for number, (x, y, z) in enumerate(nodes, 1):
        mesh.addNode(float(x), float(y), float(z), number)
    for number, quad in enumerate(quads, 1):
        quad = [int(i) for i in quad]
        if len(quad) != 4:
            raise ValueError("quad {} has {} nodes, expected 4".format(number, len(quad)))
        if len(set(quad)) != 4:
            raise ValueError("quad {} repeats a node: {}".format(number, quad))
        if min(quad) < 0 or max(quad) >= count:
            raise ValueError("quad {} refers to a node outside 0..{}: {}".format(number, count - 1, quad))
        mesh.addFace([i + 1 for i in quad], number)
    return mesh


def make_fem_mesh_object(doc, nodes, quads, name="AutoBlockMesh", label=None):
    """Add a plain Fem::FemMeshObject holding the quads to `doc` and return it."""
    mesh = fem_mesh(nodes, quads)
    obj = doc.addObject("Fem::FemMeshObject", name)
    obj.FemMesh = mesh
    if label:
        obj.Label = label
    if FreeCAD.GuiUp:
        try:
            obj.ViewObject.DisplayMode = "Faces & Wireframe"
        except Exception:
            pass
    return obj


def is_autoblock_mesh(obj):
    """True for the mesh object of an AutoBlock object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == TYPE


class AutoBlockMeshFeature:
    Type = TYPE

    # (type, name, group, tooltip, attributes); 8: Output (changing it does not touch the object).
    PROPERTIES = [
        ("App::PropertyLink", "AutoBlock", "Mesh", "The AutoBlock object whose blocks this meshes (with its "
         "MeshSize).", 0),
        ("App::PropertyInteger", "NumberOfQuads", "Result", "Quadrilaterals in the mesh.", 8),
        ("App::PropertyInteger", "NumberOfNodes", "Result", "Nodes in the mesh.", 8),
        ("App::PropertyFloat", "TargetSize", "Result", "The element size aimed at (the MeshSize, or the automatic "
         "one: 1/20 of the face's longer side).", 8),
        ("App::PropertyString", "Quality", "Result", "Summary of the mesh: size deviation, minimum scaled "
         "Jacobian, conformity.", 8),
    ]
    READ_ONLY = ("NumberOfQuads", "NumberOfNodes", "TargetSize", "Quality")

    def __init__(self, obj):
        obj.Proxy = self
        self.last_error = None
        self.ensure_properties(obj)

    def ensure_properties(self, obj):
        properties.ensure_properties(obj, self.PROPERTIES, self.READ_ONLY)

    def onDocumentRestored(self, obj):
        self.last_error = None
        self.ensure_properties(obj)

    def execute(self, obj):
        from .. import console
        from .autoblock_feature import stepper_of

        self.last_error = None
        try:
            source = obj.AutoBlock
            if source is None:
                raise ValueError("{}: no AutoBlock object to mesh (set AutoBlock)".format(obj.Label))
            stepper = stepper_of(source)
            size = float(source.MeshSize)
            result = console.MeshResult(console._mesh_data(stepper, size), stepper, size)
        except Exception as error:
            self.last_error = error
            raise
        obj.FemMesh = result.fem_mesh()
        obj.NumberOfQuads = len(result.quads)
        obj.NumberOfNodes = len(result.nodes)
        obj.TargetSize = result.target_size
        obj.Quality = result.summary()

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        self.last_error = None
        return None


class ViewProviderAutoBlockMesh:
    """The mesh drawn as a wireframe over the coloured blocks."""

    def __init__(self, vobj):
        vobj.Proxy = self
        self.ViewObject = vobj
        try:
            vobj.DisplayMode = "Wireframe"
            vobj.LineWidth = 1.0
            vobj.ShapeColor = (0.1, 0.25, 0.55)
        except Exception:  # display details are a nicety
            pass

    def attach(self, vobj):
        self.ViewObject = vobj

    def getIcon(self):
        return paths.icon("AutoBlock_Mesh")

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


def mesh_objects_of(autoblock):
    """The mesh objects linked to the AutoBlock object `autoblock`."""
    return [o for o in autoblock.InList if is_autoblock_mesh(o) and o.AutoBlock == autoblock]


def make_mesh_object(autoblock, name="AutoBlockMesh"):
    """Add the mesh object of `autoblock` to its document and compute it (no transaction of its own)."""
    doc = autoblock.Document
    obj = doc.addObject("Fem::FemMeshObjectPython", name)
    AutoBlockMeshFeature(obj)
    if FreeCAD.GuiUp:
        ViewProviderAutoBlockMesh(obj.ViewObject)
    obj.Label = "{} mesh".format(autoblock.Label)
    obj.AutoBlock = autoblock
    doc.recompute([obj])
    error = obj.Proxy.last_error
    if error is None and not obj.isValid():
        error = RuntimeError("{}: recompute failed ({})".format(obj.Label, ", ".join(obj.State)))
    if error is not None:
        doc.removeObject(obj.Name)
        raise error
    return obj


def mesh_object_of(autoblock, size=None, create=True):
    """The mesh object of `autoblock` (made when it has none and create is true; else None). size, when given,
    becomes the object's MeshSize first. One undoable transaction ("AutoBlock mesh"); the document is left
    unchanged when meshing fails (ValueError for an incomplete decomposition or an infeasible size)."""
    from ..transactions import transaction

    existing = mesh_objects_of(autoblock)
    if existing and size is None:
        return existing[0]
    if not existing and not create:
        return None
    doc = autoblock.Document
    created = []
    old_size = autoblock.MeshSize
    try:
        with transaction("AutoBlock mesh"):
            if size is not None:
                autoblock.MeshSize = float(size)
            if existing:
                obj = existing[0]
                doc.recompute([autoblock, obj])
                error = obj.Proxy.last_error or autoblock.Proxy.last_error
                if error is not None:
                    raise error
            else:
                if size is not None:
                    doc.recompute([autoblock])
                obj = make_mesh_object(autoblock)
                created.append(obj.Name)
    except BaseException:
        # Without undo (freecadcmd's default) aborting the transaction changes nothing back: do it here.
        for name in created:
            if doc.getObject(name) is not None:
                doc.removeObject(name)
        if autoblock.MeshSize != old_size:
            autoblock.MeshSize = old_size
            doc.recompute()
        raise
    return obj
