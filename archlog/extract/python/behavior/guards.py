"""State conditions: what each state variable holds (flag, container, optional, constant), the
guards a test puts on a path, and the values state assignments write."""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable

from archlog.extract.python.behavior.paths import Frame
from archlog.extract.python.behavior.resolve import Resolver
from archlog.extract.python.behavior.syntax import (
    ADDS,
    EMPTY_TESTS,
    TAKES,
    is_docstring,
    kind_of,
    pairs,
    parameters_of,
    running,
    shape_of,
)
from archlog.extract.python.fold import ValueFolder
from archlog.extract.summary import Guard, Port
from archlog.values import ParamRef

_COMPARE: dict[type, Callable[[int, int], bool]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge}
_FLIPPED = {ast.Eq: ast.Eq, ast.NotEq: ast.NotEq, ast.Is: ast.Is, ast.IsNot: ast.IsNot,
            ast.Lt: ast.Gt, ast.Gt: ast.Lt, ast.LtE: ast.GtE, ast.GtE: ast.LtE}


class Guards(Resolver):
    """The kinds of state variables, the guards of tests, and the values of state writes."""

    def __init__(self, folder: ValueFolder, ports: list[Port]) -> None:
        super().__init__(folder, ports)
        self.kinds: dict[str, set[str]] = {}
        self.mutable: set[str] = set()  # state assigned inside functions
        self._classify()

    def _classify(self) -> None:
        """What each state variable holds (flag, container, optional, constant), from its
        assignments and tests, to read `if self.x:` in its own vocabulary."""
        def add(expr: ast.AST, frame: Frame, kind: str | None, written: bool = False) -> None:
            """Record a kind (and a write inside a function) for the state variable an expression is."""
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
                            self.kinds.setdefault(var, set()).update(k for k in [kind_of(stmt.value)] if k)
        for frame, nodes in [(self.module, self.module_nodes), *self.scopes]:
            for node in nodes:
                if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
                    for target, value in pairs(node.targets if isinstance(node, ast.Assign) else [node.target],
                                                node.value):
                        if isinstance(target, ast.Subscript):
                            add(target.value, frame, "container", True)
                        else:
                            add(target, frame, kind_of(value) if value is not None else None, True)
                elif isinstance(node, ast.AugAssign):
                    target = node.target
                    add(target.value if isinstance(target, ast.Subscript) else target, frame, None, True)
                elif isinstance(node, ast.Compare) and len(node.ops) == 1 and \
                        isinstance(node.ops[0], (ast.Is, ast.IsNot)):
                    for side, other in ((node.left, node.comparators[0]), (node.comparators[0], node.left)):
                        if isinstance(other, ast.Constant) and other.value is None:
                            add(side, frame, "optional")
                elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                    method = node.func.attr
                    if method in ADDS | TAKES | {"clear"}:
                        add(node.func.value, frame, "container", True)
                    elif method in EMPTY_TESTS:
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

    def constant(self, expr: ast.expr, frame: Frame) -> str | None:
        """The text of a constant: a literal, a module or class constant, an enum-like dotted name."""
        if isinstance(expr, ast.Constant):
            value = self.folder.value(expr)
            return value if isinstance(value, str) else None
        if isinstance(expr, ast.UnaryOp) and isinstance(expr.op, ast.USub) and isinstance(expr.operand, ast.Constant) \
                and isinstance(expr.operand.value, (int, float)):
            return f"-{expr.operand.value}"
        if not isinstance(expr, (ast.Name, ast.Attribute)) or self.state_var(expr, frame) in self.mutable:
            return None
        if isinstance(expr, ast.Name) and self.is_parameter(expr.id, frame):
            return None
        value = self.folder.value(expr, scope=self.function(frame))
        if isinstance(value, str):
            return value
        root: ast.expr = expr
        while isinstance(root, ast.Attribute):
            root = root.value
        if isinstance(expr, ast.Attribute) and isinstance(root, ast.Name) and \
                (root.id in self.folder.aliases or root.id in self.folder.class_attrs):
            return ast.unparse(expr)
        return None

    def is_parameter(self, name: str, frame: Frame) -> bool:
        """A parameter of the function the frame runs."""
        return frame.func is not None and name in parameters_of(frame.func)

    def write_value(self, var: str, expr: ast.expr | None, frame: Frame) -> str:
        """A state assignment's value: true/false, unset (None), set (an object), empty/nonempty
        (a container), a constant's text, or ? when not known."""
        if expr is None:
            return "?"
        if isinstance(expr, ast.Constant) and expr.value is None:
            return "unset"
        text = self.constant(expr, frame)
        if text is not None:
            return text
        if isinstance(expr, ast.Call) and isinstance(self.folder.value(expr, scope=self.function(frame)), ParamRef):
            return "?"  # a parameter: the configuration decides
        kinds = self.kinds.get(var, set())
        shape = shape_of(expr, self.folder.qualified)
        if shape in ("empty", "nonempty"):
            return shape if "container" in kinds or "optional" not in kinds else "set"
        if shape == "object" and not kinds & {"flag", "container", "constant"}:
            return "set"
        return "?"

    # -- conditions -----------------------------------------------------------------------
    def condition(self, test: ast.expr, truth: bool, frame: Frame, depth: int = 0) -> list[Guard]:
        """The state guards that hold when `test` evaluates to `truth`."""
        if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
            return self.condition(test.operand, not truth, frame, depth)
        if isinstance(test, ast.BoolOp):
            conjunction = isinstance(test.op, ast.And)
            if conjunction == truth:  # `a and b` true, `a or b` false: every operand
                return [g for v in test.values for g in self.condition(v, truth, frame, depth)]
            rest = [v for v in test.values if running(v) is not conjunction]  # ros ok() holds while running
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

    def exact(self, test: ast.expr, truth: bool, frame: Frame, depth: int = 0) -> bool:
        """Whether the guards `condition` gives for `test` are all it takes: they hold exactly when
        `test` evaluates to `truth` (a comparison of a message's field, `a or b`, an unknown call: no)."""
        if running(test) is truth or (truth and _main_guard(test)):
            return True
        if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
            return self.exact(test.operand, not truth, frame, depth)
        if isinstance(test, ast.BoolOp):
            rest = [v for v in test.values if running(v) is not truth]
            if isinstance(test.op, ast.And) == truth:
                return all(self.exact(v, truth, frame, depth) for v in rest)
            return len(rest) == 1 and self.exact(rest[0], truth, frame, depth)
        if isinstance(test, ast.Compare) and len(test.ops) == 1:
            length = test.left if isinstance(test.left, ast.Call) else test.comparators[0]
            if isinstance(length, ast.Call) and isinstance(length.func, ast.Name) and length.func.id == "len":
                return _emptiness(test) is not None and bool(self.condition(test, truth, frame, depth))
            return bool(self.condition(test, truth, frame, depth))
        if isinstance(test, ast.Call):
            func = test.func
            if isinstance(func, ast.Name) and func.id == "bool" and len(test.args) == 1:
                return self.exact(test.args[0], truth, frame, depth)
            targets = self.callables(func, frame) if depth < 3 else []
            if len(targets) == 1 and not isinstance(targets[0].func, ast.Lambda):
                body = [s for s in targets[0].func.body if not is_docstring(s)]
                if len(body) == 1 and isinstance(body[0], ast.Return) and body[0].value is not None:
                    return self.exact(body[0].value, truth, self.bind(targets[0], test, frame), depth + 1)
        return bool(self.condition(test, truth, frame, depth))

    def guard(self, var: str, value: str, at: ast.AST) -> Guard:
        """A guard on `var` at the line of `at`."""
        return Guard(var, value, self.file, getattr(at, "lineno", 0))

    def comparison(self, subject: ast.expr, op: ast.cmpop, other: ast.expr, truth: bool, frame: Frame) -> list[Guard]:
        """The guards of `subject op other`: len(x) against a number, `is None`, `==` a constant."""
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

    def call_condition(self, test: ast.Call, truth: bool, frame: Frame, depth: int) -> list[Guard]:
        """len(x), x.empty(), bool(x), and predicates of the file that return one expression."""
        func = test.func
        if isinstance(func, ast.Name) and func.id in ("len", "bool") and len(test.args) == 1:
            var = self.state_var(test.args[0], frame)
            if func.id == "bool":
                return self.condition(test.args[0], truth, frame, depth)
            return [self.guard(var, "nonempty" if truth else "empty", test)] if var else []
        if isinstance(func, ast.Attribute) and func.attr in EMPTY_TESTS and not test.args:
            var = self.state_var(func.value, frame)
            return [self.guard(var, "empty" if truth else "nonempty", test)] if var else []
        targets = self.callables(func, frame) if depth < 3 else []
        if len(targets) == 1 and not isinstance(targets[0].func, ast.Lambda):
            body = [s for s in targets[0].func.body if not is_docstring(s)]
            if len(body) == 1 and isinstance(body[0], ast.Return) and body[0].value is not None:
                return self.condition(body[0].value, truth, self.bind(targets[0], test, frame), depth + 1)
        return []


def _emptiness(test: ast.Compare) -> bool | None:
    """For `len(x) OP n` (either side): True when it tests exactly that x is non-empty, False
    exactly empty, None when it tests a length in between (len(x) > 2)."""
    op, other = test.ops[0], test.comparators[0] if isinstance(test.left, ast.Call) else test.left
    if not isinstance(other, ast.Constant) or type(other.value) is not int or type(op) not in _COMPARE:
        return None
    holds = _COMPARE[type(op)] if isinstance(test.left, ast.Call) else _COMPARE[type(_FLIPPED[type(op)]())]
    positive = {holds(n, other.value) for n in range(1, max(other.value, 0) + 3)}
    return None if len(positive) != 1 or positive == {holds(0, other.value)} else positive.pop()


def _main_guard(test: ast.expr) -> bool:
    """`__name__ == "__main__"`: true where a node runs as a script."""
    return isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], ast.Eq) and \
        {ast.unparse(test.left), ast.unparse(test.comparators[0])} == {"__name__", "'__main__'"}
