"""The AutoBlock object: a Part::FeaturePython linked to a source face, whose Shape is that face cut
into blocks (merged conformally: neighbouring blocks share their edges). It recomputes when the source
changes; it saves and reopens like any feature (its proxy keeps no state: everything lives in
properties). Its FEM mesh object (fem_mesh.py) follows it.

make_autoblock() is what the Auto-Block button runs.
"""

import contextlib
import json

import FreeCAD

from .. import console, native, preferences
from ..transactions import transaction
from . import properties

TYPE = "AutoBlock::AutoBlock"


def is_autoblock(obj):
    """True for an AutoBlock object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == TYPE


# Properties: (type, name, group, tooltip, attributes). Attributes: 8 = Output (changing it does not touch the
# object); read-only and hidden are editor modes. A face's AutoBlock object and a solid's (solid_blocks.py) share
# the decomposition's settings and results (a solid's are its cap's).
DECOMPOSITION_PROPERTIES = [
    ("App::PropertyEnumeration", "Policy", "Decomposition", "How cuts are chosen (on a solid: its cap's): auto (the "
     "default: the exact search where it finishes in time, the trained sac-mesh where it does not), a shipped "
     "trained policy (sac-mesh: few, fat blocks; sac-paper: Eq. (1)) or a baseline (optimal: maximum return by "
     "exact search; greedy; random).", 0),
    ("App::PropertyFile", "PolicyFile", "Decomposition", "A policy file made by training (Train a policy); "
     "used instead of Policy when set.", 0),
    ("App::PropertyEnumeration", "RewardPreset", "Decomposition", "The reward the cuts are scored with: empty "
     "for the policy's own (sac-mesh: mesh; sac-paper, the baselines: paper), paper (Eq. (1) of DiPrete et al. "
     "2022) or mesh (few, fat blocks). The baselines maximise it.", 0),
    ("App::PropertyInteger", "Seed", "Decomposition", "Seed of the random policies.", 0),
    ("App::PropertyFloat", "TimeLimit", "Decomposition", "Seconds per face (on a solid: for its cap) before greedy "
     "finishes the remaining parts (optimal, auto and learned policies).", 0),
]
RESULT_PROPERTIES = [
    ("App::PropertyInteger", "NumberOfBlocks", "Result", "Blocks in the partition (on a face with edges at "
     "other angles: convex quadrilaterals and templates, see Status; on a solid: prism blocks).", 8),
    ("App::PropertyInteger", "MinimumBlocks", "Result", "Fewest rectangles of any partition of the face (a "
     "lower bound; 0: unknown, a face with edges at other angles).", 8),
    ("App::PropertyInteger", "NumberOfCuts", "Result", "Cuts the policy made.", 8),
    ("App::PropertyFloat", "Return", "Result", "Sum of the cuts' rewards.", 8),
    ("App::PropertyString", "Status", "Result", "Summary of the last decomposition.", 8),
    ("App::PropertyString", "RewardUsed", "Result", "The reward preset the cuts were scored with.", 8),
    ("App::PropertyString", "CutSequence", "Result", "The cuts (JSON, in the face's own frame; on a solid: its "
     "cap's, with the cap's number and frame), for stepping through them.", 8),
]
RESULT_READ_ONLY = ("NumberOfBlocks", "MinimumBlocks", "NumberOfCuts", "Return", "Status", "RewardUsed")


class AutoBlockFeature:
    Type = TYPE

    def __init__(self, obj):
        obj.Proxy = self
        self.last_error = None
        self.last_complete = False
        self.ensure_properties(obj)

    PROPERTIES = [
        ("App::PropertyLinkSub", "Source", "Input", "The face to cut: an object and, when it has several faces, one "
         "of them. Recomputes when it changes.", 0),
    ] + DECOMPOSITION_PROPERTIES + [
        ("App::PropertyLength", "MeshSize", "Mesh", "Target quad size of the object's FEM mesh (0: automatic, 1/20 "
         "of the face's longer side).", 0),
    ] + RESULT_PROPERTIES
    READ_ONLY = RESULT_READ_ONLY
    HIDDEN = ("CutSequence",)

    def ensure_properties(self, obj):
        properties.ensure_properties(obj, self.PROPERTIES, self.READ_ONLY, self.HIDDEN)
        self.refresh_choices(obj)

    @staticmethod
    def refresh_choices(obj):
        """Fill the enumerations from the core, keeping the current choice."""
        try:
            module = native.load()
        except native.NativeModuleMissing:
            return
        # RewardPreset: "" (the policy's own, the core's default) and the core's presets.
        presets = [""] + [p for p in module.reward_presets() if p]
        for name, choices in (("Policy", list(module.policy_names())), ("RewardPreset", presets)):
            current = getattr(obj, name, None)
            if list(obj.getEnumerationsOfProperty(name) or []) != choices:
                setattr(obj, name, choices)
                if current in choices:
                    setattr(obj, name, current)

    def onDocumentRestored(self, obj):
        self.last_error = None
        self.ensure_properties(obj)

    def execute(self, obj):
        self.last_error = None
        self.last_complete = False
        try:
            result = self.decompose(obj)
        except Exception as error:
            self.last_error = error
            raise
        self.last_complete = result.complete
        obj.Shape = result.shape
        self.set_results(obj, result, result.cut_sequence())

    def set_results(self, obj, result, cut_sequence):
        """Set the result properties from a DecompositionResult (a face's, or a solid's cap's) and its cut sequence
        (JSON text), which is stored with the settings it was made with."""
        obj.NumberOfBlocks = result.n_blocks + (result.n_templates if result.general else 0)
        obj.MinimumBlocks = result.min_blocks or 0
        obj.NumberOfCuts = len(result.cuts)
        obj.Return = result.ret
        obj.Status = "{}: {}".format(result.policy, result.summary())
        obj.RewardUsed = result.reward
        sequence = json.loads(cut_sequence)
        sequence["settings"] = self.settings(obj)
        obj.CutSequence = json.dumps(sequence)

    @staticmethod
    def settings(obj):
        """What a decomposition of the object depends on besides its source face."""
        return {"policy": obj.PolicyFile or obj.Policy, "reward": obj.RewardPreset, "seed": obj.Seed,
                "time_limit": obj.TimeLimit}

    @classmethod
    def decompose(cls, obj):
        if not obj.Source:
            raise ValueError("{}: no source face (set Source)".format(obj.Label))
        source, subs = obj.Source
        # A face with edges at other angles whose stored cut sequence was made with the same settings on the same
        # face (e.g. a reopened document) is replayed, not searched again: the general engine's search has a time
        # budget, so searching again could give other blocks.
        stored = json.loads(obj.CutSequence) if obj.CutSequence else {}
        if stored.get("engine") == "general" and stored.get("settings") == cls.settings(obj):
            try:
                return console.replay((source, list(subs)), stored)
            except ValueError:
                pass  # another face (the source changed): decompose it
        return console.decompose((source, list(subs)), policy=obj.PolicyFile or obj.Policy, reward=obj.RewardPreset,
                                 seed=obj.Seed, time_limit=obj.TimeLimit)

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        self.last_error = None
        self.last_complete = False
        return None


def make_autoblock(source, sub=None, policy=None, reward=None, mesh_size=None, seed=0, time_limit=30.0,
                   name="AutoBlock", mesh=None):
    """Create the parametric AutoBlock object of `source` (a document object; sub: "FaceN" when it has several
    faces) and compute it. policy: a name or policy file (None: the preferred default, auto unless set);
    reward: a preset, "" for the policy's own (None: the preferred one, "" unless set); mesh_size (None: the
    preferred one); mesh: also make its FEM mesh object (fem_mesh.py) of the blocks (None: when the
    decomposition is complete, which meshing needs; True: required; False: no).

    One undoable transaction ("Auto-Block"), or part of the caller's when one is open. Raises ValueError for an
    unsupported face or a bad option, and then the document is left unchanged.
    """
    if isinstance(sub, (list, tuple)):
        sub = sub[0] if len(sub) == 1 else (None if not sub else sub)
    if not hasattr(source, "Document"):
        raise TypeError("make_autoblock needs a document object, got {}".format(type(source).__name__))
    # Check before touching the document.
    console.check_face(source, sub)
    spec, reward = chosen_settings(policy, reward)
    doc = source.Document
    with new_objects(doc) as created:
        obj = add_feature(doc, created, name, AutoBlockFeature, "ViewProviderAutoBlock",
                          "{} {}".format(name, source.Label) + (" {}".format(sub) if sub else ""))
        set_settings(obj, spec, reward, seed, time_limit, mesh_size)
        obj.Source = (source, [sub] if sub else [])
        recompute_checked(obj)
        meshable = native.has("meshing") and obj.Proxy.last_complete
        if mesh or (mesh is None and meshable):
            from .fem_mesh import make_mesh_object

            try:
                created.append(make_mesh_object(obj).Name)
            except ValueError as error:
                if mesh:
                    raise
                # The blocks stand without their mesh (e.g. a mesh size asking for too many quads).
                FreeCAD.Console.PrintWarning("AutoBlock: {}: no FEM mesh: {}\n".format(obj.Label, error))
    return obj


@contextlib.contextmanager
def new_objects(doc):
    """One undoable transaction ("Auto-Block", or the caller's when one is open) for new objects: the block
    appends the names of the objects it adds to the yielded list; when it raises, they are removed (without undo,
    freecadcmd's default, aborting the transaction leaves them) and the error passes on."""
    created = []
    try:
        with transaction("Auto-Block"):
            yield created
    except BaseException:
        for object_name in reversed(created):
            if doc.getObject(object_name) is not None:
                doc.removeObject(object_name)
        raise


def add_feature(doc, created, name, feature, view_provider, label):
    """Add a Part::FeaturePython called `name` with proxy class `feature` (and, with the GUI up, the view provider
    class named `view_provider` of view_autoblock.py) and label `label`; its name is appended to `created` (see
    new_objects)."""
    obj = doc.addObject("Part::FeaturePython", name)
    created.append(obj.Name)
    feature(obj)
    if FreeCAD.GuiUp:
        from ..viewproviders import view_autoblock

        getattr(view_autoblock, view_provider)(obj.ViewObject)
    obj.Label = label
    return obj


def chosen_settings(policy, reward):
    """(policy, reward) as make_autoblock and make_autoblock_solid store them: policy None -> the preferred default,
    reward None -> the preferred preset. ValueError for an unknown reward preset."""
    spec = policy or preferences.default_policy()
    reward = preferences.reward_preset() if reward is None else reward
    presets = list(native.load().reward_presets())
    if reward and reward not in presets:
        raise ValueError("unknown reward preset '{}' (expected {}, or '' for the policy's own)".format(
            reward, ", ".join(presets)))
    return spec, reward


def set_settings(obj, spec, reward, seed, time_limit, mesh_size):
    """Store the decomposition's settings and the mesh size (None: the preferred one) in a new object: a policy
    name in Policy, anything else (a policy file) in PolicyFile."""
    if spec in list(native.load().policy_names()):
        obj.Policy = spec
    else:
        obj.PolicyFile = spec
    obj.RewardPreset = reward
    obj.Seed = int(seed)
    obj.TimeLimit = float(time_limit)
    obj.MeshSize = preferences.mesh_size() if mesh_size is None else float(mesh_size)


def recompute_checked(obj):
    """Recompute a new object; raise what its proxy's execute raised (last_error), or RuntimeError when it is
    not valid afterwards."""
    obj.Document.recompute([obj])
    error = obj.Proxy.last_error
    if error is None and not obj.isValid():
        error = RuntimeError("{}: recompute failed ({})".format(obj.Label, ", ".join(obj.State)))
    if error is not None:
        raise error


def stepper_of(obj):
    """A Stepper over an AutoBlock object's cuts (an AutoBlock solid object's: its cap's, drawn on the cap).
    Raises ValueError when the object is out of date (its source changed since its last recompute) or has no
    result."""
    from .solid_blocks import cap_in_frame, is_autoblock_solid

    solid = is_autoblock_solid(obj)
    if not (solid or is_autoblock(obj)):
        raise ValueError("{} is not an AutoBlock object".format(getattr(obj, "Label", obj)))
    out_of_date = ValueError("{} is out of date or has no result: recompute it first".format(obj.Label))
    if "Touched" in obj.State or "Invalid" in obj.State or not obj.CutSequence or not obj.Source:
        raise out_of_date
    data = json.loads(obj.CutSequence)
    if solid:
        try:
            local, frame, label = cap_in_frame(obj, data)
        except (ValueError, IndexError, KeyError):
            raise out_of_date from None
    else:
        source, subs = obj.Source
        face, local, frame, label = console.local_face((source, list(subs)))
    # The source may have changed without a recompute yet (FreeCAD marks dependents only when recomputing).
    if not console.same_face(data.get("face"), local):
        raise out_of_date
    from ..stepping import Stepper

    return Stepper(local.exportBrepToString(), frame, console.sequence_specs(data), int(data.get("max_steps", 0)),
                   label, obj.PolicyFile or obj.Policy, console.sequence_reward(data), console.sequence_rules(data),
                   console.sequence_min_edge_intervals(data))
