"""rospy and rclpy nodes: recover node names, ports, params, timers and QoS with Python's ast,
then the behavior of their publish calls (behavior/).

Nothing is imported or run. Values fold with fold.py; anything not folded is an explicit
Unknown with file:line. Loops and comprehensions over known elements are walked once per element
(within the steps budget), their variables bound to it; over a list parameter, once, each port
named from it standing for one port per element the configuration sets. Python 2 sources are
repaired line by line (repair.py) so their ROS calls are still recovered.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from archlog import budget, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.builtin_ports import builtin
from archlog.extract.cpp.cache import ResultCache, key
from archlog.extract.python.behavior.triggers import recover_behavior
from archlog.extract.python.callback_groups import standard_group
from archlog.extract.python.fold import Element, ValueFolder, parameters
from archlog.extract.python.imports import Module, imported_calls, package_modules
from archlog.extract.python.index import Function, arg
from archlog.extract.python.parameters import ParamReader, declared_pair
from archlog.extract.python.qos_profile import QosReader
from archlog.extract.python.repair import REPAIR_LINES, NestedTooDeeply, parse_tolerant
from archlog.extract.python.several import OUTSIDE, Nodes
from archlog.extract.summary import NodeSummary, ParamSpec, Port
from archlog.values import Alternatives, Concat, Namespace, ParamList, ParamRef, Unknown, Value, concat

# rospy-style constructors: qualified name -> (kind, keyword of the name, keyword of the type)
_ROSPY = {
    "rospy.Publisher": ("publisher", "name", "data_class"),
    "rospy.Subscriber": ("subscriber", "name", "data_class"),
    "rospy.Service": ("service_server", "name", "service_class"),
    "rospy.ServiceProxy": ("service_client", "name", "service_class"),
    "rospy.wait_for_message": ("subscriber", "topic", "topic_type"),
    "message_filters.Subscriber": ("subscriber", "topic", "data_class"),
    "actionlib.SimpleActionServer": ("action_server", "name", "ActionSpec"),
    "actionlib.SimpleActionClient": ("action_client", "ns", "ActionSpec"),
    "actionlib.ActionServer": ("action_server", "ns", "ActionSpec"),
    "actionlib.ActionClient": ("action_client", "ns", "ActionSpec"),
}
# rclpy Node methods: method -> (kind, index of the type, index of the name)
_RCLPY_METHODS = {
    "create_publisher": ("publisher", 0, 1), "create_lifecycle_publisher": ("publisher", 0, 1),
    "create_subscription": ("subscriber", 0, 1),
    "create_service": ("service_server", 0, 1), "create_client": ("service_client", 0, 1),
}
_RCLPY_ACTIONS = {"rclpy.action.ActionServer": "action_server", "rclpy.action.ActionClient": "action_client"}
# library objects with fixed ports (tf broadcasters and listeners, the diagnostics updater):
# qualified name -> ports they create
_FIXED = {
    "tf.TransformBroadcaster": [("publisher", "/tf")],
    "tf2_ros.TransformBroadcaster": [("publisher", "/tf")],
    "tf2_ros.StaticTransformBroadcaster": [("publisher", "/tf_static")],
    "tf.TransformListener": [("subscriber", "/tf"), ("subscriber", "/tf_static")],
    "tf2_ros.TransformListener": [("subscriber", "/tf"), ("subscriber", "/tf_static")],
    "diagnostic_updater.Updater": [("publisher", "/diagnostics")],
}
_PARAM_READS = {"rospy.get_param": True, "rospy.search_param": False, "rospy.has_param": False}
_PARAM_WRITES = {"rospy.set_param", "rospy.delete_param"}
_FIXED_TYPES = {"/tf": "tf2_msgs/TFMessage", "/tf_static": "tf2_msgs/TFMessage",
                "/diagnostics": "diagnostic_msgs/DiagnosticArray"}
# rclpy's parameter clients: a client of each parameter service of the remote node
_PARAMETER_CLIENTS = ("rclpy.parameter_client.AsyncParameterClient",)
_LIFECYCLE = ("rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode", "rclpy.lifecycle.node.LifecycleNode")
# rclpy Node keywords that add (True) or remove (False) a group of built-in ports: keyword -> (group, adds)
_NODE_FLAGS = {"enable_logger_service": ("logger_service", True), "start_parameter_services": ("parameter_services", False),
               "enable_rosout": ("rosout", False)}
_RCLPY_ONLY = {*_RCLPY_METHODS, "declare_parameter", "declare_parameters", "get_parameter", "get_parameter_or",
               "create_timer"}
_DIAGNOSTIC_MESSAGES = ("DiagnosticArray", "DiagnosticStatus", "KeyValue")  # diagnostic_updater re-exports them
_ROS_WORDS = re.compile(r"rospy\.|rclpy|Publisher|Subscriber|Service|create_")


SOURCE_CAP = 1 << 20
"""Largest rospy/rclpy source read (bytes): reading costs ~5 s a MiB, and no node is near it."""


def extract_python(path: Path, package: str, executable: str, shown: str, diagnostics: DiagnosticSink,
                   display: Callable[[Path], str] = str) -> NodeSummary:
    """Read one rospy/rclpy script, and the classes and functions it calls from its package's
    modules (shown with `display`); never imports or runs them."""
    summary = NodeSummary(package, executable, "python")
    try:
        data = sandbox.read_bytes(path, "source")
    except sandbox.Refused as exc:
        diagnostics.add(shown, 1, exc.code, f"not read: {exc}", "error")
        summary.incomplete = f"{shown}: cannot be read"
        return summary
    if len(data) > SOURCE_CAP:
        diagnostics.add(shown, 1, "too-large", f"{len(data)} bytes, over the {SOURCE_CAP}-byte cap for Python node "
                        "sources; its ROS calls are not recovered", "error")
        summary.incomplete = f"{shown}: too large to read"
        return summary
    source = data.decode("utf-8", errors="replace")
    modules = {display(m.path): m for m in package_modules(path, source)}
    cache = ResultCache("python")
    cache_key = key(package, executable, shown, data, *[part for s, m in modules.items() for part in (s, m.data)])
    cached = cache.get(cache_key)
    if not (isinstance(cached, tuple) and len(cached) == 2 and isinstance(cached[0], NodeSummary)):
        found = DiagnosticSink()
        cached = (_read_guarded(source, summary, shown, found, modules), found.items)
        cache.put(cache_key, cached)
    diagnostics.extend(cached[1])
    return cached[0]


def _read_guarded(source: str, summary: NodeSummary, shown: str, diagnostics: DiagnosticSink,
                  modules: dict[str, Module]) -> NodeSummary:
    """`_read` within a budget of its own, with the parser's limits or a walk's an error diagnostic."""
    try:
        with budget.scope():
            return _read(source, summary, shown, diagnostics, modules)
    except (NestedTooDeeply, RecursionError, MemoryError) as exc:
        diagnostics.add(shown, getattr(exc, "line", 1), "python-nesting", "code nested deeper than Python's parser "
                        "(or archlog's walk over it) allows; its ROS calls are not recovered", "error")
        return NodeSummary(summary.package, summary.executable, "python", incomplete=f"{shown}: nested too deeply")


def _read(source: str, summary: NodeSummary, shown: str, diagnostics: DiagnosticSink,
          modules: dict[str, Module]) -> NodeSummary:
    """Parse (repairing Python 2), extract the ports (with those of the package's modules the script
    calls), then recover the behavior of publish calls."""
    tree = _tree(source, shown, summary, diagnostics)
    if tree is None:
        return summary
    nodes = Nodes()
    reader = NodeReader(summary, shown, tree, nodes)
    reader.run()
    summary.publishes, summary.writes = recover_behavior(reader, summary.ports, diagnostics)
    readers = [reader]
    calls = imported_calls(tree, list(modules.values()))
    for module_shown, module in modules.items():
        module_tree = _tree(module.data.decode("utf-8", errors="replace"), module_shown, summary, diagnostics) \
            if calls[module] else None
        if module_tree is not None:
            readers.append(NodeReader(summary, module_shown, module_tree, nodes))
            readers[-1].run(calls[module])
            if missing := sorted(calls[module] - _defined(module_tree)):
                summary.incomplete = summary.incomplete or f"{module_shown}:1: {', '.join(missing)} not defined " \
                    "here (imported from elsewhere?): its ROS code is not read"
    for read in readers:
        for line, code, message, severity in read.notes:
            diagnostics.add(read.file, line, code, message, severity)
    summary = nodes.split(summary)
    for node in [summary, *summary.others]:
        node.ports = _without_untyped_duplicates(node.ports)
    if not summary.name_file and not summary.ports and not summary.incomplete:
        summary.incomplete = f"{shown}:1: sets up no ROS node (no rospy.init_node, no rclpy node) here or in the " \
            "package modules it calls that archlog reads: if it is a node, its ROS code is elsewhere"
    return summary


def _defined(tree: ast.Module) -> set[str]:
    """The classes and functions a module defines at its top level."""
    return {stmt.name for stmt in tree.body if isinstance(stmt, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))}


def _tree(source: str, shown: str, summary: NodeSummary, diagnostics: DiagnosticSink) -> ast.Module | None:
    """A source's syntax tree, repairing Python 2 line by line (a note); None, with an error, for a
    source that does not parse or is mostly not Python (archlog does not pretend to have read it).
    Lines with ROS calls that could not be read leave the summary incomplete."""
    tree, repaired, dropped = parse_tolerant(source)
    lines = source.splitlines()
    if tree is not None and len(repaired) * 2 > len([ln for ln in lines if ln.strip()]):
        tree = None
    if tree is None:
        why = f"is not repaired: {len(lines)} lines, over the {REPAIR_LINES}-line repair cap" \
            if len(lines) > REPAIR_LINES else "does not parse as Python 3 or 2"
        diagnostics.add(shown, repaired[0] if repaired else 1, "python-syntax",
                        f"{why}; its ROS calls are not recovered", "error")
        summary.incomplete = f"{shown}: does not parse"
        return None
    if repaired:
        diagnostics.add(shown, repaired[0], "python2",
                        f"Python 2 (or newer) syntax: {len(repaired)} line(s) repaired or skipped to recover its ROS "
                        "calls", "note")
        lost = [n for n in dropped if _ROS_WORDS.search(lines[n - 1])]
        if lost:
            summary.incomplete = f"{shown}:{lost[0]}: a line with ROS calls could not be read"
    return tree


def _without_untyped_duplicates(ports: list[Port]) -> list[Port]:
    """wait_for_service(name) next to ServiceProxy(name, Type) is one client, with its type."""
    typed = {(p.kind, p.name) for p in ports if p.kind == "service_client" and not isinstance(p.type, Unknown)
             and isinstance(p.name, str)}
    return [p for p in ports if not (isinstance(p.type, Unknown) and (p.kind, p.name) in typed)]


class NodeReader(ValueFolder):
    """Walks a module's scopes in order and reads the ROS calls in each into the summary."""

    def __init__(self, summary: NodeSummary, shown: str, tree: ast.Module, nodes: Nodes) -> None:
        super().__init__(shown, tree)
        self.summary = summary
        self.nodes = nodes
        self.profiles = QosReader(self)
        self.notes: list[tuple[int, str, str, str]] = []  # diagnostics: line, code, message, severity
        self.seen: set[Port] = set()
        self.params = ParamReader(tree, self.qualified, self.value)
        self.branch_of: dict[int, tuple[ast.AST, int]] | None = None  # see branches_around()
        self.parent_of: dict[int, ast.AST] = {}

    def run(self, only: set[str] | None = None) -> None:
        """Read the ROS calls of every scope (or only of the module's classes and functions named),
        in source order."""
        for stmt in self.tree.body:
            if only is None or isinstance(stmt, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) \
                    and stmt.name in only:
                self._visit(stmt)

    def is_rclpy_node_class(self, cls: str | None, depth: int = 0, lifecycle: bool = False) -> bool:
        """A class deriving (in the file, up to 5 levels) from an rclpy Node (a LifecycleNode with `lifecycle`)."""
        bases = self.class_bases.get(cls or "", [])
        roots = _LIFECYCLE if lifecycle else ("rclpy.node.Node", *_LIFECYCLE)
        return any(b in roots or (depth < 5 and self.is_rclpy_node_class(b, depth + 1, lifecycle)) for b in bases)

    def builtin_ports(self, call: ast.Call, lifecycle: bool) -> None:
        """The built-in port groups (system/infrastructure.py) a node's construction asks for or turns off:
        a lifecycle node, enable_logger_service=True, start_parameter_services=False, enable_rosout=False."""
        self.summary.ros = 2
        flags = {kw.arg: self.value(kw.value) for kw in call.keywords if kw.arg in _NODE_FLAGS}
        wanted = [group for flag, (group, on) in _NODE_FLAGS.items() if on and flags.get(flag) == "true"]
        off = [group for flag, (group, on) in _NODE_FLAGS.items() if not on and flags.get(flag) == "false"]
        for node in (self.summary, self.nodes.part(self.owner())):
            node.infrastructure = tuple(dict.fromkeys([*node.infrastructure, *wanted,
                                                       *(["lifecycle"] if lifecycle else [])]))
            node.without = tuple(dict.fromkeys([*node.without, *off]))

    # -- traversal --------------------------------------------------------------------------
    def _visit(self, node: ast.AST) -> None:
        """Visit a node in its function scope (methods in their class)."""
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            cls = self.scope.cls if self.scope else self.class_of.get(id(node))
            self._walk_function(self.functions.get((cls, node.name)) or Function(node, cls))
            return
        if isinstance(node, ast.ClassDef):
            for child in node.body:
                if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    self._walk_function(self.functions.get((node.name, child.name)) or Function(child, node.name))
                else:
                    self._visit(child)
            return
        if isinstance(node, (ast.For, ast.AsyncFor)):
            self._loop([(node.target, node.iter)], node.body)
            for stmt in node.orelse:
                self._visit(stmt)
            return
        if isinstance(node, (ast.ListComp, ast.SetComp, ast.GeneratorExp, ast.DictComp)):
            results = [node.key, node.value] if isinstance(node, ast.DictComp) else [node.elt]
            self._loop([(g.target, g.iter) for g in node.generators],
                       [test for g in node.generators for test in g.ifs] + results)
            return
        if isinstance(node, ast.Call):
            self._call(node)
        for sub in ast.iter_child_nodes(node):
            self._visit(sub)

    def _walk_function(self, function: Function) -> None:
        """Visit a function's body in its scope: once per call site of the file when they pass
        different values (each call runs its own ports: a helper called with one name per call), its
        parameters bound to that call's arguments; once, unbound, otherwise."""
        outer, self.scope = self.scope, function
        sites = self.per_call_site(function)
        for site in sites or [{}]:
            saved = dict(self.bound)
            self.bound.update({self.key_of(name, function): item for name, item in site.items()})
            for stmt in function.node.body:
                self._visit(stmt)
            self.bound = saved
        self.scope = outer

    def per_call_site(self, function: Function) -> list[dict[str, Element]]:
        """The arguments of each call site of a function, by parameter, when call sites pass different
        literals for a parameter (`self.listen("gripper")`, `self.listen("wrist")`), no two of them in
        different branches of one `if` (only one of those runs), and the steps budget pays for the
        walks; else no call site."""
        names = [name for name in parameters(function) if name not in function.assigns and
                 not (function.cls and name in ("self", "cls"))]
        passed = {name: self.arguments(function, name) for name in names}
        sites = self.call_sites(function.cls, function.node.name)
        if len(sites) < 2 or not any(_literals_differ([e for e, _c in args]) for args in passed.values()
                                     if len(args) == len(sites)):
            return []
        if self.exclusive(sites):
            return []
        try:
            budget.charge("steps", len(sites) * sum(1 for stmt in function.node.body for _ in ast.walk(stmt)))
        except budget.BudgetExceeded:
            return []
        return [{name: Element(args[index][0], args[index][1]) if args[index][0] is not None else
                 Element(None, None, Unknown(f"{name} (not passed)", self.file, function.node.lineno))
                 for name, args in passed.items() if len(args) == len(sites)} for index in range(len(sites))]

    def exclusive(self, nodes: list[ast.Call]) -> bool:
        """Whether two of the nodes are in different branches of one `if` (or try/except)."""
        branches: dict[int, set[int]] = {}
        for node in nodes:
            for statement, branch in self.branches_around(node):
                branches.setdefault(statement, set()).add(branch)
        return any(len(taken) > 1 for taken in branches.values())

    def branches_around(self, target: ast.AST) -> list[tuple[int, int]]:
        """The (if or try statement, branch index) pairs a node is inside."""
        if self.branch_of is None:  # each node's innermost enclosing branch, indexed at the first question
            self.branch_of = {}
            for node in ast.walk(self.tree):
                for index, part in enumerate(_branches(node)):
                    for stmt in part:
                        self.branch_of[id(stmt)] = (node, index)
                for child in ast.iter_child_nodes(node):
                    self.parent_of.setdefault(id(child), node)
        found: list[tuple[int, int]] = []
        at: ast.AST | None = target
        while at is not None:
            if id(at) in self.branch_of:
                statement, index = self.branch_of[id(at)]
                found.append((id(statement), index))
            at = self.parent_of.get(id(at))
        return found

    def _loop(self, walks: list[tuple[ast.expr, ast.expr]], body: list[ast.expr] | list[ast.stmt]) -> None:
        """Visit `body` once per element of the first (target, sequence) walk, its target bound to the
        element, nested walks inside; a sequence not known (or too long for the steps budget) binds
        its target to one element standing for all: a list parameter's, or an unknown one."""
        if not walks:
            for node in body:
                self._visit(node)
            return
        target, sequence = walks[0]
        self._visit(sequence)
        items = self.elements(sequence, self.scope)
        if isinstance(items, list):
            try:
                budget.charge("steps", len(items) * sum(1 for node in body for _ in ast.walk(node)))
            except budget.BudgetExceeded as exc:
                self.notes.append((sequence.lineno, "budget-exceeded", f"{exc}: the loop over "
                                   f"{ast.unparse(sequence)} is read once, its variable unknown", "warning"))
                items = self.unknown(sequence, "not unrolled")
        if not isinstance(items, list):
            items = [Element(None, None, items if isinstance(items, ParamList) else
                             Unknown(f"an element of {items.expr}", self.file, sequence.lineno))]
        for item in items:
            with self._bound(target, item):
                self._loop(walks[1:], body)

    @contextmanager
    def _bound(self, target: ast.expr, item: Element) -> Iterator[None]:
        """Loop variables bound to one element while a loop's body is walked."""
        saved = dict(self.bound)
        self._bind(target, item)
        try:
            yield
        finally:
            self.bound = saved

    def _bind(self, target: ast.expr, item: Element) -> None:
        """Bind a name to an element; a tuple of names to the parts of a tuple element (unknown parts
        when the element is not a tuple of as many known parts)."""
        if isinstance(target, ast.Name):
            self.bound[self.key_of(target.id, self.scope)] = item
        elif isinstance(target, (ast.Tuple, ast.List)):
            parts = list(item.parts) if item.parts is not None else \
                self.elements(item.expr, item.scope) if item.expr is not None else None
            for index, sub in enumerate(target.elts):
                self._bind(sub, parts[index] if isinstance(parts, list) and len(parts) == len(target.elts) else
                           Element(None, None, self.unknown(sub, "unpacked from an element not known")))

    def message_type(self, expr: ast.expr | None, ros2: bool) -> Value:
        """`pkg/Type` (ROS 1) or `pkg/msg/Type` (ROS 2) from `pkg.msg.Type`."""
        name = self.qualified(expr) if expr is not None else None
        parts = name.split(".") if name else []
        if len(parts) == 2 and parts[0] == "diagnostic_updater" and parts[1] in _DIAGNOSTIC_MESSAGES:
            parts = ["diagnostic_msgs", "msg", parts[1]]  # what `from diagnostic_msgs.msg import *` gives it
        if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
            base = parts[2]
            if parts[1] == "msg" and base.endswith("Action"):
                base = base[: -len("Action")]
            return f"{parts[0]}/{parts[1]}/{base}" if ros2 else f"{parts[0]}/{base}"
        if expr is None:
            return Unknown("<missing type>", self.file, 0)
        root = expr
        while isinstance(root, ast.Attribute):
            root = root.value
        if isinstance(root, ast.Name) and root.id in self.conditional:
            return self.unknown(expr, f"one of {', '.join(self.conditional[root.id])}, by which import runs")
        return self.unknown(expr, "message type not resolved")

    # -- ROS calls --------------------------------------------------------------------------
    def _call(self, call: ast.Call) -> None:
        """One call: a rospy, rclpy, tf or actionlib API call adds its port or names the node."""
        func = self.qualified(call.func)
        method = call.func.attr if isinstance(call.func, ast.Attribute) else None
        if not self.summary.params_dynamic and (why := self.params.dynamic(call, func, method, self.uses_rclpy())):
            self.summary.params_dynamic = f"{self.file}:{call.lineno}: {why}"
        if func == "rospy.init_node":
            self.summary.ros = 1
            self.set_name(call, self.value(arg(call, 0, "name")))
            anon = arg(call, 2, "anonymous")
            self.summary.anonymous = isinstance(anon, ast.Constant) and anon.value is True
        elif func in _ROSPY:
            kind, name_kw, type_kw = _ROSPY[func]
            self.add(kind, call, self.value(arg(call, 0, name_kw)), self.message_type(arg(call, 1, type_kw), False),
                     queue=self.queue(call, func))
        elif func in _FIXED:
            for kind, topic in _FIXED[func]:
                self.add(kind, call, topic, _FIXED_TYPES[topic])
        elif func == "tf2_ros.Buffer" and ((debug := arg(call, 1, "debug")) is None or
                                           self.value(debug) not in ("false", "0")):
            self.add("service_server", call, "~tf2_frames", "tf2_msgs/FrameGraph")  # its debug service
        elif func in _PARAM_READS and call.args:
            default = arg(call, 1, "default") if _PARAM_READS[func] else None
            self.add("param_read", call, self.value(call.args[0]), "",
                     self.value(default) if default is not None else None,
                     param=self.params.rospy_read(call) if func == "rospy.get_param" else None)
        elif func in _PARAM_WRITES and call.args:
            value = self.value(arg(call, 1, "param_value")) if func == "rospy.set_param" else "delete"
            self.add("param_write", call, self.value(call.args[0]), "", value)
        elif func == "rospy.wait_for_service" and call.args:
            self.add("service_client", call, self.value(call.args[0]), self.unknown(call, "type not given"))
        elif func in ("rospy.Timer", "rospy.Rate"):
            self.add("timer", call, self.period(arg(call, 0, "period" if func == "rospy.Timer" else "hz"), func), "")
        elif func in _RCLPY_ACTIONS:
            self.add(_RCLPY_ACTIONS[func], call, self.value(arg(call, 2, "action_name")),
                     self.message_type(arg(call, 1, "action_type"), True))
        elif func in _PARAMETER_CLIENTS:
            remote = self.value(arg(call, 1, "remote_node_name"))
            for _kind, name, type_ in builtin().groups["parameter_services"].ports:
                self.add("service_client", call, concat(remote, name.removeprefix("~")), type_)
        elif method and self.is_rclpy_call(call):
            self.rclpy_call(call, method)
        elif func in ("rclpy.create_node", "rclpy.node.Node", *_LIFECYCLE) or (
                isinstance(call.func, ast.Attribute) and call.func.attr == "__init__"
                and isinstance(call.func.value, ast.Call) and isinstance(call.func.value.func, ast.Name)
                and call.func.value.func.id == "super" and self.scope and self.is_rclpy_node_class(self.scope.cls)):
            self.set_name(call, self.value(arg(call, 0, "node_name")))
            cls = self.scope.cls if self.scope else None
            self.builtin_ports(call, func in _LIFECYCLE or self.is_rclpy_node_class(cls, lifecycle=True))
            namespace = next((kw.value for kw in call.keywords if kw.arg == "namespace"), None)
            if namespace is not None:
                self.summary.namespace = self.nodes.part(self.owner()).namespace = self.value(namespace)

    def is_rclpy_call(self, call: ast.Call) -> bool:
        """A method call on an rclpy Node: `self` in a Node subclass, or any object of a module
        that uses rclpy when the method is one only rclpy nodes have (create_publisher, ...)."""
        func = call.func
        if not isinstance(func, ast.Attribute):
            return False
        target = func.value
        if isinstance(target, ast.Name) and target.id == "self" and self.scope is not None and \
                self.is_rclpy_node_class(self.scope.cls):
            return True
        return self.uses_rclpy() and func.attr in _RCLPY_ONLY

    def uses_rclpy(self) -> bool:
        """The module imports rclpy (or something of it)."""
        return any(v == "rclpy" or v.startswith("rclpy.") for v in self.aliases.values())

    def rclpy_call(self, call: ast.Call, method: str) -> None:
        """An rclpy Node method: publishers, subscriptions, services, parameters, timers."""
        if method in _RCLPY_METHODS:
            kind, type_at, name_at = _RCLPY_METHODS[method]
            name_kw = "topic" if kind in ("publisher", "subscriber") else "srv_name"
            type_kw = "msg_type" if kind in ("publisher", "subscriber") else "srv_type"
            qos = self.profiles.facts(arg(call, 3 if kind == "subscriber" else 2, "qos_profile"), self.scope) \
                if kind in ("publisher", "subscriber") else ()
            self.add(kind, call, self.value(arg(call, name_at, name_kw)),
                     self.message_type(arg(call, type_at, type_kw), True), qos=qos)
        elif method in ("declare_parameter", "get_parameter", "get_parameter_or") and call.args:
            name = self.value(call.args[0])
            default = arg(call, 1, "value") if method == "declare_parameter" else \
                arg(call, 1, "alternative_value") if method == "get_parameter_or" else None
            spec = self.params.declaration(call, default, arg(call, 2, "descriptor")) \
                if method == "declare_parameter" else None
            if default is None and isinstance(name, str):
                default = self.declared.get(name)
            self.add("param_read", call, name, "", self.value(default) if default is not None else None, handle="~",
                     param=spec)
        elif method == "declare_parameters":
            prefix = self.value(arg(call, 0, "namespace"))
            params = arg(call, 1, "parameters")
            for item in params.elts if isinstance(params, (ast.List, ast.Tuple)) else []:
                name_expr, value, descriptor = declared_pair(item)
                name = self.value(name_expr)
                full = concat(prefix, ".", name) if prefix else name
                self.add("param_read", call, full, "", self.value(value) if value is not None else None, handle="~",
                         param=self.params.declaration(call, value, descriptor))
        elif method == "create_timer":
            period = self.value(arg(call, 0, "timer_period_sec")) if standard_group(arg(call, 2, "callback_group"), self.tree) \
                else Unknown("the period of a timer in a callback group of the program's own", self.file, call.lineno)
            self.add("timer", call, period, "")

    def queue(self, call: ast.Call, func: str) -> Value | None:
        """A rospy queue_size: a number, 'unbounded' (None; a Subscriber's default), or 'unset'."""
        if func not in ("rospy.Publisher", "rospy.Subscriber"):
            return None
        size = next((kw.value for kw in call.keywords if kw.arg == "queue_size"), None)
        if size is None:
            return "unset" if func == "rospy.Publisher" else "unbounded"
        if isinstance(size, ast.Constant) and size.value is None:
            return "unbounded"
        value = self.value(size)
        return "unbounded" if value == "0" and func == "rospy.Subscriber" else value

    def period(self, expr: ast.expr | None, func: str) -> Value:
        """A timer's period in seconds: Duration(x) / Duration.from_sec(x), or 1/hz for a Rate."""
        if expr is None:
            return Unknown("<missing period>", self.file, 0)
        if isinstance(expr, ast.Call) and expr.args and (self.qualified(expr.func) or "").startswith("rospy.Duration"):
            expr = expr.args[0]
        value = self.value(expr)
        if func == "rospy.Rate" and isinstance(value, str):
            try:
                return repr(1 / float(value))
            except (ValueError, ZeroDivisionError):
                return self.unknown(expr, "not a rate")
        return value

    def owner(self) -> str:
        """Whose ports the walk is reading: the rclpy Node subclass of the method, else the code outside them."""
        cls = self.scope.cls if self.scope else None
        return cls if cls and self.is_rclpy_node_class(cls) else OUTSIDE

    def set_name(self, call: ast.Call, name: Value) -> None:
        """The name of the node the walk's code creates (each Node subclass, and the code outside them, is a
        node of its own: several.py); a note when one of them names several nodes."""
        part = self.nodes.part(self.owner())
        if part.name is not None and part.name != name:
            self.notes.append((call.lineno, "python-several-nodes", f"this code creates several nodes "
                               f"({part.name}, {name}); archlog reads them as one node named after the last", "note"))
        part.name, part.file, part.line = name, self.file, call.lineno
        self.summary.default_name = name
        self.summary.name_file, self.summary.name_line = self.file, call.lineno

    def add(self, kind: str, call: ast.Call, name: Value, type_: Value, default: Value | None = None,
            qos: tuple[tuple[str, str], ...] = (), queue: Value | None = None, handle: str = "",
            param: ParamSpec | None = None) -> None:
        """One port (once, however many times a loop walks its call); `handle` "~" for ROS 2
        parameters (node-private). Only a name may hold a list parameter's element, once."""
        if isinstance(name, Alternatives) and name.every:  # a loop makes one port per value
            for option in name.options:
                self.add(kind, call, option, type_, default, qos, queue, handle, param)
            return
        name, type_ = (name if _expandable(name) else _unlisted(name, call)), _unlisted(type_, call)
        default, queue = (_unlisted(v, call) if v is not None else None for v in (default, queue))
        port = Port(kind, name, type_, self.file, call.lineno, call.col_offset + 1, handle, default, qos, queue,
                    param=param)
        if port not in self.seen:
            self.seen.add(port)
            self.summary.ports.append(port)
            self.nodes.owners.setdefault(port, self.owner())


def _literals_differ(passed: list[ast.expr | None]) -> bool:
    """Call sites that all pass a literal for a parameter, not all the same one (told apart without
    folding: folding each call site's argument through its callers' call sites grows exponentially)."""
    return all(isinstance(e, ast.Constant) for e in passed) and \
        len({e.value for e in passed if isinstance(e, ast.Constant)}) > 1


def _branches(node: ast.AST) -> list[list[ast.AST]]:
    """The branches of an if (statement or expression) or a try (its body and each handler), of which one runs."""
    if isinstance(node, ast.IfExp):
        return [[node.body], [node.orelse]]
    if isinstance(node, ast.If):
        return [list[ast.AST](node.body), list[ast.AST](node.orelse)]
    if isinstance(node, ast.Try):
        return [list[ast.AST](node.body), *[list[ast.AST](h.body) for h in node.handlers]]
    return []


def _listed(value: Value) -> list[ParamList]:
    """The list parameter elements a value holds."""
    if isinstance(value, ParamList):
        return [value]
    inner: tuple[Value, ...] = value.parts if isinstance(value, Concat) else value.options \
        if isinstance(value, Alternatives) else (value.name, value.default) if isinstance(value, ParamRef) else \
        (value.handle,) if isinstance(value, Namespace) else ()
    return [found for part in inner for found in _listed(part)]


def _expandable(name: Value) -> bool:
    """A name binding can expand per element: none, or one list parameter element joined with other parts."""
    listed = _listed(name)
    return not listed or len(listed) == 1 and (name is listed[0] or isinstance(name, Concat) and listed[0] in name.parts)


def _unlisted(value: Value, call: ast.Call) -> Value:
    """A value holding a list parameter's element where none can be expanded: unknown."""
    listed = _listed(value)
    return Unknown(f"an element of list parameter {listed[0].name}", listed[0].file, call.lineno) if listed else value

