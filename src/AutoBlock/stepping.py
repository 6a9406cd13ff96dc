"""A decomposition cut by cut: what the step-through panel shows, also usable from the console.

    stepper = AutoBlock.decompose(face).stepper()          # or AutoBlock.stepper_of(autoblock_object)
    view = stepper.step(2)      # the episode after 2 cuts, and the 3rd cut
    view.pieces, view.next.vertex, view.next.line, view.ret, view.blocks

The native module replays the cut sequence on the face (microseconds per cut) and returns polygons;
they become faces here, in global coordinates.
"""

import math

import FreeCAD

from . import faces, native


class Piece:
    """A piece of the face at a step: id, block (a rectangle set aside; else a part still to cut),
    index (for blocks: its place in the order set aside, which is also its colour's index), face."""

    __slots__ = ("id", "block", "index", "face", "outer", "holes")

    def __init__(self, id, block, index, face, outer, holes):
        self.id = id
        self.block = block
        self.index = index
        self.face = face
        self.outer = outer
        self.holes = holes


class NextCut:
    """The cut chosen at a step: part (id), vertices (the part's model vertices, global), chosen (index),
    vertex (global), direction, line (list of (start, end) global points where it crosses the part),
    reward, n_parts, scores (per-vertex value-network scores of a learned policy, the better of the cuts
    through each vertex; None for a baseline) and scores_note (why there are none)."""

    __slots__ = ("part", "vertices", "chosen", "vertex", "direction", "line", "reward", "n_parts", "scores",
                 "scores_note", "local_vertices")

    def __init__(self, **values):
        for key, value in values.items():
            setattr(self, key, value)


class StepView:
    """The episode after `step` of `steps` cuts: pieces, blocks (count), ret (return so far), status,
    next (NextCut, or None after the last cut), frame, z (in the frame), normal (the face's, global), size
    (the face's longer side)."""

    def __init__(self, **values):
        for key, value in values.items():
            setattr(self, key, value)


class Stepper:
    """Steps through one decomposition. local_brep: the face in its frame (BREP text); frame; cuts:
    [(part, x, y, direction)] in that frame; max_steps as decomposed; label; policy (its spec); reward: the
    preset the cuts were scored with (the decomposition's)."""

    def __init__(self, local_brep, frame, cuts, max_steps, label, policy, reward="paper"):
        self.local_brep = local_brep
        self.frame = frame
        self.cuts = list(cuts)
        self.max_steps = max_steps
        self.label = label
        self.policy = policy
        self.reward = reward or "paper"
        self._cache = {}

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
        data = module.step(self.local_brep, self.cuts, int(k), self.max_steps, self.reward, self.label)
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
                                faces.out_of_frame(local, self.frame), p["outer"], p["holes"]))
            if p["block"]:
                block_index += 1
        nxt = None
        if data["next"] is not None:
            n = data["next"]
            to_global = lambda xy: faces.point_out_of_frame(xy[0], xy[1], z, self.frame)  # noqa: E731
            scores, note = self._scores(module, k)
            nxt = NextCut(
                part=n["part"], vertices=[to_global(v) for v in n["vertices"]], local_vertices=list(n["vertices"]),
                chosen=n["chosen"], vertex=to_global(n["vertex"]), direction=n["direction"],
                line=[(to_global(a), to_global(b)) for a, b in n["line"]], reward=n["reward"],
                n_parts=n["n_parts"], scores=scores, scores_note=note)
        normal = self.frame.Rotation.multVec(FreeCAD.Vector(0, 0, 1 if data["normal_up"] else -1))
        view = StepView(step=data["step"], steps=data["steps"], pieces=pieces, blocks=data["blocks"],
                        ret=data["return"], status=data["status"], next=nxt, frame=self.frame, z=z,
                        normal=normal, size=size, label=self.label)
        self._cache[k] = view
        return view

    def _scores(self, module, k):
        """Per-vertex value scores at step k (a vertex no cut can use scores None), or (None, why not)."""
        if not native.has("vertex_scores"):
            return None, "value scores need a learned policy, which this build does not have"
        try:
            # One score per vertex of the next cut's part, in the order of step()["next"]["vertices"];
            # ValueError when the policy has no value network (a baseline) or its file is gone.
            scores = module.vertex_scores(self.local_brep, self.cuts, int(k), self.policy, self.max_steps,
                                          self.reward, self.label)
        except ValueError as error:
            return None, str(error)
        return [s if math.isfinite(s) else None for s in scores], ""
