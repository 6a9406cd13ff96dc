"""Auto-Block: the selected planar faces -> one parametric AutoBlock object each; a selected solid (an object
holding one swept solid, selected whole), or a selected cap face of one (unless the preferences say "mesh the
face") -> an AutoBlock solid object (prism blocks) and its hexa8 FEM mesh, one per solid."""

import FreeCAD
import FreeCADGui

from .base import BaseCommand


def selected_targets():
    """[(object, sub or None, object to hide)] for every selected face, or every selected object when no face
    of it is selected. Objects inside containers (a Body, an App::Part) are reached through their path, so
    that the containers' placements apply."""
    from ..faces import selection_target

    targets = []
    for selection in FreeCADGui.Selection.getSelectionEx("", 0):
        obj = selection.Object
        names = list(selection.SubElementNames) or [""]
        seen = set()
        for name in names:
            target = selection_target(obj, name)
            if (target[0].Name, target[1]) not in seen:
                seen.add((target[0].Name, target[1]))
                targets.append(target)
    return targets


class AutoBlockCommand(BaseCommand):
    NAME = "AutoBlock_AutoBlock"
    ICON = "AutoBlock_AutoBlock"
    MENU_TEXT = "Auto-Block"
    TOOL_TIP = ("Cut the selected planar faces into blocks: one parametric AutoBlock object per face, with a FEM "
                "mesh of quads on rectilinear faces (select faces, a sketch, or objects holding one face); a selected swept "
                "solid (a box, an extrusion, a Pad), or a cap face of one, is split into prism blocks with a FEM mesh of "
                "hexahedra (Preferences: a cap face may mesh the face alone instead)")

    def IsActive(self):
        return FreeCADGui.ActiveDocument is not None and bool(FreeCADGui.Selection.getSelection())

    def run(self):
        from .. import console, preferences
        from ..gui_utils import ask_yes_no, busy, echo, object_ref, report_error
        from ..objects.autoblock_feature import is_autoblock
        from ..objects.fem_mesh import is_autoblock_hex_mesh, is_autoblock_mesh
        from ..objects.solid_blocks import is_autoblock_solid
        from ..transactions import transaction

        targets = selected_targets()
        if not targets:
            report_error("Auto-Block", "Select one or more planar faces (or a sketch, or an object holding one face).")
            return
        # Check every face and solid first: with one bad one, nothing changes. An object selected whole whose
        # shape holds a solid is a solid (split into prisms and meshed with hexahedra); so is a selected cap face
        # of a sweepable solid (console.cap_solid: the object holding it, e.g. the Pad of "Pad.Face6"), unless the
        # preferences say to mesh the face alone; any other face is a face. Several caps of one solid: one solid.
        # A solid that is a sweep only once its split faces are merged (boxes fused into an L without refining)
        # is a problem too, unless it is the only kind: then the user is asked whether to mesh refined copies.
        problems = []
        refinable = []  # (object, its problem)
        solids = {}  # (object name, sub) -> the object holding the solid (whole, or a cap of it selected)
        caps_mean_solids = preferences.cap_face() == "solid"
        for obj, sub, _ in targets:
            try:
                if console.is_solid(obj, sub):
                    try:
                        console.check_solid(obj)
                    except ValueError as error:
                        if not console.refines_to_solid(obj):
                            raise
                        refinable.append((obj, str(error)))
                        continue
                    solids[(obj.Name, sub)] = obj
                    continue
                holder = console.cap_solid(obj, sub) if sub and caps_mean_solids else None
                if holder is not None:
                    solids[(obj.Name, sub)] = holder
                else:
                    console.check_face(obj, sub)
            except (ValueError, TypeError) as error:
                problems.append(str(error))
        if problems:
            problems += [problem for _, problem in refinable]
            report_error("Auto-Block", "Unsupported face{}; nothing was changed:\n\n{}".format(
                "s" if len(problems) > 1 else "", "\n\n".join(problems)))
            return
        refine = list({obj.Name: obj for obj, _ in refinable}.values())
        if refine and not ask_yes_no("Auto-Block", "{} {} no swept solid as {}, but would be with {} split faces "
                                     "merged (as Part > Create a copy > Refine shape merges them).\n\nMesh a refined "
                                     "copy of {}?".format(
                                         ", ".join(obj.Label for obj in refine), "is" if len(refine) == 1 else "are",
                                         "it is" if len(refine) == 1 else "they are",
                                         "its" if len(refine) == 1 else "their",
                                         "it" if len(refine) == 1 else "each")):
            return
        doc = targets[0][0].Document
        before = set(o.Name for o in doc.Objects)
        with busy(), transaction("Auto-Block"):
            echo("import AutoBlock")
            made = set()
            for obj in refine:
                echo("refined = AutoBlock.refined_copy({})".format(object_ref(obj)))
                echo("AutoBlock.make_autoblock_solid(refined)")
                echo("if refined.ViewObject is not None: refined.ViewObject.Visibility = False")
            for obj, sub, _ in targets:
                if any(obj is r for r in refine):
                    continue
                solid = solids.get((obj.Name, sub))
                if solid is not None:
                    if (solid.Document.Name, solid.Name) not in made:
                        made.add((solid.Document.Name, solid.Name))
                        # A cap: its console twin names the selected face, (object, "FaceN").
                        echo("AutoBlock.make_autoblock_solid({})".format(
                            "({}, {!r})".format(object_ref(obj), sub) if sub else object_ref(solid)))
                elif sub:
                    echo("AutoBlock.make_autoblock({}, {!r})".format(object_ref(obj), sub))
                else:
                    echo("AutoBlock.make_autoblock({})".format(object_ref(obj)))
            for leaf in {t[2] for t in targets}:
                if leaf.ViewObject is not None and leaf.ViewObject.Visibility:
                    echo("Gui.getDocument({!r}).getObject({!r}).Visibility = False".format(leaf.Document.Name,
                                                                                             leaf.Name))
        created = [o for o in doc.Objects if o.Name not in before]
        FreeCADGui.Selection.clearSelection()
        for obj in created:
            if is_autoblock(obj) or is_autoblock_solid(obj):
                FreeCADGui.Selection.addSelection(obj)
                FreeCAD.Console.PrintMessage("AutoBlock: {}: {}\n".format(obj.Label, obj.Status))
            elif is_autoblock_mesh(obj) or is_autoblock_hex_mesh(obj):
                FreeCAD.Console.PrintMessage("AutoBlock: {}: {}\n".format(obj.Label, obj.Quality))
