"""The Train task panel (resources/ui/train.ui): data (folders or generated shapes), episodes, seed, reward
preset, output file and what a fresh run starts from (random weights or a trained policy); a background run with a progress bar, a live plot of training and test return,
Cancel, resume from the checkpoint, and making the result the default policy.

It drives a training backend through the protocol of training.py: by default the core's trainer, started
through the console call it echoes (AutoBlock.start_training(AutoBlock.TrainingRequest(...))), which runs
in a background thread with the GIL released, so FreeCAD stays responsive. A core that cannot train gets a
note saying so and disabled controls.
"""

import os

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtGui, QtWidgets

from .. import paths, preferences, training
from .return_plot import ReturnPlot

_panel = None


def current_panel():
    return _panel


def show(backend=None):
    """Open the Train panel. backend: a training backend (see training.py; tests pass a double); None: the
    core's, if any."""
    global _panel
    panel = TrainPanel(backend)
    _panel = panel
    FreeCADGui.Control.showDialog(panel)
    return panel


class TrainPanel:
    POLL_MS = 200
    RANDOM_WEIGHTS = "random weights"

    def __init__(self, backend=None):
        self.native = backend is None  # the core's trainer, started through its echoed console call
        self.backend = backend if backend is not None else training.training_backend()
        self.run = None
        self.result = None
        self.form = FreeCADGui.PySideUic.loadUi(paths.ui("train"))
        self.form.setWindowIcon(QtGui.QIcon(paths.icon("AutoBlock_Train")))
        f = self.form
        self.plot = ReturnPlot(f.plotHost)
        f.plotLayout.addWidget(self.plot)
        try:
            from .. import native

            presets = [p for p in native.load().reward_presets() if p]
        except Exception:
            presets = ["paper"]
        f.reward.addItems(presets)
        f.reward.setToolTip("The reward the policy learns to maximise: paper (Eq. (1) of DiPrete et al. 2022) or "
                            "mesh (few, fat blocks; the shipped sac-mesh, auto's fallback, was trained with it)")
        if preferences.params().GetString(preferences.REWARD_PRESET, "") in presets:
            f.reward.setCurrentText(preferences.params().GetString(preferences.REWARD_PRESET, ""))
        # Start from: random weights, or a shipped trained policy (or a policy file typed in): --init.
        f.init.addItem(self.RANDOM_WEIGHTS)
        try:
            from .. import console

            f.init.addItems([n for n in console.policy_names() if console.policy_info(n)["learned"]])
        except Exception:
            pass
        f.resume.toggled.connect(lambda on: f.init.setEnabled(not on))
        data = os.path.join(paths.MODELS, "data")
        f.trainFolderEdit.setText(os.path.join(data, "train"))
        f.testFolderEdit.setText(os.path.join(data, "test"))
        f.outputEdit.setText(os.path.join(FreeCAD.getUserAppDataDir(), "AutoBlock", "policy.pt"))
        f.trainFolderButton.clicked.connect(lambda: self._browse_folder(f.trainFolderEdit))
        f.testFolderButton.clicked.connect(lambda: self._browse_folder(f.testFolderEdit))
        f.outputButton.clicked.connect(self._browse_output)
        f.outputEdit.textChanged.connect(self._update_resume)
        f.startButton.clicked.connect(self.start)
        f.cancelButton.clicked.connect(self.cancel)
        f.defaultButton.clicked.connect(self.make_default)
        self.timer = QtCore.QTimer()
        self.timer.setInterval(self.POLL_MS)
        self.timer.timeout.connect(self.poll)
        self.available = self.backend is not None
        f.noteLabel.setText(training.NOT_AVAILABLE)
        f.noteLabel.setVisible(not self.available)
        for widget in (f.trainBox, f.testBox, f.runBox, f.startButton):
            widget.setEnabled(self.available)
        f.statusLabel.setText("Ready." if self.available else "")
        self._update_resume()

    # -- form -> request ----------------------------------------------------------------------------
    def _browse_folder(self, edit):
        folder = QtWidgets.QFileDialog.getExistingDirectory(self.form, "Choose a folder of faces", edit.text())
        if folder:
            edit.setText(folder)

    def _browse_output(self):
        name, _ = QtWidgets.QFileDialog.getSaveFileName(self.form, "Policy file", self.form.outputEdit.text())
        if name:
            self.form.outputEdit.setText(name)

    def _update_resume(self):
        exists = os.path.exists(self.form.outputEdit.text() + ".checkpoint")
        self.form.resume.setEnabled(self.available and exists and self.run is None)
        if not exists:
            self.form.resume.setChecked(False)

    def request(self):
        f = self.form
        train_generate = test_generate = None
        if f.trainGenerateRadio.isChecked():
            train_generate = {"count": f.trainCount.value(), "min_rects": f.trainMinRects.value(),
                              "max_rects": f.trainMaxRects.value(), "holes": f.trainHoles.isChecked(),
                              "general": f.trainGeneral.value(), "arcs": f.trainArcs.value(), "seed": f.seed.value()}
        if f.testGenerateRadio.isChecked():
            test_generate = {"count": f.testCount.value(), "min_rects": f.trainMinRects.value(),
                             "max_rects": f.trainMaxRects.value(), "holes": f.trainHoles.isChecked(),
                             "general": f.testGeneral.value(), "arcs": f.testArcs.value(), "seed": f.seed.value() + 1}
        return training.TrainingRequest(
            output=f.outputEdit.text().strip(),
            train_folder=None if train_generate else f.trainFolderEdit.text().strip(),
            train_generate=train_generate,
            test_folder=None if test_generate else (f.testFolderEdit.text().strip() or None),
            test_generate=test_generate, episodes=f.episodes.value(), seed=f.seed.value(),
            reward=f.reward.currentText(), resume=f.resume.isChecked(), threads=preferences.threads(),
            eval_every=f.evalEvery.value(), init=self._init())

    def _init(self):
        """The policy a fresh run starts from (None: random weights; a resumed run keeps its checkpoint's)."""
        text = self.form.init.currentText().strip()
        if self.form.resume.isChecked() or not text or text == self.RANDOM_WEIGHTS:
            return None
        return text

    # -- running ----------------------------------------------------------------------------------------
    def _set_running(self, running):
        f = self.form
        for widget in (f.trainBox, f.testBox, f.runBox, f.startButton):
            widget.setEnabled(self.available and not running)
        f.cancelButton.setEnabled(running)

    def _status(self, text, error=False):
        self.form.statusLabel.setText(text)
        self.form.statusLabel.setStyleSheet("color: #b00020;" if error else "")

    def start(self):
        if not self.available or self.run is not None:
            return
        request = self.request()
        try:
            request.validate()
            output_dir = os.path.dirname(os.path.abspath(request.output))
            if not os.path.isdir(output_dir):
                raise ValueError("the output folder {} does not exist".format(output_dir))
        except ValueError as error:
            self._status(str(error), error=True)
            FreeCAD.Console.PrintError("AutoBlock: training: {}\n".format(error))
            return
        FreeCAD.Console.PrintMessage("AutoBlock: training {} episodes -> {}\n".format(request.episodes, request.output))
        self.result = None
        self.form.defaultButton.setEnabled(False)
        self.plot.clear()
        self.form.progressBar.setRange(0, request.episodes)
        self.form.progressBar.setValue(0)
        before = training.last_started()
        try:
            if self.native:
                from ..gui_utils import echo

                # The console call, echoed and run: it starts the run in the background and returns it.
                echo("import AutoBlock")
                echo("_autoblock_training = AutoBlock.start_training({!r})".format(request))
                run = training.last_started()
                if run is None or run is before:
                    raise RuntimeError("training did not start (see the report view)")
            else:
                run = training.start(request, self.backend)
        except Exception as error:  # never raised into FreeCAD: said in the panel and the report view
            from ..gui_utils import message_of

            self._status(message_of(error), error=True)
            FreeCAD.Console.PrintError("AutoBlock: training: {}\n".format(message_of(error)))
            return
        self.run = run
        self._set_running(True)
        self._status("Training (in the background: FreeCAD stays usable)...")
        self.timer.start()

    def poll(self):
        if self.run is None:
            self.timer.stop()
            return
        done = self.run.done  # read before draining: a finished run has queued all its events
        for event in self.run.poll():
            if event.status:  # before the first episode: what the run computes
                self._status(event.status[:1].upper() + event.status[1:] + "...")
                continue
            if event.episodes:
                self.form.progressBar.setRange(0, event.episodes)
            self.form.progressBar.setValue(event.episode)
            self.plot.add(event.episode, event.train_return, event.test_return)
            parts = ["episode {} of {}".format(event.episode, event.episodes)]
            if event.train_return is not None:
                parts.append("training return {:.3f} (10-episode average)".format(event.train_return))
            if event.test_return is not None:
                parts.append("test return {:.3f}".format(event.test_return))
            if event.message:
                parts.append(event.message)
            self._status(", ".join(parts))
        if done:
            self._finish()

    def _finish(self):
        run, self.run = self.run, None
        self.timer.stop()
        self._set_running(False)
        self._update_resume()
        if run.error:
            self._status("Training failed: {}. Tick 'Resume' to continue from the checkpoint.".format(run.error)
                         if os.path.exists(run.request.checkpoint) else "Training failed: {}".format(run.error),
                         error=True)
            FreeCAD.Console.PrintError("AutoBlock: training failed: {}\n".format(run.error))
            return
        self.result = run.result or {}
        if self.result.get("cancelled"):
            self._status("Cancelled after {} episodes. Tick 'Resume' and Train to continue from the checkpoint.".format(
                self.result.get("episodes_done", "some")))
        else:
            final = self.result.get("final_test_return")
            self._status("Done: {}{}".format(self.result.get("policy_file") or run.request.output,
                                             "" if final is None else " (final test return {:.3f})".format(final)))
            FreeCAD.Console.PrintMessage("AutoBlock: training done: {}\n".format(self.result.get("policy_file")))
        self.form.defaultButton.setEnabled(bool(self.result.get("policy_file")) and not self.result.get("cancelled"))

    def cancel(self):
        if self.run is not None:
            self.run.cancel()
            self._status("Cancelling (a checkpoint is kept for resuming)...")

    def make_default(self):
        if not self.result or not self.result.get("policy_file"):
            return
        policy_file = self.result["policy_file"]
        FreeCADGui.doCommand("import AutoBlock.preferences")
        FreeCADGui.doCommand("AutoBlock.preferences.set_default_policy({!r})".format(policy_file))
        self._status("New AutoBlock objects now use {}.".format(policy_file))

    # -- task panel protocol ----------------------------------------------------------------------
    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Close)

    def reject(self):
        global _panel
        if self.run is not None:
            self.run.cancel()
            FreeCAD.Console.PrintWarning("AutoBlock: training cancelled because its panel was closed; a checkpoint "
                                         "is kept for resuming\n")
        self.timer.stop()
        FreeCADGui.Control.closeDialog()
        _panel = None
        return True

    def accept(self):
        return self.reject()
