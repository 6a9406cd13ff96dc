"""AutoBlock for FreeCAD: cut planar faces bounded by straight edges into blocks (rectangles on rectilinear faces,
convex quadrilaterals and templates on faces with edges at other angles) and mesh them with quads (rectilinear
faces for now).

Console API (freecadcmd or FreeCAD's Python console):

    import AutoBlock
    result = AutoBlock.decompose(face_or_object, policy=None)   # or (object, "Face3")
    result.blocks       # list of Part.Face
    result.shape        # the partitioned face (blocks sharing edges)
    result.cuts         # list of AutoBlock.Cut
    result.ret          # return (sum of the cuts' rewards)
    result.n_blocks
    AutoBlock.mesh(result, size=0.5)                            # a MeshResult: nodes, quads, quality, export()
    obj = AutoBlock.make_autoblock(source_object, "Face3")     # the parametric object and its FEM mesh
    AutoBlock.mesh(obj)                                         # its FEM mesh object
    AutoBlock.export_mesh(obj, "face.msh")                      # or .vtu, .inp
    hexes = AutoBlock.mesh(solid_or_object, size=1.0)           # a swept solid: a HexMeshResult (hexahedra)
    obj = AutoBlock.make_autoblock_solid(pad)                   # prism blocks and a hexa8 FEM mesh object
    AutoBlock.cap_solid(body, "Pad.Face6")                      # the Pad when Face6 is a cap of its swept solid
    AutoBlock.refines_to_solid(fusion)                          # a swept solid only once its split faces merge
    AutoBlock.make_autoblock_solid(AutoBlock.refined_copy(fusion))  # then: a Part::Refine copy, meshed
    AutoBlock.stepper_of(obj)                                   # a solid object: its cap's cuts, on the cap
    AutoBlock.write_back(obj, mode="new")                       # or "replace"
    AutoBlock.stepper_of(obj).step(2)                           # the decomposition after 2 cuts, with scores
    AutoBlock.replay(face_or_object, obj.CutSequence)           # a general face's stored cuts, not searched again
    AutoBlock.train(AutoBlock.TrainingRequest("p.pt", train_folder=..., test_folder=...))
    AutoBlock.start_training(request)                           # the same in the background: a TrainingRun
    AutoBlock.policy_names(), AutoBlock.default_policy(), AutoBlock.policy_info("sac-mesh"),
    AutoBlock.reward_presets(), AutoBlock.capabilities()
    AutoBlock.combine_policies("sac-mesh", "general.pt", "both.pt")  # two networks: rectilinear, general faces

Importing this package is cheap: the names above load their modules (and the native module) on
first use.
"""

__version__ = "0.1.0"

_LAZY = {
    "decompose": ("console", "decompose"),
    "check_face": ("console", "check_face"),
    "replay": ("console", "replay"),
    "policy_names": ("console", "policy_names"),
    "reward_presets": ("console", "reward_presets"),
    "capabilities": ("console", "capabilities"),
    "mesh": ("console", "mesh"),
    "mesh_solid": ("console", "mesh_solid"),
    "check_solid": ("console", "check_solid"),
    "is_solid": ("console", "is_solid"),
    "cap_solid": ("console", "cap_solid"),
    "refines_to_solid": ("console", "refines_to_solid"),
    "refined_copy": ("console", "refined_copy"),
    "HexMeshResult": ("console", "HexMeshResult"),
    "make_autoblock_solid": ("objects.solid_blocks", "make_autoblock_solid"),
    "is_autoblock_solid": ("objects.solid_blocks", "is_autoblock_solid"),
    "hex_mesh_objects_of": ("objects.solid_blocks", "hex_mesh_objects_of"),
    "export_mesh": ("console", "export_mesh"),
    "MeshResult": ("console", "MeshResult"),
    "default_policy": ("console", "default_policy"),
    "policy_info": ("console", "policy_info"),
    "combine_policies": ("console", "combine_policies"),
    "train": ("console", "train"),
    "start_training": ("training", "start"),
    "Cut": ("console", "Cut"),
    "GeneralCut": ("console", "GeneralCut"),
    "DecompositionResult": ("console", "DecompositionResult"),
    "Stepper": ("stepping", "Stepper"),
    "make_autoblock": ("objects.autoblock_feature", "make_autoblock"),
    "stepper_of": ("objects.autoblock_feature", "stepper_of"),
    "is_autoblock": ("objects.autoblock_feature", "is_autoblock"),
    "write_back": ("objects.write_back", "write_back"),
    "TrainingRequest": ("training", "TrainingRequest"),
}

__all__ = sorted(_LAZY)


def __getattr__(name):
    if name in _LAZY:
        import importlib

        module_name, attribute = _LAZY[name]
        value = getattr(importlib.import_module("." + module_name, __name__), attribute)
        globals()[name] = value
        return value
    raise AttributeError("module 'AutoBlock' has no attribute '{}'".format(name))


def __dir__():
    return sorted(list(globals()) + list(_LAZY))
