"""Behavior of rospy and rclpy nodes: how each publish call is reached (a timer, an unbounded
loop, the callback of a subscriber, service or action, start-up code), the state conditions on
the way, and the assignments to that state.

Paths are followed from entries (registered callbacks, module code, `main`, constructors)
through calls to the file's own functions, binding arguments at each call: a publisher passed as
an argument resolves per path, and a caller's guards and loop hold in its callees. Built on the
indexes of python.py's extractor; values fold with its evaluator. Nothing is imported or run.
"""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, replace

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python import _arg, _assigns, _Extractor, _Function, _in_scope, _is_self_attr
from archlog.extract.summary import TRIGGERS, Guard, Publish, Site, StateWrite
from archlog.values import ParamRef, Unknown, Value

FunctionNode = ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
NO_INDEX = 99  # a keyword-only argument

# calls that register a callback: qualified name (or rclpy Node method) -> (trigger, (index, keyword) of callbacks)
_REGISTRATIONS: dict[str, tuple[str, tuple[tuple[int, str], ...]]] = {
    "rospy.Subscriber": ("callback", ((2, "callback"),)),
    "rospy.Service": ("callback", ((2, "handler"),)),
    "rospy.Timer": ("timer", ((1, "callback"),)),
    "actionlib.SimpleActionServer": ("callback", ((2, "execute_cb"),)),
    "actionlib.ActionServer": ("callback", ((2, "goal_cb"), (3, "cancel_cb"))),
    "rclpy.action.ActionServer": ("callback", ((3, "execute_callback"), (NO_INDEX, "goal_callback"),
                                               (NO_INDEX, "handle_accepted_callback"), (NO_INDEX, "cancel_callback"))),
}
_RCLPY_REGISTRATIONS = {"create_subscription": ("callback", ((2, "callback"),)),
                        "create_service": ("callback", ((2, "callback"),)),
                        "create_timer": ("timer", ((1, "callback"),))}
_LATER_REGISTRATIONS = {"registerCallback", "register_goal_callback", "register_preempt_callback"}
_SOURCE_KINDS = ("subscriber", "service_server", "action_server", "timer")
_PUBLISH_METHODS = ("publish", "sendTransform")
_ADDS = {"append", "appendleft", "extend", "extendleft", "insert", "add", "put", "put_nowait", "update", "setdefault"}
_TAKES = {"pop", "popleft", "popitem", "remove", "discard", "get", "get_nowait"}
_EMPTY_TESTS = {"empty", "is_empty", "isEmpty"}
_CONTAINER_TYPES = ("list", "dict", "set", "deque", "OrderedDict", "defaultdict", "Queue", "LifoQueue", "SimpleQueue")
_SCALAR_CALLS = {"bool", "int", "float", "str", "len", "abs", "min", "max", "round", "sum", "any", "all", "isinstance"}
_EXITS = {"sys.exit", "exit", "quit", "os._exit"}
_COMPARE: dict[type, Callable[[int, int], bool]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge}
_FLIPPED = {ast.Eq: ast.Eq, ast.NotEq: ast.NotEq, ast.Is: ast.Is, ast.IsNot: ast.IsNot,
            ast.Lt: ast.Gt, ast.Gt: ast.Lt, ast.LtE: ast.GtE, ast.GtE: ast.LtE}
_MAX_DEPTH = 16  # calls on one path
_BUDGET = 4000  # function bodies walked per file


def recover_behavior(extractor: _Extractor, diagnostics: DiagnosticSink) -> tuple[list[Publish], list[StateWrite]]:
    """The publish calls of a file read by `extractor` (after its run), one per way each is
    reached, and the assignments to the state variables their guards test."""
    if not any(port.kind == "publisher" for port in extractor.summary.ports):
        return [], []  # publishes nothing of its own (not a node, or a library handed its publishers)
    behavior = _Behavior(extractor)
    behavior.run()
    if behavior.budget <= 0:
        diagnostics.add(extractor.file, 1, "python-behavior",
                        f"more than {_BUDGET} paths through the file's functions: the triggers of some publish calls "
                        "are not recovered", "note")
    tested = {g.var for p in behavior.publishes for g in p.guards}
    order = {t: i for i, t in enumerate(TRIGGERS)}
    publishes = sorted(behavior.publishes, key=lambda p: (
        p.line, order[p.trigger], p.source.line if p.source else 0, p.publisher.line if p.publisher else 0,
        [(g.var, g.value, g.line) for g in p.guards], str(p.period)))
    writes = sorted((w for w in behavior.writes if w.var in tested),
                    key=lambda w: (w.line, w.var, w.value, w.source.line if w.source else 0))
    return publishes, writes


@dataclass(frozen=True)
class _Frame:
    """A function as it runs on one path: the arguments bound at its call, the enclosing
    function (closures) and the class of `self`. `func` None is module level."""

    func: FunctionNode | None
    cls: str | None = None
    args: tuple[tuple[str, ast.expr, _Frame], ...] = ()
    outer: _Frame | None = None
    called: bool = False  # reached through a call: unbound parameters take their defaults

    def __hash__(self) -> int:  # frames nest: hash once
        if "_hash" not in self.__dict__:
            object.__setattr__(self, "_hash", hash((self.func, self.cls, self.args, self.outer, self.called)))
        return self.__dict__["_hash"]

    def bound(self, name: str) -> tuple[ast.expr, _Frame] | None:
        return next(((e, f) for n, e, f in self.args if n == name), None)


@dataclass(frozen=True)
class _Target:
    """A function a call or a callback registration may run."""

    func: FunctionNode
    cls: str | None
    outer: _Frame | None
    method: bool = False  # reached through an instance: its first parameter is self
    preset: tuple[tuple[ast.expr, _Frame], ...] = ()  # functools.partial's arguments


@dataclass(frozen=True)
class _Context:
    """A path: how it started (trigger and source port), the guards so far, the period of the
    innermost unbounded loop (a 1-tuple inside one) and the functions on it."""

    trigger: str
    source: Site | None
    guards: tuple[Guard, ...] = ()
    loop: tuple[Value] | None = None
    stack: tuple[int, ...] = ()

    def guarded(self, guards: list[Guard]) -> _Context:
        known = {(g.var, g.value) for g in self.guards}
        new = {(g.var, g.value): g for g in guards if (g.var, g.value) not in known}
        return replace(self, guards=self.guards + tuple(new.values())) if new else self

    def keeping(self, others: list[_Context]) -> _Context:
        """After branches that join again: the guards every branch has."""
        common = set.intersection(*({(g.var, g.value) for g in c.guards} for c in others))
        return replace(self, guards=tuple(g for g in others[0].guards if (g.var, g.value) in common))


class _Behavior:
    """One file: its scopes and state variables, then the walk from every entry."""

    def __init__(self, ex: _Extractor) -> None:
        self.ex, self.file = ex, ex.file
        self.sites = {kind: {Site(p.file, p.line) for p in ex.summary.ports if p.kind == kind}
                      for kind in ("publisher", *_SOURCE_KINDS)}
        self.publishes: dict[Publish, None] = {}
        self.writes: dict[StateWrite, None] = {}
        self.walked: set[tuple[object, ...]] = set()
        self.reached: set[int] = set()
        self.arguments: dict[tuple[int, str], list[tuple[ast.expr, _Frame]]] = {}
        self.returned: dict[int, list[ast.expr]] = {}
        self.calls: dict[int, list[ast.Call]] = {}  # expression -> the calls it makes
        self.resolved: dict[tuple[str, int, _Frame], list] = {}  # memo of origins, callables, classes_of
        self.budget = _BUDGET
        self.module = _Frame(None)
        self.module_nodes = _in_scope(ex.tree.body)
        self.scopes: list[tuple[_Frame, list[ast.AST]]] = []
        self.functions = {id(f.node): f for f in ex.functions.values()}
        self.owner: dict[int, str] = {id(f.node): f.cls for f in ex.functions.values() if f.cls}
        self.frames: dict[int, _Frame] = {}  # function -> its frame when not called
        self.names: dict[int, tuple[set[str], set[str]]] = {}  # function -> (local names, declared global)
        self.nested: dict[int, dict[str, ast.FunctionDef | ast.AsyncFunctionDef]] = {}
        self.subclasses: dict[str, list[str]] = {}
        for cls, bases in ex.class_bases.items():
            for base in bases:
                if base in ex.class_attrs:
                    self.subclasses.setdefault(base, []).append(cls)
        self._scan(self.module_nodes, self.module)
        self.global_values: dict[str, list[tuple[ast.expr, _Frame]]] = {
            name: [(e, self.module) for e in values if isinstance(e, ast.expr)]
            for name, values in ex.module_assigns.items()}
        for frame, nodes in self.scopes:
            for node in nodes:
                if isinstance(node, ast.Assign) and frame.func is not None:
                    for target in node.targets:
                        if isinstance(target, ast.Name) and target.id in self.local_names(frame.func)[1]:
                            self.global_values.setdefault(target.id, []).append((node.value, frame))
        self.instantiated = {n.func.id for n in ast.walk(ex.tree) if isinstance(n, ast.Call)
                             and isinstance(n.func, ast.Name) and n.func.id in ex.class_attrs}
        self.kinds: dict[str, set[str]] = {}
        self.mutable: set[str] = set()  # state assigned inside functions
        self._classify()

    # -- scopes ---------------------------------------------------------------------------
    def _scan(self, nodes: list[ast.AST], frame: _Frame) -> None:
        """Every function, method and lambda with its frame when not called from anywhere."""
        nested: dict[str, ast.FunctionDef | ast.AsyncFunctionDef] = {}
        for node in nodes:
            if isinstance(node, ast.ClassDef):
                for item in node.body:
                    if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        self.owner[id(item)] = node.name
                        self._add_scope(_Frame(item, node.name))
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                outer = frame if frame.func is not None else None
                if not isinstance(node, ast.Lambda) and outer is not None:
                    nested[node.name] = node
                self._add_scope(_Frame(node, frame.cls, outer=outer))
        if frame.func is not None:
            self.nested[id(frame.func)] = nested

    def _add_scope(self, frame: _Frame) -> None:
        func = frame.func
        assert func is not None
        nodes = _in_scope([func.body] if isinstance(func, ast.Lambda) else func.body)  # type: ignore[list-item]
        declared = {name for n in nodes if isinstance(n, ast.Global) for name in n.names}
        stores = {n.id for n in nodes if isinstance(n, ast.Name) and isinstance(n.ctx, (ast.Store, ast.Del))}
        nonlocal_ = {name for n in nodes if isinstance(n, ast.Nonlocal) for name in n.names}
        self.names[id(func)] = ((stores | nonlocal_ | set(_params(func))) - declared, declared)
        if id(func) not in self.functions and not isinstance(func, ast.Lambda):
            function = _Function(func, frame.cls)
            _assigns(func.body, function.assigns, nested=True)
            self.functions[id(func)] = function
        self.scopes.append((frame, nodes))
        self.frames[id(func)] = frame
        self._scan(nodes, frame)

    def function(self, frame: _Frame | None) -> _Function | None:
        """python.py's scope for a frame (a lambda's is its enclosing function's)."""
        while frame is not None and frame.func is not None:
            if id(frame.func) in self.functions:
                return self.functions[id(frame.func)]
            frame = frame.outer
        return None

    def canonical(self, function: _Function | None, cls: str | None = None) -> _Frame:
        """The frame of a function not reached through a call (its parameters come from every call site)."""
        if function is None:
            return _Frame(None, cls)
        frame = self.frames.get(id(function.node)) or _Frame(function.node, function.cls)
        return replace(frame, cls=cls or frame.cls)

    def returns(self, func: FunctionNode) -> list[ast.expr]:
        """What a function returns (its return statements' values, a lambda's body)."""
        if isinstance(func, ast.Lambda):
            return [func.body]
        if id(func) not in self.returned:
            self.returned[id(func)] = [r.value for r in _in_scope(func.body) if isinstance(r, ast.Return) and r.value]
        return self.returned[id(func)]

    def local_names(self, func: FunctionNode) -> tuple[set[str], set[str]]:
        """A function's local names (parameters, assigned, nonlocal) and those it declares global."""
        return self.names.get(id(func), (set(_params(func)), set()))

    def lineage(self, cls: str) -> list[str]:
        """A class and its bases defined in the file."""
        found = [cls]
        for name in found:
            found += [b for b in self.ex.class_bases.get(name, []) if b in self.ex.class_attrs and b not in found]
        return found

    def descendants(self, cls: str) -> list[str]:
        found = [cls]
        for name in found:
            found += [s for s in self.subclasses.get(name, []) if s not in found]
        return found[1:]

    # -- state variables ------------------------------------------------------------------
    def state_var(self, expr: ast.AST, frame: _Frame) -> str | None:
        """`Class.attr` for `self.attr` (the class at the root of its hierarchy in the file), the
        name of a module variable; None for locals, parameters and anything else."""
        if _is_self_attr(expr) and frame.cls:
            return f"{self.lineage(frame.cls)[-1]}.{expr.attr}"  # type: ignore[attr-defined]
        if not isinstance(expr, ast.Name):
            return None
        while frame is not None and frame.func is not None:
            local, declared = self.local_names(frame.func)
            if expr.id in declared:
                return expr.id
            if expr.id in local:
                return None
            frame = frame.outer  # type: ignore[assignment]
        return expr.id if expr.id in self.global_values else None

    def _classify(self) -> None:
        """What each state variable holds (flag, container, optional, constant), from its
        assignments and tests, to read `if self.x:` in its own vocabulary."""
        def add(expr: ast.AST, frame: _Frame, kind: str | None, written: bool = False) -> None:
            var = self.state_var(expr, frame)
            if var is not None:
                if kind:
                    self.kinds.setdefault(var, set()).add(kind)
                if written and frame.func is not None:
                    self.mutable.add(var)

        class_bodies = [n for n in self.module_nodes if isinstance(n, ast.ClassDef)]
        for cls in class_bodies:
            for stmt in cls.body:
                if isinstance(stmt, (ast.Assign, ast.AnnAssign)) and stmt.value is not None:
                    for target in stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]:
                        if isinstance(target, ast.Name):
                            var = f"{self.lineage(cls.name)[-1]}.{target.id}"
                            self.kinds.setdefault(var, set()).update(k for k in [_kind(stmt.value)] if k)
        for frame, nodes in [(self.module, self.module_nodes), *self.scopes]:
            for node in nodes:
                if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
                    for target, value in _pairs(node.targets if isinstance(node, ast.Assign) else [node.target],
                                                node.value):
                        if isinstance(target, ast.Subscript):
                            add(target.value, frame, "container", True)
                        else:
                            add(target, frame, _kind(value) if value is not None else None, True)
                elif isinstance(node, ast.AugAssign):
                    target = node.target
                    add(target.value if isinstance(target, ast.Subscript) else target, frame, None, True)
                elif isinstance(node, ast.Compare) and len(node.ops) == 1 and isinstance(node.ops[0], (ast.Is, ast.IsNot)):
                    for side, other in ((node.left, node.comparators[0]), (node.comparators[0], node.left)):
                        if isinstance(other, ast.Constant) and other.value is None:
                            add(side, frame, "optional")
                elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                    method = node.func.attr
                    if method in _ADDS | _TAKES | {"clear"}:
                        add(node.func.value, frame, "container", True)
                    elif method in _EMPTY_TESTS:
                        add(node.func.value, frame, "container")
                elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "len" \
                        and len(node.args) == 1:
                    add(node.args[0], frame, "container")

    def truthy(self, var: str, truth: bool) -> str:
        """What `if var:` tests, in the variable's vocabulary."""
        kinds = self.kinds.get(var, set())
        yes, no = ("true", "false") if "flag" in kinds else ("nonempty", "empty") if "container" in kinds \
            else ("set", "unset") if "optional" in kinds else ("true", "false")
        return yes if truth else no

    def constant(self, expr: ast.expr, frame: _Frame) -> str | None:
        """The text of a constant: a literal, a module or class constant, an enum-like dotted name."""
        if isinstance(expr, ast.Constant):
            value = self.ex.value(expr)
            return value if isinstance(value, str) else None
        if isinstance(expr, ast.UnaryOp) and isinstance(expr.op, ast.USub) and isinstance(expr.operand, ast.Constant) \
                and isinstance(expr.operand.value, (int, float)):
            return f"-{expr.operand.value}"
        if not isinstance(expr, (ast.Name, ast.Attribute)) or self.state_var(expr, frame) in self.mutable:
            return None
        if isinstance(expr, ast.Name) and self.is_parameter(expr.id, frame):
            return None
        value = self.ex.value(expr, scope=self.function(frame))
        if isinstance(value, str):
            return value
        root: ast.expr = expr
        while isinstance(root, ast.Attribute):
            root = root.value
        if isinstance(expr, ast.Attribute) and isinstance(root, ast.Name) and \
                (root.id in self.ex.aliases or root.id in self.ex.class_attrs):
            return ast.unparse(expr)
        return None

    def is_parameter(self, name: str, frame: _Frame) -> bool:
        return frame.func is not None and name in _params(frame.func)

    def write_value(self, var: str, expr: ast.expr | None, frame: _Frame) -> str:
        """A state assignment's value: true/false, unset (None), set (an object), empty/nonempty
        (a container), a constant's text, or ? when not known."""
        if expr is None:
            return "?"
        if isinstance(expr, ast.Constant) and expr.value is None:
            return "unset"
        text = self.constant(expr, frame)
        if text is not None:
            return text
        if isinstance(expr, ast.Call) and isinstance(self.ex.value(expr, scope=self.function(frame)), ParamRef):
            return "?"  # a parameter: the configuration decides
        kinds = self.kinds.get(var, set())
        shape = _shape(expr, self.ex.qualified)
        if shape in ("empty", "nonempty"):
            return shape if "container" in kinds or "optional" not in kinds else "set"
        if shape == "object" and not kinds & {"flag", "container", "constant"}:
            return "set"
        return "?"

    # -- conditions -----------------------------------------------------------------------
    def condition(self, test: ast.expr, truth: bool, frame: _Frame, depth: int = 0) -> list[Guard]:
        """The state guards that hold when `test` evaluates to `truth`."""
        if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
            return self.condition(test.operand, not truth, frame, depth)
        if isinstance(test, ast.BoolOp):
            conjunction = isinstance(test.op, ast.And)
            if conjunction == truth:  # `a and b` true, `a or b` false: every operand
                return [g for v in test.values for g in self.condition(v, truth, frame, depth)]
            rest = [v for v in test.values if _running(v) is not conjunction]  # ros ok() holds while running
            return self.condition(rest[0], truth, frame, depth) if len(rest) == 1 else []
        if isinstance(test, ast.Compare) and len(test.ops) == 1:
            left, op, right = test.left, test.ops[0], test.comparators[0]
            found = self.comparison(left, op, right, truth, frame)
            return found if found or type(op) not in _FLIPPED else \
                self.comparison(right, _FLIPPED[type(op)](), left, truth, frame)
        if isinstance(test, ast.Call):
            return self.call_condition(test, truth, frame, depth)
        var = self.state_var(test, frame)
        return [self.guard(var, self.truthy(var, truth), test)] if var else []

    def guard(self, var: str, value: str, at: ast.AST) -> Guard:
        return Guard(var, value, self.file, getattr(at, "lineno", 0))

    def comparison(self, subject: ast.expr, op: ast.cmpop, other: ast.expr, truth: bool, frame: _Frame) -> list[Guard]:
        if isinstance(subject, ast.Call) and isinstance(subject.func, ast.Name) and subject.func.id == "len" \
                and len(subject.args) == 1 and (var := self.state_var(subject.args[0], frame)) and \
                isinstance(other, ast.Constant) and type(other.value) is int and 0 <= other.value <= 64 and \
                type(op) in _COMPARE:
            holds = _COMPARE[type(op)]
            at_zero = holds(0, other.value)
            positive = [holds(n, other.value) for n in range(1, other.value + 3)]
            if at_zero != truth:
                return [self.guard(var, "nonempty", subject)]
            if not any(p == truth for p in positive):
                return [self.guard(var, "empty", subject)]
            return []
        var = self.state_var(subject, frame)
        if var is None:
            return []
        if isinstance(op, (ast.Is, ast.IsNot)) and isinstance(other, ast.Constant) and other.value is None:
            return [self.guard(var, "unset" if isinstance(op, ast.Is) == truth else "set", subject)]
        if isinstance(op, (ast.Eq, ast.Is, ast.NotEq, ast.IsNot)) and isinstance(op, (ast.Eq, ast.Is)) == truth:
            text = self.constant(other, frame)
            return [self.guard(var, text, subject)] if text is not None else []
        return []

    def call_condition(self, test: ast.Call, truth: bool, frame: _Frame, depth: int) -> list[Guard]:
        """len(x), x.empty(), bool(x), and predicates of the file that return one expression."""
        func = test.func
        if isinstance(func, ast.Name) and func.id in ("len", "bool") and len(test.args) == 1:
            var = self.state_var(test.args[0], frame)
            if func.id == "bool":
                return self.condition(test.args[0], truth, frame, depth)
            return [self.guard(var, "nonempty" if truth else "empty", test)] if var else []
        if isinstance(func, ast.Attribute) and func.attr in _EMPTY_TESTS and not test.args:
            var = self.state_var(func.value, frame)
            return [self.guard(var, "empty" if truth else "nonempty", test)] if var else []
        targets = self.callables(func, frame) if depth < 3 else []
        if len(targets) == 1 and not isinstance(targets[0].func, ast.Lambda):
            body = [s for s in targets[0].func.body if not _is_docstring(s)]
            if len(body) == 1 and isinstance(body[0], ast.Return) and body[0].value is not None:
                return self.condition(body[0].value, truth, self.bind(targets[0], test, frame), depth + 1)
        return []

    # -- what expressions hold ------------------------------------------------------------
    def values(self, name: str, frame: _Frame) -> list[tuple[ast.expr, _Frame]]:
        """The expressions a name may hold, each with the frame to read it in."""
        while frame is not None and frame.func is not None:
            bound = frame.bound(name)
            if bound is not None:
                return [bound]
            if name in _params(frame.func):
                default = _defaults(frame.func).get(name)
                if frame.called or isinstance(frame.func, ast.Lambda):
                    return [(default, frame)] if default is not None else []
                return self.passed(frame.func, name)
            local, declared = self.local_names(frame.func)
            if name in declared:
                break
            if name in local:
                function = self.functions.get(id(frame.func))
                return [(e, frame) for e in function.assigns.get(name, []) if isinstance(e, ast.expr)] \
                    if function else []
            frame = frame.outer  # type: ignore[assignment]
        return self.global_values.get(name, [])

    def passed(self, func: FunctionNode, name: str) -> list[tuple[ast.expr, _Frame]]:
        """What the call sites in the file pass for a parameter (its default when they do not)."""
        key = (id(func), name)
        if key not in self.arguments:
            function = self.functions.get(id(func))
            self.arguments[key] = [(e, self.canonical(caller)) for e, caller in
                                   (self.ex.arguments(function, name) if function else []) if e is not None]
        return self.arguments[key]

    def attribute_values(self, expr: ast.Attribute, frame: _Frame, depth: int) -> list[tuple[ast.expr, _Frame]]:
        """The values assigned to an attribute of `self` or of an instance of a class of the file."""
        found: list[tuple[ast.expr, _Frame]] = []
        for cls in self.classes_of(expr.value, frame, depth):
            for owner in self.lineage(cls) + self.descendants(cls):
                for value in self.ex.class_attrs.get(owner, {}).get(expr.attr, []):
                    if isinstance(value, ast.expr):
                        found.append((value, self.canonical(self.ex.attr_scope.get(id(value)), cls)))
        return found

    def memo(self, compute: Callable[[ast.expr, _Frame, int], list], expr: ast.expr, frame: _Frame,
             depth: int) -> list:
        """A resolution computed once per expression and frame (near the top of a resolution,
        where the depth limit does not cut it short)."""
        if depth > 2:
            return compute(expr, frame, depth)
        key = (compute.__name__, id(expr), frame)
        if key not in self.resolved:
            self.resolved[key] = compute(expr, frame, depth)
        return self.resolved[key]

    def classes_of(self, expr: ast.expr, frame: _Frame, depth: int = 0) -> list[str]:
        """The classes of the file an object may be an instance of."""
        return self.memo(self._classes_of, expr, frame, depth)

    def _classes_of(self, expr: ast.expr, frame: _Frame, depth: int) -> list[str]:
        if isinstance(expr, ast.Name) and expr.id == "self" and frame.cls:
            return [frame.cls]
        found = list(dict.fromkeys(c.func.id for c, _f in self.origins(expr, frame, depth + 1)
                                   if isinstance(c.func, ast.Name) and c.func.id in self.ex.class_attrs))
        if not found and isinstance(expr, ast.Name) and frame.func is not None and \
                (annotation := _annotations(frame.func).get(expr.id)) is not None:
            name = annotation.value if isinstance(annotation, ast.Constant) else ast.unparse(annotation)
            found = [name] if name in self.ex.class_attrs else []  # a parameter annotated with a class of the file
        return found

    def origins(self, expr: ast.expr, frame: _Frame, depth: int = 0) -> list[tuple[ast.Call, _Frame]]:
        """The calls that may have made the object an expression holds: a constructor, or what a
        function of the file returns."""
        return self.memo(self._origins, expr, frame, depth)

    def _origins(self, expr: ast.expr, frame: _Frame, depth: int) -> list[tuple[ast.Call, _Frame]]:
        if depth > 10:
            return []
        if isinstance(expr, ast.Call):
            if isinstance(expr.func, ast.Name) and expr.func.id in self.ex.class_attrs:
                return [(expr, frame)]
            targets = self.callables(expr.func, frame, depth + 1)
            if not targets:
                return [(expr, frame)]
            return [o for t in targets for callee in [self.bind(t, expr, frame)]
                    for r in self.returns(t.func) for o in self.origins(r, callee, depth + 1)]
        if isinstance(expr, ast.IfExp):
            return self.origins(expr.body, frame, depth + 1) + self.origins(expr.orelse, frame, depth + 1)
        if isinstance(expr, ast.Name):
            return [o for e, f in self.values(expr.id, frame) for o in self.origins(e, f, depth + 1)]
        if isinstance(expr, ast.Attribute):
            return [o for e, f in self.attribute_values(expr, frame, depth + 1) for o in self.origins(e, f, depth + 1)]
        return []

    def callables(self, expr: ast.expr, frame: _Frame, depth: int = 0) -> list[_Target]:
        """The functions of the file a callee expression may be: methods (with overrides in
        subclasses), module and nested functions, lambdas, functools.partial, constructors, and
        callables stored in attributes."""
        return self.memo(self._callables, expr, frame, depth)

    def _callables(self, expr: ast.expr, frame: _Frame, depth: int) -> list[_Target]:
        if depth > 10:
            return []
        if isinstance(expr, ast.Lambda):
            return [_Target(expr, frame.cls, frame)]
        if isinstance(expr, ast.Call) and (self.ex.qualified(expr.func) or "").endswith("partial") and expr.args:
            return [replace(t, preset=t.preset + tuple((a, frame) for a in expr.args[1:]))
                    for t in self.callables(expr.args[0], frame, depth + 1)]
        if isinstance(expr, ast.Attribute):
            value = expr.value
            if isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and value.func.id == "super":
                owner = self.owner_class(frame)
                bases = self.lineage(owner)[1:] if owner else []
                return self.methods(bases, expr.attr, frame.cls, overrides=False)
            found = [t for cls in self.classes_of(value, frame, depth + 1)
                     for t in self.methods([cls], "run" if expr.attr == "start" and self.is_thread(cls) else expr.attr,
                                           cls)]
            return found or [t for e, f in self.attribute_values(expr, frame, depth + 1)  # a stored callable
                             for t in self.callables(e, f, depth + 1)]
        if not isinstance(expr, ast.Name):
            return []
        name = expr.id
        scope: _Frame | None = frame
        while scope is not None and scope.func is not None:
            nested = self.nested.get(id(scope.func), {})
            if name in nested:
                return [_Target(nested[name], scope.cls, scope)]
            if scope.bound(name) or name in self.local_names(scope.func)[0]:
                return [t for e, f in self.values(name, scope) for t in self.callables(e, f, depth + 1)]
            scope = scope.outer
        if (None, name) in self.ex.functions:
            return [_Target(self.ex.functions[(None, name)].node, None, None)]
        if name in self.ex.class_attrs:
            return self.methods([name], "__init__", name)
        return [t for e, f in self.global_values.get(name, []) for t in self.callables(e, f, depth + 1)]

    def methods(self, classes: list[str], name: str, cls: str | None, overrides: bool = True) -> list[_Target]:
        """A method as found from the classes upward, and its overrides in subclasses of the file."""
        found: list[_Target] = []
        for start in classes:
            for owner in self.lineage(start):
                if (owner, name) in self.ex.functions:
                    found.append(_Target(self.ex.functions[(owner, name)].node, cls, None, True))
                    break
            for sub in self.descendants(start) if overrides else []:
                if (sub, name) in self.ex.functions:
                    found.append(_Target(self.ex.functions[(sub, name)].node, sub, None, True))
        return list({id(t.func): t for t in found}.values())

    def is_thread(self, cls: str) -> bool:
        """A threading.Thread subclass (its start() runs its run())."""
        return any(base == "threading.Thread" for c in self.lineage(cls) for base in self.ex.class_bases.get(c, []))

    def owner_class(self, frame: _Frame) -> str | None:
        while frame is not None and frame.func is not None:
            if id(frame.func) in self.owner:
                return self.owner[id(frame.func)]
            frame = frame.outer  # type: ignore[assignment]
        return None

    def bind(self, target: _Target, call: ast.Call | None, frame: _Frame,
             extra: list[tuple[ast.expr, _Frame]] | None = None) -> _Frame:
        """The callee's frame: partial's arguments, then the call's; `extra` (callback_args)
        binds the last parameters."""
        return self.bind_arguments(target, call.args if call else [], call.keywords if call else [], frame, extra)

    def bind_arguments(self, target: _Target, passed: list[ast.expr], keywords: list[ast.keyword], frame: _Frame,
                       extra: list[tuple[ast.expr, _Frame]] | None = None) -> _Frame:
        params = _params(target.func, positional=True)
        if target.method and params:
            params = params[1:]
        positional = list(target.preset)
        for arg in passed:
            if isinstance(arg, ast.Starred):
                break
            positional.append((arg, frame))
        args = [(p, e, f) for p, (e, f) in zip(params, positional)]
        args += [(kw.arg, kw.value, frame) for kw in keywords if kw.arg]
        if extra and len(params) > len(positional):
            args += [(p, e, f) for p, (e, f) in zip(params[len(params) - len(extra):], extra)]
        return _Frame(target.func, target.cls, tuple(args), target.outer, True)

    def publisher_sites(self, expr: ast.expr, frame: _Frame) -> list[Site]:
        """The publisher ports (rospy/rclpy publishers, tf broadcasters) an object may be."""
        return list(dict.fromkeys(s for c, _f in self.origins(expr, frame)
                                  if (s := Site(self.file, c.lineno)) in self.sites["publisher"]))

    # -- loops ----------------------------------------------------------------------------
    def period(self, loop: ast.While, frame: _Frame) -> Value:
        """The loop's period in seconds: from its sleep (rate.sleep(), rospy.sleep(x),
        time.sleep(x), spin_once's timeout), preferring those at the top of its body."""
        top = [s.value for s in loop.body if isinstance(s, ast.Expr) and isinstance(s.value, ast.Call)]
        anywhere = [n for n in _in_scope(loop.body) if isinstance(n, ast.Call)]
        for calls in (top, anywhere):
            found = list(dict.fromkeys(p for c in calls if (p := self.sleep(c, frame)) is not None))
            if len(found) == 1:
                return found[0]
            if found:
                return Unknown("several sleeps in the loop", self.file, loop.lineno)
        return Unknown("no sleep in the loop", self.file, loop.lineno)

    def state_only(self, test: ast.expr, frame: _Frame) -> bool:
        """A test of state only (`while not self.done`): with a sleep, the loop runs until
        shutdown or until a callback changes the state."""
        if self.state_var(test, frame) or isinstance(test, ast.Constant):
            return True
        if isinstance(test, ast.Call):
            return _running(test) is not None
        return isinstance(test, (ast.UnaryOp, ast.BoolOp, ast.Compare)) and all(
            self.state_only(c, frame) for c in ast.iter_child_nodes(test) if isinstance(c, ast.expr))

    def sleep(self, call: ast.Call, frame: _Frame) -> Value | None:
        """The seconds a call sleeps (Unknown when not known); None when it does not sleep."""
        name = self.ex.qualified(call.func) or ""
        scope = self.function(frame)
        if isinstance(call.func, ast.Attribute) and call.func.attr == "wait" and (call.args or call.keywords):
            return Unknown(ast.unparse(call), self.file, call.lineno)  # a condition or event with a timeout
        if name in ("rospy.sleep", "time.sleep") and call.args:
            arg = call.args[0]
            if isinstance(arg, ast.Call) and (self.ex.qualified(arg.func) or "").startswith("rospy.Duration") \
                    and arg.args:
                arg = arg.args[0]
            return self.ex.value(arg, scope=scope)
        if name == "rclpy.spin_once":
            timeout = _arg(call, NO_INDEX, "timeout_sec")
            return self.ex.value(timeout, scope=scope) if timeout is not None else \
                Unknown("spin_once waits for a callback", self.file, call.lineno)
        if isinstance(call.func, ast.Attribute) and call.func.attr == "sleep" and not call.args:
            rates = [self.rate(c, f) for c, f in self.origins(call.func.value, frame)]
            found = list(dict.fromkeys(r for r in rates if r is not None))
            return found[0] if len(found) == 1 else Unknown(ast.unparse(call), self.file, call.lineno)
        return None

    def rate(self, call: ast.Call, frame: _Frame) -> Value | None:
        """Seconds of rospy.Rate(hz) / node.create_rate(hz); a parameter's default folds."""
        rospy = self.ex.qualified(call.func) == "rospy.Rate"
        if not rospy and not (isinstance(call.func, ast.Attribute) and call.func.attr == "create_rate"):
            return None
        hz = _arg(call, 0, "hz" if rospy else "frequency")
        if hz is None:
            return Unknown(ast.unparse(call), self.file, call.lineno)
        value = self.ex.value(hz, scope=self.function(frame))
        if isinstance(value, ParamRef):
            value = value.default
        try:
            return repr(1 / float(value)) if isinstance(value, str) else Unknown(f"1/{ast.unparse(hz)}", self.file,
                                                                                 call.lineno)
        except (ValueError, ZeroDivisionError):
            return Unknown(f"1/{ast.unparse(hz)}", self.file, call.lineno)

    # -- entries --------------------------------------------------------------------------
    def run(self) -> None:
        for frame, nodes in [(self.module, self.module_nodes), *self.scopes]:
            for node in nodes:
                if isinstance(node, ast.Call):
                    self.register(node, frame)
        self.walk(self.ex.tree.body, self.module, _Context("startup", None))
        for startup in (True, False):  # main and constructors run at start-up; the rest: unknown
            for frame, _nodes in self.scopes:
                func = frame.func
                if id(func) in self.reached:
                    continue
                name = getattr(func, "name", "")
                if startup == ((name == "main" and frame.cls is None and frame.outer is None) or name == "__init__"):
                    self.enter(replace(frame, called=True), _Context("startup" if startup else "unknown", None))
        walked = {p.line for p in self.publishes}
        for frame, nodes in [(self.module, self.module_nodes), *self.scopes]:  # past the budget or the depth
            for node in nodes:
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
                        node.func.attr in _PUBLISH_METHODS and node.lineno not in walked and \
                        not self.callables(node.func, frame) and (sites := self.publish_sites(node, frame)):
                    self.publish(node, _Context("unknown", None), sites)

    def register(self, call: ast.Call, frame: _Frame, exact: bool = False) -> None:
        """A call that registers callbacks: each callback is an entry with the port's site. In a
        base class, it registers once for each class of the file made from it (then `exact`)."""
        name = self.ex.qualified(call.func) or ""
        method = call.func.attr if isinstance(call.func, ast.Attribute) else ""
        spec = _REGISTRATIONS.get(name) or _RCLPY_REGISTRATIONS.get(method)
        if frame.cls and not exact and (spec or method in _LATER_REGISTRATIONS):
            concrete = [c for c in [frame.cls, *self.descendants(frame.cls)] if c in self.instantiated]
            if concrete and concrete != [frame.cls]:
                for cls in concrete:
                    self.register(call, replace(frame, cls=cls), exact=True)
                return
        if spec:
            site = Site(self.file, call.lineno)
            if not any(site in self.sites[k] for k in _SOURCE_KINDS):
                return
            extra = _arg(call, 3, "callback_args") if name == "rospy.Subscriber" else None
            for index, keyword in spec[1]:
                callback = _arg(call, index, keyword)
                if callback is not None:
                    self.start(callback, frame, spec[0], site, [(extra, frame)] if extra is not None else [])
        elif method in _LATER_REGISTRATIONS and call.args:
            for site in self.port_sites(call.func.value, frame):  # type: ignore[attr-defined]
                trigger = "timer" if site in self.sites["timer"] else "callback"
                self.start(call.args[0], frame, trigger, site, [(a, frame) for a in call.args[1:]])

    def port_sites(self, expr: ast.expr, frame: _Frame) -> list[Site]:
        """The source ports an object stands for: a subscriber, an action server, or the
        subscribers a message_filters synchronizer joins."""
        sites: list[Site] = []
        for origin, where in self.origins(expr, frame):
            site = Site(self.file, origin.lineno)
            if any(site in self.sites[k] for k in _SOURCE_KINDS):
                sites.append(site)
            elif (self.ex.qualified(origin.func) or "").endswith("Synchronizer") and origin.args:
                inputs = origin.args[0]
                elements = inputs.elts if isinstance(inputs, (ast.List, ast.Tuple)) else \
                    [e for value, _f in self.values(inputs.id, where) if isinstance(value, (ast.List, ast.Tuple))
                     for e in value.elts] if isinstance(inputs, ast.Name) else []
                sites += [s for e in elements for s in self.port_sites(e, where)]
        return list(dict.fromkeys(sites))

    def start(self, callback: ast.expr, frame: _Frame, trigger: str, site: Site,
              extra: list[tuple[ast.expr, _Frame]]) -> None:
        for target in self.callables(callback, frame):
            self.enter(self.bind(target, None, frame, extra), _Context(trigger, site))

    def enter(self, frame: _Frame, ctx: _Context) -> None:
        """Walk a function's body on a path (once per frame and path state)."""
        func = frame.func
        assert func is not None
        key = (frame, ctx.trigger, ctx.source, ctx.guards, ctx.loop)
        if key in self.walked or id(func) in ctx.stack or len(ctx.stack) >= _MAX_DEPTH or self.budget <= 0:
            return
        self.walked.add(key)
        self.budget -= 1
        self.reached.add(id(func))
        ctx = replace(ctx, stack=ctx.stack + (id(func),))
        if isinstance(func, ast.Lambda):
            self.expression(func.body, frame, ctx)
        else:
            self.walk(func.body, frame, ctx)

    # -- walking --------------------------------------------------------------------------
    def walk(self, body: list[ast.stmt], frame: _Frame, ctx: _Context) -> _Context | None:
        """A block in order; returns the path state after it, None when it always leaves
        (return, raise, continue, break): the guards of early returns hold for what follows."""
        for stmt in body:
            after = self.statement(stmt, frame, ctx)
            if after is None:
                return None
            ctx = after
        return ctx

    def statement(self, stmt: ast.stmt, frame: _Frame, ctx: _Context) -> _Context | None:
        if isinstance(stmt, ast.If):
            self.expression(stmt.test, frame, ctx)
            yes = self.walk(stmt.body, frame, ctx.guarded(self.condition(stmt.test, True, frame)))
            no = self.walk(stmt.orelse, frame, ctx.guarded(self.condition(stmt.test, False, frame)))
            return _join(ctx, [c for c in (yes, no) if c is not None])
        if isinstance(stmt, ast.While):
            self.expression(stmt.test, frame, ctx)
            inner = ctx.guarded(self.condition(stmt.test, True, frame))
            if _periodic(stmt.test) or (self.state_only(stmt.test, frame) and any(
                    self.sleep(c, frame) is not None for c in _in_scope(stmt.body) if isinstance(c, ast.Call))):
                inner = replace(inner, loop=(self.period(stmt, frame),))
            self.walk(stmt.body, frame, inner)
            self.walk(stmt.orelse, frame, ctx)
            return ctx if _breaks(stmt.body) else ctx.guarded(self.condition(stmt.test, False, frame))
        if isinstance(stmt, (ast.For, ast.AsyncFor)):
            self.expression(stmt.iter, frame, ctx)
            self.walk(stmt.body, frame, ctx)
            self.walk(stmt.orelse, frame, ctx)
            return ctx
        if isinstance(stmt, (ast.With, ast.AsyncWith)):
            for item in stmt.items:
                self.expression(item.context_expr, frame, ctx)
            return self.walk(stmt.body, frame, ctx)
        if isinstance(stmt, (ast.Try, ast.TryStar)):
            body = self.walk(stmt.body, frame, ctx)
            ends = [self.walk(stmt.orelse, frame, body) if body is not None else None]
            ends += [self.walk(h.body, frame, ctx) for h in stmt.handlers]
            self.walk(stmt.finalbody, frame, ctx)
            return _join(ctx, [c for c in ends if c is not None])
        if isinstance(stmt, ast.Match):
            self.expression(stmt.subject, frame, ctx)
            ends = [self.walk(case.body, frame, ctx) for case in stmt.cases]
            return _join(ctx, [c for c in ends if c is not None] + [ctx])
        if isinstance(stmt, (ast.Return, ast.Raise)):
            for part in (stmt.value,) if isinstance(stmt, ast.Return) else (stmt.exc, stmt.cause):
                if part is not None:
                    self.expression(part, frame, ctx)
            return None
        if isinstance(stmt, (ast.Continue, ast.Break)):
            return None
        if isinstance(stmt, ast.ClassDef):
            if frame.func is None:
                self.class_body(stmt, ctx)
            return ctx
        if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)):
            return ctx
        if isinstance(stmt, (ast.Assign, ast.AnnAssign, ast.AugAssign)) and stmt.value is not None:
            self.expression(stmt.value, frame, ctx)
            targets = stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]
            for target, value in _pairs(targets, stmt.value if not isinstance(stmt, ast.AugAssign) else None):
                self.assignment(target, value, frame, ctx, stmt.lineno)
            return self.received(stmt.value, ctx)
        for child in ast.iter_child_nodes(stmt):
            if isinstance(child, ast.expr):
                self.expression(child, frame, ctx)
        if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Call) and \
                self.ex.qualified(stmt.value.func) in _EXITS:
            return None
        return self.received(stmt.value, ctx) if isinstance(stmt, ast.Expr) else ctx

    def received(self, expr: ast.expr, ctx: _Context) -> _Context:
        """After rospy.wait_for_message(topic) a message has arrived: a state of its own
        (`wait_for_message@LINE`) that only that subscriber sets guards what follows."""
        waits = [c for c in self.calls.get(id(expr), []) if self.ex.qualified(c.func) == "rospy.wait_for_message"
                 and Site(self.file, c.lineno) in self.sites["subscriber"]]
        for wait in waits:
            var = f"wait_for_message@{wait.lineno}"
            self.writes[StateWrite(var, "set", Site(self.file, wait.lineno), self.file, wait.lineno)] = None
        return ctx.guarded([self.guard(f"wait_for_message@{w.lineno}", "set", w) for w in waits])

    def class_body(self, cls: ast.ClassDef, ctx: _Context) -> None:
        """Class attributes are initial values of instance state."""
        frame = _Frame(None, cls.name)
        for stmt in cls.body:
            if isinstance(stmt, (ast.Assign, ast.AnnAssign)) and stmt.value is not None:
                for target in stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]:
                    if isinstance(target, ast.Name):
                        var = f"{self.lineage(cls.name)[-1]}.{target.id}"
                        self.write(var, self.write_value(var, stmt.value, frame), ctx, stmt.lineno)

    def assignment(self, target: ast.expr, value: ast.expr | None, frame: _Frame, ctx: _Context, line: int) -> None:
        """A write to state; `a if c else b` writes either."""
        if isinstance(value, ast.IfExp):
            for branch in (value.body, value.orelse):
                self.assignment(target, branch, frame, ctx, line)
        elif isinstance(target, ast.Subscript):
            var = self.state_var(target.value, frame)
            if var:
                self.write(var, "nonempty" if value is not None else "?", ctx, line)
        elif var := self.state_var(target, frame):
            self.write(var, self.write_value(var, value, frame), ctx, line)

    def write(self, var: str, value: str, ctx: _Context, line: int) -> None:
        source = ctx.source if ctx.trigger in ("timer", "callback") else None
        self.writes[StateWrite(var, value, source, self.file, line)] = None

    def expression(self, expr: ast.expr, frame: _Frame, ctx: _Context) -> None:
        """The calls an expression makes (not those inside its lambdas)."""
        if id(expr) not in self.calls:
            self.calls[id(expr)] = [n for n in _in_scope([expr]) if isinstance(n, ast.Call)]  # type: ignore[list-item]
        for call in self.calls[id(expr)]:
            self.call(call, frame, ctx)

    def call(self, call: ast.Call, frame: _Frame, ctx: _Context) -> None:
        func = call.func
        name = self.ex.qualified(func) or ""
        if isinstance(func, ast.Attribute) and (var := self.state_var(func.value, frame)):
            if func.attr in _ADDS or func.attr == "clear":  # taking from a container never fills it
                self.write(var, "nonempty" if func.attr in _ADDS else "empty", ctx, call.lineno)
        targets = self.callables(func, frame)
        if not targets and (sites := self.publish_sites(call, frame)):
            self.publish(call, ctx, sites)
        if name in ("threading.Thread", "rospy.on_shutdown"):  # runs a function (with a thread's args)
            callee = _arg(call, 0, "h") if name == "rospy.on_shutdown" else _arg(call, NO_INDEX, "target")
            passed = _arg(call, NO_INDEX, "args") if name == "threading.Thread" else None
            for target in self.callables(callee, frame) if callee is not None else []:
                self.enter(self.bind_arguments(target, passed.elts if isinstance(passed, (ast.Tuple, ast.List))
                                               else [], [], frame), ctx)
        for target in targets:
            self.enter(self.bind(target, call, frame), ctx)

    def publish_sites(self, call: ast.Call, frame: _Frame) -> list[Site | None]:
        """For a publish call (`.publish()`, or `.sendTransform()` of a broadcaster) that is not a
        method of the file, the sites of the publishers it may use (None: not known); else []."""
        func = call.func
        if not isinstance(func, ast.Attribute) or func.attr not in _PUBLISH_METHODS:
            return []
        sites: list[Site | None] = list(self.publisher_sites(func.value, frame))
        return sites or ([None] if func.attr == "publish" else [])

    def publish(self, call: ast.Call, ctx: _Context, sites: list[Site | None]) -> None:
        trigger, source, period = ctx.trigger, ctx.source, None
        if trigger not in ("timer", "callback") and ctx.loop is not None:
            trigger, source, period = "loop", None, ctx.loop[0]
        for site in sites:
            self.publishes[Publish(site, self.file, call.lineno, trigger, source, ctx.guards, period)] = None


# -- helpers -------------------------------------------------------------------------------
def _params(func: FunctionNode, positional: bool = False) -> list[str]:
    args = func.args
    names = [a.arg for a in args.posonlyargs + args.args]
    if not positional:
        names += [a.arg for a in args.kwonlyargs] + [a.arg for a in (args.vararg, args.kwarg) if a is not None]
    return names


def _defaults(func: FunctionNode) -> dict[str, ast.expr]:
    args = func.args
    positional = args.posonlyargs + args.args
    found = {a.arg: d for a, d in zip(positional[len(positional) - len(args.defaults):], args.defaults)}
    found.update({a.arg: d for a, d in zip(args.kwonlyargs, args.kw_defaults) if d is not None})
    return found


def _annotations(func: FunctionNode) -> dict[str, ast.expr]:
    if isinstance(func, ast.Lambda):
        return {}
    args = func.args
    return {a.arg: a.annotation for a in args.posonlyargs + args.args + args.kwonlyargs if a.annotation is not None}


def _pairs(targets: Sequence[ast.expr], value: ast.expr | None) -> Iterator[tuple[ast.expr, ast.expr | None]]:
    """Each assigned target with its value (tuple unpacking pairs up when the shapes agree)."""
    for target in targets:
        if isinstance(target, (ast.Tuple, ast.List)):
            values = value.elts if isinstance(value, (ast.Tuple, ast.List)) and \
                len(value.elts) == len(target.elts) else [None] * len(target.elts)
            for element, element_value in zip(target.elts, values):
                yield from _pairs([element], element_value)
        else:
            yield target, value


def _kind(value: ast.expr) -> str | None:
    """flag, container, optional (None or an object) or constant, from an assigned value."""
    if isinstance(value, ast.Constant):
        return "optional" if value.value is None else "flag" if isinstance(value.value, bool) else "constant"
    if isinstance(value, (ast.Compare, ast.UnaryOp)) and not isinstance(getattr(value, "op", None), ast.USub):
        return "flag"
    if isinstance(value, (ast.List, ast.Dict, ast.Set, ast.ListComp, ast.DictComp, ast.SetComp)) or \
            isinstance(value, ast.Call) and _callee_name(value) in _CONTAINER_TYPES:
        return "container"
    return "optional" if _shape(value, lambda _e: None) == "object" else None


def _shape(value: ast.expr, qualified: Callable[[ast.expr], str | None]) -> str | None:
    """empty or nonempty for a container literal (or an empty container constructor), object
    for what holds a value (a call, a name, an attribute), None when not known."""
    if isinstance(value, (ast.List, ast.Tuple, ast.Set)):
        return "nonempty" if value.elts else "empty"
    if isinstance(value, ast.Dict):
        return "nonempty" if value.keys else "empty"
    if isinstance(value, ast.Call):
        callee = qualified(value.func) or _callee_name(value)
        if callee.rsplit(".", 1)[-1] in _CONTAINER_TYPES:
            return None if value.args else "empty"
        return None if callee in _SCALAR_CALLS else "object"
    return "object" if isinstance(value, (ast.Name, ast.Attribute, ast.Subscript)) else None


def _callee_name(call: ast.Call) -> str:
    func = call.func
    return func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""


def _running(expr: ast.expr) -> bool | None:
    """The value of a test while the node runs: rospy.is_shutdown() is False, rclpy.ok() and a
    true constant are True; None for anything else."""
    if isinstance(expr, ast.Constant):
        return bool(expr.value)
    if isinstance(expr, ast.UnaryOp) and isinstance(expr.op, ast.Not):
        inner = _running(expr.operand)
        return None if inner is None else not inner
    if isinstance(expr, ast.Call) and not expr.args:
        name = _callee_name(expr)
        return False if name == "is_shutdown" else True if name == "ok" else None
    return None


def _periodic(test: ast.expr) -> bool:
    """An unbounded loop: `while not rospy.is_shutdown()`, `while rclpy.ok()`, `while True`
    (also combined with further conditions by `and`)."""
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And):
        return any(_running(v) is True for v in test.values)
    return _running(test) is True


def _breaks(body: list[ast.stmt]) -> bool:
    """A break of this loop (not of loops nested in it)."""
    pending: list[ast.AST] = list(body)
    while pending:
        node = pending.pop()
        if isinstance(node, ast.Break):
            return True
        if not isinstance(node, (ast.For, ast.AsyncFor, ast.While, ast.FunctionDef, ast.AsyncFunctionDef,
                                 ast.ClassDef, ast.Lambda)):
            pending.extend(ast.iter_child_nodes(node))
        elif isinstance(node, (ast.For, ast.AsyncFor, ast.While)):
            pending.extend(node.orelse)
    return False


def _join(before: _Context, ends: list[_Context]) -> _Context | None:
    """The path state where branches meet (None when none of them reaches it)."""
    if not ends:
        return None
    return ends[0] if len(ends) == 1 else before.keeping(ends)


def _is_docstring(stmt: ast.stmt) -> bool:
    return isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant) and isinstance(stmt.value.value, str)
