"""rospy and rclpy nodes: recover node names, ports, params, timers and QoS with Python's ast.

Nothing is imported or run. Values are folded from literals, module and class constants,
`self` attributes, f-strings, `%` and `.format`, `+`, and function or `__init__` parameters
whose call sites in the file agree (a small function summary). Anything else is an explicit
Unknown with file:line. Python 2 sources are repaired line by line (parso finds the statements
that do not parse) so their ROS calls are still recovered.
"""

from __future__ import annotations

import ast
import heapq
import re
from collections import deque
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import parso

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.qos import DURATIONS, Qos, number, preset_name, seconds_text
from archlog.extract.summary import NodeSummary, Port
from archlog.values import Alternatives, ParamRef, Unknown, Value, alternatives, concat

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
    "create_publisher": ("publisher", 0, 1), "create_subscription": ("subscriber", 0, 1),
    "create_service": ("service_server", 0, 1), "create_client": ("service_client", 0, 1),
}
_RCLPY_ACTIONS = {"rclpy.action.ActionServer": "action_server", "rclpy.action.ActionClient": "action_client"}
# tf broadcasters and listeners: qualified name -> ports they create
_TF = {
    "tf.TransformBroadcaster": [("publisher", "/tf")],
    "tf2_ros.TransformBroadcaster": [("publisher", "/tf")],
    "tf2_ros.StaticTransformBroadcaster": [("publisher", "/tf_static")],
    "tf.TransformListener": [("subscriber", "/tf"), ("subscriber", "/tf_static")],
    "tf2_ros.TransformListener": [("subscriber", "/tf"), ("subscriber", "/tf_static")],
}
_PARAM_READS = {"rospy.get_param": True, "rospy.search_param": False, "rospy.has_param": False}
_PARAM_WRITES = {"rospy.set_param", "rospy.delete_param"}
_TF_MESSAGE = {"/tf": "tf2_msgs/TFMessage", "/tf_static": "tf2_msgs/TFMessage"}
_RCLPY_ONLY = {*_RCLPY_METHODS, "declare_parameter", "declare_parameters", "get_parameter", "get_parameter_or",
               "create_timer"}
_PARAMETER_VALUES = {"value", "string_value", "integer_value", "double_value", "bool_value"}
_KIND = {ast.AugAssign: "augmented assignment", ast.For: "loop variable", ast.With: "with target"}
_BRANCHING = (ast.If, ast.For, ast.While, ast.Try, ast.AsyncFor, ast.Match)
_SELF = "self."  # the key of self.method() calls (no class is named so)


SOURCE_CAP = 1 << 20
"""Largest rospy/rclpy source read (bytes): reading costs ~5 s a MiB, and no node is near it."""


class NestedTooDeeply(Exception):
    """Code nested deeper than Python's parser allows (brackets, indentation, expressions)."""

    def __init__(self, line: int) -> None:
        super().__init__(f"nested too deeply at line {line}")
        self.line = line


def extract_python(path: Path, package: str, executable: str, shown: str, diagnostics: DiagnosticSink) -> NodeSummary:
    """Read one rospy/rclpy script; never imports or runs it."""
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
    try:
        return _read(data.decode("utf-8", errors="replace"), summary, shown, diagnostics)
    except (NestedTooDeeply, RecursionError, MemoryError) as exc:  # the parser's limits, or a walk's
        diagnostics.add(shown, getattr(exc, "line", 1), "python-nesting", "code nested deeper than Python's parser "
                        "(or archlog's walk over it) allows; its ROS calls are not recovered", "error")
        return NodeSummary(package, executable, "python", incomplete=f"{shown}: nested too deeply")


def _read(source: str, summary: NodeSummary, shown: str, diagnostics: DiagnosticSink) -> NodeSummary:
    tree, repaired, dropped = parse_tolerant(source)
    lines = source.splitlines()
    if tree is not None and len(repaired) * 2 > len([ln for ln in lines if ln.strip()]):
        tree = None  # mostly not Python: do not pretend to have read it
    if tree is None:
        why = f"is not repaired: {len(lines)} lines, over the {REPAIR_LINES}-line repair cap" \
            if len(lines) > REPAIR_LINES else "does not parse as Python 3 or 2"
        diagnostics.add(shown, repaired[0] if repaired else 1, "python-syntax",
                        f"{why}; its ROS calls are not recovered", "error")
        summary.incomplete = f"{shown}: does not parse"
        return summary
    if repaired:
        diagnostics.add(shown, repaired[0], "python2",
                        f"Python 2 (or newer) syntax: {len(repaired)} line(s) repaired or skipped to recover its ROS "
                        "calls", "note")
        lost = [n for n in dropped if _ROS_WORDS.search(lines[n - 1])]
        if lost:
            summary.incomplete = f"{shown}:{lost[0]}: a line with ROS calls could not be read"
    extractor = _Extractor(summary, shown, tree)
    extractor.run()
    from archlog.extract.python_behavior import recover_behavior  # built on this module
    summary.publishes, summary.writes = recover_behavior(extractor, diagnostics)
    for line, message in extractor.notes:
        diagnostics.add(shown, line, "python-several-nodes", message, "note")
    summary.ports = _without_untyped_duplicates(summary.ports)
    return summary


def _without_untyped_duplicates(ports: list[Port]) -> list[Port]:
    """wait_for_service(name) next to ServiceProxy(name, Type) is one client, with its type."""
    typed = {(p.kind, p.name) for p in ports if p.kind == "service_client" and not isinstance(p.type, Unknown)
             and isinstance(p.name, str)}
    return [p for p in ports if not (isinstance(p.type, Unknown) and (p.kind, p.name) in typed)]


# -- Python 2 and broken sources ----------------------------------------------------------
_ROS_WORDS = re.compile(r"rospy\.|rclpy|Publisher|Subscriber|Service|create_")
# applied to lines without trailing blanks, so that no pattern backtracks over a run of them
_REPAIRS = [
    (re.compile(r"^(\s*)print\s*>>\s*[^,]+,\s*(.*)$"), r"\1print(\2)"),
    (re.compile(r"^(\s*)print\s+(?!\()(.*)$"), r"\1print(\2)"),
    (re.compile(r"^(\s*)print$"), r"\1print()"),
    (re.compile(r"^(\s*except\s+[^,:]+),\s*(\w+)\s*:"), r"\1 as \2:"),
    (re.compile(r"^(\s*)exec\s+(?!\()(.*)$"), r"\1exec(\2)"),
    (re.compile(r"^(\s*raise\s+[\w.]+)\s*,\s*(.+)$"), r"\1(\2)"),
    (re.compile(r"\b0([0-7]+)\b"), r"0o\1"),
    (re.compile(r"\b(\d+)[lL]\b"), r"\1"),
    (re.compile(r"\bur(['\"])"), r"u\1"),
    (re.compile(r"<>"), "!="),
    (re.compile(r"`([^`]*)`"), r"repr(\1)"),
    # newer than the running Python (3.12 type statements and generic parameter lists)
    (re.compile(r"^(\s*)type\s+(\w+)\s*(?:\[[^\]]*\])?\s*="), r"\1\2 ="),
    (re.compile(r"^(\s*(?:async\s+)?def\s+\w+)\[[^\]]*\]\s*\("), r"\1("),
    (re.compile(r"^(\s*class\s+\w+)\[[^\]]*\]"), r"\1"),
]


REPAIR_LINES = 20_000
"""Longest source that is repaired (parso reads ~10k lines a second); longer ones that do not
parse are reported, not repaired."""
_TOO_DEEP = ("too many nested parentheses", "too many levels of indentation")
_REPAIR_ROUNDS = 6  # parso passes; each finds every error it can, so Python 2 needs one or two


def parse_tolerant(source: str) -> tuple[ast.Module | None, list[int], list[int]]:
    """Parse with ast; on failure repair the lines parso (error recovery) or ast points at:
    first with Python 2 rewrites, then by neutralising the statement. Line numbers never move.
    Returns the tree, the repaired lines, and those of them whose statement was dropped.
    Raises NestedTooDeeply for code nested deeper than Python's parser allows."""
    lines = source.splitlines()
    repaired: dict[int, None] = {}  # in the order repaired
    dropped: list[int] = []
    grammar = parso.load_grammar()
    budget = max(10, len(lines) // 4)  # past this many repairs the file is not Python 2 either
    for _round in range(_REPAIR_ROUNDS + 1):
        try:
            return ast.parse("\n".join(lines) + "\n"), list(repaired), dropped
        except (RecursionError, MemoryError):
            raise NestedTooDeeply(1) from None
        except SyntaxError as exc:
            if exc.msg in _TOO_DEEP:
                raise NestedTooDeeply(exc.lineno or 1) from None
            if len(lines) > REPAIR_LINES or len(repaired) > budget or _round == _REPAIR_ROUNDS:
                break
            bad = sorted({e.start_pos[0] for e in grammar.iter_errors(grammar.parse("\n".join(lines)))}
                         | {exc.lineno or 1})
        progress = False
        for line_number in bad:
            if not 1 <= line_number <= len(lines):
                continue
            text = lines[line_number - 1].rstrip()
            fixed = text
            for pattern, replacement in _REPAIRS:
                fixed = pattern.sub(replacement, fixed)
            if fixed == text:
                indent = text[: len(text) - len(text.lstrip())]
                fixed = indent + ("if True:" if text.rstrip().endswith(":") else "pass")
                if fixed == text:
                    continue
                dropped.append(line_number)
            lines[line_number - 1] = fixed
            progress = True
            repaired[line_number] = None
        if not progress:
            break
    return None, list(repaired), dropped


# -- scopes ---------------------------------------------------------------------------------
@dataclass
class _Function:
    node: ast.FunctionDef | ast.AsyncFunctionDef
    cls: str | None
    assigns: dict[str, list[ast.expr]] = field(default_factory=dict)


class _Extractor:
    """Walks a module once to index names, then again to read the ROS calls in their scopes."""

    def __init__(self, summary: NodeSummary, shown: str, tree: ast.Module) -> None:
        self.summary, self.file, self.tree = summary, shown, tree
        self.aliases: dict[str, str] = {}
        self.module_assigns: dict[str, list[ast.expr]] = {}
        self.class_attrs: dict[str, dict[str, list[ast.expr]]] = {}
        self.attr_scope: dict[int, _Function] = {}
        self.class_bases: dict[str, list[str]] = {}
        self.functions: dict[tuple[str | None, str], _Function] = {}
        # call sites in walk order: (None, function), (class, "__init__"), (_SELF, method) for self.method()
        self.calls: dict[tuple[str | None, str], list[tuple[int, ast.Call]]] = {}
        self.class_of: dict[int, str | None] = {}  # id of a function node -> its class
        self.owners: dict[int, _Function] | None = None  # id of a node -> the function it is in
        self.declared: dict[str, ast.expr] = {}
        self.notes: list[tuple[int, str]] = []
        self.scope: _Function | None = None

    def run(self) -> None:
        self._index()
        for stmt in self.tree.body:
            self._visit(stmt)

    # -- indexing ---------------------------------------------------------------------------
    def _index(self) -> None:
        for node in ast.walk(self.tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    self.aliases[a.asname or a.name.split(".")[0]] = a.name if a.asname else a.name.split(".")[0]
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                for a in node.names:
                    self.aliases[a.asname or a.name] = f"{node.module}.{a.name}"
        _assigns(self.tree.body, self.module_assigns, nested=True)
        for node in self.tree.body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                self._function(node, None)
            elif isinstance(node, ast.ClassDef):
                self.class_bases[node.name] = [self.qualified(b) or "" for b in node.bases]
                attrs = self.class_attrs.setdefault(node.name, {})
                _assigns(node.body, attrs, nested=False)
                for item in node.body:
                    if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        self._function(item, node.name)
                        for sub in ast.walk(item):
                            if isinstance(sub, (ast.Assign, ast.AnnAssign)):
                                for target in sub.targets if isinstance(sub, ast.Assign) else [sub.target]:
                                    if _is_self_attr(target) and sub.value is not None:
                                        attrs.setdefault(target.attr, []).append(sub.value)
                                        self.attr_scope[id(sub.value)] = self.functions[(node.name, item.name)]
                            elif isinstance(sub, ast.AugAssign) and _is_self_attr(sub.target):
                                attrs.setdefault(sub.target.attr, []).append(sub)
        for order, node in enumerate(ast.walk(self.tree)):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
                    node.func.attr == "declare_parameter" and len(node.args) > 1 and \
                    isinstance(node.args[0], ast.Constant):
                self.declared[str(node.args[0].value)] = node.args[1]
            if isinstance(node, ast.Call):
                if isinstance(node.func, ast.Name):
                    key = (node.func.id, "__init__") if node.func.id in self.class_attrs else (None, node.func.id)
                    self.calls.setdefault(key, []).append((order, node))
                elif isinstance(node.func, ast.Attribute) and isinstance(node.func.value, ast.Name) \
                        and node.func.value.id == "self":
                    self.calls.setdefault((_SELF, node.func.attr), []).append((order, node))

    def call_sites(self, cls: str | None, name: str) -> list[ast.Call]:
        """The calls of a function, or of a method (by its class, or as self.name() in any class)."""
        via_self = self.calls.get((_SELF, name), []) if cls in self.class_attrs else []
        return [call for _order, call in heapq.merge(self.calls.get((cls, name), []), via_self)]

    def _function(self, node: ast.FunctionDef | ast.AsyncFunctionDef, cls: str | None) -> None:
        function = _Function(node, cls)
        self.class_of[id(node)] = cls
        _assigns(node.body, function.assigns, nested=True)
        self.functions[(cls, node.name)] = function

    def qualified(self, expr: ast.expr) -> str | None:
        if isinstance(expr, ast.Name):
            return self.aliases.get(expr.id, expr.id)
        if isinstance(expr, ast.Attribute):
            base = self.qualified(expr.value)
            return f"{base}.{expr.attr}" if base else None
        return None

    def is_rclpy_node_class(self, cls: str | None, depth: int = 0) -> bool:
        bases = self.class_bases.get(cls or "", [])
        return any(b in ("rclpy.node.Node", "rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode")
                   or (depth < 5 and self.is_rclpy_node_class(b, depth + 1)) for b in bases)

    # -- traversal --------------------------------------------------------------------------
    def _visit(self, node: ast.AST) -> None:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            outer = self.scope
            cls = outer.cls if outer else self.class_of.get(id(node))
            self.scope = self.functions.get((cls, node.name)) or _Function(node, cls)
            for child in node.body:
                self._visit(child)
            self.scope = outer
            return
        if isinstance(node, ast.ClassDef):
            for child in node.body:
                if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    outer = self.scope
                    self.scope = self.functions.get((node.name, child.name)) or _Function(child, node.name)
                    for stmt in child.body:
                        self._visit(stmt)
                    self.scope = outer
                else:
                    self._visit(child)
            return
        if isinstance(node, ast.Call):
            self._call(node)
        for child in ast.iter_child_nodes(node):
            self._visit(child)

    # -- values -----------------------------------------------------------------------------
    def unknown(self, expr: ast.expr, why: str = "") -> Unknown:
        return Unknown(ast.unparse(expr) + (f" ({why})" if why else ""), self.file, getattr(expr, "lineno", 0))

    def value(self, expr: ast.expr | None, depth: int = 0, scope: _Function | None = None) -> Value:
        scope = self.scope if scope is None else scope
        if expr is None:
            return Unknown("<missing argument>", self.file, 0)
        if depth > 10:
            return self.unknown(expr, "too deep")
        if isinstance(expr, ast.Constant):
            if isinstance(expr.value, str):
                return expr.value
            if isinstance(expr.value, bool):
                return str(expr.value).lower()
            if isinstance(expr.value, (int, float)):
                return str(expr.value)
            return self.unknown(expr)
        if isinstance(expr, ast.Name):
            return self.name_value(expr, depth, scope)
        if _is_self_attr(expr) and scope is not None and scope.cls:
            return self.single(self.class_attrs.get(scope.cls, {}).get(expr.attr, []), expr, depth, scope)
        if isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) and expr.value.id in self.class_attrs:
            return self.single(self.class_attrs[expr.value.id].get(expr.attr, []), expr, depth, None)
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Add):
            return concat(self.value(expr.left, depth + 1, scope), self.value(expr.right, depth + 1, scope))
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Mod) and isinstance(expr.left, ast.Constant):
            return self.percent(expr, depth, scope)
        if isinstance(expr, ast.JoinedStr):
            parts = [self.value(v.value, depth + 1, scope) if isinstance(v, ast.FormattedValue)
                     and v.conversion == -1 and v.format_spec is None else
                     (v.value if isinstance(v, ast.Constant) else self.unknown(expr)) for v in expr.values]
            return concat(*parts)
        if isinstance(expr, ast.Call):
            return self.call_value(expr, depth, scope)
        if isinstance(expr, ast.IfExp):
            return alternatives([self.value(expr.body, depth + 1, scope), self.value(expr.orelse, depth + 1, scope)],
                                False, self.unknown(expr, "one of several values"))
        if isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Call) and expr.attr in _PARAMETER_VALUES:
            return self.call_value(expr.value, depth + 1, scope)
        return self.unknown(expr)

    def name_value(self, expr: ast.Name, depth: int, scope: _Function | None) -> Value:
        if scope is not None:
            if expr.id in scope.assigns:
                return self.single(scope.assigns[expr.id], expr, depth, scope)
            params = [a.arg for a in scope.node.args.args + scope.node.args.kwonlyargs]
            if expr.id in params:
                return self.parameter(scope, expr.id, expr, depth)
        return self.single(self.module_assigns.get(expr.id, []), expr, depth, None)

    def single(self, exprs: list[ast.expr], at: ast.expr, depth: int, scope: _Function | None) -> Value:
        """The value of a variable: one assignment gives its value, several (if/else) give
        alternatives, a loop over a literal list gives every element."""
        if len(exprs) == 1 and isinstance(exprs[0], ast.For) and isinstance(exprs[0].iter, (ast.List, ast.Tuple)):
            return alternatives([self.value(e, depth + 1, scope) for e in exprs[0].iter.elts], True,
                                self.unknown(at, "loop over values not known statically"))
        values = [self.value(e, depth + 1, self.attr_scope.get(id(e), scope)) if isinstance(e, ast.expr)
                  else self.unknown(at, _KIND[type(e)]) for e in exprs]
        if not values:
            return self.unknown(at, "not assigned in this file")
        return alternatives(values, False, self.unknown(at, "assigned values not all known"))

    def parameter(self, scope: _Function, name: str, at: ast.expr, depth: int) -> Value:
        """A parameter takes the value all call sites in the file pass (or its default)."""
        values = {self.value(passed, depth + 1, caller) if passed is not None else self.unknown(at)
                  for passed, caller in self.arguments(scope, name)}
        if len(values) == 1:
            return next(iter(values))
        return self.unknown(at, "call sites pass different values" if values else "parameter not passed in this file")

    def arguments(self, scope: _Function, name: str) -> list[tuple[ast.expr | None, _Function | None]]:
        """What each call site in the file passes for a parameter (its default when it passes
        nothing), with the caller's scope; the default alone when no call site is in the file."""
        args = scope.node.args
        positional = [a.arg for a in args.args]
        if scope.cls and positional and positional[0] in ("self", "cls"):
            positional = positional[1:]
        defaults = dict(zip([a.arg for a in args.args][len(args.args) - len(args.defaults):], args.defaults))
        defaults.update({a.arg: d for a, d in zip(args.kwonlyargs, args.kw_defaults) if d is not None})
        found: list[tuple[ast.expr | None, _Function | None]] = []
        for call in self.call_sites(scope.cls, scope.node.name):
            passed = next((kw.value for kw in call.keywords if kw.arg == name), None)
            if passed is None and name in positional and positional.index(name) < len(call.args):
                passed = call.args[positional.index(name)]
            found.append((passed if passed is not None else defaults.get(name), self.function_of(call)))
        if not found and name in defaults:
            found.append((defaults[name], scope))
        return found

    def function_of(self, node: ast.AST) -> _Function | None:
        if self.owners is None:  # indexed once, at the first question
            self.owners = {}
            for function in self.functions.values():
                for sub in ast.walk(function.node):
                    self.owners.setdefault(id(sub), function)
        return self.owners.get(id(node))

    def percent(self, expr: ast.BinOp, depth: int, scope: _Function | None) -> Value:
        template = expr.left.value
        items = expr.right.elts if isinstance(expr.right, ast.Tuple) else [expr.right]
        pieces = re.split(r"%[sdr]", template) if isinstance(template, str) else []
        if len(pieces) != len(items) + 1:
            return self.unknown(expr)
        parts: list[Value] = [pieces[0]]
        for item, piece in zip(items, pieces[1:]):
            parts += [self.value(item, depth + 1, scope), piece]
        return concat(*parts)

    def call_value(self, expr: ast.Call, depth: int, scope: _Function | None) -> Value:
        func = self.qualified(expr.func)
        if isinstance(expr.func, ast.Attribute) and expr.func.attr == "format" and \
                isinstance(expr.func.value, ast.Constant) and isinstance(expr.func.value.value, str):
            return self.format_value(expr, depth, scope)
        if func == "rospy.get_param" and expr.args:
            name = self.value(expr.args[0], depth + 1, scope)
            default = _arg(expr, 1, "default")
            if isinstance(name, str):
                return ParamRef(name, self.value(default, depth + 1, scope) if default is not None
                                else self.unknown(expr, "parameter without default"), "", self.file, expr.lineno)
        if func in ("rospy.resolve_name", "str", "os.path.join") and len(expr.args) == 1:
            return self.value(expr.args[0], depth + 1, scope)
        if isinstance(expr.func, ast.Attribute) and expr.func.attr == "get_parameter_value" and \
                isinstance(expr.func.value, ast.Call):
            return self.call_value(expr.func.value, depth + 1, scope)
        if isinstance(expr.func, ast.Attribute) and expr.func.attr in ("declare_parameter", "get_parameter",
                                                                      "get_parameter_or") and expr.args:
            name = self.value(expr.args[0], depth + 1, scope)
            default = _arg(expr, 1, "value" if expr.func.attr == "declare_parameter" else "alternative_value")
            if isinstance(name, str):
                default = default if default is not None and expr.func.attr != "get_parameter" else \
                    self.declared.get(name)
                return ParamRef(name, self.value(default, depth + 1, scope) if default is not None
                                else self.unknown(expr, "parameter without default"), "~", self.file, expr.lineno)
        return self.unknown(expr)

    def format_value(self, expr: ast.Call, depth: int, scope: _Function | None) -> Value:
        template = expr.func.value.value  # type: ignore[union-attr]
        parts: list[Value] = []
        position = 0
        for index, match in enumerate(re.finditer(r"\{(\w*)\}", template)):
            parts.append(template[position:match.start()])
            key = match.group(1)
            if key.isdigit() or not key:
                slot = int(key) if key else index
                item = expr.args[slot] if slot < len(expr.args) else None
            else:
                item = next((kw.value for kw in expr.keywords if kw.arg == key), None)
            parts.append(self.value(item, depth + 1, scope) if item is not None else self.unknown(expr))
            position = match.end()
        parts.append(template[position:])
        return concat(*parts)

    def message_type(self, expr: ast.expr | None, ros2: bool) -> Value:
        name = self.qualified(expr) if expr is not None else None
        parts = name.split(".") if name else []
        if len(parts) == 3 and parts[1] in ("msg", "srv", "action"):
            base = parts[2]
            if parts[1] == "msg" and base.endswith("Action"):
                base = base[: -len("Action")]
            return f"{parts[0]}/{parts[1]}/{base}" if ros2 else f"{parts[0]}/{base}"
        if expr is None:
            return Unknown("<missing type>", self.file, 0)
        return self.unknown(expr, "message type not resolved")

    # -- ROS calls --------------------------------------------------------------------------
    def _call(self, call: ast.Call) -> None:
        func = self.qualified(call.func)
        method = call.func.attr if isinstance(call.func, ast.Attribute) else None
        if func == "rospy.init_node":
            self.set_name(call, self.value(_arg(call, 0, "name")))
            anon = _arg(call, 2, "anonymous")
            self.summary.anonymous = isinstance(anon, ast.Constant) and anon.value is True
        elif func in _ROSPY:
            kind, name_kw, type_kw = _ROSPY[func]
            self.add(kind, call, self.value(_arg(call, 0, name_kw)), self.message_type(_arg(call, 1, type_kw), False),
                     queue=self.queue(call, func))
        elif func in _TF:
            for kind, topic in _TF[func]:
                self.add(kind, call, topic, _TF_MESSAGE[topic])
        elif func in _PARAM_READS and call.args:
            default = _arg(call, 1, "default") if _PARAM_READS[func] else None
            self.add("param_read", call, self.value(call.args[0]), "",
                     self.value(default) if default is not None else None)
        elif func in _PARAM_WRITES and call.args:
            value = self.value(_arg(call, 1, "param_value")) if func == "rospy.set_param" else "delete"
            self.add("param_write", call, self.value(call.args[0]), "", value)
        elif func == "rospy.wait_for_service" and call.args:
            self.add("service_client", call, self.value(call.args[0]), self.unknown(call, "type not given"))
        elif func in ("rospy.Timer", "rospy.Rate"):
            self.add("timer", call, self.period(_arg(call, 0, "period" if func == "rospy.Timer" else "hz"), func), "")
        elif func in _RCLPY_ACTIONS:
            self.add(_RCLPY_ACTIONS[func], call, self.value(_arg(call, 2, "action_name")),
                     self.message_type(_arg(call, 1, "action_type"), True))
        elif method and self.is_rclpy_call(call):
            self.rclpy_call(call, method)
        elif func in ("rclpy.create_node", "rclpy.node.Node") or (
                isinstance(call.func, ast.Attribute) and call.func.attr == "__init__"
                and isinstance(call.func.value, ast.Call) and isinstance(call.func.value.func, ast.Name)
                and call.func.value.func.id == "super" and self.scope and self.is_rclpy_node_class(self.scope.cls)):
            self.set_name(call, self.value(_arg(call, 0, "node_name")))
            namespace = next((kw.value for kw in call.keywords if kw.arg == "namespace"), None)
            if namespace is not None:
                self.summary.namespace = self.value(namespace)

    def is_rclpy_call(self, call: ast.Call) -> bool:
        """A method call on an rclpy Node: `self` in a Node subclass, or any object of a module
        that uses rclpy when the method is one only rclpy nodes have (create_publisher, ...)."""
        target = call.func.value  # type: ignore[union-attr]
        if isinstance(target, ast.Name) and target.id == "self" and self.scope is not None and \
                self.is_rclpy_node_class(self.scope.cls):
            return True
        method = call.func.attr  # type: ignore[union-attr]
        uses_rclpy = any(v == "rclpy" or v.startswith("rclpy.") for v in self.aliases.values())
        return uses_rclpy and method in _RCLPY_ONLY

    def rclpy_call(self, call: ast.Call, method: str) -> None:
        if method in _RCLPY_METHODS:
            kind, type_at, name_at = _RCLPY_METHODS[method]
            name_kw = "topic" if kind in ("publisher", "subscriber") else "srv_name"
            type_kw = "msg_type" if kind in ("publisher", "subscriber") else "srv_type"
            qos = self.qos(_arg(call, 3 if kind == "subscriber" else 2, "qos_profile")) \
                if kind in ("publisher", "subscriber") else ()
            self.add(kind, call, self.value(_arg(call, name_at, name_kw)),
                     self.message_type(_arg(call, type_at, type_kw), True), qos=qos)
        elif method in ("declare_parameter", "get_parameter", "get_parameter_or") and call.args:
            name = self.value(call.args[0])
            default = _arg(call, 1, "value") if method == "declare_parameter" else \
                _arg(call, 1, "alternative_value") if method == "get_parameter_or" else None
            if default is None and isinstance(name, str):
                default = self.declared.get(name)
            self.add("param_read", call, name, "", self.value(default) if default is not None else None, handle="~")
        elif method == "declare_parameters":
            prefix = self.value(_arg(call, 0, "namespace"))
            params = _arg(call, 1, "parameters")
            for item in params.elts if isinstance(params, (ast.List, ast.Tuple)) else []:
                pair = item.elts if isinstance(item, ast.Tuple) else [item]
                name = self.value(pair[0])
                full = concat(prefix, ".", name) if prefix else name
                self.add("param_read", call, full, "", self.value(pair[1]) if len(pair) > 1 else None, handle="~")
        elif method == "create_timer":
            self.add("timer", call, self.value(_arg(call, 0, "timer_period_sec")), "")

    def qos(self, expr: ast.expr | None) -> tuple[tuple[str, str], ...]:
        """QoS policies from a depth, a preset, a QoSProfile(...) call, or a variable holding one
        (with the attributes set on it before the call)."""
        return self.qos_value(expr, 0, self.scope, expr.lineno).facts() if expr is not None else ()

    def qos_value(self, expr: ast.expr, depth: int, scope: _Function | None, line: int) -> Qos:
        text = ast.unparse(expr)
        if depth > 8:
            return Qos.unknown(text)
        name = self.qualified(expr)
        if name and (preset := preset_name(name)) and not (isinstance(expr, ast.Name) and self.assigned(expr, scope)):
            return Qos.preset(preset)
        if isinstance(expr, ast.Call):
            func = self.qualified(expr.func) or ""
            if func.endswith("QoSProfile"):
                return self.qos_profile(expr, scope)
            if func in ("copy.copy", "copy.deepcopy") and expr.args:
                return self.qos_value(expr.args[0], depth + 1, scope, line)
            if func.endswith("QoSPresetProfiles.get_from_short_key") and expr.args and \
                    isinstance(expr.args[0], ast.Constant) and (preset := preset_name(
                        f"QoSPresetProfiles.{str(expr.args[0].value).upper()}")):
                return Qos.preset(preset)
        if isinstance(expr, ast.Name) and (assigned := self.assigned(expr, scope)):
            where = None if assigned == [e for e in self.module_assigns.get(expr.id, []) if isinstance(e, ast.expr)] \
                else scope
            qos = self.one_qos([(value, where) for value in assigned], depth, line, text)
            for target, value, conditional in self.attribute_sets(expr.id, where, line):
                self.qos_set(qos, target, value, where)
                if conditional:
                    qos.set(target, None, ast.unparse(value))
            return qos
        if isinstance(expr, ast.Name) and scope is not None and expr.id in [a.arg for a in scope.node.args.args +
                                                                            scope.node.args.kwonlyargs]:
            passed = [(e, caller) for e, caller in self.arguments(scope, expr.id) if e is not None]
            return self.one_qos(passed, depth, line, text) if passed else Qos.unknown(text)
        if _is_self_attr(expr) and scope is not None and scope.cls and \
                (values := self.class_attrs.get(scope.cls, {}).get(expr.attr)):
            last = values[-1]
            return self.qos_value(last, depth + 1, self.attr_scope.get(id(last), scope), line) \
                if isinstance(last, ast.expr) else Qos.unknown(text)
        value = self.value(expr, scope=scope)
        if isinstance(value, str) and number(value) is not None:
            qos = Qos.preset("default")
            qos.initialise("keep_last", value, text)
            return qos
        return Qos.unknown(text)

    def one_qos(self, sources: list[tuple[ast.expr, _Function | None]], depth: int, line: int, text: str) -> Qos:
        """The QoS several expressions agree on (if/else branches, call sites), else unknown."""
        found = [self.qos_value(e, depth + 1, where, getattr(e, "lineno", line)) for e, where in sources]
        if found and all(q.facts() == found[0].facts() for q in found):
            return found[0].copy()
        return Qos.unknown(text)

    def assigned(self, expr: ast.Name, scope: _Function | None) -> list[ast.expr]:
        """The values assigned to a name, in its function or else at module level."""
        found = scope.assigns.get(expr.id) if scope is not None else None
        found = found if found else self.module_assigns.get(expr.id, [])
        return [e for e in found if isinstance(e, ast.expr)]

    def attribute_sets(self, variable: str, scope: _Function | None, line: int) -> list[tuple[str, ast.expr, bool]]:
        """`variable.policy = value` statements before `line`, in the function (or module), and
        whether they run only under a condition (in an if, a loop, a try)."""
        body = scope.node.body if scope is not None else self.tree.body
        conditional = {id(n) for block in _in_scope(body) if isinstance(block, _BRANCHING)
                       for child in ast.iter_child_nodes(block) for n in _in_scope([child])}
        return [(target.attr, node.value, id(node) in conditional) for node in _in_scope(body)
                if isinstance(node, ast.Assign) and node.lineno < line for target in node.targets
                if isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name)
                and target.value.id == variable]

    def qos_profile(self, call: ast.Call, scope: _Function | None) -> Qos:
        """QoSProfile(history=..., depth=..., reliability=..., ...): rmw's default profile for
        what is not given; a depth without a history means keep_last."""
        qos = Qos.preset("default")
        given = {kw.arg for kw in call.keywords}
        if "depth" in given and "history" not in given:
            qos.set("history", "keep_last", ast.unparse(call))
        for kw in call.keywords:
            if kw.arg is not None:
                self.qos_set(qos, kw.arg, kw.value, scope)
        return qos

    def qos_set(self, qos: Qos, policy: str, value: ast.expr, scope: _Function | None) -> None:
        """One policy from a QoSProfile keyword or an attribute assignment."""
        text = ast.unparse(value)
        if policy in DURATIONS:
            seconds = self.seconds(value, scope)
            qos.apply(policy, seconds_text(seconds) if seconds is not None else None, text)
        elif policy == "depth":
            depth = self.value(value, scope=scope)
            qos.apply("depth", depth if isinstance(depth, str) and number(depth) is not None else None, text)
        else:
            qos.apply(policy, self.qualified(value) or text, text)

    def seconds(self, expr: ast.expr, scope: _Function | None) -> Fraction | None:
        """Seconds of rclpy's Duration(seconds=..., nanoseconds=...) (also builtin_interfaces'
        Duration(sec=..., nanosec=...)); None when not known."""
        if not (isinstance(expr, ast.Call) and (self.qualified(expr.func) or "").endswith("Duration")):
            if isinstance(expr, ast.Name) and (assigned := self.assigned(expr, scope)):
                return self.seconds(assigned[-1], scope)
            return None
        total = Fraction(0)
        for index, (keyword, alias, scale) in enumerate((("seconds", "sec", 1), ("nanoseconds", "nanosec", 10 ** 9))):
            part = _arg(expr, index, keyword) or next((kw.value for kw in expr.keywords if kw.arg == alias), None)
            if part is None:
                continue
            value = self.value(part, scope=scope)
            amount = number(value) if isinstance(value, str) else None
            if amount is None:
                return None
            total += amount / scale
        return total

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

    def set_name(self, call: ast.Call, name: Value) -> None:
        if self.summary.default_name is not None and self.summary.default_name != name:
            self.notes.append((call.lineno, f"this file creates several nodes ({self.summary.default_name}, {name}); "
                                            "archlog reads them as one node named after the last"))
        self.summary.default_name = name
        self.summary.name_file, self.summary.name_line = self.file, call.lineno

    def add(self, kind: str, call: ast.Call, name: Value, type_: Value, default: Value | None = None,
            qos: tuple[tuple[str, str], ...] = (), queue: Value | None = None, handle: str = "") -> None:
        """One port; `handle` "~" for ROS 2 parameters (node-private)."""
        if isinstance(name, Alternatives) and name.every:  # a loop makes one port per value
            for option in name.options:
                self.add(kind, call, option, type_, default, qos, queue, handle)
            return
        self.summary.ports.append(Port(kind, name, type_, self.file, call.lineno, call.col_offset + 1, handle, default,
                                       qos, queue))


def _arg(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
    for kw in call.keywords:
        if kw.arg == keyword:
            return kw.value
    return call.args[index] if len(call.args) > index else None


def _is_self_attr(expr: ast.AST) -> bool:
    return isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) and expr.value.id == "self"


def _in_scope(body: list[ast.stmt]) -> list[ast.AST]:
    """The nodes of a block, descending into if/for/while/with/try but not into nested scopes."""
    found: list[ast.AST] = []
    pending: deque[ast.AST] = deque(body)
    while pending:
        node = pending.popleft()
        found.append(node)
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            pending.extend(ast.iter_child_nodes(node))
    return found


def _assigns(body: list[ast.stmt], into: dict[str, list[ast.expr]], nested: bool) -> None:
    """Record `name = expr` (and `name += ...`, loop and with targets as further values) in a
    block; `nested` also reads its if/for/while/with/try bodies (not nested functions)."""
    nodes = _in_scope(body) if nested else list(body)
    for node in nodes:
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    into.setdefault(target.id, []).append(node.value)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.value is not None:
            into.setdefault(node.target.id, []).append(node.value)
        elif isinstance(node, ast.AugAssign) and isinstance(node.target, ast.Name):
            into.setdefault(node.target.id, []).append(node)  # type: ignore[arg-type]
        elif isinstance(node, (ast.For, ast.With)):
            targets = [node.target] if isinstance(node, ast.For) else [i.optional_vars for i in node.items]
            for target in targets:
                if isinstance(target, ast.Name):
                    into.setdefault(target.id, []).append(node)  # type: ignore[arg-type]
