"""What a generated test runs on: the configuration under test on a private ROS 1 master, fed and
watched through a bridge, and the Hypothesis state machine the generated module extends.

A `Session` owns one master (its own port on 127.0.0.1, its own process group, ROS_HOME in a
temporary folder) and one bridge node for a whole test run; every example launches the nodes
under test with Debian's roslaunch (the chosen nodes only, parameters drawn for the example set
first) and stops them afterwards, so no example sees another's state. With `reuse` the nodes stay
up across examples (for nodes declared stateless) and are relaunched only when one died. ROS runs
only under /usr/bin/python3: the launcher and the bridge are scripts in `debian/`.
"""

from __future__ import annotations

import atexit
import contextlib
import dataclasses
import importlib.util
import itertools
import json
import math
import os
import queue
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import xmlrpc.client
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from hypothesis import note, target
from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument
from hypothesis.stateful import RuleBasedStateMachine, initialize, invariant, precondition, rule
from hypothesis.strategies._internal.featureflags import FeatureFlags

from archlog import observe
from archlog.testgen import processes
from archlog.testgen.lines import LineCoverage
from archlog.testgen.settings import Settings
from archlog.testgen.strategies import Strategies, fill_counters, pick, stale

DEBIAN = Path(__file__).resolve().parent / "debian"
_POLL = 0.05
# how long a difference between the live and the recovered interface must last to count: DDS discovers
# a node's endpoints one by one, seconds after the node itself on a loaded machine (a service missing
# for the response bound failed a correct node's test in CI); and a process of the last example killed
# while it shut down stays a participant listing the node without its endpoints until its lease ends
# (Fast DDS: 20 s), the graph's by-node queries answering for it (a correct node's publisher and
# subscriber "only recovered" for 10 s on a machine at load 9)
_DISCOVERY = 25.0
STEP_SETTLE = 0.1  # seconds after a step's messages before the properties are checked
GOAL_SETTLED = ("rejected", "feedback", "done")  # a goal's states in which its server has told how it goes


@contextlib.contextmanager
def bounded_shrinking() -> Iterator[None]:
    """Shrinking fit for examples that each run real processes (a second or more), while a generated
    test runs: bounded by ARCHLOG_TESTGEN_SHRINK_SECONDS (default 60), and starting with the steps.
    Hypothesis's coarse first pass tries to lower every rule choice of the example with up to three
    re-randomised runs each, and its next pass makes every part of the example trivial in turn (a
    needed step's every field too); with a run of the system per attempt that used the whole budget
    before the last steps were reached. The first pass here makes each step trivial (a `drop`), first
    to last, one attempt each (two when the step's shape changes); the usual passes follow."""
    from hypothesis.internal.conjecture import engine, shrinker

    saved = engine.MAX_SHRINKING_SECONDS, shrinker.Shrinker.initial_coarse_reduction
    engine.MAX_SHRINKING_SECONDS = int(os.environ.get("ARCHLOG_TESTGEN_SHRINK_SECONDS", "60"))
    shrinker.Shrinker.initial_coarse_reduction = _trivial_steps  # type: ignore[method-assign]
    try:
        yield
    finally:
        engine.MAX_SHRINKING_SECONDS, shrinker.Shrinker.initial_coarse_reduction = saved  # type: ignore[method-assign]


def _trivial_steps(shrinker: Any) -> None:
    """Hypothesis's "make this span trivial" attempt for each step of the state machine, in order."""
    from hypothesis.stateful import STATE_MACHINE_RUN_LABEL

    class At:  # the chooser the attempt asks which span to try
        def __init__(self, index: int) -> None:
            self.index = index

        def choose(self, values: Any, condition: Any = None) -> int:
            return self.index

    index = 0
    while index < len(shrinker.spans):
        if shrinker.spans[index].label == STATE_MACHINE_RUN_LABEL:
            shrinker.try_trivial_spans(At(index))
        index += 1


class Violation(AssertionError):
    """A property that failed at a known moment (`since`, wall clock) before it was checked: what was
    sent after that moment played no part in the failure."""

    def __init__(self, message: str, since: float) -> None:
        super().__init__(message)
        self.since = since


class StartError(RuntimeError):
    """The configuration could not be started (roscore, roslaunch or the bridge failed); the message
    carries the log tail."""


@dataclass
class Event:
    """A message received on a watched output: its topic, receive time (wall clock) and content."""

    topic: str
    time: float
    msg: Any


@dataclass
class Session:
    """One private master and bridge, and the nodes under test launched on it."""

    model: dict[str, Any]
    tmp: Path = field(default_factory=lambda: Path(tempfile.mkdtemp(prefix="archlog-testgen-")))
    core: subprocess.Popen | None = None
    bridge: subprocess.Popen | None = None
    launcher: subprocess.Popen | None = None
    events: queue.Queue = field(default_factory=queue.Queue)
    launched_params: dict[str, Any] | None = None
    launches: int = 0  # starts asked of the launcher

    def __post_init__(self) -> None:
        self.uri = f"http://127.0.0.1:{processes.free_port()}"
        package_path = ":".join(self.model["paths"])
        self.env = processes.ros_env(self.tmp, self.uri, package_path)
        self.master = observe.master(self.uri)
        scripts = self.model.get("scripts", {})
        measured = bool(scripts) and measuring() and subprocess.run(
            [str(processes.SYSTEM_PYTHON), "-c", "import coverage"], capture_output=True).returncode == 0
        self.lines = LineCoverage(self.tmp / "coverage", scripts) if measured else None

    # -- master and bridge, once per run -------------------------------------------------

    def start(self, timeout: float = 30.0) -> None:
        deadline = time.monotonic() + timeout
        self.core = processes.spawn([str(processes.ROSCORE), "-p", self.uri.rsplit(":", 1)[1]], self.env,
                                    self.tmp / "roscore.log")
        while True:
            try:
                observe.call(self.master.getSystemState)
                break
            except (OSError, xmlrpc.client.Error, RuntimeError):
                if self.core.poll() is not None or time.monotonic() > deadline:
                    raise StartError(f"roscore did not start:\n{processes.tail(self.tmp / 'roscore.log')}") from None
                time.sleep(0.1)
        spec = self.tmp / "bridge.json"
        spec.write_text(json.dumps({"inputs": self.model["inputs"], "outputs": self.model["outputs"],
                                    "services": self.model.get("services", {}), "nodes": self.model["nodes"]}))
        with open(self.tmp / "bridge.log", "ab") as log:
            self.bridge = subprocess.Popen([str(processes.SYSTEM_PYTHON), str(DEBIAN / "bridge.py"), str(spec)],
                                           env=self.env, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=log,
                                           start_new_session=True)
        threading.Thread(target=self._read_bridge, daemon=True).start()

    def _read_bridge(self) -> None:
        assert self.bridge is not None and self.bridge.stdout is not None
        for line in self.bridge.stdout:
            self.events.put(json.loads(line))

    def send(self, command: dict[str, Any]) -> None:
        assert self.bridge is not None and self.bridge.stdin is not None
        if self.bridge.poll() is not None:
            raise StartError(f"the bridge exited:\n{processes.tail(self.tmp / 'bridge.log')}")
        self.bridge.stdin.write((json.dumps(command) + "\n").encode())
        self.bridge.stdin.flush()

    def close(self) -> None:
        atexit.unregister(self.close)
        with contextlib.suppress(OSError, xmlrpc.client.Error):
            self.stop_nodes()
        write_stats(self.launches, self.lines.covered() if self.lines else {})
        processes.stop_together([self.launcher, self.bridge, self.core], 2.0)
        processes.kill_leftovers(f"ROS_HOME={self.tmp}".encode())
        shutil.rmtree(self.tmp, ignore_errors=True)

    # -- the nodes under test, per example ----------------------------------------------------

    def launch(self, params: dict[str, Any], timeout: float = 30.0) -> None:
        """Start the nodes under test with `params` set; wait until they are registered and the bridge
        is connected to them."""
        self.stop_nodes()
        if self.launcher is None or self.launcher.poll() is not None:
            self._start_launcher()
        assert self.launcher is not None and self.launcher.stdin is not None
        self.launches += 1
        (self.tmp / "launch.json.done").unlink(missing_ok=True)
        self.launcher.stdin.write((json.dumps({"params": params}) + "\n").encode())
        self.launcher.stdin.flush()
        self.launched_params = params
        deadline = time.monotonic() + timeout
        while (pids := self.launched()) is None or any(self.down(n) for n in self.model["nodes"]):
            if pids and not all(map(processes.alive, pids)):
                break  # a node died starting: the properties say so
            if self.launcher.poll() is not None or time.monotonic() > deadline:
                raise StartError(f"the nodes under test did not come up:\n{processes.tail(self.log)}")
            time.sleep(_POLL)
        if pids and not all(map(processes.alive, pids)):
            return
        self.send({"op": "wait", "timeout": 5.0})
        deadline = time.monotonic() + 15.0
        events = iter(lambda: self.events.get(timeout=max(deadline - time.monotonic(), 0.1)), None)
        next(event for event in events if event["ev"] == "ready")  # the events before it say nothing here

    def _start_launcher(self) -> None:
        spec = self.tmp / "launch.json"
        measured = {node: [str(self.tmp / "coverage" / "data"), str(Path(script).parent), script]
                    for node, script in self.model.get("scripts", {}).items()} if self.lines else {}
        spec.write_text(json.dumps({"files": self.model["launch"], "args": self.model["args"],
                                    "nodes": self.model["nodes"] if self.model["isolated"] else None,
                                    "coverage": measured}))
        self.launcher = processes.spawn([str(processes.SYSTEM_PYTHON), str(DEBIAN / "launch.py"), str(spec)],
                                        self.env, self.log, stdin=subprocess.PIPE)
        self.launches = 0

    def launched(self) -> list[int] | None:
        """The processes of the last start, once the launcher reported it done."""
        try:
            number, *pids = map(int, (self.tmp / "launch.json.done").read_text().split())
        except (OSError, ValueError):
            return None
        return pids if number == self.launches else None

    @property
    def log(self) -> Path:
        return self.tmp / "launch.log"

    def stop_nodes(self, grace: float = 3.0) -> None:
        """Stop the nodes under test: killed outright, or, when their coverage is measured, SIGINT first
        (coverage.py writes its data as a node ends) and killed after `grace` seconds."""
        uris = [self._node_uri(node) for node in self.model["nodes"]]
        pids = [pid for pid in (self._pid(uri) for uri in uris if uri) if pid]
        for pid in pids:
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.kill(pid, signal.SIGINT if self.lines else signal.SIGKILL)
        end = time.monotonic() + (grace if self.lines else 0.0)
        while any(map(processes.alive, pids)) and time.monotonic() < end:
            time.sleep(_POLL)
        for pid in filter(processes.alive, pids):
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.kill(pid, signal.SIGKILL)

    def new_lines(self) -> int | None:
        """Lines of the Python nodes' files that the nodes stopped since the last call ran first (None: not
        measured)."""
        return self.lines.new_lines() if self.lines else None

    def down(self, node: str) -> str | None:
        """Why the node is not up (None: it is registered on the master and its process answers there)."""
        uri = self._node_uri(node)
        if uri is None:
            return "not registered on the master"
        return None if self._pid(uri) is not None else "registered, but its process does not answer"

    def _node_uri(self, node: str) -> str | None:
        answer: Any = self.master.lookupNode(observe.CALLER_ID, node)
        return answer[2] if answer[0] == 1 else None

    def _pid(self, uri: str) -> int | None:
        try:
            answer: Any = observe.master(uri).getPid(observe.CALLER_ID)
        except (OSError, xmlrpc.client.Error):
            return None
        return answer[2] if answer[0] == 1 else None

    def graph(self) -> observe.Architecture:
        """The live graph of the nodes under test."""
        return observe.read_master(self.master).restricted(set(self.model["nodes"]))


class System(Protocol):
    """What the state machine drives: a `Session` (ROS 1) or a ros2.Ros2Session."""

    model: dict[str, Any]
    events: queue.Queue
    launches: int
    launched_params: dict[str, Any] | None

    @property
    def log(self) -> Path: ...
    def start(self) -> None: ...
    def send(self, command: dict[str, Any]) -> None: ...
    def launch(self, params: dict[str, Any]) -> None: ...
    def stop_nodes(self) -> None: ...
    def new_lines(self) -> int | None: ...
    def down(self, node: str) -> str | None: ...
    def graph(self) -> observe.Architecture: ...
    def close(self) -> None: ...


_SESSIONS: dict[str, System] = {}
_CALLS = itertools.count()  # a number for each service call of this process, to match its response


def shared_session(model: dict[str, Any], create: Callable[[], System]) -> System:
    """The session of this model for the whole run (created and started on first use, closed at exit)."""
    key = json.dumps(model, sort_keys=True)
    if key not in _SESSIONS:
        session = create()
        _SESSIONS[key] = session
        atexit.register(session.close)
        session.start()
    return _SESSIONS[key]


def measuring() -> bool:
    """The line coverage of Python nodes under test is measured: coverage.py is installed here and
    ARCHLOG_TESTGEN_COVERAGE is not 0."""
    return importlib.util.find_spec("coverage") is not None and os.environ.get("ARCHLOG_TESTGEN_COVERAGE") != "0"


COVERAGE: dict[str, tuple[int, int]] = {}  # node under test -> lines run, lines of its file (sessions closed)


def write_stats(launches: int, covered: dict[str, tuple[int, int]] | None = None) -> None:
    """Keep the line coverage of the nodes under test for the report, and for benchmarks write how
    many examples ran (launches of the nodes under test) and the coverage in the file
    ARCHLOG_TESTGEN_STATS names, if set."""
    COVERAGE.update(covered or {})
    if os.environ.get("ARCHLOG_TESTGEN_STATS"):
        Path(os.environ["ARCHLOG_TESTGEN_STATS"]).write_text(json.dumps({"launches": launches,
                                                                           "coverage": covered or {}}))


def report_coverage(config: Any) -> None:
    """Write the line coverage of the Python nodes under test into pytest's terminal report."""
    terminal = config.pluginmanager.get_plugin("terminalreporter")
    capture = config.pluginmanager.get_plugin("capturemanager")
    with capture.global_and_fixture_disabled() if capture is not None else contextlib.nullcontext():
        for node, (run_lines, lines) in sorted(COVERAGE.items()):
            if terminal is not None and lines:
                terminal.write_line(f"\narchlog testgen: {node} ran {run_lines} of {lines} lines "
                                    f"({100 * run_lines / lines:.0f}%) of its file under the generated test")
    COVERAGE.clear()


def close_sessions() -> None:
    """Stop every session of this process (a test module's fixture calls it)."""
    while _SESSIONS:
        _SESSIONS.popitem()[1].close()


class Properties:
    """The user's properties: hooks called with every message received on a watched output
    (`on_<topic>`, the topic's name with non-word characters as `_`), with every response of an open
    service (`on_<service>`, the Event's msg the response), with every answer, feedback and result
    of a goal sent to an open action (`on_<action>`, see _goal_event) and after every step
    (`invariant`). `history` holds every event received so far in the example, `sent` every
    message sent, request made and goal sent; assert in the hooks."""

    def __init__(self) -> None:
        self.history: list[Event] = []
        self.sent: list[dict[str, Any]] = []

    def invariant(self) -> None:
        """Called after every step."""


def load_properties(path: Path) -> type[Properties]:
    """The `Properties` class of the user's file (the built-in empty one if the file is gone)."""
    if not path.is_file():
        return Properties
    spec = importlib.util.spec_from_file_location(path.stem, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.Properties


def hook_name(topic: str) -> str:
    return "on_" + "".join(c if c.isalnum() else "_" for c in topic.strip("/"))


class ArchitectureMachine(RuleBasedStateMachine):
    """The state machine a generated module extends with one `publish_<topic>` rule per open input,
    one `call_<service>` rule per open service and one `send_goal_<action>` rule per open action.

    Steps: publish a drawn message; the temporal mutations (drop one message of a topic's
    sequence, resend the last one, send two in swapped order, a burst, a stale stamp); spin. After
    every step the built-in properties and the user's are checked; the last step is followed by
    `settle` seconds and a final check. A failure is raised at the end of the example (so that what
    Hypothesis draws never depends on the system's timing); the steps after it do nothing. Every
    message actually sent is kept in `actions`, written as a replay file when a property fails."""

    model: dict[str, Any] = {}
    settings: Settings = Settings()
    properties_class: type[Properties] = Properties
    replay_path: Path | None = None

    def __init__(self) -> None:
        super().__init__()
        # Every rule in every example (no swarm testing, which turns some rules off per example): a step
        # of a failing example can then always become a `drop` while shrinking, not only once the rule
        # flags were shrunk open (each attempt being a run of the system).
        self._rules_strategy.enabled_rules_strategy = st.just(FeatureFlags())  # without data: all on
        self.session = shared_session(self.model, self.new_session)
        self.strategies = Strategies(self.model["specs"], self.settings)
        self.properties = self.properties_class()
        self.actions: list[dict[str, Any]] = []
        self.times: list[float] = []  # when each action was taken
        self.counters: dict[str, int] = {}
        self.last: dict[str, dict[str, Any]] = {}
        self.first_sent: dict[str, float] = {}
        self.started = 0.0
        self.failure: str | None = None
        self.periodic: dict[str, float] = {}  # the periodic outputs seen at their period after launch
        self.answered: set[int] = set()  # the calls (their action's index) that got a response
        self.goals: dict[int, tuple[str, str]] = {}  # goal sent -> its action, and sent|accepted|rejected|feedback|done

    def new_session(self) -> System:
        return Session(self.model)

    # -- set-up -------------------------------------------------------------------------

    @initialize(data=st.data())
    def launch(self, data: st.DataObject) -> None:
        params = {name: data.draw(param_strategy(options, self.model["params"].get(name)), label=name)
                  for name, options in sorted(self.settings.params.items())}
        self.start(params)

    def start(self, params: dict[str, Any]) -> None:
        """Launch the nodes under test with `params` and see which periodic outputs show their period."""
        self._act({"op": "params", "params": params})
        run(self.session, params, self.settings.reuse)
        self.started = time.time()
        if self.settings.properties["periodic"]:
            try:
                self.periodic = confirm_periods(self)
            except AssertionError as exc:
                self.failure = str(exc)

    # -- steps --------------------------------------------------------------------------

    def publish(self, topic: str, msg: Any) -> None:
        """Send `msg` on `topic` as the next of the topic's sequence."""
        self._send(topic, fill_counters(msg, self._next(topic)))

    def call(self, service: str, request: Any) -> None:
        """Call `service` with `request` and wait for its response (at most the response bound): a
        response is recorded as an Event of the service; none within the bound, while the nodes under
        test live, fails the example."""
        if self.failure is not None:
            return
        now = time.time()
        number = next(_CALLS)
        self.session.send({"op": "call", "service": service, "request": request, "id": number,
                           "timeout": self.settings.response_bound})
        self._act({"op": "call", "service": service, "request": request}, now)
        self.properties.sent.append({"service": service, "request": request})
        if not self._awaited(lambda: number in self.answered, now + self.settings.response_bound) and self.failure is None:
            self.failure = (f"{service} gave no response within {self.settings.response_bound:.1f} s "
                            f"(after step {len(self.actions)})")

    def send_goal(self, action: str, goal: Any) -> None:
        """Send `goal` to `action`: the server must accept or reject it within the response bound and,
        once accepted, send its result or a first feedback within the bound again (a server that works
        longer on a goal says so by its feedback). A goal sent while an earlier goal of the action is
        still open is not timed (a server may work on its goals one at a time)."""
        if self.failure is not None:
            return
        busy = any(a == action and state not in GOAL_SETTLED for a, state in self.goals.values())
        now = time.time()
        number = next(_CALLS)
        self.goals[number] = (action, "sent")
        self.session.send({"op": "goal", "action": action, "goal": goal, "id": number})
        self._act({"op": "goal", "action": action, "goal": goal}, now)
        self.properties.sent.append({"action": action, "goal": goal})
        bound = self.settings.response_bound
        answered = self._awaited(lambda: self.goals[number][1] != "sent", now + bound)
        settled = answered and self._awaited(lambda: self.goals[number][1] in GOAL_SETTLED, time.time() + bound)
        if not settled and not busy and self.failure is None:
            what = "accepted, but neither a result nor a feedback came" if answered else "neither accepted nor rejected"
            self.failure = f"{action}: a goal was {what} within {bound:.1f} s (after step {len(self.actions)})"

    def _awaited(self, done: Callable[[], bool], end: float) -> bool:
        """Check the properties until `done()` or the wall clock `end`; whether it is done (a node
        that died meanwhile is the failure, not the silence)."""
        while self.failure is None and not done() and time.time() < end:
            time.sleep(_POLL)
            self._check(final=False)
        if self.failure is None and not done():
            self._check(final=False)
        return done()

    @precondition(lambda self: bool(self.model["inputs"]))
    @rule(data=st.data())
    def drop(self, data: st.DataObject) -> None:
        """Lose the next message of a topic: the topic's sequence skips one (what the lost message held
        cannot matter, so it is not drawn)."""
        topic = data.draw(pick(sorted(self.model["inputs"])), label="topic")
        seq = self._next(topic)
        if self.failure is None:
            self._act({"op": "drop", "topic": topic, "seq": seq})

    @precondition(lambda self: bool(self.last))
    @rule(data=st.data())
    def resend(self, data: st.DataObject) -> None:
        """Send the last message of a topic again, unchanged (a duplicate)."""
        topic = data.draw(pick(sorted(self.last)), label="topic")
        self._send(topic, self.last[topic])

    @precondition(lambda self: bool(self.model["inputs"]))
    @rule(data=st.data())
    def reorder(self, data: st.DataObject) -> None:
        """Draw the next two messages of a topic and send them in swapped order."""
        topic = data.draw(pick(sorted(self.model["inputs"])), label="topic")
        strategy = self.strategies.message(self.model["inputs"][topic])
        first, second = (fill_counters(data.draw(strategy, label=n), self._next(topic)) for n in ("first", "second"))
        self._send(topic, second, settle=False)
        self._send(topic, first)

    @precondition(lambda self: bool(self.model["inputs"]))
    @rule(data=st.data(), count=st.integers(2, 3))
    def burst(self, data: st.DataObject, count: int) -> None:
        """Send `count` messages of a topic back to back."""
        topic = data.draw(pick(sorted(self.model["inputs"])), label="topic")
        msg = data.draw(self.strategies.message(self.model["inputs"][topic]), label="msg")
        for n in range(count):
            self._send(topic, fill_counters(msg, self._next(topic)), settle=n == count - 1)

    @precondition(lambda self: bool(self.model["inputs"]))
    @rule(data=st.data(), age=st.floats(1.0, 3600.0))
    def send_stale(self, data: st.DataObject, age: float) -> None:
        """Send the next message of a topic with its Header stamps `age` seconds in the past."""
        topic = data.draw(pick(sorted(self.model["inputs"])), label="topic")
        msg = data.draw(self.strategies.message(self.model["inputs"][topic]), label="msg")
        self._send(topic, stale(fill_counters(msg, self._next(topic)), age))

    @rule(seconds=st.floats(0.05, 1.0))
    def spin(self, seconds: float) -> None:
        """Let the system run (a delay between messages)."""
        if self.failure is None:
            self._act({"op": "spin", "seconds": seconds})
            time.sleep(seconds)

    @invariant()
    def properties_hold(self) -> None:
        """Check after every step; a failure is kept and raised at the end of the example, so that the
        steps drawn do not depend on when the system's reaction arrives."""
        if self.started and self.failure is None:
            self._check(final=False)

    def teardown(self) -> None:
        try:
            if self.started and self.failure is None:  # long enough for a periodic output's silence to show
                time.sleep(max([self.settings.settle, *(_allowed(self, p) for p in self.periodic.values())]))
                self._check(final=True)
            if self.failure is not None and sys.exc_info()[0] is None:  # not while a step's exception unwinds
                self._report(self.failure)
                raise AssertionError(self.failure)
        finally:
            if not self.settings.reuse:
                self.session.stop_nodes()
                new = self.session.new_lines()
                if new is not None and self.failure is None and sys.exc_info()[0] is None:
                    with contextlib.suppress(InvalidArgument):  # outside a Hypothesis test: a replay
                        target(float(new), label="lines of the nodes run for the first time")

    # -- sending and checking -------------------------------------------------------------

    def _next(self, topic: str) -> int:
        self.counters[topic] = self.counters.get(topic, 0) + 1
        return self.counters[topic]

    def _send(self, topic: str, msg: Any, settle: bool = True) -> None:
        self.last[topic] = msg  # even after a failure: what may be drawn next must not depend on timing
        if self.failure is not None:  # the example has failed: the steps left are drawn but do nothing
            return
        now = time.time()  # before sending: the answer may come back at once
        self.first_sent.setdefault(topic, now)
        self.session.send({"op": "publish", "topic": topic, "msg": msg})
        self._act({"op": "publish", "topic": topic, "msg": msg}, now)
        self.properties.sent.append({"topic": topic, "msg": msg})
        if settle:
            time.sleep(STEP_SETTLE)

    def _act(self, action: dict[str, Any], at: float | None = None) -> None:
        self.actions.append(action)
        self.times.append(time.time() if at is None else at)

    def _check(self, final: bool) -> None:
        try:
            check_properties(self, final)
        except Violation as exc:  # the actions after the moment it failed are not part of the failure
            kept = sum(t <= exc.since for t in self.times)
            self.failure = f"{exc} (by step {kept}, seen after step {len(self.actions)})"
            del self.actions[max(kept, 1):], self.times[max(kept, 1):]
        except AssertionError as exc:
            self.failure = f"{exc} (after step {len(self.actions)})"

    def _report(self, reason: str) -> None:
        lines = [f"property failed: {reason}", "messages sent (after mutation):"]
        lines += [f"  {json.dumps(a)}" for a in self.actions]
        lines.append(f"nodes' output (tail of {self.session.log}):\n{processes.tail(self.session.log, 15)}")
        try:
            note("\n".join(lines))
        except InvalidArgument:  # outside a Hypothesis test: a replay
            print("\n".join(lines))
        if self.replay_path is not None:
            self.replay_path.parent.mkdir(parents=True, exist_ok=True)
            self.replay_path.write_text(json.dumps({"model": self.model, "settings": self.settings.to_dict(),
                                                    "actions": self.actions, "reason": reason}, indent=1) + "\n")


def run(session: System, params: dict[str, Any], reuse: bool) -> None:
    """Launch the nodes under test (in `reuse` mode only if they are down or their parameters changed)."""
    up = reuse and session.launches > 0 and session.launched_params == params \
        and not any(session.down(n) for n in session.model["nodes"])
    if not up:
        session.launch(params)
    _drain(session)


def _drain(session: System) -> list[dict[str, Any]]:
    drained = []
    while True:
        try:
            drained.append(session.events.get_nowait())
        except queue.Empty:
            return drained


def param_strategy(options: dict[str, Any], default: str | None) -> st.SearchStrategy:
    """Values for a parameter: the listed ones, or a number between min and max typed like its default."""
    if "values" in options:
        return pick(options["values"])
    integer = default is not None and default.lstrip("-").isdigit()
    low, high = options.get("min"), options.get("max")
    return st.integers(low, high) if integer else st.floats(low, high, allow_nan=False)


def check_properties(machine: ArchitectureMachine, final: bool) -> None:
    """The built-in properties switched on in the settings, then the user's; AssertionError names the
    first that fails."""
    session, model, settings = machine.session, machine.model, machine.settings
    _record(machine)
    if settings.properties["alive"]:
        dead = [f"{n} ({why})" for n in model["nodes"] if (why := session.down(n))]
        assert not dead, f"node(s) died: {', '.join(dead)}"
    now = time.time()
    for topic, period in machine.periodic.items():
        _check_period(machine, topic, period, now)
    if settings.properties["requires"] and final:  # liveness: only where the behavior model decides it
        for topic, period in model.get("follows", {}).items():
            inputs = model["requires"][topic]
            sent = [machine.first_sent[i] for i in inputs if i in machine.first_sent]
            if len(sent) < len(inputs):
                continue
            bound = settings.response_bound + period
            after = [e for e in machine.properties.history if e.topic == topic and e.time >= max(sent)]
            if now - max(sent) >= bound and not after:
                raise Violation(f"{topic} requires {', '.join(inputs)}, which was published, but nothing came "
                                f"on {topic} within {bound:.1f} s", max(sent) + bound)
    if settings.properties["interface"] and final:
        differences = _interface_differences(session, observe.Architecture.from_json(model["interface"]),
                                             max(settings.response_bound, _DISCOVERY))
        assert not differences, "the live interface differs from the recovered one: " + "; ".join(
            f"{kind}: only recovered {row['only_recovered']}, only observed {row['only_observed']}"
            for kind, row in differences.items())
    machine.properties.invariant()


def _interface_differences(session: System, want: observe.Architecture, bound: float) -> dict[str, dict]:
    """The differences between the recovered interface and the live graph that last `bound` seconds: a
    DDS graph is eventually consistent (a restarted node's endpoints are discovered one by one). Only
    the nodes the graph shows are compared (that every node under test runs is `alive`'s)."""
    end = time.monotonic() + bound
    while True:
        seen = session.graph()
        differences = {kind: row for kind, row in observe.compare(_typed_as_seen(want.restricted(seen.nodes), seen),
                                                                   seen).items()
                       if row["only_recovered"] or row["only_observed"]}
        if not differences or time.monotonic() >= end:
            return differences
        time.sleep(_POLL * 2)


def _typed_as_seen(want: observe.Architecture, seen: observe.Architecture) -> observe.Architecture:
    """The recovered interface with each port of unknown type ("") given the type seen live on the
    same node and topic (the code chose its type at run time): an unknown type is not a difference."""
    def typed(ports: frozenset[tuple[str, str, str]], live: frozenset[tuple[str, str, str]]) -> frozenset:
        types = {(node, topic): type_ for node, topic, type_ in live}
        return frozenset((node, topic, type_ or types.get((node, topic), "")) for node, topic, type_ in ports)

    return dataclasses.replace(want, publishers=typed(want.publishers, seen.publishers),
                               subscribers=typed(want.subscribers, seen.subscribers))


def _record(machine: ArchitectureMachine) -> None:
    """Add the messages received since the last call to the history, checking each as it comes."""
    for event in _drain(machine.session):
        if event["ev"] == "error":
            raise AssertionError(f"the bridge could not publish on {event['topic']}: {event['error']}")
        if event["ev"] == "log" and event["t"] >= machine.started:
            check_log(machine.settings, event)
        if event["ev"] == "response":
            machine.answered.add(event["id"])
            if "error" in event:  # the call failed in the test's client (a request the class refuses)
                raise AssertionError(f"the call of {event['service']} failed: {event['error']}")
            event = {**event, "topic": event["service"], "msg": event["response"]}
        elif event["ev"] in ("goal", "feedback", "result"):
            if event["id"] not in machine.goals:  # a goal of an earlier example
                continue
            event = _goal_event(machine, event)
        elif event["ev"] != "msg" or event["t"] < machine.started:
            continue
        received = Event(event["topic"], event["t"], event["msg"])
        machine.properties.history.append(received)
        _check_requires(machine, received)
        hook: Callable[[Event], None] | None = getattr(machine.properties, hook_name(received.topic), None)
        if hook is not None:
            try:
                hook(received)
            except Violation:
                raise
            except AssertionError as exc:  # about a message received at a known moment
                raise Violation(str(exc), received.time) from exc


def _goal_event(machine: ArchitectureMachine, event: dict[str, Any]) -> dict[str, Any]:
    """A goal's answer, feedback or result as an event of its action (its msg says which, with the
    goal's number); the goal's state follows it."""
    action, number = event["action"], event["id"]
    if "error" in event:  # the goal was not sent (a value the goal class refuses)
        raise AssertionError(f"sending a goal to {action} failed: {event['error']}")
    if event["ev"] == "goal":
        state, msg = ("accepted" if event["accepted"] else "rejected"), {"goal": number, "accepted": event["accepted"]}
    elif event["ev"] == "feedback":
        state, msg = "feedback", {"goal": number, "feedback": event["msg"]}
    else:
        state, msg = "done", {"goal": number, "status": event["status"], "result": event["msg"]}
    if machine.goals[number][1] != "done":
        machine.goals[number] = (action, state)
    return {**event, "topic": action, "msg": msg}


def check_log(settings: Settings, event: dict[str, Any]) -> None:
    """An ERROR a node under test logged with a Python traceback fails the `callbacks` property:
    rospy caught an exception raised in one of the node's callbacks ("bad callback") or service
    handlers, logged it to /rosout, and the node lives on (no other property would see it)."""
    text = event["text"]
    if settings.properties["callbacks"] and "Traceback (most recent call last)" in text:
        # a service handler's traceback is logged as the repr of its list of lines
        lines = [line.strip(" '\"[],") for line in text.replace("\\n", "\n").splitlines()]
        last = next(line for line in reversed(lines) if line)
        raise Violation(f"{event['node']} raised in a callback: {last}", event["t"])


def _check_requires(machine: ArchitectureMachine, event: Event) -> None:
    """An output that requires an input must be silent until the input was published."""
    if not machine.settings.properties["requires"] or event.topic in machine.model.get("services", {}):
        return
    for required in machine.model["requires"].get(event.topic, []):
        sent = machine.first_sent.get(required)
        assert sent is not None and sent <= event.time, \
            f"{event.topic} was published before its required input {required} ever was"


def confirm_periods(machine: ArchitectureMachine) -> dict[str, float]:
    """The recovered periodic outputs that show their period before any input is sent (three messages
    in a row, each within the period and its tolerance); only these are checked, so that a publication
    the extraction thought unconditional (a guard it missed) cannot fail falsely. Waits at most three
    periods and 0.3 s."""
    wanted = machine.model["periodic"]
    if not wanted:
        return {}
    end = time.time() + 3 * max(wanted.values()) + 0.3
    confirmed: dict[str, float] = {}
    while time.time() < end and len(confirmed) < len(wanted):
        time.sleep(_POLL)
        _record(machine)
        for topic, period in wanted.items():
            times = [e.time for e in machine.properties.history if e.topic == topic]
            if len(times) >= 3 and max(b - a for a, b in zip(times[-3:], times[-2:])) <= _allowed(machine, period):
                confirmed[topic] = period
    return confirmed


def _allowed(machine: ArchitectureMachine, period: float) -> float:
    """The longest silence allowed on an output of this period: the tolerance, and a quarter second
    for scheduling on a loaded machine."""
    return period * (1 + machine.settings.period_tolerance) + 0.25


def _check_period(machine: ArchitectureMachine, topic: str, period: float, now: float) -> None:
    """A confirmed periodic output is never silent for longer than its period and tolerance."""
    times = [e.time for e in machine.properties.history if e.topic == topic] + [now]
    allowed = _allowed(machine, period)
    for before, after in zip(times, times[1:]):
        if after - before > allowed and not math.isclose(after - before, allowed):
            raise Violation(f"{topic} is recovered as published every {period} s, was, then was silent for "
                            f"{after - before:.2f} s", before + allowed)
