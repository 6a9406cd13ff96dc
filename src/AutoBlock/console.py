"""The console API: decompose and mesh faces from freecadcmd or FreeCAD's Python console.

    import AutoBlock
    result = AutoBlock.decompose(face_or_object)            # or (object, "Face3")
    result.blocks, result.shape, result.cuts, result.ret, result.n_blocks
    result.general                                          # edges at other angles: the general engine
    mesh = AutoBlock.mesh(result)                           # or a face, or an AutoBlock object
    mesh.nodes, mesh.quads, mesh.quality, mesh.export("face.msh")
    hexes = AutoBlock.mesh(solid_or_object)                 # a swept solid: hexahedra (mesh_solid)
    hexes.nodes, hexes.hexes, hexes.hex_block, hexes.blocks, hexes.quality, hexes.fem_mesh()

Everything here is a thin layer over the native module: it picks the face, carries it into its own
frame (faces.py), passes it as BREP text, and turns the answer into FreeCAD shapes and vectors.
"""

import json

import FreeCAD  # noqa: F401  (before Part)
import Part

from . import faces, native, preferences, text


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
        return "Cut(part {}, {} at {}, {}, reward {:.3f})".format(
            self.part, self.direction, text.point(self.local[0], self.local[1]), text.counted(self.n_parts, "piece"),
            self.reward)


class GeneralCut:
    """One action of a general face's decomposition (edges at any angle: the general engine).

    part: id of the part it cut; kind: "full" (the whole line through origin, clipped to the part), "partial"
    (the ray from origin to the first boundary it meets) or "template" (a convex part finished as quads around
    an interior point: no origin, no direction); origin: the cut's start on the part's boundary (FreeCAD.Vector,
    global; None for a template); local: the same (x, y) in the face's frame; direction: (dx, dy) in that frame;
    angle: its angle in degrees in that frame; forced: taken by the engine's last resort; chords: the segments cut
    [(start, end)] (global); n_parts, reward, children as for Cut.
    """

    __slots__ = ("part", "kind", "origin", "local", "direction", "angle", "forced", "chords", "n_parts", "reward",
                 "children")

    def __init__(self, data, z, frame):
        to_global = lambda xy: faces.point_out_of_frame(xy[0], xy[1], z, frame)  # noqa: E731
        self.part = data["part"]
        self.kind = data["kind"]
        cut = self.kind != "template"
        self.local = tuple(data["origin"]) if cut else None
        self.origin = to_global(self.local) if cut else None
        self.direction = tuple(data["direction"]) if cut else None
        self.angle = data["angle_degrees"] if cut else None
        self.forced = bool(data.get("forced", False))
        self.chords = [(to_global(a), to_global(b)) for a, b in data.get("chords", [])]
        self.n_parts = data["n_parts"]
        self.reward = data["reward"]
        self.children = list(data.get("children", []))

    @property
    def vertex(self):
        """The cut's origin (as Cut.vertex); None for a template."""
        return self.origin

    def spec(self):
        """The action as the native module's step takes it: (part, kind, ox, oy, dx, dy, forced)."""
        if self.kind == "template":
            return (self.part, "template", 0.0, 0.0, 0.0, 0.0, False)
        return (self.part, self.kind, self.local[0], self.local[1], self.direction[0], self.direction[1], self.forced)

    def __repr__(self):
        if self.kind == "template":
            return "GeneralCut(part {}, template, reward {:.3f})".format(self.part, self.reward)
        return "GeneralCut(part {}, {} at {} towards {:.1f} degrees, {}, reward {:.3f})".format(
            self.part, self.kind, text.point(self.local[0], self.local[1]), self.angle,
            text.counted(self.n_parts, "piece"), self.reward)


class DecompositionResult:
    """The result of AutoBlock.decompose.

    blocks: list of Part.Face, in the order the episode set them aside; shape: the partitioned face (the
    blocks merged conformally: neighbours share their edges and vertices); cuts: list of Cut; ret: the return
    (sum of the cuts' rewards); n_blocks; min_blocks: the minimum number of rectangles of any partition (a
    lower bound); status: "complete" or "truncated"; complete, truncated, time_capped; policy; reward (the
    preset the cuts were scored with); seconds; face: the input face; frame: the placement of the face's own
    frame; label: the input's name. (A swept solid's cap, HexMeshResult.cap, has no blocks and no shape: its
    blocks are the prism blocks' bottoms.)

    A face with edges at other angles (general True, the general engine): blocks are convex quadrilaterals
    and templates (n_templates: convex parts finished as quads around an interior point; blocks holds both,
    n_blocks counts the quadrilaterals), cuts are GeneralCut, min_blocks is None (no known minimum), and
    report is the core's JSON report (as `autoblock decompose --json` writes it, in the face's frame).
    policy_fallback: None, or {"policy", "reason"} when the policy asked for gave blocks that do not mesh and
    these are the search's (policy is then "search").
    """

    def __init__(self, data, face, local_face, frame, label):
        self.face = face
        self.frame = frame
        self.label = label
        self.general = data.get("engine") == "general"
        self.policy = data["policy"]
        self.reward = data["reward"]
        self.ret = data["return"]
        self.n_blocks = data["n_blocks"]
        self.n_templates = data.get("n_templates", 0)
        self.min_blocks = data["min_blocks"]
        self.status = data["status"]
        self.complete = data["complete"]
        self.truncated = data["truncated"]
        self.time_capped = data["time_capped"]
        self.seconds = data["seconds"]
        self.max_steps = data["max_steps"]
        self.policy_fallback = data.get("policy_fallback")
        # A general face's block rules and its mesh's minimum intervals per edge (what a replay and a mesh
        # of its cuts need: the search tries several, see the README's "Tries").
        self.rules = sequence_rules(data)
        self.min_edge_intervals = sequence_min_edge_intervals(data)
        self._local_brep = local_face.exportBrepToString()
        self._z = data["face"]["z"]
        self._fingerprint = face_fingerprint(data["face"])
        self.blocks = [faces.out_of_frame(_shape_from_brep(text), frame).Faces[0] for text in data["blocks"]]
        # A solid's cap (HexMeshResult.cap) comes without its blocks: they are the prism blocks' bottoms.
        self.shape = faces.out_of_frame(_shape_from_brep(data["shape"]), frame) if data["shape"] else None
        self.report = {k: v for k, v in data.items() if k not in ("blocks", "shape")} if self.general else None
        if self.general:
            self.cuts = [GeneralCut(c, self._z, frame) for c in data["cuts"]]
        else:
            self.cuts = [
                Cut(c["part"], faces.point_out_of_frame(c["vertex"][0], c["vertex"][1], self._z, frame),
                    tuple(c["vertex"]), c["direction"], c["n_parts"], c["reward"], list(c["children"]))
                for c in data["cuts"]
            ]

    def summary(self):
        """'6 blocks (minimum 5), 5 cuts, return 30.593 (paper reward), complete'; a general face: '5 blocks and
        1 template, 5 cuts, ...'"""
        if self.general:
            pieces = text.counted(self.n_blocks, "block") + (
                " and " + text.counted(self.n_templates, "template") if self.n_templates else "")
        else:
            pieces = "{} (minimum {})".format(text.counted(self.n_blocks, "block"), self.min_blocks)
        return "{}, {}, return {:.3f} ({} reward), {}{}".format(
            pieces, text.counted(len(self.cuts), "cut"), self.ret, self.reward, self.status,
            " (search time limit hit)" if self.time_capped else "")

    def __repr__(self):
        return "<AutoBlock result: {}: {}>".format(self.label, self.summary())

    def to_dict(self):
        """The result as JSON-able data (blocks as corner lists in global coordinates)."""
        if self.general:
            vector = lambda v: None if v is None else list(v)  # noqa: E731
            return {
                "input": self.label, "engine": "general", "policy": self.policy, "reward_preset": self.reward,
                "return": self.ret, "n_blocks": self.n_blocks, "n_templates": self.n_templates, "status": self.status,
                "time_capped": self.time_capped, "seconds": self.seconds,
                "cuts": [{"part": c.part, "kind": c.kind, "origin": vector(c.origin), "direction": vector(c.direction),
                          "n_parts": c.n_parts, "reward": c.reward} for c in self.cuts],
                "blocks": [[list(v.Point) for v in b.OuterWire.OrderedVertexes] for b in self.blocks],
            }
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
        """The cut sequence as stored in an AutoBlock object (JSON text, the face's frame). A general face's
        (version 3, "engine": "general"): [part, kind, origin x, origin y, direction x, direction y, forced,
        reward, n_parts] per action, with "rules" and "min_edge_intervals" (sequence_rules; a sequence stored
        without them replays with the face's own rules, as sequences were made before)."""
        if self.general:
            return json.dumps({
                "version": 3,
                "engine": "general",
                "policy": self.policy,
                "face": self._fingerprint,
                "max_steps": self.max_steps,
                "reward": self.reward,
                "rules": self.rules,
                "min_edge_intervals": self.min_edge_intervals,
                "cuts": [list(c.spec()) + [c.reward, c.n_parts] for c in self.cuts],
            })
        return json.dumps({
            "version": 2,
            "face": self._fingerprint,
            "max_steps": self.max_steps,
            "reward": self.reward,
            "cuts": [[c.part, c.local[0], c.local[1], c.direction, c.reward, c.n_parts] for c in self.cuts],
        })

    def stepper(self):
        """A Stepper over this decomposition's cuts (see stepping.py)."""
        from .stepping import Stepper

        return Stepper(self._local_brep, self.frame, sequence_specs(json.loads(self.cut_sequence())),
                       self.max_steps, self.label, self.policy, self.reward, self.rules, self.min_edge_intervals)


def sequence_specs(data):
    """The cuts of a stored cut sequence (parsed JSON, see DecompositionResult.cut_sequence) as the native module
    takes them: (part, x, y, direction) on a grid face, (part, kind, ox, oy, dx, dy, forced) on a general one."""
    if data.get("engine") == "general":
        return [(int(c[0]), str(c[1]), float(c[2]), float(c[3]), float(c[4]), float(c[5]), bool(c[6]))
                for c in data["cuts"]]
    return [(int(c[0]), float(c[1]), float(c[2]), str(c[3])) for c in data["cuts"]]


def sequence_rules(data):
    """A general sequence's block rules (parsed JSON or a decomposition's data): [min corner, max corner, flat
    tolerance] in degrees, or [] (the face's own, as a search makes them) when it has none."""
    rules = data.get("rules")
    if isinstance(rules, dict):
        return [float(rules["min_corner_degrees"]), float(rules["max_corner_degrees"]),
                float(rules["flat_tolerance_degrees"])]
    return [float(r) for r in rules] if rules else []


def sequence_min_edge_intervals(data):
    """The intervals a general sequence's mesh takes at least on every model edge (1 when not stored)."""
    return max(1, int(data.get("min_edge_intervals") or 1))


def sequence_reward(data):
    """The reward preset a stored cut sequence (parsed JSON) was scored with: version 1 had only the paper's."""
    return str(data.get("reward") or "paper")


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


def _in_frame_note(frame, error, size=0.0):
    """The core's message about a face in its own frame, with where that frame lies (size: the face's, for the
    tolerance its coordinates are printed to; 0: the origin's distance from the model's origin)."""
    if faces.is_identity(frame):
        return error
    return ValueError("{} (coordinates in the face's own plane: origin {})".format(
        error, text.vector(frame.Base, text.tolerance_of(size or frame.Base.Length))))


def check_face(target, sub=None):
    """Checks that `target` designates a supported face. Returns its figures (dict: corners, holes, area,
    min_blocks, ...); raises ValueError saying what is wrong and where."""
    face, local, frame, label = local_face(target, sub)
    try:
        return dict(native.load().check_face(local.exportBrepToString(), label))
    except ValueError as error:
        raise _in_frame_note(frame, error, face.BoundBox.DiagonalLength) from None


def decompose(face_or_object, policy=None, reward=None, seed=0, time_limit=30.0, max_steps=0, sub=None,
              general_time_limit=None):
    """Cut one planar face bounded by straight edges into blocks: rectangles when its edges run along two
    perpendicular directions (the grid engine), convex quadrilaterals and templates when they run at other
    angles (the general engine: policies auto, search, greedy, random; result.general is True).

    face_or_object: a Part.Face, a shape holding one face (or closed wires, as a sketch), a document
        object, or (object, "FaceN").
    policy: a name of AutoBlock.policy_names() or a policy file; None: the preferred default (auto unless
        the preferences say otherwise).
    reward: a reward preset (AutoBlock.reward_presets()) to score the cuts with; "": the policy's own (a
        trained policy's, "paper" for the baselines); None: the preferred one ("" unless set).
    seed: for the random policies; time_limit: seconds per face before greedy finishes (optimal, auto, learned);
    max_steps: step cap (0: 10 x corners + 10); general_time_limit: the general engine's search budget in
    seconds (None: the core's default).
    Returns a DecompositionResult. Raises ValueError for an unsupported face or a bad option.
    """
    face, local, frame, label = local_face(face_or_object, sub)
    module = native.load()
    try:
        data = module.decompose(local.exportBrepToString(), policy or preferences.default_policy(),
                                preferences.reward_preset() if reward is None else reward, int(seed),
                                float(time_limit), int(max_steps), label,
                                -1.0 if general_time_limit is None else float(general_time_limit))
    except ValueError as error:
        raise _in_frame_note(frame, error, face.BoundBox.DiagonalLength) from None
    return DecompositionResult(data, face, local, frame, label)


def replay(target, cut_sequence, sub=None):
    """A face with edges at other angles decomposed again by replaying a stored cut sequence, without searching:
    the same blocks, cut by OpenCASCADE, for the same face (e.g. after reopening a document).

    target: as for decompose(); cut_sequence: DecompositionResult.cut_sequence() (JSON text or its parsed
    dict; an AutoBlock object's CutSequence). Returns a DecompositionResult (its policy: the one that made the
    sequence). Raises ValueError when the sequence is not a general face's, the face is not the one it was made
    on (its figures differ), or an action does not belong to the face.
    """
    data = json.loads(cut_sequence) if isinstance(cut_sequence, str) else dict(cut_sequence)
    if data.get("engine") != "general":
        raise ValueError("replay takes the cut sequence of a face with edges at other angles (engine 'general'); "
                         "decompose other faces")
    face, local, frame, label = local_face(target, sub)
    if not same_face(data.get("face"), local):
        raise ValueError("{}: not the face this cut sequence was made on (its figures differ)".format(label))
    try:
        out = native.load().replay(local.exportBrepToString(), sequence_specs(data), int(data.get("max_steps", 0)),
                                   sequence_reward(data), str(data.get("policy") or "replay"), label,
                                   sequence_rules(data), sequence_min_edge_intervals(data))
    except ValueError as error:
        raise _in_frame_note(frame, error, face.BoundBox.DiagonalLength) from None
    return DecompositionResult(out, face, local, frame, label)


def policy_names():
    """The policy names (from the core): the shipped trained policies, then the baselines."""
    return list(native.load().policy_names())


def default_policy():
    """The policy used when none is given: the preferences' choice, else the core's default (auto)."""
    return preferences.default_policy()


def policy_info(policy=None):
    """What a policy is (from the core): {"name", "learned" (a trained policy, with a value network), "reward"
    (the preset it aims at), "scores_by" (whose value network scores vertices: its own, auto's fallback's, or
    None), "general_network" (a second network decides on general faces)}. policy: a name or a policy file; None: the default. ValueError when unknown."""
    return dict(native.load().policy_info(policy or preferences.default_policy()))


def combine_policies(grid, general, output):
    """Write output, one policy file with two value networks: grid's (a shipped name or a policy file) for faces
    whose edges run along two perpendicular directions, general's for every other face (edges at other angles,
    arcs). The twin of `autoblock combine`. Returns the file's meta as a dict. ValueError for unreadable files,
    networks aiming at different reward presets, or a missing folder."""
    return json.loads(native.load().combine_policies(str(grid), str(general), str(output)))


def reward_presets():
    """The reward presets (from the core); "" (not listed) means each policy's own."""
    return list(native.load().reward_presets())


def capabilities():
    """What this build can do beyond the baselines (from the core)."""
    return native.capabilities()


def _placement_numbers(frame):
    """A placement as 12 numbers for the core's mesh files: the row-major rotation, then the translation."""
    m = frame.toMatrix()
    return [m.A11, m.A12, m.A13, m.A21, m.A22, m.A23, m.A31, m.A32, m.A33, m.A14, m.A24, m.A34]


class MeshResult:
    """A quad mesh of a decomposition (AutoBlock.mesh of a face or a result).

    nodes: list of FreeCAD.Vector (global coordinates); quads: list of (a, b, c, d), 0-based node indices,
    counter-clockwise seen from +Z of the face's own frame; quad_block: the block (0-based, in the order set aside) of every
    quad; n_blocks; target_size: the element size aimed at; quality: dict (min_scaled_jacobian,
    mean_scaled_jacobian, max_aspect_ratio, max_skew, min_angle, max_angle, irregular_interior_vertices, bound: the
    best minimum scaled Jacobian any all-quad mesh of the face can have, 1 for a rectilinear face);
    conformal (the core's independent check); decomposition: the DecompositionResult meshed.
    """

    def __init__(self, data, stepper, size, decomposition=None):
        self._stepper = stepper
        self.size = float(size)
        self.decomposition = decomposition
        frame = stepper.frame
        self.nodes = [faces.point_out_of_frame(x, y, z, frame) for x, y, z in data["nodes"]]
        self.quads = [tuple(q) for q in data["quads"]]
        self.quad_block = list(data["quad_block"])
        self.n_blocks = data["blocks"]
        self.target_size = data["target_size"]
        self.max_relative_deviation = data["max_relative_deviation"]
        self.quality = dict(data["quality"])
        self.conformal = data["conformal"]
        self.file = data["file"] or None

    def summary(self):
        """'5 blocks, 96 nodes, 70 quads, size 0.6 (max deviation 0.0 %), min scaled Jacobian 1, conformal'"""
        return "{}, {}, {}, size {} (max deviation {:.1f} %), min scaled Jacobian {:.4g}, {}".format(
            text.counted(self.n_blocks, "block"), text.counted(len(self.nodes), "node"),
            text.counted(len(self.quads), "quad"), text.significant(self.target_size), 100.0 * self.max_relative_deviation,
            self.quality["min_scaled_jacobian"], "conformal" if self.conformal else "NOT conformal")

    def __repr__(self):
        return "<AutoBlock mesh: {}: {}>".format(self._stepper.label, self.summary())

    def fem_mesh(self):
        """The quads as a Fem.FemMesh (global coordinates)."""
        from .objects.fem_mesh import fem_mesh

        return fem_mesh([(p.x, p.y, p.z) for p in self.nodes], self.quads)

    def export(self, path):
        """Write the mesh with the core's exporters: .msh (Gmsh 4.1), .vtu (VTK) or .inp (Abaqus/CalculiX), in
        global coordinates, one group per block. Returns path. ValueError for another extension."""
        _mesh_data(self._stepper, self.size, path)
        return path


def _mesh_data(stepper, size, out=""):
    """The native mesh of a stepper's decomposition (and the file `out`, when given)."""
    try:
        return native.load().mesh(stepper.local_brep, stepper.cuts, float(size), stepper.max_steps, stepper.reward,
                                  str(out or ""), _placement_numbers(stepper.frame), stepper.label,
                                  stepper.rules, stepper.min_edge_intervals)
    except ValueError as error:
        raise _in_frame_note(stepper.frame, error) from None


def global_shape(obj):
    """The shape of document object `obj` where it stands in the model: its own placement and those of the
    containers holding it (a Pad given directly is placed by its Body, and the Body by an App::Part)."""
    shape = Part.getShape(obj)  # with obj's own placement
    parent = obj.getParentGeoFeatureGroup() if hasattr(obj, "getParentGeoFeatureGroup") else None
    if parent is not None and not shape.isNull():
        shape.Placement = parent.getGlobalPlacement().multiply(shape.Placement)
    return shape


def solid_of(target, sub=None):
    """(shape, label) when `target` designates a solid to mesh with hexahedra, else None (a face).

    A solid: a Part.Shape, or a document object's shape, holding a solid (or no solid and a closed shell of
    several faces, as the core reads it), with no face named. A face, (object, "FaceN") or anything without a
    shape is not.
    """
    if isinstance(target, tuple) and len(target) == 2 and sub is None:
        target, sub = target
    if isinstance(sub, (list, tuple)):
        sub = sub[0] if len(sub) == 1 else (None if not sub else sub)
    if sub:
        return None
    if isinstance(target, Part.Shape):
        shape, label = target, "the shape"
    elif hasattr(target, "TypeId") and hasattr(target, "Document") and hasattr(target, "Shape"):
        shape, label = global_shape(target), target.Label
    else:
        return None
    if shape is None or shape.isNull():
        return None
    if shape.Solids or (len(shape.Shells) == 1 and len(shape.Faces) > 1):
        return shape, label
    return None


def cap_solid(target, sub=None):
    """The document object holding the solid whose cap `target` designates, else None.

    target: (object, "FaceN"), or an object and the path to a face inside a container (Body, "Pad.Face6"), as
    the selection gives it. The object holding that face (the Pad) is returned when its shape is one solid that
    is a straight sweep of a planar face (check_solid) and FaceN is one of its two caps; None for a side face, a
    face of a solid that is not such a sweep, a face alone or anything else. This is what Auto-Block does with a
    selected face: a cap stands for its solid, make_autoblock_solid((object, "FaceN")) (unless the preferences
    say otherwise), any other face is cut on its own (make_autoblock(object, "FaceN")).
    """
    if isinstance(target, tuple) and len(target) == 2 and sub is None:
        target, sub = target
    if isinstance(sub, (list, tuple)):
        sub = sub[0] if len(sub) == 1 else None
    if not sub or not isinstance(sub, str) or not hasattr(target, "getSubObject"):
        return None
    prefix, _, element = sub.rpartition(".")
    if not element.startswith("Face") or not element[4:].isdigit():
        return None
    holder = target.getSubObject(prefix + ".", retType=1) if prefix else target
    if holder is None or not is_solid(holder):
        return None
    try:
        caps = check_solid(holder)["caps"]
    except ValueError:
        return None
    return holder if int(element[4:]) in caps else None


def is_solid(target, sub=None):
    """True when AutoBlock meshes `target` (as decompose takes it) as a swept solid, with hexahedra."""
    return solid_of(target, sub) is not None


def _solid_shape(target, sub=None):
    found = solid_of(target, sub)
    if found is None:
        raise ValueError("{} is not a solid: mesh_solid takes a solid, a shape or an object holding one solid "
                         "(a face gives quads: AutoBlock.mesh)".format(
                             getattr(target, "Label", type(target).__name__)))
    return found


def check_solid(target, sub=None):
    """Checks that `target` (a solid, a shape or an object holding one) is a straight sweep of a planar face.
    Returns the core's figures (dict: caps (bottom, top face numbers), sweep (x, y, z), volume, area); raises
    ValueError with the core's one-line reason (naming the face) otherwise."""
    shape, label = _solid_shape(target, sub)
    return dict(native.load().check_solid(shape.exportBrepToString(), label))


def refines_to_solid(target, sub=None):
    """True when `target` (a solid, a shape or an object holding one) is no swept solid as it is but would be
    with its faces that could be one merged (shape.removeSplitter(), FreeCAD's Part > Create a copy > Refine
    shape): two boxes fused into an L without refining, say, whose caps are split too. False for anything
    else (a swept solid already, no solid, or no sweep even refined)."""
    found = solid_of(target, sub)
    if found is None:
        return False
    shape, label = found
    core = native.load()
    try:
        core.check_solid(shape.exportBrepToString(), label)
        return False
    except ValueError:
        pass
    refined = shape.removeSplitter()
    if len(refined.Faces) >= len(shape.Faces):
        return False
    try:
        core.check_solid(refined.exportBrepToString(), label)
    except ValueError:
        return False
    return True


def refined_copy(target):
    """A refined copy of the document object `target` (its faces that could be one merged: FreeCAD's
    Part::Refine feature, Part > Create a copy > Refine shape), added to its document in one undoable
    transaction and returned; it follows `target` when that recomputes. Raises ValueError when `target` is
    no document object with a shape."""
    from .transactions import transaction

    if not (hasattr(target, "TypeId") and hasattr(target, "Document") and hasattr(target, "Shape")):
        raise ValueError("refined_copy takes a document object with a shape, not {}".format(type(target).__name__))
    doc = target.Document
    with transaction("Refined copy"):
        copy = doc.addObject("Part::Refine", target.Name + "Refined")
        copy.Source = target
        copy.Label = target.Label + " (refined)"
        doc.recompute()
    return copy


class HexMeshResult:
    """A hexahedral mesh of a swept solid (AutoBlock.mesh_solid, or AutoBlock.mesh of a solid).

    nodes: list of FreeCAD.Vector (global coordinates); hexes: list of 8 node indices (0-based) in the
    Abaqus/CalculiX C3D8 (and VTK) order: 0-3 one quad, 4-7 the same quad one layer on, positive volume;
    hex_block: the block (0-based) of every hexahedron; n_blocks; layers; target_size; caps: the solid's cap
    face numbers (bottom, top; 1-based, as Face1, Face2, ...); sweep: FreeCAD.Vector from the bottom cap to the
    top one; volume, area: the solid's; quality: dict (min_scaled_jacobian, mean_scaled_jacobian,
    max_aspect_ratio, mean_aspect_ratio, max_skew, edges, irregular_edges, irregular_interior_edges);
    conformal (the core's independent check: faces shared by two hexahedra, volumes and areas add up);
    blocks: the prism blocks (list of Part.Solid); shape: their compound (neighbours share faces);
    policy; label; cap: the bottom cap's decomposition (a DecompositionResult without blocks: its cuts, return,
    cut_sequence(), stepper() to step through the cuts on the cap).
    """

    def __init__(self, data, label, request=None):
        self.label = label
        self._request = request
        self.file = data.get("file") or None
        self.nodes = [FreeCAD.Vector(x, y, z) for x, y, z in data["nodes"]]
        self.hexes = [tuple(h) for h in data["hexes"]]
        self.hex_block = list(data["hex_block"])
        self.n_blocks = data["n_blocks"]
        self.layers = data["layers"]
        self.target_size = data["target_size"]
        self.grading = data["grading"]
        self.caps = tuple(data["caps"])
        self.sweep = FreeCAD.Vector(*data["sweep"])
        self.volume = data["volume"]
        self.area = data["area"]
        self.quality = dict(data["quality"])
        self.conformal = data["conformal"]
        self.problem = data["problem"]
        self.policy = data["policy"]
        self.seconds = data["seconds"]
        self.blocks = [_shape_from_brep(t).Solids[0] for t in data["blocks"]]
        self.shape = _shape_from_brep(data["shape"]) if data["shape"] else None
        cap = data["cap"]
        frame = faces.placement_of(cap["frame"])
        local = _shape_from_brep(cap["brep"]).Faces[0]
        self.cap = DecompositionResult(cap, faces.out_of_frame(local, frame), local, frame, cap["face"]["source"])

    def cut_sequence(self):
        """The cap's cut sequence as an AutoBlock solid object stores it (JSON text): the cap's
        (DecompositionResult.cut_sequence), with the cap's face number ("cap") and frame ("frame", 12 numbers)."""
        sequence = json.loads(self.cap.cut_sequence())
        sequence["cap"] = self.caps[0]
        sequence["frame"] = _placement_numbers(self.cap.frame)
        return json.dumps(sequence)

    def stepper(self):
        """A Stepper over the cap's cuts (drawn on the cap, see stepping.py)."""
        return self.cap.stepper()

    def summary(self):
        """'caps Face5 and Face6: 3 blocks, 220 nodes, 120 hexahedra, 3 layers, size 1, min scaled Jacobian 1,
        0 irregular edges, conformal'"""
        return "caps Face{} and Face{}: {}, {}, {}, {}, size {}, min scaled Jacobian {:.4g}, {}, {}".format(
            self.caps[0], self.caps[1], text.counted(self.n_blocks, "block"), text.counted(len(self.nodes), "node"),
            text.counted(len(self.hexes), "hexahedron", "hexahedra"), text.counted(self.layers, "layer"),
            text.significant(self.target_size), self.quality["min_scaled_jacobian"],
            text.counted(self.quality["irregular_edges"], "irregular edge"),
            "conformal" if self.conformal else "NOT conformal ({})".format(self.problem))

    def __repr__(self):
        return "<AutoBlock hex mesh: {}: {}>".format(self.label, self.summary())

    def fem_mesh(self):
        """The hexahedra as a Fem.FemMesh of hexa8 volumes (global coordinates; FreeCAD's node order)."""
        from .objects.fem_mesh import fem_hex_mesh

        return fem_hex_mesh([(p.x, p.y, p.z) for p in self.nodes], self.hexes)

    def export(self, path, element="C3D8"):
        """Write the hexahedra with the core's exporters (as `autoblock mesh SOLID --out`): .msh (Gmsh 4.1, a
        physical volume per block and a physical surface per face of the solid), .vtu (VTK) or .inp
        (Abaqus/CalculiX; element "C3D8" or "C3D8I"; element sets per block, node sets and surfaces per face),
        global coordinates. The same solid and settings are meshed again. Returns path. ValueError for another
        extension."""
        brep, arguments = self._request
        native.load().mesh_solid(brep, **dict(arguments, blocks=False, out=str(path), element=str(element)))
        self.file = str(path)
        return path


def mesh_solid(target, size=None, layers=0, grading=1.0, policy=None, reward=None, seed=0, time_limit=30.0,
               max_steps=0, blocks=True, general_time_limit=None, out=None, element="C3D8"):
    """Mesh a swept solid with hexahedra: its bottom cap decomposed into blocks and quad-meshed like any face
    (policy, reward, seed, time_limit, max_steps, general_time_limit as for decompose), the quads swept along the
    solid in layers.

    target: a Part.Solid or a shape holding one solid (or a closed shell), or a document object (a Part box, an
        extrusion, a PartDesign Pad or Body) whose shape is one solid: a straight sweep of a planar face (two
        congruent planar caps joined by planar sides along one direction, normal or oblique).
    size: target element size (None or 0: the solid's longest bounding-box side / 20); layers: along the sweep
    (0: the sweep's length over the size); grading: each layer's thickness over the previous one's (1: uniform);
    blocks: also return the prism blocks (Part solids); out: also write the hexahedra to a .msh, .vtu or .inp file
    (element: "C3D8" or "C3D8I" for .inp), see HexMeshResult.export.
    Returns a HexMeshResult. Raises ValueError with the core's one-line reason for any other solid (a curved face,
    caps that differ, more than one solid, ...) or a bad option.
    """
    shape, label = _solid_shape(target)
    brep = shape.exportBrepToString()
    arguments = dict(policy=policy or preferences.default_policy(),
                     reward=preferences.reward_preset() if reward is None else reward, seed=int(seed),
                     time_limit=float(time_limit), max_steps=int(max_steps), size=float(size or 0.0), layers=int(layers),
                     grading=float(grading), source=label,
                     general_time_limit=-1.0 if general_time_limit is None else float(general_time_limit))
    data = native.load().mesh_solid(brep, blocks=bool(blocks), out=str(out or ""), element=str(element), **arguments)
    return HexMeshResult(data, label, (brep, arguments))


def mesh(target, size=None, policy=None, reward=None, seed=0, time_limit=30.0, max_steps=0, sub=None, layers=0,
         grading=1.0):
    """Mesh the blocks of a decomposition with quadrilaterals (the core's conformal merge, interval assignment
    and mapped meshing).

    target:
      - a solid, or a shape or document object holding one solid (and no sub): a swept solid meshed with
        hexahedra: returns mesh_solid(target, size, layers, grading, ...), a HexMeshResult;
      - an AutoBlock solid object (make_autoblock_solid): returns its hexa8 FEM mesh object (made when it has
        none);
      - an AutoBlock object: returns its FEM mesh object (Fem::FemMeshObjectPython, created when it has none,
        in one undoable transaction); size, when given, becomes the object's MeshSize. The mesh follows the
        object when it recomputes.
      - a DecompositionResult: returns a MeshResult of its blocks.
      - anything AutoBlock.decompose takes: decomposes it (policy, reward, seed, time_limit, max_steps, sub as
        there) and returns a MeshResult (its .decomposition is the result).
    size: target element size in model units (None or 0: automatic, 1/20 of the face's longer side; for an
    AutoBlock object None keeps its MeshSize). Raises ValueError for an incomplete decomposition or an
    infeasible size.
    """
    from .objects.autoblock_feature import is_autoblock
    from .objects.fem_mesh import is_autoblock_hex_mesh, is_autoblock_mesh, mesh_object_of
    from .objects.solid_blocks import hex_mesh_object_of, is_autoblock_solid

    if is_autoblock(target):
        return mesh_object_of(target, size=size, create=True)
    if is_autoblock_mesh(target) or is_autoblock_hex_mesh(target):
        return target
    if is_autoblock_solid(target):
        return hex_mesh_object_of(target)
    if not isinstance(target, DecompositionResult) and is_solid(target, sub):
        return mesh_solid(target, size=size, layers=layers, grading=grading, policy=policy, reward=reward, seed=seed,
                          time_limit=time_limit, max_steps=max_steps)
    result = target if isinstance(target, DecompositionResult) else decompose(
        target, policy=policy, reward=reward, seed=seed, time_limit=time_limit, max_steps=max_steps, sub=sub)
    stepper = result.stepper()
    size = float(size or 0.0)
    return MeshResult(_mesh_data(stepper, size), stepper, size, result)


def export_mesh(target, path, size=None):
    """Write the quad mesh of `target` (an AutoBlock object, its FEM mesh object, a DecompositionResult or a
    MeshResult; or the hexahedra of an AutoBlock solid object, its mesh object or a HexMeshResult) to `path`: .msh (Gmsh 4.1), .vtu (VTK) or .inp (Abaqus/CalculiX), through the core's exporters,
    in global coordinates. size: as for mesh() (None: the object's MeshSize, or automatic). Returns the
    MeshResult. ValueError for another extension or a missing folder."""
    import os

    from .objects.autoblock_feature import is_autoblock, stepper_of
    from .objects.fem_mesh import is_autoblock_mesh

    folder = os.path.dirname(os.path.abspath(str(path)))
    if not os.path.isdir(folder):
        raise ValueError("{}: the folder {} does not exist".format(path, folder))
    if isinstance(target, (MeshResult, HexMeshResult)):
        target.export(path)
        return target
    from .objects.fem_mesh import is_autoblock_hex_mesh
    from .objects.solid_blocks import is_autoblock_solid, mesh_solid_object

    if is_autoblock_hex_mesh(target):
        target = target.AutoBlock
    if is_autoblock_solid(target):
        return mesh_solid_object(target, out=path)
    if is_autoblock_mesh(target):
        target = target.AutoBlock
        if target is None:
            raise ValueError("the mesh object is not linked to an AutoBlock object")
    if is_autoblock(target):
        stepper = stepper_of(target)
        size = float(target.MeshSize if size is None else size)
        result = MeshResult(_mesh_data(stepper, size, path), stepper, size)
        result.file = str(path)
        return result
    if isinstance(target, DecompositionResult):
        result = mesh(target, size)
        result.export(path)
        result.file = str(path)
        return result
    raise TypeError("export_mesh needs an AutoBlock object, its mesh object, a decomposition or a mesh result, "
                    "got {}".format(type(target).__name__))


def train(request, progress=None):
    """Train a policy (blocking). request: an AutoBlock.TrainingRequest; progress(event): called for every
    training.Progress event; returning False cancels (a checkpoint stays for request.resume). Returns the result
    dict (policy_file, checkpoint, log, curves, cancelled, ...). See training.py."""
    from . import training

    return training.train(request, progress)
