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
    return _fem_mesh(nodes, quads, "quad", 4, lambda mesh, ids, number: mesh.addFace(ids, number))


def _fem_mesh(nodes, elements, kind, size, add, order=None):
    """A Fem.FemMesh of `nodes` ([(x, y, z)], numbered from 1) and `elements` (0-based node indices, `size` each,
    taken in `order` when given), each added by add(mesh, node numbers, element number). Raises ValueError naming
    the `kind` of element for a bad index."""
    import Fem

    count = len(nodes)
    mesh = Fem.FemMesh()
    for number, (x, y, z) in enumerate(nodes, 1):
        mesh.addNode(float(x), float(y), float(z), number)
    for number, element in enumerate(elements, 1):
        element = [int(i) for i in element]
        if len(element) != size:
            raise ValueError("{} {} has {} nodes, expected {}".format(kind, number, len(element), size))
        if len(set(element)) != size:
            raise ValueError("{} {} repeats a node: {}".format(kind, number, element))
        if min(element) < 0 or max(element) >= count:
            raise ValueError("{} {} refers to a node outside 0..{}: {}".format(kind, number, count - 1, element))
        add(mesh, [element[k] + 1 for k in (order or range(size))], number)
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

    SOURCE = "AutoBlock object"

    def execute(self, obj):
        self.last_error = None
        try:
            source = obj.AutoBlock
            if source is None:
                raise ValueError("{}: no {} to mesh (set AutoBlock)".format(obj.Label, self.SOURCE))
            result = self.mesh_of(source)
        except Exception as error:
            self.last_error = error
            raise
        obj.FemMesh = result.fem_mesh()
        obj.NumberOfNodes = len(result.nodes)
        obj.TargetSize = result.target_size
        obj.Quality = result.summary()
        self.set_counts(obj, result)

    @staticmethod
    def mesh_of(source):
        """The console's mesh result of the source object."""
        from .. import console
        from .autoblock_feature import stepper_of

        stepper = stepper_of(source)
        size = float(source.MeshSize)
        return console.MeshResult(console._mesh_data(stepper, size), stepper, size)

    @staticmethod
    def set_counts(obj, result):
        obj.NumberOfQuads = len(result.quads)

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


def _recompute_or_remove(obj):
    """Compute a new mesh object; remove it again when that fails (and raise why)."""
    from .autoblock_feature import recompute_checked

    try:
        recompute_checked(obj)
    except BaseException:
        obj.Document.removeObject(obj.Name)
        raise


def mesh_objects_of(autoblock):
    """The mesh objects linked to the AutoBlock object `autoblock`."""
    return [o for o in autoblock.InList if is_autoblock_mesh(o) and o.AutoBlock == autoblock]


def make_mesh_object(autoblock, name="AutoBlockMesh", feature=None):
    """Add the mesh object of `autoblock` to its document and compute it (no transaction of its own). feature: its
    proxy class (None: AutoBlockMeshFeature, the quads of a face's AutoBlock object)."""
    doc = autoblock.Document
    obj = doc.addObject("Fem::FemMeshObjectPython", name)
    (feature or AutoBlockMeshFeature)(obj)
    if FreeCAD.GuiUp:
        ViewProviderAutoBlockMesh(obj.ViewObject)
    obj.Label = "{} mesh".format(autoblock.Label)
    obj.AutoBlock = autoblock
    _recompute_or_remove(obj)
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


# FreeCAD's hexa8 (SMESH) order against the core's C3D8 order (hex_mesh.h): each quad turned the other way.
# FreeCAD's own .inp writer (FemMesh.writeABAQUS, used by its CalculiX tools) maps it back to a positive C3D8.
C3D8_TO_HEXA8 = (0, 3, 2, 1, 4, 7, 6, 5)


def fem_hex_mesh(nodes, hexes):
    """A Fem.FemMesh of 8-node hexahedra. nodes: [(x, y, z)]; hexes: [(8 node indices)], 0-based, in the C3D8
    order (0-3 one quad, 4-7 the same one layer on, positive volume). Raises ValueError for a bad index."""
    return _fem_mesh(nodes, hexes, "hexahedron", 8, lambda mesh, ids, number: mesh.addVolume(ids, number),
                     C3D8_TO_HEXA8)


HEX_TYPE = "AutoBlock::HexMesh"


def is_autoblock_hex_mesh(obj):
    """True for the hexahedral mesh object of an AutoBlock solid object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == HEX_TYPE


class AutoBlockHexMeshFeature(AutoBlockMeshFeature):
    """The hexa8 FEM mesh of an AutoBlock solid object (solid_blocks.py): recomputed with it, so it follows
    the source solid, the policy, MeshSize, Layers and Grading."""

    Type = HEX_TYPE
    SOURCE = "AutoBlock solid object"

    PROPERTIES = [
        ("App::PropertyLink", "AutoBlock", "Mesh", "The AutoBlock solid object whose hexahedra this holds.", 0),
        ("App::PropertyInteger", "NumberOfHexahedra", "Result", "Hexahedra in the mesh.", 8),
        ("App::PropertyInteger", "NumberOfNodes", "Result", "Nodes in the mesh.", 8),
        ("App::PropertyInteger", "NumberOfLayers", "Result", "Layers along the sweep.", 8),
        ("App::PropertyFloat", "TargetSize", "Result", "The element size aimed at.", 8),
        ("App::PropertyString", "Quality", "Result", "Summary of the mesh: minimum scaled Jacobian, irregular "
         "edges, conformity.", 8),
    ]
    READ_ONLY = ("NumberOfHexahedra", "NumberOfNodes", "NumberOfLayers", "TargetSize", "Quality")

    @staticmethod
    def mesh_of(source):
        from .solid_blocks import hex_mesh_of

        return hex_mesh_of(source)

    @staticmethod
    def set_counts(obj, result):
        obj.NumberOfHexahedra = len(result.hexes)
        obj.NumberOfLayers = result.layers


def make_hex_mesh_object(solid_object, name="AutoBlockHexMesh"):
    """Add the hexa8 mesh object of an AutoBlock solid object to its document and compute it (no transaction of
    its own; removed again when meshing fails)."""
    return make_mesh_object(solid_object, name, AutoBlockHexMeshFeature)
