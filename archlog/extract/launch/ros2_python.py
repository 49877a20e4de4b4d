"""Python launch files read statically: the module is walked with `ast` (never imported or run)
and `generate_launch_description()` is interpreted over known values.

Expressions (ros2_python_values) reuse the restricted evaluator of archlog.extract.launch.evaluate,
extended with what launch files do: calls of the launch API (ros2_api), of functions defined in
the file, and of a few methods of strings, lists, dicts and launch objects; comprehensions over
known lists. A branch
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
from pathlib import Path

from archlog import budget, sandbox
from archlog.extract.launch.evaluate import BUILTINS, STR_METHODS, TooDeep, call_size, parse
from archlog.extract.launch.model import LaunchError
from archlog.extract.launch.ros2_actions import Action, Condition, Where
from archlog.extract.launch.ros2_api import API_MODULES, CONSTRUCTORS, FUNCTIONS, perform_in, probe, read_text
from archlog.extract.launch.ros2_api_values import (
    CallSite,
    ConfigsView,
    ContextValue,
    Description,
    FileHandle,
    PathValue,
    Ref,
    S,
    Unread,
    entities,
)
from archlog.extract.launch.ros2_execute import Ros2Launch
from archlog.extract.launch.ros2_python_values import Function, Scope, Values, constant, plain, why
from archlog.extract.launch.ros2_subst import text

MAX_DEPTH = 16
_LIST_METHODS = {"append", "extend", "insert", "pop", "index", "count", "copy", "remove", "reverse"}
_DICT_METHODS = {"get", "items", "keys", "values", "update", "copy", "setdefault", "pop"}
_STR_EXTRA = {"splitlines", "partition", "rpartition", "rsplit", "casefold", "removeprefix", "removesuffix",
              "isalpha", "isalnum", "islower", "isupper", "isspace"}


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
        if not isinstance(function, Function):
            launcher.diagnostics.add(shown, 1, "launch-python", "no generate_launch_description() in this Python "
                                     "launch file: nothing is launched from it", "warning")
            return None
        result = interp.call(function, [], {}, function.node.lineno)
        return entities(result, Where(path, function.node.lineno))
    except (budget.BudgetExceeded, RecursionError, MemoryError) as exc:
        raise budget.crossed(shown, interp.line, exc) from None


class _Return(Exception):
    def __init__(self, value: object) -> None:
        self.value = value


class _Break(Exception):
    """`break` (and, with `skip`, `continue`) out of a loop body."""

    def __init__(self, skip: bool) -> None:
        self.skip = skip


class _Stop(Exception):
    """A `raise` in a branch that is not known to be taken: the branch ends there."""


class _Interpreter(Values):
    """Reads one Python launch file: its statements, and the calls of its functions, of the launch
    API and of methods of the values it holds."""

    def block(self, body: list[ast.stmt]) -> None:
        for stmt in body:
            budget.spend("steps")
            self.line = stmt.lineno
            self.statement(stmt)

    def statement(self, stmt: ast.stmt) -> None:
        if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)):
            args = stmt.args
            defaults = tuple(self.value(d) for d in args.defaults)
            kw_defaults = tuple(None if d is None else self.value(d) for d in args.kw_defaults)
            self.assign_name(stmt.name, Function(stmt, self.scope, defaults, kw_defaults))
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
            self.launcher.hole(Where(self.path, stmt.lineno), "launch-unknown", "a while loop is not read "
                               "statically; what it launches is not part of this configuration")

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
                with suppress(_Stop):
                    self.block(body)
            finally:
                self.guards.pop()

    def loop(self, stmt: ast.For | ast.AsyncFor) -> None:
        items = self.iterable(self.value(stmt.iter))
        if isinstance(items, Unread):
            self.launcher.hole(Where(self.path, stmt.lineno), "launch-unknown", f"loop over a value not known "
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

    def call(self, function: object, args: list[object], kwargs: dict[str, object], line: int) -> object:
        if isinstance(function, Function):
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
            if any(not plain(v) for v in [*args, *kwargs.values()]):
                return Unread(f"{getattr(function, '__name__', 'a builtin')}() of a launch object", line)
            try:
                return function(*args, **kwargs)  # type: ignore[operator]
            except (TypeError, ValueError, KeyError, IndexError, AttributeError, OverflowError) as exc:
                return Unread(f"{getattr(function, '__name__', 'a call')}: {exc}", line)
        return Unread(f"a call of {why(function)}", line)

    def call_function(self, function: Function, args: list[object], kwargs: dict[str, object], line: int) -> object:
        if self.depth >= MAX_DEPTH:
            return Unread("functions nested too deeply", line)
        scope = Scope(function.scope)
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
            return state if isinstance(state, bool) else Unread(f"condition {state[0]}", line)
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
            return Unread(f"{why(target)}.{name}()", line)
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
        if not all(plain(a) for a in [*args, *kwargs.values()]):
            return Unread(f"str.{name}() of a launch object", line)
        if name in STR_METHODS:
            call = ast.Call(ast.Attribute(constant(target), name), [constant(a) for a in args],
                            [ast.keyword(k, constant(v)) for k, v in kwargs.items()])
            return super().visit_Call(call)
        if name not in _STR_EXTRA:
            return Unread(f"str.{name}()", line)
        try:
            return getattr(target, name)(*args, **kwargs)
        except (TypeError, ValueError) as exc:
            return Unread(f"{name}(): {exc}", line)
