"""The ROS 2 side of a generated test: the nodes under test started as processes (a Python node's
entry point or script, else `ros2 run`; name, namespace, remaps and typed parameters as recovered) on
a private DDS domain, fed, called and watched by an rclpy node inside the test process (its clients
call the open services and send goals to the open actions), with the message classes the generated
module imports. `Ros2Session` has the interface of runtime.Session, so the state machine, its steps
and its properties are the same for ROS 1 and ROS 2.

archlog never imports rclpy: the generated module does (it is skipped where ROS 2 is missing) and
hands it to the machine with the message classes.
"""

from __future__ import annotations

import atexit
import contextlib
import importlib
import importlib.util
import json
import os
import pty
import queue
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import IO, Any

from archlog import observe
from archlog.testgen import processes
from archlog.testgen.lines import LineCoverage
from archlog.testgen.runtime import ArchitectureMachine, measuring, write_stats

_POLL = 0.05
MAX_DOMAIN = 232
LIFECYCLE = "lifecycle_msgs/srv/ChangeState"  # the service a lifecycle node is configured and activated by
TRANSITIONS = (1, 3)  # configure, activate (lifecycle_msgs/msg/Transition)
DDS_LEASE = 20.0  # seconds a participant that vanished without a goodbye stays discovered (Fast DDS's default)
ACTION_PART = "/_action/"  # an action's topics and services are named ACTION + this + their role


def message_class(type_: str) -> type:
    """The rosidl class of `pkg/msg/Name` (or `pkg/Name`, as get_fields_and_field_types names nested types)."""
    package, _, name = type_.replace("/msg/", "/").partition("/")
    return getattr(importlib.import_module(f"{package}.msg"), name)


def to_message(value: dict[str, Any], cls: type, now: float) -> Any:
    """An instance of the rosidl class `cls` from a drawn message (a dict); a {"now": offset} time
    is `now` + offset seconds."""
    msg = cls()
    for name, kind in cls.get_fields_and_field_types().items():  # type: ignore[attr-defined]
        if name in value:
            setattr(msg, name, _field(value[name], kind, now))
    return msg


def _field(value: Any, kind: str, now: float) -> Any:
    """A field's value for its rosidl type string ('double', 'sequence<int32, 5>', 'double[9]',
    'octet', 'geometry_msgs/Vector3', 'string<10>', ...)."""
    if kind.startswith("sequence<"):
        element = kind[len("sequence<"):-1].split(",")[0].strip()
        return [_field(v, element, now) for v in value]
    if kind.endswith("]"):
        return [_field(v, kind[:kind.index("[")], now) for v in value]
    if kind == "octet":
        return bytes([value & 0xFF])
    if isinstance(value, dict):
        if set(value) == {"now"}:
            stamp = max(now + value["now"], 0.0)
            value = {"sec": int(stamp), "nanosec": int((stamp - int(stamp)) * 1e9)}
        return to_message(value, message_class(kind), now)
    return value


def to_json(value: Any) -> Any:
    """A received message as plain data (arrays as lists, bytes as ints)."""
    if hasattr(value, "get_fields_and_field_types"):
        return {name: to_json(getattr(value, name)) for name in value.get_fields_and_field_types()}
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    if hasattr(value, "tolist"):  # array.array and numpy arrays
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [to_json(v) for v in value]
    return value


def run_command(node: dict[str, Any], params: dict[str, Any], coverage: Path | None = None) -> list[str] | None:
    """How to start a node under test without ros2cli: its console_scripts entry point or script under
    this Python (measured by coverage.py into the folder `coverage`, if given), else `ros2 run` where
    ros2 is installed (None: neither); then its name, namespace, remaps, and parameters with their
    types (the configuration's, then the drawn ones, given as /node/name and set as the node's own)."""
    measure = "" if coverage is None else (
        f"import atexit, coverage; c = coverage.Coverage(data_file={str(coverage / 'data')!r}, data_suffix=True, "
        f"source=[{str(Path(node_file(node)).parent)!r}]); c.start(); atexit.register(lambda: (c.stop(), c.save())); ")
    if node.get("entry"):
        module, _, function = node["entry"].partition(":")
        command = [sys.executable, "-c", f"{measure}import sys; from {module} import {function} as main; sys.exit(main())"]
    elif node.get("script") and measure:
        command = [sys.executable, "-c", f"{measure}import runpy, sys; sys.argv[0] = {node['script']!r}; "
                   f"runpy.run_path({node['script']!r}, run_name='__main__')"]
    elif node.get("script"):
        command = [sys.executable, node["script"]]
    elif shutil.which("ros2"):
        command = ["ros2", "run", node["pkg"], node["exe"]]
    else:
        return None
    namespace, _, base = node["name"].rpartition("/")
    nodes = node.get("nodes", [node["name"]])
    command += ["--ros-args"]
    if len(nodes) == 1:  # `__node` would name every node of a process holding several
        command += ["-r", f"__node:={base}"]
    command += ["-r", f"__ns:={namespace or '/'}"]
    for source, target in node["remaps"]:
        command += ["-r", f"{source}:={target}"]
    for name, value in {**node["params"], **params}.items():
        owner = next((n for n in nodes if name.startswith(n + "/")), None)
        if owner is not None:
            command += ["-p", f"{name[len(owner) + 1:].replace('/', '.')}:={_typed(value)}"]
    return command


def exit_status(code: int) -> str:
    """How a process ended, from its return code (negative: the signal that ended it)."""
    if code < 0:
        with contextlib.suppress(ValueError):
            return f"was ended by {signal.Signals(-code).name}"
    return f"exited with code {code}"


def node_file(node: dict[str, Any]) -> str:
    """The Python file of a node under test: its script, or its entry point's module."""
    if node.get("script"):
        return str(node["script"])
    module = Path(node["root"], *node["entry"].partition(":")[0].split("."))
    return str(module / "__init__.py" if module.is_dir() else module.with_suffix(".py"))


def _typed(value: Any) -> str:
    """A parameter value for `-p`, which reads it as YAML: a number or boolean as itself; a text as
    written, so that the node reads it typed as launch_ros would (`false` a boolean, `0.8` a double)."""
    return value if isinstance(value, str) and value.strip() else json.dumps(value)


def unstartable(model: dict[str, Any]) -> str | None:
    """Why a node under test cannot be started here (no Python source and no ros2 executable), or None."""
    missing = [node["name"] for node in model["commands"] if run_command(node, {}) is None]
    return f"cannot start {', '.join(missing)}: not a Python node of the workspace, and no ros2 executable" \
        if missing else None


def private_domain() -> int:
    """A DDS domain for this test process, in ARCHLOG_TESTGEN_DOMAINS (LOW-HIGH, default 1-99; at
    most 232, the highest whose ports the DDS port formula keeps in range)."""
    low, high = (int(x) for x in os.environ.get("ARCHLOG_TESTGEN_DOMAINS", "1-99").split("-"))
    low, high = min(low, MAX_DOMAIN), min(high, MAX_DOMAIN)
    return low + os.getpid() % (high - low + 1)


def qos_profile(rclpy: Any, wanted: dict[str, Any]) -> Any:
    """The QoS a test publisher offers: what the subscribers under test ask for (see model._qos)."""
    from_seconds = rclpy.duration.Duration
    qos = rclpy.qos.QoSProfile(depth=100)
    if wanted.get("durability") == "transient_local":
        qos.durability = rclpy.qos.DurabilityPolicy.TRANSIENT_LOCAL
    if wanted.get("liveliness") == "manual_by_topic":
        qos.liveliness = rclpy.qos.LivelinessPolicy.MANUAL_BY_TOPIC
    if "deadline" in wanted:
        qos.deadline = from_seconds(seconds=wanted["deadline"])
    if "liveliness_lease_duration" in wanted:
        qos.liveliness_lease_duration = from_seconds(seconds=wanted["liveliness_lease_duration"])
    return qos


def watching_qos(rclpy: Any) -> Any:
    """A test subscriber matches any publisher: best effort, volatile, no deadline."""
    return rclpy.qos.QoSProfile(depth=100, reliability=rclpy.qos.ReliabilityPolicy.BEST_EFFORT)


class Ros2Session:
    """The nodes under test on a private domain, and the rclpy node that feeds and watches them.
    Events are put on `events` as the ROS 1 bridge writes them ({"ev": "msg" | "ready" | "error"})."""

    def __init__(self, model: dict[str, Any], rclpy: Any, classes: dict[str, type]) -> None:
        self.model, self.rclpy, self.classes = model, rclpy, classes
        self.tmp = Path(tempfile.mkdtemp(prefix="archlog-testgen-"))
        self.events: queue.Queue = queue.Queue()
        self.procs: dict[str, subprocess.Popen] = {}  # node (of a process started) -> its process
        self.launched_params: dict[str, Any] | None = None
        self.launches = 0
        self.domain = private_domain()
        self.env = dict(os.environ, ROS_DOMAIN_ID=str(self.domain), ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
                        ROS_HOME=str(self.tmp), ROS_LOG_DIR=str(self.tmp / "log"), PYTHONUNBUFFERED="1")
        self.env.pop("ROS_LOCALHOST_ONLY", None)  # deprecated; it would override the discovery range
        self.terminals: list[int] = []  # the controlling side of each started process's terminal
        measured = measuring()
        self.coverage = self.tmp / "coverage" if measured else None
        self.lines = LineCoverage(self.tmp / "coverage", {node["name"]: node_file(node) for node in model["commands"]
                                                          if node.get("entry") or node.get("script")}) if measured else None

    @property
    def log(self) -> Path:
        return self.tmp / "launch.log"

    def start(self) -> None:
        rclpy = self.rclpy
        os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"  # read when the context starts
        self.context = rclpy.context.Context()
        rclpy.init(context=self.context, domain_id=self.domain)
        self.node = rclpy.create_node("archlog_testgen_bridge", context=self.context)
        inputs, outputs = self.model["inputs"], self.model["outputs"]
        self.publishers = {t: self.node.create_publisher(self.classes[ty], t, qos_profile(rclpy, self.model["qos"].get(t, {})))
                           for t, ty in inputs.items()}
        for topic, type_ in outputs.items():
            self.node.create_subscription(self.classes[type_], topic, lambda m, t=topic: self.events.put(
                {"ev": "msg", "topic": t, "t": time.time(), "msg": to_json(m)}), watching_qos(rclpy))
        self.clients = {name: self.node.create_client(self.classes[type_], name)
                        for name, type_ in self.model.get("services", {}).items()}
        self.goal_clients = {name: rclpy.action.ActionClient(self.node, self.classes[type_], name)
                             for name, type_ in self.model.get("actions", {}).items()}
        self.executor = rclpy.executors.SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        threading.Thread(target=self.executor.spin, daemon=True).start()

    def send(self, command: dict[str, Any]) -> None:
        if command["op"] == "publish":
            topic = command["topic"]
            try:
                now = self.node.get_clock().now().nanoseconds / 1e9
                self.publishers[topic].publish(to_message(command["msg"], self.classes[self.model["inputs"][topic]], now))
            except (AssertionError, TypeError, ValueError) as exc:  # a value the message class refuses
                self.events.put({"ev": "error", "topic": topic, "error": f"{type(exc).__name__}: {exc}"})
        elif command["op"] == "call":
            self._call(command)
        elif command["op"] == "goal":
            self._goal(command)
        elif command["op"] == "wait":
            end = time.monotonic() + command["timeout"]
            while (missing := self._unconnected()) and time.monotonic() < end:
                time.sleep(_POLL)
            self.events.put({"ev": "ready", "missing": missing})

    def _call(self, command: dict[str, Any]) -> None:
        """Call a service of the nodes under test; its response (or why the request could not be made)
        is put on `events` when it comes."""
        service, number = command["service"], command["id"]
        client = self.clients[service]

        def answered(future: Any) -> None:
            self.events.put({"ev": "response", "service": service, "id": number, "t": time.time(),
                             "response": to_json(future.result())})

        try:
            now = self.node.get_clock().now().nanoseconds / 1e9
            request = to_message(command["request"], client.srv_type.Request, now)
        except (AssertionError, TypeError, ValueError) as exc:  # a value the request class refuses
            self.events.put({"ev": "response", "service": service, "id": number, "t": time.time(),
                             "error": f"{type(exc).__name__}: {exc}"})
            return
        client.call_async(request).add_done_callback(answered)

    def _goal(self, command: dict[str, Any]) -> None:
        """Send a goal to an action of the nodes under test; its answer (accepted or not), feedback and
        result (or why the goal could not be sent) are put on `events` as they come."""
        action, number = command["action"], command["id"]

        def put(ev: str, **fields: Any) -> None:
            self.events.put({"ev": ev, "action": action, "id": number, "t": time.time(), **fields})

        def answered(future: Any) -> None:
            handle = future.result()
            put("goal", accepted=bool(handle.accepted))
            if handle.accepted:
                handle.get_result_async().add_done_callback(
                    lambda done: put("result", status=done.result().status, msg=to_json(done.result().result)))

        try:
            now = self.node.get_clock().now().nanoseconds / 1e9
            kind: Any = self.classes[self.model["actions"][action]]
            goal = to_message(command["goal"], kind.Goal, now)
        except (AssertionError, TypeError, ValueError) as exc:  # a value the goal class refuses
            put("goal", error=f"{type(exc).__name__}: {exc}")
            return
        self.goal_clients[action].send_goal_async(
            goal, feedback_callback=lambda message: put("feedback", msg=to_json(message.feedback))
        ).add_done_callback(answered)

    def _unconnected(self) -> list[str]:
        return sorted([t for t, p in self.publishers.items() if p.get_subscription_count() == 0]
                      + [t for t in self.model["outputs"] if self.node.count_publishers(t) == 0]
                      + [s for s, c in self.clients.items() if not c.service_is_ready()]
                      + [a for a, c in self.goal_clients.items() if not c.server_is_ready()])

    def launch(self, params: dict[str, Any], timeout: float = 30.0) -> None:
        """Start the nodes under test with `params`; wait until they are in the graph and connected."""
        self.stop_nodes()
        self.launches += 1
        self.launched_params = params
        with open(self.log, "ab") as out:
            for node in self.model["commands"]:
                command = run_command(node, params, self.coverage)
                if command is None:
                    raise RuntimeError(unstartable(self.model))
                env = dict(self.env, PYTHONPATH=os.pathsep.join(p for p in (node.get("root"), self.env.get("PYTHONPATH")) if p))
                proc = self._start(command, env, out)
                self.procs.update(dict.fromkeys(node.get("nodes", [node["name"]]), proc))
        deadline = time.monotonic() + timeout
        while any(self.down(n) for n in self.model["nodes"]):
            if any(p.poll() is not None for p in self.procs.values()):
                return  # a node died starting: the properties say so
            if time.monotonic() > deadline:
                raise RuntimeError(f"the nodes under test did not come up:\n{processes.tail(self.log)}")
            time.sleep(_POLL)
        while self._twice() and time.monotonic() < deadline:  # a stale namesake from the last example
            time.sleep(_POLL)
        for node in self.model.get("lifecycle", []):
            self._activate(node, deadline)
        self.send({"op": "wait", "timeout": 5.0})

    def _start(self, command: list[str], env: dict[str, str], out: IO[bytes]) -> subprocess.Popen:
        """Start a process under test in a session of its own, its standard input a pseudo-terminal of
        its own, as `ros2 run` in a shell gives it (keyboard teleops and prompts wait on it; nothing is
        typed): no other process reads it or changes its modes, and its controlling side stays open
        here until the process stopped, so that a read never sees the terminal hang up."""
        terminal, own = pty.openpty()
        self.terminals.append(terminal)
        try:
            return subprocess.Popen(command, env=env, stdout=out, stderr=subprocess.STDOUT, stdin=own,
                                    start_new_session=True, cwd=self.tmp)
        finally:
            os.close(own)  # the process holds its own copy

    def _activate(self, node: str, deadline: float) -> None:
        """Configure and activate a lifecycle node (its ports made in on_configure then exist); a
        transition refused or unanswered is left to the properties (the node stays inactive)."""
        cls: Any = self.classes[LIFECYCLE]
        client = self.node.create_client(cls, f"{node}/change_state")
        try:
            if not client.wait_for_service(timeout_sec=max(deadline - time.monotonic(), 0.1)):
                return
            for transition in TRANSITIONS:
                request = cls.Request()
                request.transition.id = transition
                future = client.call_async(request)
                while not future.done() and time.monotonic() < deadline:
                    time.sleep(_POLL)
                if not future.done() or not future.result().success:
                    return
        finally:
            self.node.destroy_client(client)

    def stop_nodes(self, grace: float = 3.0) -> None:
        """Stop the nodes under test cleanly (SIGINT, then SIGKILL after `grace` seconds) and wait until
        they left the graph: at most three times `grace` seconds more after a clean stop, and up to the
        DDS lease after a kill. A node killed outright (or slow to leave on a loaded machine) stays in
        the other participants' discovery data until its lease ends, and the next example's nodes (same
        names) would look up at once, their requests, messages and graph queries going to the dead
        ones, and would look dead when the lease ends before they are discovered."""
        stopped = list({id(p): p for p in self.procs.values()}.values())
        processes.stop_together(stopped, grace)
        names = set(self.procs)
        self.procs = {}
        for terminal in self.terminals:
            os.close(terminal)
        self.terminals = []
        killed = any(p.returncode == -signal.SIGKILL for p in stopped)
        end = time.monotonic() + (DDS_LEASE + grace if killed else 3 * grace)
        while names and names & set(self._names()) and time.monotonic() < end:
            time.sleep(_POLL)

    def new_lines(self) -> int | None:
        """Lines of the Python nodes' files that the nodes stopped since the last call ran first (None: not
        measured)."""
        return self.lines.new_lines() if self.lines else None

    def down(self, node: str) -> str | None:
        """Why the node is not up (None: its process runs and the graph lists it)."""
        proc = self.procs.get(node)
        if proc is None:
            return "not started"
        if proc.poll() is not None:
            return f"its process {exit_status(proc.returncode)}"
        return None if node in self._names() else "its process runs, but the graph does not list it"

    def _twice(self) -> list[str]:
        """The nodes under test the graph lists more than once."""
        listed = [(ns.rstrip("/") + "/" + name) for name, ns in self.node.get_node_names_and_namespaces()]
        return [n for n in self.model["nodes"] if listed.count(n) > 1]

    def _names(self) -> dict[str, tuple[str, str]]:
        return {(ns.rstrip("/") + "/" + name): (name, ns) for name, ns in self.node.get_node_names_and_namespaces()}

    def graph(self) -> observe.Architecture:
        """The live graph of the nodes under test, minus ROS 2's infrastructure (/rosout,
        /parameter_events, the parameter services) and the built-in ports the model lists (left out of
        the recovered interface too); an action server is its action's name (its hidden `_action`
        topics and services are not listed, nor those of action clients). A node listed without any
        endpoint, not even the /rosout publisher every node has, is left out: the graph's by-node answer
        is then about a participant it knows only in part (seen at a load of 10: a node's ports missing
        for the whole settling bound while the node ran), not about the node."""
        found: dict[str, set] = {"publishers": set(), "subscribers": set(), "services": set(), "action_servers": set()}
        builtin = {(node, name) for node, name in self.model.get("builtin", [])}
        names = {n: v for n, v in self._names().items() if n in self.model["nodes"]}
        for full, (name, ns) in list(names.items()):
            publishers = self.node.get_publisher_names_and_types_by_node(name, ns)
            subscribers = self.node.get_subscriber_names_and_types_by_node(name, ns)
            services = self.node.get_service_names_and_types_by_node(name, ns)
            if not (publishers or subscribers or services):
                del names[full]
                continue
            for kind, ports in (("publishers", publishers), ("subscribers", subscribers)):
                found[kind] |= {(full, t, ty) for t, types in ports if t not in observe.ROS2_INFRA_TOPICS
                                and ACTION_PART not in t and (full, t) not in builtin for ty in types}
            parameters = {f"{full}/{x}" for x in observe.ROS2_PARAMETER_SERVICES}
            for s, _types in services:
                if s.endswith(ACTION_PART + "send_goal"):
                    found["action_servers"].add((full, s.removesuffix(ACTION_PART + "send_goal")))
                elif s not in parameters and ACTION_PART not in s and (full, s) not in builtin:
                    found["services"].add((full, s))
        return observe.Architecture(frozenset(names), frozenset(found["publishers"]), frozenset(found["subscribers"]),
                                    frozenset(found["services"]), action_servers=frozenset(found["action_servers"]),
                                    kinds=(*observe.KINDS, "action_servers"))

    def close(self) -> None:
        atexit.unregister(self.close)
        self.stop_nodes()
        write_stats(self.launches, self.lines.covered() if self.lines else {})
        if hasattr(self, "executor"):
            self.executor.shutdown()
            self.node.destroy_node()
            self.context.try_shutdown()
        shutil.rmtree(self.tmp, ignore_errors=True)


class Ros2Machine(ArchitectureMachine):
    """The state machine of a ROS 2 configuration; the generated module sets `rclpy` (the module) and
    `classes` (each message type of the open inputs and outputs -> the rosidl class it imports)."""

    rclpy: Any = None
    classes: dict[str, type] = {}

    def new_session(self) -> Ros2Session:
        return Ros2Session(self.model, self.rclpy, self.classes)
