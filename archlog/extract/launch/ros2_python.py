"""Python launch files read statically: the module is walked with `ast` (never imported or run)
and `generate_launch_description()` is interpreted over known values.

Expressions reuse the restricted evaluator of substitution.py, extended with what launch files
do: calls of the launch API (launch2_api), of functions defined in the file, and of a few
methods of strings, lists, dicts and launch objects; comprehensions over known lists. A branch
whose test is not known (it depends on a launch argument) is read on both sides, the actions
made there conditional on it. An OpaqueFunction runs at launch time with the context launch
would give it. What cannot be read is an `Unread` value, reported where it ends up. Reading spends
from the budget (archlog.budget): the source's nesting is checked before it is walked, each
statement and expression evaluated is a step, and what the file builds (strings, lists) is
charged before it is built. A value refused is Unread (reported at its line); steps spent past
the limit end the reading at the statement that crossed it.
"""

from __future__ import annotations

import ast
import os
from contextlib import suppress
from dataclasses import dataclass
from pathlib import Path

from archlog import budget, sandbox
from archlog.extract.launch.evaluate import BUILTINS, STR_METHODS, Evaluator, TooDeep, call_size, parse, result_size
from archlog.extract.launch.model import LaunchError, RefusedRead, SubstitutionError, UnknownArg
from archlog.extract.launch.ros2_actions import Action, Condition, Where
from archlog.extract.launch.ros2_api import (
    API_MODULES,
    CONSTRUCTORS,
    FUNCTIONS,
    CallSite,
    ConfigsView,
    ContextValue,
    Description,
    FileHandle,
    LineDict,
    LineTuple,
    PathValue,
    Ref,
    S,
    Unread,
    entities,
    environment,
    perform_in,
    probe,
    read_text,
    to_parts,
)
from archlog.extract.launch.ros2_execute import Ros2Launch
from archlog.extract.launch.ros2_subst import text

MAX_DEPTH = 16
MAX_ITEMS = 10_000
_LIST_METHODS = {"append", "extend", "insert", "pop", "index", "count", "copy", "remove", "reverse"}
_DICT_METHODS = {"get", "items", "keys", "values", "update", "copy", "setdefault", "pop"}
_STR_EXTRA = {"splitlines", "partition", "rpartition", "rsplit", "casefold", "removeprefix", "removesuffix",
              "isalpha", "isalnum", "islower", "isupper", "isspace"}
_PATH_ATTRS = {"parent": lambda p: str(Path(p).parent), "name": lambda p: Path(p).name,
               "stem": lambda p: Path(p).stem, "suffix": lambda p: Path(p).suffix}


def describe(path: Path, launcher: Ros2Launch) -> list[Action] | None:
    """The actions `generate_launch_description()` of a Python launch file returns; None (with a
    diagnostic) when the file cannot be read or has no such function."""
    shown = launcher.workspace.display(path)
    try:
        source = sandbox.read_text(path, "launch")
    except sandbox.Refused as exc:
        launcher.diagnostics.add(shown, 1, exc.code, f"cannot read launch file: {exc}", "error")
        return None
    try:
        tree = parse(source, str(path))
    except (SyntaxError, ValueError) as exc:
        line = exc.lineno if isinstance(exc, SyntaxError) and exc.lineno else 1
        launcher.diagnostics.add(shown, line, "launch-python", f"Python launch file does not parse: {exc}", "error")
        return None
    except TooDeep as exc:
        raise budget.crossed(shown, exc.line, exc) from None
    interp = _Interpreter(path, launcher)
    try:
        with suppress(_Return, _Break, _Stop):  # module code that returns or raises ends there
            interp.block(tree.body)  # type: ignore[attr-defined]
        function = interp.globals.get("generate_launch_description")
        if not isinstance(function, _Function):
            launcher.diagnostics.add(shown, 1, "launch-python", "no generate_launch_description() in this Python "
                                     "launch file: nothing is launched from it", "warning")
            return None
        result = interp.call(function, [], {}, function.node.lineno)
        return entities(result, Where(path, function.node.lineno))
    except (budget.BudgetExceeded, RecursionError, MemoryError) as exc:
        raise budget.crossed(shown, interp.line, exc) from None


@dataclass(frozen=True)
class _Function:
    """A function (or lambda) defined in the file, with the scope it was defined in."""

    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
    scope: _Scope
    defaults: tuple[object, ...]
    kw_defaults: tuple[object, ...]


class _Scope:
    """Variables of a module or function body; lookups go outwards."""

    def __init__(self, parent: _Scope | None) -> None:
        self.vars: dict[str, object] = {}
        self.parent = parent

    def find(self, name: str) -> _Scope | None:
        scope: _Scope | None = self
        while scope is not None and name not in scope.vars:
            scope = scope.parent
        return scope


class _Return(Exception):
    def __init__(self, value: object) -> None:
        self.value = value


class _Break(Exception):
    """`break` (and, with `skip`, `continue`) out of a loop body."""

    def __init__(self, skip: bool) -> None:
        self.skip = skip


class _Stop(Exception):
    """A `raise` in a branch that is not known to be taken: the branch ends there."""


class _Interpreter(Evaluator):
    """Reads one Python launch file."""

    def __init__(self, path: Path, launcher: Ros2Launch) -> None:
        super().__init__(self._lookup)
        self.path = path
        self.launcher = launcher
        self.env = launcher.env
        self.guards: list[Condition] = []
        self.module = _Scope(None)
        self.module.vars.update({"__file__": str(path), "__name__": path.stem})
        self.globals = self.module.vars
        self.scope = self.module
        self.depth = 0
        self.sites: list[int] = []  # the lines of the function calls in progress
        self.line = 1
        self.refused: set[int] = set()  # lines where a value was refused within the budget

    def find(self, pkg: str) -> Path | None:
        return self.launcher.workspace.find(pkg)

    def not_given(self, name: str, line: int) -> None:
        self.launcher.diag(Where(self.path, line), "env-not-given", sandbox.not_given_message(name), "note")

    def site(self, line: int) -> int:
        """Where an action made at `line` is reported: at the call of the helper function it was
        made in, when the entry function (generate_launch_description, an OpaqueFunction) called one."""
        return self.sites[1] if len(self.sites) > 1 else line

    def refused_read(self, exc: RefusedRead, line: int) -> None:
        self.launcher.diag(Where(self.path, line), exc.code, f"file not read: {exc}")

    # -- statements -----------------------------------------------------------------------
    def block(self, body: list[ast.stmt]) -> None:
        for stmt in body:
            budget.spend("steps")
            self.line = stmt.lineno
            self.statement(stmt)

    def statement(self, stmt: ast.stmt) -> None:
        if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)):
            args = stmt.args
            self.assign_name(stmt.name, _Function(stmt, self.scope, tuple(self.value(d) for d in args.defaults),
                                                  tuple(None if d is None else self.value(d) for d in args.kw_defaults)))
        elif isinstance(stmt, ast.Assign):
            value = self.value(stmt.value)
            for target in stmt.targets:
                self.assign(target, value)
        elif isinstance(stmt, (ast.AnnAssign, ast.AugAssign)) and stmt.value is not None:
            value = self.value(stmt.value if isinstance(stmt, ast.AnnAssign) else
                               ast.BinOp(stmt.target, stmt.op, stmt.value, lineno=stmt.lineno, col_offset=0))
            self.assign(stmt.target, value)
        elif isinstance(stmt, ast.Expr):
            self.value(stmt.value)
        elif isinstance(stmt, ast.Return):
            raise _Return(None if stmt.value is None else self.value(stmt.value))
        elif isinstance(stmt, ast.If):
            self.branch(stmt)
        elif isinstance(stmt, (ast.For, ast.AsyncFor)):
            self.loop(stmt)
        elif isinstance(stmt, (ast.With, ast.AsyncWith)):
            for item in stmt.items:
                value = self.value(item.context_expr)
                if item.optional_vars is not None:
                    self.assign(item.optional_vars, value)
            self.block(stmt.body)
        elif isinstance(stmt, ast.Try):
            self.block(stmt.body)
            self.block(stmt.orelse)
            self.block(stmt.finalbody)
        elif isinstance(stmt, (ast.Import, ast.ImportFrom)):
            self.imports(stmt)
        elif isinstance(stmt, ast.Raise):
            if self.guards:
                raise _Stop()
            raise _Return(Unread(f"the launch file raises {ast.unparse(stmt.exc) if stmt.exc else ''}", stmt.lineno))
        elif isinstance(stmt, (ast.Break, ast.Continue)):
            raise _Break(isinstance(stmt, ast.Continue))
        elif isinstance(stmt, ast.ClassDef):
            self.assign_name(stmt.name, Unread(f"class {stmt.name} defined in the launch file", stmt.lineno))
        elif isinstance(stmt, ast.While):
            self.launcher.diag(Where(self.path, stmt.lineno), "launch-unknown",
                               "a while loop is not read statically; what it launches is not part of this configuration")

    def imports(self, stmt: ast.Import | ast.ImportFrom) -> None:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                self.assign_name(alias.asname or alias.name.split(".")[0],
                                 Ref(alias.name if alias.asname else alias.name.split(".")[0]))
            return
        for alias in stmt.names:
            name = alias.asname or alias.name
            if stmt.level or not stmt.module:
                self.assign_name(name, Unread(f"relative import of {alias.name}", stmt.lineno))
            else:
                self.assign_name(name, Ref(f"{stmt.module}.{alias.name}"))

    def assign_name(self, name: str, value: object) -> None:
        self.scope.vars[name] = value

    def assign(self, target: ast.expr, value: object) -> None:
        if isinstance(target, ast.Name):
            self.assign_name(target.id, value)
        elif isinstance(target, (ast.Tuple, ast.List)):
            items = list(value) if isinstance(value, (list, tuple)) else None
            if items is None or len(items) != len(target.elts):
                items = [Unread(f"unpacking {_why(value)}", target.lineno)] * len(target.elts)
            for element, item in zip(target.elts, items):
                self.assign(element, item)
        elif isinstance(target, ast.Subscript):
            container, key = self.value(target.value), self.value(target.slice)
            if isinstance(container, dict) and _hashable(key) or isinstance(container, list) and isinstance(key, int) and -len(container) <= key < len(container):
                container[key] = value

    def branch(self, stmt: ast.If) -> None:
        test = self.value(stmt.test)
        if not isinstance(test, Unread):
            self.block(stmt.body if test else stmt.orelse)
            return
        shown = ast.unparse(stmt.test)
        for guard, body in ((f"if {shown}", stmt.body), (f"if not ({shown})", stmt.orelse)):
            if not body:
                continue
            self.guards.append(Condition("guard", text(guard)))
            try:
                self.block(body)
            except _Stop:
                pass
            finally:
                self.guards.pop()

    def loop(self, stmt: ast.For | ast.AsyncFor) -> None:
        items = self.iterable(self.value(stmt.iter))
        if isinstance(items, Unread):
            self.launcher.diag(Where(self.path, stmt.lineno), "launch-unknown", f"loop over a value not known "
                               f"statically ({items.reason}); what it launches is not part of this configuration")
            return
        for item in items:
            self.assign(stmt.target, item)
            try:
                self.block(stmt.body)
            except _Break as exc:
                if not exc.skip:
                    return
        self.block(stmt.orelse)

    def iterable(self, value: object) -> list[object] | Unread:
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, (list, tuple, str)) and len(value) <= MAX_ITEMS:
            return list(value)
        return value if isinstance(value, Unread) else Unread(f"iterating over {_why(value)}", self.line)

    # -- calls ----------------------------------------------------------------------------
    def call(self, function: object, args: list[object], kwargs: dict[str, object], line: int) -> object:
        if isinstance(function, _Function):
            return self.call_function(function, args, kwargs, line)
        if isinstance(function, Ref):
            name = function.name
            handler = FUNCTIONS.get(name)
            if handler is None and name.split(".")[0] in API_MODULES:
                handler = CONSTRUCTORS.get(name.rpartition(".")[2])
            if handler is None:
                return Unread(f"a call to {name}", line)
            try:
                return handler(CallSite(args, kwargs, line, self))
            except LaunchError as exc:
                return Unread(str(exc), line)
        if function is dict and args == [Ref("os.environ")] and not kwargs:
            return args[0]  # a copy of the environment reads as the environment
        if any(function is builtin for builtin in BUILTINS.values()):
            args = [a.path if isinstance(a, PathValue) else a for a in args]  # str(path) is its text
            if any(isinstance(v, Unread) for v in [*args, *kwargs.values()]):
                return next(v for v in [*args, *kwargs.values()] if isinstance(v, Unread))
            budget.charge("characters", call_size(function, args, kwargs))
            if any(not _plain(v) for v in [*args, *kwargs.values()]):
                return Unread(f"{getattr(function, '__name__', 'a builtin')}() of a launch object", line)
            try:
                return function(*args, **kwargs)  # type: ignore[operator]
            except (TypeError, ValueError, KeyError, IndexError, AttributeError, OverflowError) as exc:
                return Unread(f"{getattr(function, '__name__', 'a call')}: {exc}", line)
        return Unread(f"a call of {_why(function)}", line)

    def call_function(self, function: _Function, args: list[object], kwargs: dict[str, object], line: int) -> object:
        if self.depth >= MAX_DEPTH:
            return Unread("functions nested too deeply", line)
        scope = _Scope(function.scope)
        spec = function.node.args
        positional = [*spec.posonlyargs, *spec.args]
        for index, arg in enumerate(positional):
            default_index = index - (len(positional) - len(function.defaults))
            if index < len(args):
                scope.vars[arg.arg] = args[index]
            elif arg.arg in kwargs:
                scope.vars[arg.arg] = kwargs.pop(arg.arg)
            elif default_index >= 0:
                scope.vars[arg.arg] = function.defaults[default_index]
            else:
                scope.vars[arg.arg] = Unread(f"argument {arg.arg} not given", line)
        if spec.vararg is not None:
            scope.vars[spec.vararg.arg] = list(args[len(positional):])
        for arg, default in zip(spec.kwonlyargs, function.kw_defaults):
            scope.vars[arg.arg] = kwargs.pop(arg.arg, default)
        if spec.kwarg is not None:
            scope.vars[spec.kwarg.arg] = {k: v for k, v in kwargs.items() if k not in scope.vars}
        saved, self.scope = self.scope, scope
        self.depth += 1
        self.sites.append(line)
        try:
            if isinstance(function.node, ast.Lambda):
                return self.value(function.node.body)
            self.block(function.node.body)
            return None
        except _Return as result:
            return result.value
        except _Break:
            return Unread("break outside a loop", line)
        finally:
            self.depth -= 1
            self.sites.pop()
            self.scope = saved

    # -- expressions ----------------------------------------------------------------------
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
            if _hashable(k):
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
        budget.charge("characters", sum(len(p) for p in pieces))  # type: ignore[arg-type]
        return "".join(pieces)  # type: ignore[arg-type]

    def visit_FormattedValue(self, node: ast.FormattedValue) -> object:
        value = self.value(node.value)
        if isinstance(value, PathValue):
            value = value.path
        if not _plain(value):
            return value if isinstance(value, Unread) else Unread("a launch object formatted into a string",
                                                                  node.lineno)
        return super().visit_FormattedValue(ast.FormattedValue(_constant(value), node.conversion, node.format_spec))

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
        if not (_plain(left) and _plain(right)):
            return Unread(f"{ast.unparse(node)} over launch objects", node.lineno)
        return super().visit_BinOp(ast.BinOp(_constant(left), node.op, _constant(right)))

    def visit_Compare(self, node: ast.Compare) -> object:
        values = [self.value(node.left), *(self.value(c) for c in node.comparators)]
        unread = next((v for v in values if isinstance(v, Unread)), None)
        if unread is not None:
            return unread
        if not all(_plain(v) for v in values):
            return Unread(f"{ast.unparse(node)} compares launch objects", node.lineno)
        rebuilt = ast.Compare(_constant(values[0]), node.ops, [_constant(v) for v in values[1:]])
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
        if not _plain(operand):
            return Unread(f"{ast.unparse(node)} of a launch object", node.lineno)
        return super().visit_UnaryOp(ast.UnaryOp(node.op, _constant(operand)))

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
            return Unread(f"indexing {_why(target)}", node.lineno)
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
        return Unread(f"attribute {node.attr} of {_why(target)}", node.lineno)

    def visit_Lambda(self, node: ast.Lambda) -> object:
        return _Function(node, self.scope, tuple(self.value(d) for d in node.args.defaults),
                         tuple(None if d is None else self.value(d) for d in node.args.kw_defaults))

    def visit_ListComp(self, node: ast.ListComp) -> object:
        return self.comprehension(node.generators, lambda: self.value(node.elt), node.lineno)

    visit_GeneratorExp = visit_SetComp = visit_ListComp  # type: ignore[assignment]

    def visit_DictComp(self, node: ast.DictComp) -> object:
        pairs = self.comprehension(node.generators, lambda: (self.value(node.key), self.value(node.value)),
                                   node.lineno)
        if not isinstance(pairs, list):
            return pairs
        return {k: v for k, v in pairs if _hashable(k)}

    def comprehension(self, generators: list[ast.comprehension], element: object, line: int) -> object:
        results: list[object] = []
        saved, self.scope = self.scope, _Scope(self.scope)
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

    def visit_Call(self, node: ast.Call) -> object:
        args: list[object] = []
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                spread = self.value(arg.value)
                args.extend(spread if isinstance(spread, (list, tuple)) else [spread])
            else:
                args.append(self.value(arg))
        kwargs: dict[str, object] = {}
        for keyword in node.keywords:
            value = self.value(keyword.value)
            if keyword.arg is not None:
                kwargs[keyword.arg] = value
            elif isinstance(value, dict):
                kwargs.update({str(k): v for k, v in value.items()})
        if isinstance(node.func, ast.Attribute):
            target = self.value(node.func.value)
            if not isinstance(target, Ref):
                return self.method(target, node.func.attr, args, kwargs, node.lineno)
            function: object = Ref(f"{target.name}.{node.func.attr}")
        else:
            function = self.value(node.func)
        if isinstance(function, Unread):
            return function
        return self.call(function, args, kwargs, node.lineno)

    def method(self, target: object, name: str, args: list[object], kwargs: dict[str, object], line: int) -> object:
        """A method call on a value the file holds."""
        if isinstance(target, Unread):
            return target
        if isinstance(target, Description) and name in ("add_action", "add_entity"):
            target.actions.append(args[0] if args else None)
            return None
        if isinstance(target, S) and name == "perform":
            return perform_in(target, args[0] if args else None, line)
        if isinstance(target, S) and name == "find" and args and isinstance(args[0], str):
            found = self.find(args[0])
            return str(found) if found is not None else Unread(f"package '{args[0]}' not found", line)
        if isinstance(target, ContextValue) and name == "perform_substitution":
            return perform_in(args[0] if args else None, target, line)
        if isinstance(target, Condition) and name == "evaluate" and args and isinstance(args[0], ContextValue):
            state = self.launcher.condition((target,), args[0].ctx)
            return state if isinstance(state, bool) else Unread(f"condition {state}", line)
        if isinstance(target, ConfigsView) and name == "get":
            return self.config(target, args[0] if args else None, args[1] if len(args) > 1 else None, line)
        if isinstance(target, (FileHandle, PathValue)) and name in ("read", "read_text"):
            return read_text(target, line, self)
        if isinstance(target, PathValue) and name in ("resolve", "absolute", "expanduser"):
            return PathValue(os.path.realpath(target.path))
        if isinstance(target, PathValue) and name in ("exists", "is_file", "is_dir"):
            return probe({"exists": os.path.exists, "is_file": os.path.isfile, "is_dir": os.path.isdir}[name],
                         target.path, line)
        if isinstance(target, PathValue) and name in ("as_posix", "joinpath"):
            path = Path(target.path)
            if name == "joinpath":
                return PathValue(str(path.joinpath(*[str(a) for a in args])))
            return path.as_posix()
        if isinstance(target, FileHandle) and name in ("__enter__", "close"):
            return target
        if isinstance(target, str):
            return self.string_method(target, name, args, kwargs, line)
        allowed = (_LIST_METHODS if isinstance(target, list) else _DICT_METHODS if isinstance(target, dict)
                   else {"index", "count"} if isinstance(target, tuple) else set())
        if name not in allowed:
            return Unread(f"{_why(target)}.{name}()", line)
        budget.charge("characters", sum(len(a) for a in args if isinstance(a, (list, tuple, dict))))
        try:
            result = getattr(target, name)(*args, **kwargs)
        except (TypeError, ValueError, KeyError, IndexError, AttributeError) as exc:
            return Unread(f"{name}(): {exc}", line)
        return list(result) if name in ("items", "keys", "values") else result

    def string_method(self, target: str, name: str, args: list[object], kwargs: dict[str, object], line: int
                      ) -> object:
        """A str method: those the restricted evaluator allows go through it (with its guards on
        format()), a few more pure ones are called here."""
        if not all(_plain(a) for a in [*args, *kwargs.values()]):
            return Unread(f"str.{name}() of a launch object", line)
        if name in STR_METHODS:
            call = ast.Call(ast.Attribute(_constant(target), name), [_constant(a) for a in args],
                            [ast.keyword(k, _constant(v)) for k, v in kwargs.items()])
            return super().visit_Call(call)
        if name not in _STR_EXTRA:
            return Unread(f"str.{name}()", line)
        try:
            return getattr(target, name)(*args, **kwargs)
        except (TypeError, ValueError) as exc:
            return Unread(f"{name}(): {exc}", line)

    def config(self, view: ConfigsView, name: object, default: object, line: int) -> object:
        """context.launch_configurations[name] (or .get(name, default))."""
        if not isinstance(name, str):
            return Unread("a launch configuration whose name is not known", line)
        value = view.ctx.configs.get(name, default)
        if isinstance(value, UnknownArg):
            return Unread(f"launch argument '{name}' is not known ({value.reason})", line)
        return value


def _constant(value: object) -> ast.Constant:
    """A computed value wrapped for the evaluator (which reads a Constant's value as it is)."""
    return ast.Constant(value)  # type: ignore[arg-type]


def _plain(value: object) -> bool:
    """A plain Python value (what the restricted evaluator computes with); looking at each element
    is an evaluation step."""
    budget.spend("steps")
    if isinstance(value, (list, tuple)):
        return all(_plain(v) for v in value)
    if isinstance(value, dict):
        return all(_plain(k) and _plain(v) for k, v in value.items())
    return value is None or isinstance(value, (str, int, float, bool, bytes))


def _hashable(value: object) -> bool:
    try:
        hash(value)
    except TypeError:
        return False
    return not isinstance(value, Unread)


def _why(value: object) -> str:
    return value.reason if isinstance(value, Unread) else type(value).__name__
