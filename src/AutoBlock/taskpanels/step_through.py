"""The step-through task panel (resources/ui/step_through.ui): first / previous / next / last and a
slider over an AutoBlock object's cut sequence. The 3-D view shows the pieces at each step (step_scene.py)
while the object itself is hidden; closing the panel restores the view and leaves the document as it
was (nothing in it changes).

Position k (0 .. number of cuts) is the episode after k cuts, with the cut the policy chose next: its
part, vertex, line and reward; the return is shown before and after that cut.
"""

import html
import re

import FreeCAD
import FreeCADGui
from PySide2 import QtGui, QtWidgets

from .. import paths, text
from ..viewproviders.view_autoblock import block_colours
from .step_scene import CURRENT_COLOUR, CUT_COLOUR, PART_COLOUR, StepScene

_panel = None


def current_panel():
    """The open step-through panel, or None."""
    return _panel


def open_step_panel(obj):
    """Open the panel on AutoBlock object `obj` (what its view provider's setEdit does; an AutoBlock solid object:
    its cap's cuts, drawn on the cap). Returns True when open."""
    global _panel
    from ..gui_utils import report_exception
    from ..objects.autoblock_feature import stepper_of

    try:
        stepper = stepper_of(obj)
        panel = StepThroughPanel(obj, stepper)
    except Exception as error:
        report_exception("Step through the cuts", error)
        return False
    _panel = panel
    FreeCADGui.Control.showDialog(panel)
    return True


def close_step_panel(obj=None):
    """Close the panel and restore the view (what unsetEdit does)."""
    global _panel
    if _panel is not None:
        _panel.cleanup()
        _panel = None
    FreeCADGui.Control.closeDialog()


def _hex(colour):
    return "#{:02x}{:02x}{:02x}".format(*(int(round(255 * c)) for c in colour[:3]))


def _nowrap(words):
    """Rich text that keeps `words` on one line (a policy name such as sac-mesh must not split at its hyphen)."""
    return "<span style='white-space:nowrap'>{}</span>".format(html.escape(str(words)))


def plain_text(rich):
    """The text a rich-text label shows, without its tags (for tests and the console)."""
    return html.unescape(re.sub(r"<br\s*/?>", "\n", re.sub(r"<(?!br)[^>]*>", "", rich)))


class StepThroughPanel:
    def __init__(self, obj, stepper):
        self.obj = obj
        self.stepper = stepper
        self.form = FreeCADGui.PySideUic.loadUi(paths.ui("step_through"))
        self.form.setWindowIcon(QtGui.QIcon(paths.icon("AutoBlock_StepThrough")))
        self.colours = [c[:3] for c in block_colours(max(obj.NumberOfBlocks, 1))]
        style = self.form.style()
        buttons = ((self.form.firstButton, QtWidgets.QStyle.SP_MediaSkipBackward, self.first),
                   (self.form.previousButton, QtWidgets.QStyle.SP_MediaSeekBackward, self.previous),
                   (self.form.nextButton, QtWidgets.QStyle.SP_MediaSeekForward, self.next),
                   (self.form.lastButton, QtWidgets.QStyle.SP_MediaSkipForward, self.last))
        for button, icon, slot in buttons:
            button.setIcon(style.standardIcon(icon))
            button.clicked.connect(slot)
        self.form.slider.setRange(0, stepper.steps)
        self.form.slider.valueChanged.connect(self.show_step)
        policy, _, status = obj.Status.partition(": ")
        self.form.titleLabel.setText("<b>{}</b><br>{}{}".format(
            html.escape(obj.Label), _nowrap(policy), (": " + html.escape(status)) if status else ""))
        # One entry per line: the panel is often a narrow column (the Combo View).
        self.form.legendLabel.setText("<br>".join(
            "<span style='color:{}'>{}</span>&nbsp;{}".format(colour, mark, words) for colour, mark, words in (
                (_hex(self.colours[0]), "&#9632;", "blocks set aside (final colours)"),
                (_hex([c * 0.85 for c in PART_COLOUR]), "&#9632;", "parts still to cut"),
                (_hex(CURRENT_COLOUR), "&#9632;", "the part cut at this step"),
                (_hex(CUT_COLOUR), "&#9675;", "the chosen vertex, ringed in red"),
                (_hex(CUT_COLOUR), "&#9473;", "the cut line"))))
        gui_document = FreeCADGui.getDocument(obj.Document.Name)
        self.view = gui_document.ActiveView
        if not hasattr(self.view, "getSceneGraph"):
            raise ValueError("the active view of {} is not a 3-D view".format(obj.Document.Label))
        # Hide the object and its FEM mesh through their scene graphs only (no property changes: the document
        # stays as it is).
        from ..objects.fem_mesh import mesh_objects_of
        from ..objects.solid_blocks import hex_mesh_objects_of, is_autoblock_solid

        self.switch = obj.ViewObject.SwitchNode
        self.saved_child = self.switch.whichChild.getValue()
        meshes = hex_mesh_objects_of(obj) if is_autoblock_solid(obj) else mesh_objects_of(obj)
        self.hidden = [(o.ViewObject.SwitchNode, o.ViewObject.SwitchNode.whichChild.getValue())
                       for o in meshes if o.ViewObject is not None]
        self.scene = StepScene(self.view)
        self.switch.whichChild = -1
        for switch, _ in self.hidden:
            switch.whichChild = -1
        self.step = -1
        self.show_step(0)

    # -- navigation -------------------------------------------------------------------------------
    def first(self):
        self.form.slider.setValue(0)

    def previous(self):
        self.form.slider.setValue(max(self.step - 1, 0))

    def next(self):
        self.form.slider.setValue(min(self.step + 1, self.stepper.steps))

    def last(self):
        self.form.slider.setValue(self.stepper.steps)

    def show_step(self, k):
        from ..gui_utils import message_of

        try:
            view = self.stepper.step(k)
        except Exception as error:
            FreeCAD.Console.PrintError("AutoBlock: step {}: {}\n".format(k, message_of(error)))
            self.form.positionLabel.setText("Step {}: {}".format(k, message_of(error)))
            return
        self.step = k
        if self.form.slider.value() != k:
            self.form.slider.setValue(k)
        self.current = view
        self.scene.show(view, self.colours)
        self.update_labels(view)
        self.form.firstButton.setEnabled(k > 0)
        self.form.previousButton.setEnabled(k > 0)
        self.form.nextButton.setEnabled(k < self.stepper.steps)
        self.form.lastButton.setEnabled(k < self.stepper.steps)

    @staticmethod
    def position_text(step, steps, status):
        """What the panel says about where it is: 'Step 0 of 3: no cut made yet; in red: cut 1', ...,
        'Step 3 of 3: all 3 cuts made, complete'."""
        if steps == 0:
            return "The face is a block already: no cut needed"
        if step < steps:
            made = "no cut made yet" if step == 0 else text.counted(step, "cut") + " made"
            return "Step {} of {}: {}; in red: cut {}".format(step, steps, made, step + 1)
        made = "the only cut made" if steps == 1 else "all {} made".format(text.counted(steps, "cut"))
        return "Step {} of {}: {}, {}".format(step, steps, made, status)

    def update_labels(self, view):
        f = self.form
        queued = sum(1 for p in view.pieces if not p.block)
        tolerance = view.tolerance
        f.positionLabel.setText(self.position_text(view.step, view.steps, view.status))
        if view.next is None:
            for label in (f.partLabel, f.vertexLabel, f.directionLabel, f.rewardLabel):
                label.setText("-")
            f.returnLabel.setText("{:.3f} (total)".format(view.ret))
            f.blocksLabel.setText("{}{}".format(
                text.counted(view.blocks, "block"),
                ", {} left unfinished".format(text.counted(queued, "part")) if queued else ""))
            f.scoresLabel.setText("No cut at this step.")
            return
        cut = view.next
        f.partLabel.setText("#{} ({})".format(cut.part, text.counted(len(cut.vertices), "corner")))
        if cut.vertex is None:  # a general face's template: no cut line
            f.vertexLabel.setText("-")
        elif cut.kind not in ("axis", None) and cut.chosen < 0:
            f.vertexLabel.setText("{} (on an edge)".format(text.vector(cut.vertex, tolerance)))
        else:
            f.vertexLabel.setText(text.vector(cut.vertex, tolerance))
        if cut.kind == "template":
            f.directionLabel.setText(cut.direction)
        elif cut.n_parts == 1:
            f.directionLabel.setText("{}, along the boundary: nothing cut".format(cut.direction))
        else:
            f.directionLabel.setText("{}, leaves {}".format(cut.direction, text.counted(cut.n_parts, "piece")))
        f.rewardLabel.setText("{:+.3f}".format(cut.reward))
        f.returnLabel.setText("{:.3f} (before this cut: {:.3f})".format(view.ret + cut.reward, view.ret))
        f.blocksLabel.setText("{} set aside, {} to cut".format(text.counted(view.blocks, "block"),
                                                               text.counted(queued, "part")))
        scored = [i for i, score in enumerate(cut.scores or []) if score is not None]
        if scored:
            best = max(scored, key=lambda i: cut.scores[i])
            chosen = cut.scores[cut.chosen] if cut.chosen < len(cut.scores) else None
            f.scoresLabel.setText(
                "The value network of {}: discs from blue (low) to red (high); highest {:.3f} at {}; the chosen "
                "vertex (ringed in red) scores {}.".format(
                    _nowrap(self.stepper.scores_by), cut.scores[best],
                    _nowrap(text.vector(cut.vertices[best], tolerance)),
                    "-" if chosen is None else "{:.3f}".format(chosen)))
        else:
            f.scoresLabel.setText("Not shown: {}.".format(html.escape(cut.scores_note or "no scores")))

    # -- task panel protocol ----------------------------------------------------------------------
    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Close)

    def reject(self):
        self._leave()
        return True

    def accept(self):
        self._leave()
        return True

    def _leave(self):
        try:
            gui_document = FreeCADGui.getDocument(self.obj.Document.Name)
            in_edit = gui_document.getInEdit() is not None
        except Exception:  # the object or its document is gone
            gui_document, in_edit = None, False
        if in_edit:
            gui_document.resetEdit()  # -> unsetEdit -> close_step_panel
        else:
            close_step_panel()

    def cleanup(self):
        """Remove the picture and show the object again (idempotent)."""
        if self.scene is not None:
            self.scene.remove()
            self.scene = None
            for switch, child in [(self.switch, self.saved_child)] + self.hidden:
                try:
                    switch.whichChild = child
                except Exception:  # the object may be gone
                    pass
