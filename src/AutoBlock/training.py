"""Training a policy: the request, the progress protocol, and the backend that runs it.

The Train panel (taskpanels/train.py) and AutoBlock.train() work against this small protocol; the core's
training binding satisfies it once it lands. Until then training_backend() returns None and both say
plainly that this build cannot train.

The protocol
------------
A backend is a callable taking a TrainingRequest and returning a TrainingRun:

    run = backend(request)
    run.start()                 # returns at once; training goes on in the background
    run.poll()                  # -> list of Progress events since the last poll (never blocks)
    run.cancel()                # asks it to stop; a checkpoint stays behind for resuming
    run.done                    # True once finished, cancelled or failed
    run.result                  # dict once finished: {"policy_file", "checkpoint", "cancelled", ...}
    run.error                   # message when it failed, else None

NativeTrainingRun implements it over the native module's training call, which the learning issue adds:

    autoblock_native.train(options: dict, progress: Callable[[dict], bool]) -> dict

options is TrainingRequest.to_options(); progress is called (with the GIL) after every episode with
{"episode", "episodes", "train_return"[, "test_return"][, "message"]} and returns False to cancel;
the result is {"policy_file", "checkpoint", "cancelled"}. It releases the GIL while it works, so
FreeCAD stays responsive. The capability flag autoblock_native.capabilities()["training"] says it exists.
"""

import os
import queue
import threading

from . import native


class TrainingRequest:
    """What to train. Data: a folder of .brep/.step faces, or generator settings (count, min/max rectangles,
    holes, seed) for training and for testing. episodes, seed, reward (preset), output (the policy file),
    resume (continue from the output's checkpoint), threads (0: all cores)."""

    def __init__(self, output, train_folder=None, train_generate=None, test_folder=None, test_generate=None,
                 episodes=10000, seed=0, reward="paper", resume=False, threads=0):
        self.output = output
        self.train_folder = train_folder
        self.train_generate = train_generate
        self.test_folder = test_folder
        self.test_generate = test_generate
        self.episodes = int(episodes)
        self.seed = int(seed)
        self.reward = reward
        self.resume = bool(resume)
        self.threads = int(threads)

    @property
    def checkpoint(self):
        """Where a run keeps its checkpoint: next to the policy file."""
        return self.output + ".checkpoint"

    def validate(self):
        """Raises ValueError saying what is wrong with the request."""
        problems = []
        if not self.output:
            problems.append("no output file")
        elif os.path.dirname(os.path.abspath(self.output)) and not os.path.isdir(
                os.path.dirname(os.path.abspath(self.output))):
            problems.append("the output folder {} does not exist".format(os.path.dirname(self.output)))
        for name, folder, generate in (("training", self.train_folder, self.train_generate),
                                       ("test", self.test_folder, self.test_generate)):
            if folder and generate:
                problems.append("{} data: give a folder or generator settings, not both".format(name))
            elif folder:
                if not os.path.isdir(folder):
                    problems.append("{} data: no such folder {}".format(name, folder))
            elif generate:
                if int(generate.get("count", 0)) < 1:
                    problems.append("{} data: generate at least one shape".format(name))
                if int(generate.get("min_rects", 2)) > int(generate.get("max_rects", 10)):
                    problems.append("{} data: minimum rectangles above the maximum".format(name))
            elif name == "training":
                problems.append("no training data: choose a folder or generate shapes")
        if self.episodes < 1:
            problems.append("episodes must be at least 1")
        if self.resume and not os.path.exists(self.checkpoint):
            problems.append("nothing to resume: {} does not exist".format(self.checkpoint))
        if problems:
            raise ValueError("; ".join(problems))

    def to_options(self):
        """The request as plain data for the native call."""
        return {
            "output": self.output, "checkpoint": self.checkpoint, "resume": self.resume,
            "train_folder": self.train_folder or "", "train_generate": dict(self.train_generate or {}),
            "test_folder": self.test_folder or "", "test_generate": dict(self.test_generate or {}),
            "episodes": self.episodes, "seed": self.seed, "reward": self.reward, "threads": self.threads,
        }


class Progress:
    """One progress event: episode of episodes, train_return and test_return (None when not measured),
    message."""

    __slots__ = ("episode", "episodes", "train_return", "test_return", "message")

    def __init__(self, episode, episodes, train_return=None, test_return=None, message=""):
        self.episode = episode
        self.episodes = episodes
        self.train_return = train_return
        self.test_return = test_return
        self.message = message

    @classmethod
    def from_dict(cls, data):
        return cls(int(data.get("episode", 0)), int(data.get("episodes", 0)), data.get("train_return"),
                   data.get("test_return"), str(data.get("message", "")))


class TrainingRun:
    """Base of training runs: a background thread calling work(report, cancelled) and queueing progress."""

    def __init__(self, request):
        self.request = request
        self.done = False
        self.result = None
        self.error = None
        self._events = queue.Queue()
        self._cancel = threading.Event()
        self._thread = None

    def start(self):
        self._thread = threading.Thread(target=self._run, name="AutoBlock training", daemon=True)
        self._thread.start()

    def _run(self):
        try:
            self.result = self.work(self._report, self._cancel.is_set)
        except Exception as error:  # reported through .error, never raised into FreeCAD
            self.error = "{}: {}".format(type(error).__name__, error)
        finally:
            self.done = True

    def _report(self, data):
        self._events.put(Progress.from_dict(data))
        return not self._cancel.is_set()

    def work(self, report, cancelled):
        """Train; call report(dict) after each episode (it returns False once cancelled). Returns the result."""
        raise NotImplementedError

    def poll(self):
        events = []
        while True:
            try:
                events.append(self._events.get_nowait())
            except queue.Empty:
                return events

    def cancel(self):
        self._cancel.set()

    def wait(self, timeout=None):
        if self._thread is not None:
            self._thread.join(timeout)


class NativeTrainingRun(TrainingRun):
    """A run of the native module's train() (see the module docstring)."""

    def work(self, report, cancelled):
        return dict(native.load().train(self.request.to_options(), report))


def training_backend():
    """The callable making TrainingRuns, or None when this build cannot train."""
    try:
        if native.has("training"):
            return NativeTrainingRun
    except native.NativeModuleMissing:
        return None
    return None


NOT_AVAILABLE = ("Training is not in this build of AutoBlock: the core has no learned policy yet, so there is "
                 "nothing to train (AutoBlock.capabilities()['training'] is False).")


def train(request, progress=None):
    """Train (blocking) and return the result dict. progress(Progress) is called for every event.
    Raises NotImplementedError when this build cannot train, ValueError for a bad request, RuntimeError
    when training fails."""
    backend = training_backend()
    if backend is None:
        raise NotImplementedError(NOT_AVAILABLE)
    request.validate()
    run = backend(request)
    run.start()
    while True:
        done = run.done  # read before draining: a finished run has queued all its events
        run.wait(0.2)
        for event in run.poll():
            if progress:
                progress(event)
        if done:
            break
    if run.error:
        raise RuntimeError(run.error)
    return run.result
