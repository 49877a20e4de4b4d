"""The values of a Python launch file: its names and scopes, and its expressions evaluated over
the restricted evaluator (archlog.extract.launch.evaluate), extended with launch objects; what
cannot be followed is an `Unread` value."""

from __future__ import annotations

import ast
from abc import ABC, abstractmethod
from dataclasses import dataclass
from pathlib import Path

from archlog import budget, sandbox
from archlog.extract.launch.evaluate import BUILTINS, Evaluator, result_size
from archlog.extract.launch.model import RefusedRead, SubstitutionError, UnknownArg
from archlog.extract.launch.ros2_actions import Condition, Where
from archlog.extract.launch.ros2_api import environment
from archlog.extract.launch.ros2_api_values import (
    ConfigsView,
    ContextValue,
    LineDict,
    LineTuple,
    PathValue,
    Ref,
    S,
    Unread,
    to_parts,
)
from archlog.extract.launch.ros2_execute import Ros2Launch

MAX_ITEMS = 10_000
_PATH_ATTRS = {"parent": lambda p: str(Path(p).parent), "name": lambda p: Path(p).name,
               "stem": lambda p: Path(p).stem, "suffix": lambda p: Path(p).suffix}


@dataclass(frozen=True)
class Function:
    """A function (or lambda) defined in the file, with the scope it was defined in."""

    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
    scope: Scope
    defaults: tuple[object, ...]
    kw_defaults: tuple[object, ...]


class Scope:
    """Variables of a module or function body; lookups go outwards."""

    def __init__(self, parent: Scope | None) -> None:
        self.vars: dict[str, object] = {}
        self.parent = parent

    def find(self, name: str) -> Scope | None:
        scope: Scope | None = self
        while scope is not None and name not in scope.vars:
            scope = scope.parent
        return scope


class Values(Evaluator, ABC):
    """The state of one Python launch file being read (its scopes, guards and lines) and the
    values of its expressions."""

    def __init__(self, path: Path, launcher: Ros2Launch) -> None:
        super().__init__(self._lookup)
        self.path = path
        self.launcher = launcher
        self.env = launcher.env
        self.guards: list[Condition] = []
        self.module = Scope(None)
        self.module.vars.update({"__file__": str(path), "__name__": path.stem})
        self.globals = self.module.vars
        self.scope = self.module
        self.depth = 0
        self.sites: list[int] = []  # the lines of the function calls in progress
        self.line = 1
        self.refused: set[int] = set()  # lines where a value was refused within the budget

    def find(self, pkg: str) -> Path | None:
        return self.launcher.workspace.find(pkg)

    def not_given(self, read: sandbox.NotGiven, line: int) -> None:
        self.launcher.diag(Where(self.path, line), *sandbox.env_note(read), "note")

    def site(self, line: int) -> int:
        """Where an action made at `line` is reported: at the call of the helper function it was
        made in, when the entry function (generate_launch_description, an OpaqueFunction) called one."""
        return self.sites[1] if len(self.sites) > 1 else line

    def refused_read(self, exc: RefusedRead, line: int) -> None:
        self.launcher.diag(Where(self.path, line), exc.code, f"file not read: {exc}")

    def assign_name(self, name: str, value: object) -> None:
        self.scope.vars[name] = value

    def assign(self, target: ast.expr, value: object) -> None:
        if isinstance(target, ast.Name):
            self.assign_name(target.id, value)
        elif isinstance(target, (ast.Tuple, ast.List)):
            items = list(value) if isinstance(value, (list, tuple)) else None
            if items is None or len(items) != len(target.elts):
                items = [Unread(f"unpacking {why(value)}", target.lineno)] * len(target.elts)
            for element, item in zip(target.elts, items):
                self.assign(element, item)
        elif isinstance(target, ast.Subscript):
            container, key = self.value(target.value), self.value(target.slice)
            if isinstance(container, list) and isinstance(key, int):
                if -len(container) <= key < len(container):
                    container[key] = value
            elif isinstance(container, dict) and hashable(key):
                container[key] = value

    def iterable(self, value: object) -> list[object] | Unread:
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, (list, tuple, str)) and len(value) <= MAX_ITEMS:
            return list(value)
        return value if isinstance(value, Unread) else Unread(f"iterating over {why(value)}", self.line)

    @abstractmethod
    def call(self, function: object, args: list[object], kwargs: dict[str, object], line: int) -> object:
        """A call of what the file holds (the statement reader calls functions)."""

    def value(self, node: ast.expr) -> object:
        """An expression's value, or Unread where the evaluator cannot follow it (or refuses to build
        it within the budget: reported once per line)."""
        line = getattr(node, "lineno", self.line)
        try:
            return self.visit(node)
        except SubstitutionError as exc:
            return Unread(str(exc), line)
        except budget.BudgetExceeded as exc:
            if budget.exhausted():
                raise
            if line not in self.refused:
                self.refused.add(line)
                self.launcher.diag(Where(self.path, line), "budget-exceeded", f"{exc}; the value is not read", "error")
            return Unread(str(exc), line)

    def _lookup(self, name: str) -> object:
        scope = self.scope.find(name)
        if scope is not None:
            return scope.vars[name]
        if name in ("open", "range", "getattr"):
            return Ref(f"builtins.{name}")
        if name in BUILTINS:
            return BUILTINS[name]
        if name in ("print", "hasattr", "type", "super", "vars", "locals", "globals"):
            return Unread(f"{name}()", self.line)
        return Unread(f"name '{name}' is not defined", self.line)

    def generic_visit(self, node: ast.AST) -> object:
        return Unread(f"{type(node).__name__} is not read statically", getattr(node, "lineno", self.line))

    def visit_Name(self, node: ast.Name) -> object:
        return self._lookup(node.id)

    def visit_Dict(self, node: ast.Dict) -> object:
        result = LineDict()
        result.lines = {}
        for key, item in zip(node.keys, node.values):
            if key is None:
                spread = self.value(item)
                if isinstance(spread, dict):
                    result.update(spread)
                continue
            k = self.value(key)
            if hashable(k):
                result[k] = self.value(item)
                result.lines[k] = key.lineno
        return result

    def visit_Tuple(self, node: ast.Tuple) -> object:
        result = LineTuple(self.value(e) for e in node.elts)
        result.line = node.lineno
        return result

    def visit_List(self, node: ast.List) -> object:
        items: list[object] = []
        for element in node.elts:
            if isinstance(element, ast.Starred):
                spread = self.value(element.value)
                spread = spread if isinstance(spread, (list, tuple)) else [spread]
                budget.charge("characters", len(spread))
                items.extend(spread)
            else:
                items.append(self.value(element))
        return items

    def visit_JoinedStr(self, node: ast.JoinedStr) -> object:
        pieces = [self.value(v) for v in node.values]
        bad = next((p for p in pieces if not isinstance(p, str)), None)
        if bad is not None:
            return bad if isinstance(bad, Unread) else Unread("a launch object formatted into a string", node.lineno)
        strings = [p for p in pieces if isinstance(p, str)]  # all of them
        budget.charge("characters", sum(len(p) for p in strings))
        return "".join(strings)

    def visit_FormattedValue(self, node: ast.FormattedValue) -> object:
        value = self.value(node.value)
        if isinstance(value, PathValue):
            value = value.path
        if not plain(value):
            return value if isinstance(value, Unread) else Unread("a launch object formatted into a string",
                                                                  node.lineno)
        return super().visit_FormattedValue(ast.FormattedValue(constant(value), node.conversion, node.format_spec))

    def visit_BinOp(self, node: ast.BinOp) -> object:
        left, right = self.value(node.left), self.value(node.right)
        for side in (left, right):
            if isinstance(side, Unread):
                return side
        if isinstance(node.op, ast.Add) and (isinstance(left, S) or isinstance(right, S)) and \
                all(isinstance(v, (str, S)) for v in (left, right)):
            parts = to_parts(left, node.lineno), to_parts(right, node.lineno)
            budget.charge("characters", len(parts[0]) + len(parts[1]))
            return S(parts[0] + parts[1])
        if isinstance(node.op, ast.Div) and isinstance(left, PathValue) and isinstance(right, (str, PathValue)):
            return PathValue(str(Path(left.path) / (right if isinstance(right, str) else right.path)))
        if isinstance(node.op, ast.Add) and isinstance(left, (list, tuple)) and isinstance(right, (list, tuple)):
            budget.charge("characters", result_size(node.op, left, right))
            return [*left, *right] if isinstance(left, list) else (*left, *right)
        if not (plain(left) and plain(right)):
            return Unread(f"{ast.unparse(node)} over launch objects", node.lineno)
        return super().visit_BinOp(ast.BinOp(constant(left), node.op, constant(right)))

    def visit_Compare(self, node: ast.Compare) -> object:
        values = [self.value(node.left), *(self.value(c) for c in node.comparators)]
        unread = next((v for v in values if isinstance(v, Unread)), None)
        if unread is not None:
            return unread
        if not all(plain(v) for v in values):
            return Unread(f"{ast.unparse(node)} compares launch objects", node.lineno)
        rebuilt = ast.Compare(constant(values[0]), node.ops, [constant(v) for v in values[1:]])
        return super().visit_Compare(rebuilt)

    def visit_BoolOp(self, node: ast.BoolOp) -> object:
        result: object = isinstance(node.op, ast.And)
        for item in node.values:
            result = self.value(item)
            if isinstance(result, Unread) or bool(result) != isinstance(node.op, ast.And):
                return result
        return result

    def visit_UnaryOp(self, node: ast.UnaryOp) -> object:
        operand = self.value(node.operand)
        if isinstance(operand, Unread):
            return operand
        if isinstance(node.op, ast.Not):
            return not operand
        if not plain(operand):
            return Unread(f"{ast.unparse(node)} of a launch object", node.lineno)
        return super().visit_UnaryOp(ast.UnaryOp(node.op, constant(operand)))

    def visit_IfExp(self, node: ast.IfExp) -> object:
        test = self.value(node.test)
        if isinstance(test, Unread):
            return test
        return self.value(node.body) if test else self.value(node.orelse)

    def visit_Subscript(self, node: ast.Subscript) -> object:
        target, index = self.value(node.value), self.value(node.slice)
        if isinstance(target, Ref) and target.name == "os.environ":
            if not isinstance(index, str):
                return Unread("os.environ[?]", node.lineno)
            return environment(self, index, Unread(f"environment variable {index} is not given", node.lineno),
                               node.lineno)
        if isinstance(target, ConfigsView):
            return self.config(target, index, None, node.lineno)
        if isinstance(target, Unread) or isinstance(index, Unread):
            return target if isinstance(target, Unread) else index
        if not isinstance(target, (dict, list, tuple, str)):
            return Unread(f"indexing {why(target)}", node.lineno)
        try:
            return target[index]  # type: ignore[index, call-overload]
        except (TypeError, KeyError, IndexError) as exc:
            return Unread(f"{ast.unparse(node)}: {exc!r}", node.lineno)

    def visit_Attribute(self, node: ast.Attribute) -> object:
        target = self.value(node.value)
        if isinstance(target, Ref):
            return Ref(f"{target.name}.{node.attr}")
        if isinstance(target, ContextValue) and node.attr == "launch_configurations":
            return ConfigsView(target.ctx)
        if isinstance(target, PathValue) and node.attr in _PATH_ATTRS:
            found = _PATH_ATTRS[node.attr](target.path)
            return PathValue(found) if node.attr == "parent" else found
        if isinstance(target, Unread):
            return target
        return Unread(f"attribute {node.attr} of {why(target)}", node.lineno)

    def visit_Lambda(self, node: ast.Lambda) -> object:
        return Function(node, self.scope, tuple(self.value(d) for d in node.args.defaults),
                         tuple(None if d is None else self.value(d) for d in node.args.kw_defaults))

    def visit_ListComp(self, node: ast.ListComp) -> object:
        return self.comprehension(node.generators, lambda: self.value(node.elt), node.lineno)

    visit_GeneratorExp = visit_SetComp = visit_ListComp  # type: ignore[assignment]

    def visit_DictComp(self, node: ast.DictComp) -> object:
        pairs = self.comprehension(node.generators, lambda: (self.value(node.key), self.value(node.value)),
                                   node.lineno)
        if not isinstance(pairs, list):
            return pairs
        return {k: v for k, v in pairs if hashable(k)}

    def comprehension(self, generators: list[ast.comprehension], element: object, line: int) -> object:
        results: list[object] = []
        saved, self.scope = self.scope, Scope(self.scope)
        try:
            failure = self._generate(generators, element, results)
        finally:
            self.scope = saved
        return failure if failure is not None else results

    def _generate(self, generators: list[ast.comprehension], element: object, results: list[object]) -> Unread | None:
        if not generators:
            results.append(element())  # type: ignore[operator]
            return None
        first = generators[0]
        items = self.iterable(self.value(first.iter))
        if isinstance(items, Unread):
            return items
        for item in items:
            self.assign(first.target, item)
            tests = [self.value(t) for t in first.ifs]
            unknown = next((t for t in tests if isinstance(t, Unread)), None)
            if isinstance(unknown, Unread):
                return unknown
            if all(tests):
                failure = self._generate(generators[1:], element, results)
                if failure is not None:
                    return failure
        return None

    def config(self, view: ConfigsView, name: object, default: object, line: int) -> object:
        """context.launch_configurations[name] (or .get(name, default))."""
        if not isinstance(name, str):
            return Unread("a launch configuration whose name is not known", line)
        value = view.ctx.configs.get(name, default)
        if isinstance(value, UnknownArg):
            return Unread(f"launch argument '{name}' is not known ({value.reason})", line)
        return value


def constant(value: object) -> ast.Constant:
    """A computed value wrapped for the evaluator (which reads a Constant's value as it is)."""
    return ast.Constant(value)  # type: ignore[arg-type]


def plain(value: object) -> bool:
    """A plain Python value (what the restricted evaluator computes with); looking at each element
    is an evaluation step."""
    budget.spend("steps")
    if isinstance(value, (list, tuple)):
        return all(plain(v) for v in value)
    if isinstance(value, dict):
        return all(plain(k) and plain(v) for k, v in value.items())
    return value is None or isinstance(value, (str, int, float, bool, bytes))


def hashable(value: object) -> bool:
    try:
        hash(value)
    except TypeError:
        return False
    return not isinstance(value, Unread)


def why(value: object) -> str:
    return value.reason if isinstance(value, Unread) else type(value).__name__
