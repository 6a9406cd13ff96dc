"""The AutoBlock solid object: a Part::FeaturePython linked to a source solid that is a straight sweep of a
planar face (a Part box or extrusion, a PartDesign Pad or Body), whose Shape is that solid split into prism
blocks (its cap's blocks swept; neighbours share their faces), coloured like a face's blocks. Its hexa8 FEM
mesh object (fem_mesh.py, AutoBlockHexMeshFeature) recomputes with it, so it follows the source solid and
the settings (Policy, MeshSize, Layers, Grading). Everything lives in properties; the proxy only keeps the
last hexahedral mesh for its mesh object (computed again when missing, e.g. after reopening).

make_autoblock_solid() is what the Auto-Block button runs on a solid (or on a cap face of one).
"""

from .. import console, faces
from .autoblock_feature import (DECOMPOSITION_PROPERTIES, RESULT_PROPERTIES, RESULT_READ_ONLY, AutoBlockFeature,
                                add_feature, chosen_settings, new_objects, recompute_checked, set_settings)

TYPE = "AutoBlock::Solid"


def is_autoblock_solid(obj):
    """True for an AutoBlock solid object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == TYPE


class AutoBlockSolidFeature(AutoBlockFeature):
    """As AutoBlockFeature (settings, enumerations from the core, no saved state), for a solid; the decomposition's
    results are its cap's (CutSequence: the cap's cuts, with the cap's face number and frame, for stepping)."""

    Type = TYPE

    PROPERTIES = [
        ("App::PropertyLinkGlobal", "Source", "Input", "The solid to split and mesh: a straight sweep of a planar face "
         "(caps congruent, planar sides along one direction). Recomputes when it changes.", 0),
    ] + DECOMPOSITION_PROPERTIES + [
        ("App::PropertyLength", "MeshSize", "Mesh", "Target hexahedron size (0: automatic, 1/20 of the solid's "
         "longest bounding-box side).", 0),
        ("App::PropertyInteger", "Layers", "Mesh", "Layers along the sweep (0: the sweep's length over the "
         "size).", 0),
        ("App::PropertyFloat", "Grading", "Mesh", "Each layer's thickness over the previous one's (1: "
         "uniform).", 0),
    ] + RESULT_PROPERTIES + [
        ("App::PropertyIntegerList", "Caps", "Result", "The solid's cap faces (bottom, top: Face numbers).", 8),
        ("App::PropertyVector", "Sweep", "Result", "From the bottom cap to the top one.", 8),
        ("App::PropertyLinkListGlobal", "Containers", "Input", "The containers placing the source (its Body, an "
         "App::Part): moving them recomputes this object. Follows Source.", 8),
    ]
    READ_ONLY = RESULT_READ_ONLY + ("Caps", "Sweep")
    HIDDEN = AutoBlockFeature.HIDDEN + ("Containers",)

    def __init__(self, obj):
        self.last_mesh = None
        super().__init__(obj)

    def onDocumentRestored(self, obj):
        self.last_mesh = None
        super().onDocumentRestored(obj)

    def onChanged(self, obj, prop):
        if prop == "Source" and "Restoring" not in obj.State and "Containers" in obj.PropertiesList:
            containers = containers_of(obj.Source)
            if list(obj.Containers) != containers:
                obj.Containers = containers

    def execute(self, obj):
        self.last_error = None
        self.last_mesh = None
        try:
            result = mesh_solid_object(obj)
        except Exception as error:
            self.last_error = error
            raise
        self.last_mesh = result
        containers = containers_of(obj.Source)
        if list(obj.Containers) != containers:  # e.g. the Body put into an App::Part since
            obj.Containers = containers
        obj.Shape = result.shape
        self.set_results(obj, result.cap, result.cut_sequence())
        obj.NumberOfBlocks = result.n_blocks
        obj.Caps = list(result.caps)
        obj.Sweep = result.sweep
        obj.Status = "{}: {}".format(result.policy, result.summary())

    def __setstate__(self, state):
        self.last_mesh = None
        return super().__setstate__(state)


def mesh_solid_object(obj, out=None):
    """The HexMeshResult of an AutoBlock solid object's source with its settings (computed now; out: also written
    to that .msh, .vtu or .inp file)."""
    if obj.Source is None:
        raise ValueError("{}: no source solid (set Source)".format(obj.Label))
    return console.mesh_solid(obj.Source, size=float(obj.MeshSize), layers=obj.Layers, grading=obj.Grading,
                              policy=obj.PolicyFile or obj.Policy, reward=obj.RewardPreset, seed=obj.Seed,
                              time_limit=obj.TimeLimit, out=out)


def containers_of(source):
    """The containers that place document object `source` (its Body, the App::Part holding that, ...)."""
    chain = []
    parent = source.getParentGeoFeatureGroup() if source is not None else None
    while parent is not None and parent not in chain:
        chain.append(parent)
        parent = parent.getParentGeoFeatureGroup()
    return chain


def cap_in_frame(obj, sequence):
    """(cap face in its frame, frame, label) of an AutoBlock solid object whose stored cut sequence (parsed
    CutSequence) is `sequence`: the cap of its source solid as it stands now, carried into the frame the cuts were
    made in. IndexError when the solid has no such face."""
    found = console.solid_of(obj.Source) if obj.Source is not None else None
    if found is None:
        raise ValueError("{}: its source holds no solid".format(obj.Label))
    shape, label = found
    cap = int(sequence["cap"])
    frame = faces.placement_of(sequence["frame"])
    return faces.into_frame(shape.Faces[cap - 1], frame), frame, "{}.Face{}".format(label, cap)


def hex_mesh_of(obj):
    """The hexahedral mesh of an AutoBlock solid object: its last recompute's, else computed now."""
    if not is_autoblock_solid(obj):
        raise ValueError("{} is not an AutoBlock solid object".format(getattr(obj, "Label", obj)))
    result = getattr(obj.Proxy, "last_mesh", None)
    return result if result is not None else mesh_solid_object(obj)


def make_autoblock_solid(source, policy=None, reward=None, mesh_size=None, layers=0, grading=1.0, seed=0,
                         time_limit=30.0, name="AutoBlockSolid", mesh=True):
    """Create the AutoBlock solid object of `source` (a document object whose shape is one swept solid: a Part
    box or extrusion, a PartDesign Pad or Body; or (object, "FaceN") naming a cap face of one, also through a
    container, (body, "Pad.Face8"), what Auto-Block does with a selected cap: the solid is the object holding
    that face, see console.cap_solid) and compute it: the solid split into prism blocks. mesh: also
    make its hexa8 FEM mesh object (Fem::FemMeshObjectPython, fem_mesh.py), which follows it on recompute.
    policy, reward, seed, time_limit: the cap's decomposition (as make_autoblock); mesh_size (None: the
    preferred one; 0: automatic), layers (0: from the size), grading: the hexahedra.

    One undoable transaction ("Auto-Block"), or part of the caller's when one is open. Raises ValueError with
    the core's one-line reason for a solid that is not a straight sweep of a planar face, or a bad option; the
    document is then left unchanged. Returns the solid object (its mesh objects: hex_mesh_objects_of).
    """
    if isinstance(source, tuple) and len(source) == 2 and hasattr(source[0], "Document"):
        holder = console.cap_solid(*source)
        if holder is None:
            raise ValueError("{}.{} is not a cap face of a swept solid (a straight sweep of a planar face): "
                             "AutoBlock.make_autoblock cuts it as a face".format(source[0].Label, source[1]))
        source = holder
    if not hasattr(source, "Document"):
        raise TypeError("make_autoblock_solid needs a document object, got {}".format(type(source).__name__))
    console.check_solid(source)  # before touching the document
    spec, reward = chosen_settings(policy, reward)
    doc = source.Document
    with new_objects(doc) as created:
        obj = add_feature(doc, created, name, AutoBlockSolidFeature, "ViewProviderAutoBlockSolid",
                          "{} {}".format(name, source.Label))
        set_settings(obj, spec, reward, seed, time_limit, mesh_size)
        obj.Layers = int(layers)
        obj.Grading = float(grading)
        obj.Source = source
        recompute_checked(obj)
        if mesh:
            from .fem_mesh import make_hex_mesh_object

            created.append(make_hex_mesh_object(obj).Name)
    return obj


def hex_mesh_objects_of(solid_object):
    """The hexa8 mesh objects linked to the AutoBlock solid object."""
    from .fem_mesh import is_autoblock_hex_mesh

    return [o for o in solid_object.InList if is_autoblock_hex_mesh(o) and o.AutoBlock == solid_object]


def hex_mesh_object_of(solid_object):
    """The hexa8 mesh object of an AutoBlock solid object, made (one undoable transaction) when it has none."""
    existing = hex_mesh_objects_of(solid_object)
    if existing:
        return existing[0]
    from .fem_mesh import make_hex_mesh_object

    with new_objects(solid_object.Document) as created:
        obj = make_hex_mesh_object(solid_object)
        created.append(obj.Name)
    return obj
