"""Training a policy: the request, the progress protocol, and the backend that runs it.

The Train panel (taskpanels/train.py) and AutoBlock.train() work against this small protocol; the core's
trainer (core/api/training_job.h, through the native module) satisfies it.

The protocol
------------
A backend is a callable taking a TrainingRequest and returning a TrainingRun:

    run = backend(request)
    run.start()                 # returns at once; training goes on in a background thread
    run.poll()                  # -> list of Progress events since the last poll (never blocks)
    run.cancel()                # asks it to stop after the current episode; a checkpoint stays for resuming
    run.done                    # True once finished, cancelled or failed
    run.result                  # dict once finished: {"policy_file", "checkpoint", "cancelled", ...}
    run.error                   # message when it failed, else None

NativeTrainingRun implements it over the native module's training call:

    autoblock_native.train(options: dict, progress: Callable[[dict], bool]) -> dict

options is TrainingRequest.to_options(). The call releases the GIL while the core trains, so FreeCAD stays
responsive; after every episode it takes the GIL and calls progress with {"episode", "episodes", "return",
"blocks", "steps", "complete", "shape", "seconds", "test_return" (None when not evaluated), "earlier" (an
episode of a resumed run's history)}, and before the first episode with {"status", "episodes"} (what the
run computes first: the test faces' reference returns); progress returns False to stop. The result is {"policy_file" (None
when cancelled), "checkpoint", "log", "curves", "cancelled", "episodes_done", "episodes", "reward",
"final_test_return"}. The Progress events add the training return averaged over the last 10 episodes, as
the paper's curves show it.
"""

import atexit
import collections
import os
import queue
import threading

from . import native


class TrainingRequest:
    """What to train. Data: a folder of .brep/.step faces (rectilinear ones, and for the lookahead agent
    faces with edges at other angles or arcs too), or generator settings (dict: count, min_rects, max_rects,
    holes, seed; general and arcs, counts of general polygons and unions and of faces with arcs, for the
    lookahead agent) for training and for testing. episodes (the total, counting those before a
    resume), seed, reward (preset: "paper" or "mesh"), output (the policy file; its checkpoint, CSV log and
    curves go next to it), resume (continue from the output's checkpoint), threads (0: all cores),
    eval_every (episodes between test evaluations and checkpoints), agent ("lookahead" or "paper"), init (a
    fresh run starting from this policy's weights: a shipped name such as "sac-mesh" or a policy file)."""

    def __init__(self, output, train_folder=None, train_generate=None, test_folder=None, test_generate=None,
                 episodes=1500, seed=0, reward="paper", resume=False, threads=0, eval_every=25, agent="lookahead",
                 init=None):
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
        self.eval_every = int(eval_every)
        self.agent = agent
        self.init = init or None

    def __repr__(self):
        fields = ["{!r}".format(self.output)]
        for name in ("train_folder", "train_generate", "test_folder", "test_generate"):
            if getattr(self, name):
                fields.append("{}={!r}".format(name, getattr(self, name)))
        fields += ["episodes={}".format(self.episodes), "seed={}".format(self.seed), "reward={!r}".format(self.reward)]
        if self.resume:
            fields.append("resume=True")
        if self.threads:
            fields.append("threads={}".format(self.threads))
        if self.eval_every != 25:
            fields.append("eval_every={}".format(self.eval_every))
        if self.agent != "lookahead":
            fields.append("agent={!r}".format(self.agent))
        if self.init:
            fields.append("init={!r}".format(self.init))
        return "AutoBlock.TrainingRequest({})".format(", ".join(fields))

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
                counts = [int(generate.get(key, 0)) for key in ("count", "general", "arcs")]
                if min(counts) < 0 or sum(counts) < 1:
                    problems.append("{} data: generate at least one shape".format(name))
                if int(generate.get("min_rects", 2)) > int(generate.get("max_rects", 10)):
                    problems.append("{} data: minimum rectangles above the maximum".format(name))
            else:
                problems.append("no {} data: choose a folder or generate shapes".format(name))
        if self.episodes < 1:
            problems.append("episodes must be at least 1")
        if self.eval_every < 1:
            problems.append("evaluate at least every episode (eval_every >= 1)")
        if self.reward not in ("paper", "mesh") and not self.resume:
            problems.append("unknown reward preset {!r} (expected paper or mesh)".format(self.reward))
        if self.resume and not os.path.exists(self.checkpoint):
            problems.append("nothing to resume: {} does not exist".format(self.checkpoint))
        if self.resume and self.init:
            problems.append("an initial policy starts a fresh run: a resumed run keeps its checkpoint's networks")
        if problems:
            raise ValueError("; ".join(problems))

    def to_options(self):
        """The request as plain data for the native call."""
        return {
            "output": self.output, "checkpoint": self.checkpoint, "resume": self.resume,
            "train_folder": self.train_folder or "", "train_generate": dict(self.train_generate or {}),
            "test_folder": self.test_folder or "", "test_generate": dict(self.test_generate or {}),
            "episodes": self.episodes, "seed": self.seed, "reward": self.reward,
            "threads": self.threads or (os.cpu_count() or 1), "eval_every": self.eval_every, "agent": self.agent,
            "init": self.init or "",
        }


class Progress:
    """One progress event: episode of episodes; episode_return (that episode's return); train_return (the
    training return averaged over the last 10 episodes); test_return (the mean deterministic return on the test
    set, None when not evaluated at this episode); earlier (an episode of a resumed run's history); message;
    status (not empty for an event before the first episode saying what the run computes, episode 0)."""

    __slots__ = ("episode", "episodes", "episode_return", "train_return", "test_return", "earlier", "message",
                 "status")

    def __init__(self, episode, episodes, train_return=None, test_return=None, message="", episode_return=None,
                 earlier=False, status=""):
        self.episode = episode
        self.episodes = episodes
        self.episode_return = episode_return
        self.train_return = train_return
        self.test_return = test_return
        self.earlier = earlier
        self.message = message
        self.status = status

    @classmethod
    def from_dict(cls, data, average=None):
        return cls(int(data.get("episode", 0)), int(data.get("episodes", 0)),
                   data.get("train_return", average), data.get("test_return"), str(data.get("message", "")),
                   data.get("return"), bool(data.get("earlier", False)), str(data.get("status", "")))

    def __repr__(self):
        if self.status:
            return "<Progress: {}>".format(self.status)
        text = "episode {} of {}".format(self.episode, self.episodes)
        if self.train_return is not None:
            text += ", training return {:.3f} (10-episode average)".format(self.train_return)
        if self.test_return is not None:
            text += ", test return {:.3f}".format(self.test_return)
        return "<Progress: {}>".format(text)


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
        self._recent = collections.deque(maxlen=10)

    def start(self):
        self._thread = threading.Thread(target=self._run, name="AutoBlock training", daemon=True)
        _running.add(self)
        self._thread.start()

    def _run(self):
        try:
            self.result = self.work(self._report, self._cancel.is_set)
        except Exception as error:  # reported through .error, never raised into FreeCAD
            self.error = "{}: {}".format(type(error).__name__, error)
        finally:
            self.done = True
            _running.discard(self)

    def _report(self, data):
        average = None
        if data.get("return") is not None:
            self._recent.append(float(data["return"]))
            average = sum(self._recent) / len(self._recent)
        self._events.put(Progress.from_dict(data, average))
        return not self._cancel.is_set()

    def run_here(self, progress=None):
        """Train in the calling thread (blocking), calling progress(Progress) as each event comes; progress
        returning False cancels the run at once (after the current episode)."""
        def report(data):
            self._report(data)
            for event in self.poll():
                if progress is not None and progress(event) is False:
                    self.cancel()
            return not self._cancel.is_set()

        _running.add(self)
        try:
            self.result = self.work(report, self._cancel.is_set)
        except Exception as error:
            self.error = "{}: {}".format(type(error).__name__, error)
        finally:
            self.done = True
            _running.discard(self)

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


# Runs under way: cancelled when FreeCAD quits, so that no training thread outlives the interpreter.
_running = set()


@atexit.register
def _cancel_running_runs():
    for run in list(_running):
        run.cancel()
    for run in list(_running):
        run.wait(30)


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


_last_started = None


def start(request, backend=None):
    """Start training in the background and return the TrainingRun (poll it, cancel it; see the protocol
    above). backend: None for the core's. Raises NotImplementedError when this build cannot train, ValueError
    for a bad request."""
    global _last_started
    backend = backend or training_backend()
    if backend is None:
        raise NotImplementedError(NOT_AVAILABLE)
    request.validate()
    run = backend(request)
    run.start()
    _last_started = run
    return run


def last_started():
    """The TrainingRun start() made last (the Train panel picks up the run its echoed console call started)."""
    return _last_started


def train(request, progress=None, backend=None):
    """Train (blocking) and return the result dict. progress(Progress) is called for every event; returning
    False cancels the run (it stops after the current episode, leaving its checkpoint for request.resume).
    Raises NotImplementedError when this build cannot train, ValueError for a bad request (or bad data, as the
    core finds it), RuntimeError when training fails."""
    backend = backend or training_backend()
    if backend is None:
        raise NotImplementedError(NOT_AVAILABLE)
    request.validate()
    run = backend(request)
    run.run_here(progress)
    if run.error:
        if run.error.startswith("ValueError: "):
            raise ValueError(run.error[len("ValueError: "):])
        raise RuntimeError(run.error)
    return run.result
