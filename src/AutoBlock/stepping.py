"""A decomposition cut by cut: what the step-through panel shows, also usable from the console.

    stepper = AutoBlock.decompose(face).stepper()          # or AutoBlock.stepper_of(autoblock_object)
    view = stepper.step(2)      # the episode after 2 cuts, and the 3rd cut
    view.pieces, view.next.vertex, view.next.line, view.ret, view.blocks

The native module replays the cut sequence on the face (microseconds per cut) and returns polygons;
they become faces here, in global coordinates.
"""

import math

import FreeCAD

from . import faces, native, text


class Piece:
    """A piece of the face at a step: id, block (set aside: a rectangle, or on a general face a block or a
    template; else a part still to cut), template (a general face's part finished as quads around its centre),
    index (for blocks: its place in the order set aside, which is also its colour's index), face."""

    __slots__ = ("id", "block", "index", "face", "outer", "holes", "template")

    def __init__(self, id, block, index, face, outer, holes, template=False):
        self.id = id
        self.block = block
        self.index = index
        self.face = face
        self.outer = outer
        self.holes = holes
        self.template = template


class NextCut:
    """The cut chosen at a step: part (id), vertices (the part's model vertices, global), chosen (index),
    vertex (global), direction, line (list of (start, end) global points where it crosses the part),
    reward, n_parts, scores (per-vertex value-network scores of a learned policy, the better of the cuts
    through each vertex; None for a baseline) and scores_note (why there are none).

    On a general face: kind ("full", "partial" or "template"; "axis" on a grid face), vertex is the cut's origin
    (None for a template), chosen is -1 when the origin lies on an edge (or for a template), direction reads
    e.g. "partial cut at 30.0 degrees" (the angle in the model's XY plane for a face parallel to it, else in the
    face's own plane), vector is the direction (dx, dy) in the face's frame, and line holds the chords the cut
    makes (angled, and for a partial cut ending at the boundary it meets)."""

    __slots__ = ("part", "vertices", "chosen", "vertex", "direction", "line", "reward", "n_parts", "scores",
                 "scores_note", "local_vertices", "kind", "vector")

    def __init__(self, **values):
        for key, value in values.items():
            setattr(self, key, value)


class StepView:
    """The episode after `step` of `steps` cuts: pieces, blocks (count), ret (return so far), status,
    next (NextCut, or None after the last cut), frame, z (in the frame), normal (the face's, global), size
    (the face's longer side), tolerance (what coordinates are printed to: the face's tolerance, or on a
    general face the lattice its corners are snapped to)."""

    def __init__(self, **values):
        for key, value in values.items():
            setattr(self, key, value)


class Stepper:
    """Steps through one decomposition. local_brep: the face in its frame (BREP text); frame; cuts:
    [(part, x, y, direction)] in that frame; max_steps as decomposed; label; policy (its spec); reward: the
    preset the cuts were scored with (the decomposition's); a general face's rules (its block rules, [min corner,
    max corner, flat tolerance] in degrees; None: the face's own) and min_edge_intervals (what its mesh takes at
    least on every model edge), as its decomposition gives them (console.sequence_rules)."""

    def __init__(self, local_brep, frame, cuts, max_steps, label, policy, reward="paper", rules=None,
                 min_edge_intervals=1):
        self.local_brep = local_brep
        self.frame = frame
        self.cuts = list(cuts)
        self.max_steps = max_steps
        self.label = label
        self.policy = policy
        self.reward = reward or "paper"
        self.rules = list(rules) if rules else []
        self.min_edge_intervals = max(1, int(min_edge_intervals or 1))
        self._cache = {}

    @property
    def general(self):
        """True for a general face's sequence (actions (part, kind, ox, oy, dx, dy, forced))."""
        return any(len(c) > 1 and isinstance(c[1], str) for c in self.cuts)

    @property
    def steps(self):
        return len(self.cuts)

    @property
    def scores_by(self):
        """Whose value network gives the scores: the policy's own, auto's learned fallback (sac-mesh), or the
        policy's name when the core cannot say."""
        try:
            return native.load().policy_info(self.policy).get("scores_by") or self.policy
        except (ValueError, RuntimeError, native.NativeModuleMissing):
            return self.policy

    def step(self, k):
        """The StepView after k cuts (0 <= k <= steps). Raises ValueError when the cuts do not belong
        to the face."""
        if k in self._cache:
            return self._cache[k]
        module = native.load()
        data = module.step(self.local_brep, self.cuts, int(k), self.max_steps, self.reward, self.label, self.rules)
        z = data["z"]
        pieces = []
        block_index = 0
        size = 0.0
        for p in data["pieces"]:
            local = faces.polygon_face(p["outer"], p["holes"], z)
            xs = [x for x, _ in p["outer"]]
            ys = [y for _, y in p["outer"]]
            size = max(size, max(xs) - min(xs), max(ys) - min(ys))
            pieces.append(Piece(p["id"], p["block"], block_index if p["block"] else -1,
                                faces.out_of_frame(local, self.frame), p["outer"], p["holes"],
                                p.get("template", False)))
            if p["block"]:
                block_index += 1
        nxt = None
        if data["next"] is not None:
            n = data["next"]
            to_global = lambda xy: faces.point_out_of_frame(xy[0], xy[1], z, self.frame)  # noqa: E731
            scores, note = self._scores(module, k)
            kind = n.get("kind", "axis")
            if kind == "axis":
                vertex, direction, vector = to_global(n["vertex"]), n["direction"], None
            else:
                vertex = to_global(n["origin"]) if n["origin"] is not None else None
                vector = tuple(n["direction"]) if n["direction"] is not None else None
                direction = self._direction_text(kind, vector)
            nxt = NextCut(
                part=n["part"], vertices=[to_global(v) for v in n["vertices"]], local_vertices=list(n["vertices"]),
                chosen=n["chosen"], vertex=vertex, direction=direction, kind=kind, vector=vector,
                line=[(to_global(a), to_global(b)) for a, b in n["line"]], reward=n["reward"],
                n_parts=n["n_parts"], scores=scores, scores_note=note)
        normal = self.frame.Rotation.multVec(FreeCAD.Vector(0, 0, 1 if data["normal_up"] else -1))
        view = StepView(step=data["step"], steps=data["steps"], pieces=pieces, blocks=data["blocks"],
                        ret=data["return"], status=data["status"], next=nxt, frame=self.frame, z=z,
                        normal=normal, size=size, label=self.label,
                        # A general face's corners are snapped to its lattice in the frame (by up to q / 2 per
                        # axis) and turned back to the model: printed to 2 q, they read as the user drew them.
                        tolerance=max(text.tolerance_of(size), 2.0 * data.get("quantum", 0.0)))
        self._cache[k] = view
        return view

    def _direction_text(self, kind, vector):
        """A general action's direction as it reads in the panel: the angle in the model's XY plane for a face
        parallel to it (as the user sees the model from the top), else in the face's own plane."""
        if vector is None:
            return text.cut_direction(kind, vector)
        along = self.frame.Rotation.multVec(FreeCAD.Vector(vector[0], vector[1], 0))
        if abs(along.z) <= 1e-9 * along.Length:
            return text.cut_direction(kind, (along.x, along.y))
        return text.cut_direction(kind, vector) + " in the face's plane"

    def _scores(self, module, k):
        """Per-vertex value scores at step k (a vertex no cut can use scores None), or (None, why not)."""
        if not native.has("vertex_scores"):
            return None, "value scores need a learned policy, which this build does not have"
        try:
            # One score per vertex of the next cut's part, in the order of step()["next"]["vertices"];
            # ValueError when the policy has no value network (a baseline) or its file is gone.
            scores = module.vertex_scores(self.local_brep, self.cuts, int(k), self.policy, self.max_steps,
                                          self.reward, self.label, self.rules)
        except ValueError as error:
            return None, str(error)
        return [s if math.isfinite(s) else None for s in scores], ""
