"""The console API: decompose faces from freecadcmd or FreeCAD's Python console.

    import AutoBlock
    result = AutoBlock.decompose(face_or_object)            # or (object, "Face3")
    result.blocks, result.shape, result.cuts, result.ret, result.n_blocks

Everything here is a thin layer over the native module: it picks the face, carries it into its own
frame (faces.py), passes it as BREP text, and turns the answer into FreeCAD shapes and vectors.
"""

import json

import FreeCAD  # noqa: F401  (before Part)
import Part

from . import faces, native, preferences


class Cut:
    """One cut of a decomposition.

    part: id of the part it cut (0: the face); vertex: the chosen model vertex (FreeCAD.Vector, global);
    local: the same vertex (x, y) in the face's frame; direction: "horizontal" or "vertical" (in that
    frame); n_parts: pieces the cut left (1: nothing changed); reward: Eq. (1); children: the pieces' ids.
    """

    __slots__ = ("part", "vertex", "local", "direction", "n_parts", "reward", "children")

    def __init__(self, part, vertex, local, direction, n_parts, reward, children):
        self.part = part
        self.vertex = vertex
        self.local = local
        self.direction = direction
        self.n_parts = n_parts
        self.reward = reward
        self.children = children

    def __repr__(self):
        return "Cut(part {}, {} at ({:g}, {:g}), {} pieces, reward {:.3f})".format(
            self.part, self.direction, self.local[0], self.local[1], self.n_parts, self.reward)


class DecompositionResult:
    """The result of AutoBlock.decompose.

    blocks: list of Part.Face, in the order the episode set them aside; shape: their compound (the
    partitioned face); cuts: list of Cut; ret: the return (sum of the cuts' rewards); n_blocks;
    min_blocks: the minimum number of rectangles of any partition (a lower bound); status: "complete"
    or "truncated"; complete, truncated, time_capped; policy; reward (the preset); seconds; face: the
    input face; frame: the placement of the face's own frame; label: the input's name.
    """

    def __init__(self, data, face, local_face, frame, label):
        self.face = face
        self.frame = frame
        self.label = label
        self.policy = data["policy"]
        self.reward = data["reward"]
        self.ret = data["return"]
        self.n_blocks = data["n_blocks"]
        self.min_blocks = data["min_blocks"]
        self.status = data["status"]
        self.complete = data["complete"]
        self.truncated = data["truncated"]
        self.time_capped = data["time_capped"]
        self.seconds = data["seconds"]
        self.max_steps = data["max_steps"]
        self._local_brep = local_face.exportBrepToString()
        self._z = data["face"]["z"]
        self._fingerprint = face_fingerprint(data["face"])
        self.blocks = [faces.out_of_frame(_shape_from_brep(text), frame).Faces[0] for text in data["blocks"]]
        self.shape = faces.out_of_frame(_shape_from_brep(data["shape"]), frame)
        self.cuts = [
            Cut(c["part"], faces.point_out_of_frame(c["vertex"][0], c["vertex"][1], self._z, frame),
                tuple(c["vertex"]), c["direction"], c["n_parts"], c["reward"], list(c["children"]))
            for c in data["cuts"]
        ]

    def summary(self):
        """'6 blocks (minimum 5), 5 cuts, return 30.593, complete'"""
        return "{} blocks (minimum {}), {} cuts, return {:.3f}, {}{}".format(
            self.n_blocks, self.min_blocks, len(self.cuts), self.ret, self.status,
            " (search time limit hit)" if self.time_capped else "")

    def __repr__(self):
        return "<AutoBlock result: {}: {}>".format(self.label, self.summary())

    def to_dict(self):
        """The result as JSON-able data (blocks as corner lists in global coordinates)."""
        return {
            "input": self.label,
            "policy": self.policy,
            "reward_preset": self.reward,
            "return": self.ret,
            "n_blocks": self.n_blocks,
            "min_blocks": self.min_blocks,
            "status": self.status,
            "time_capped": self.time_capped,
            "seconds": self.seconds,
            "cuts": [{"part": c.part, "vertex": list(c.vertex), "direction": c.direction, "n_parts": c.n_parts,
                      "reward": c.reward} for c in self.cuts],
            "blocks": [[list(v.Point) for v in b.OuterWire.OrderedVertexes] for b in self.blocks],
        }

    def cut_sequence(self):
        """The cut sequence as stored in an AutoBlock object (JSON text, the face's frame)."""
        return json.dumps({
            "version": 1,
            "face": self._fingerprint,
            "max_steps": self.max_steps,
            "cuts": [[c.part, c.local[0], c.local[1], c.direction, c.reward, c.n_parts] for c in self.cuts],
        })

    def stepper(self):
        """A Stepper over this decomposition's cuts (see stepping.py)."""
        from .stepping import Stepper

        return Stepper(self._local_brep, self.frame, _specs(self.cut_sequence()), self.max_steps, self.label,
                       self.policy)


def _specs(cut_sequence):
    data = json.loads(cut_sequence)
    return [(int(c[0]), float(c[1]), float(c[2]), str(c[3])) for c in data["cuts"]]


def _shape_from_brep(text):
    shape = Part.Shape()
    shape.importBrepFromString(text)
    if shape.isNull():
        raise RuntimeError("the native module returned an unreadable shape")
    return shape


def face_fingerprint(figures):
    """What identifies a checked face (native check_face / decompose figures): z, area, bounding box, corners."""
    return {"z": figures["z"], "area": figures["area"], "bbox": list(figures["bbox"]), "corners": figures["corners"],
            "holes": figures["holes"]}


def same_face(fingerprint, local):
    """True when the face `local` (in its frame) matches `fingerprint` (see face_fingerprint)."""
    if not fingerprint:
        return True  # saved before fingerprints existed
    try:
        figures = native.load().check_face(local.exportBrepToString())
    except ValueError:
        return False
    now = face_fingerprint(figures)
    size = max(abs(v) for v in fingerprint["bbox"] + [1e-300])
    close = lambda a, b: abs(a - b) <= 1e-9 * max(size, size * size)  # noqa: E731
    return (now["corners"] == fingerprint["corners"] and now["holes"] == fingerprint["holes"]
            and close(now["z"], fingerprint["z"]) and close(now["area"], fingerprint["area"])
            and all(close(a, b) for a, b in zip(now["bbox"], fingerprint["bbox"])))


def local_face(target, sub=None):
    """(face, local_face, frame, label): the face `target` designates, the same face in its own frame."""
    face, label = faces.face_of(target, sub)
    frame = faces.face_frame(face)
    return face, faces.into_frame(face, frame), frame, label


def _in_frame_note(frame, error):
    if faces.is_identity(frame):
        return error
    return ValueError("{} (coordinates in the face's own plane: origin ({:g}, {:g}, {:g}))".format(
        error, frame.Base.x, frame.Base.y, frame.Base.z))


def check_face(target, sub=None):
    """Checks that `target` designates a supported face. Returns its figures (dict: corners, holes, area,
    min_blocks, ...); raises ValueError saying what is wrong and where."""
    face, local, frame, label = local_face(target, sub)
    try:
        return dict(native.load().check_face(local.exportBrepToString(), label))
    except ValueError as error:
        raise _in_frame_note(frame, error) from None


def decompose(face_or_object, policy=None, reward=None, seed=0, time_limit=30.0, max_steps=0, sub=None):
    """Cut one planar rectilinear face into rectangular blocks.

    face_or_object: a Part.Face, a shape holding one face (or closed wires, as a sketch), a document
        object, or (object, "FaceN").
    policy: a name of AutoBlock.policy_names() or a policy file; None: the preferred default.
    reward: a reward preset (AutoBlock.reward_presets()); None: the preferred one.
    seed: for the random policies; time_limit: seconds of exact search for "optimal";
    max_steps: step cap (0: 10 x corners + 10).
    Returns a DecompositionResult. Raises ValueError for an unsupported face or a bad option.
    """
    face, local, frame, label = local_face(face_or_object, sub)
    module = native.load()
    try:
        data = module.decompose(local.exportBrepToString(), policy or preferences.default_policy(),
                                reward or preferences.reward_preset(), int(seed), float(time_limit), int(max_steps),
                                label)
    except ValueError as error:
        raise _in_frame_note(frame, error) from None
    return DecompositionResult(data, face, local, frame, label)


def policy_names():
    """The shipped policy names (from the core)."""
    return list(native.load().policy_names())


def reward_presets():
    """The reward presets (from the core)."""
    return list(native.load().reward_presets())


def capabilities():
    """What this build can do beyond the baselines (from the core)."""
    return native.capabilities()


def mesh(target, size=None):
    """Mesh an AutoBlock object's blocks with quads into a Fem::FemMeshObject (returned); size: target quad size
    (None: the object's MeshSize; 0: automatic).

    Needs the core's quad mesher (the meshing issue); this build has none, so this raises NotImplementedError
    saying so. objects/fem_mesh.py already turns nodes and quads into the FEM object (tested).
    """
    if not native.has("meshing"):
        raise NotImplementedError(
            "meshing is not in this build of AutoBlock: the core has no quad mesher yet "
            "(AutoBlock.capabilities()['meshing'] is False)")
    from .objects.autoblock_feature import is_autoblock, stepper_of
    from .objects.fem_mesh import make_fem_mesh_object
    from .transactions import transaction

    if not is_autoblock(target):
        raise ValueError("AutoBlock.mesh needs an AutoBlock object")
    stepper = stepper_of(target)
    mesh_size = float(target.MeshSize if size is None else size)
    # The meshing issue's binding: the face (its frame) and the cut sequence in, nodes (face frame) and
    # 4-node quads (0-based) out.
    data = native.load().mesh(stepper.local_brep, stepper.cuts, mesh_size, stepper.max_steps, stepper.label)
    nodes = [faces.point_out_of_frame(x, y, z, stepper.frame) for x, y, z in data["nodes"]]
    with transaction("AutoBlock mesh"):
        return make_fem_mesh_object(target.Document, [(p.x, p.y, p.z) for p in nodes], data["quads"],
                                    name="AutoBlockMesh", label="{} mesh".format(target.Label))


def train(request, progress=None):
    """Train a policy (blocking). request: a training.TrainingRequest. See training.py.

    Raises NotImplementedError when the core cannot train (this build).
    """
    from . import training

    return training.train(request, progress)
