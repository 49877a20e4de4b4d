"""Syntax helpers of the behavior walk: parameters, assignment targets, the kind and shape of
assigned values, and the tests and loops that hold while a node runs."""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterator, Sequence

from archlog.extract.python.behavior.paths import FunctionNode

NO_INDEX = 99  # a keyword-only argument
ADDS = {"append", "appendleft", "extend", "extendleft", "insert", "add", "put", "put_nowait", "update", "setdefault"}
TAKES = {"pop", "popleft", "popitem", "remove", "discard", "get", "get_nowait"}
EMPTY_TESTS = {"empty", "is_empty", "isEmpty"}
CONTAINER_TYPES = ("list", "dict", "set", "deque", "OrderedDict", "defaultdict", "Queue", "LifoQueue", "SimpleQueue")
SCALAR_CALLS = {"bool", "int", "float", "str", "len", "abs", "min", "max", "round", "sum", "any", "all", "isinstance"}


def parameters_of(func: FunctionNode, positional: bool = False) -> list[str]:
    """A function's parameter names (only the positional ones if `positional`)."""
    args = func.args
    names = [a.arg for a in args.posonlyargs + args.args]
    if not positional:
        names += [a.arg for a in args.kwonlyargs] + [a.arg for a in (args.vararg, args.kwarg) if a is not None]
    return names


def defaults_of(func: FunctionNode) -> dict[str, ast.expr]:
    """A function's parameter defaults by name."""
    args = func.args
    positional = args.posonlyargs + args.args
    found = {a.arg: d for a, d in zip(positional[len(positional) - len(args.defaults):], args.defaults)}
    found.update({a.arg: d for a, d in zip(args.kwonlyargs, args.kw_defaults) if d is not None})
    return found


def annotations_of(func: FunctionNode) -> dict[str, ast.expr]:
    """A function's parameter annotations by name."""
    if isinstance(func, ast.Lambda):
        return {}
    args = func.args
    return {a.arg: a.annotation for a in args.posonlyargs + args.args + args.kwonlyargs if a.annotation is not None}


def pairs(targets: Sequence[ast.expr], value: ast.expr | None) -> Iterator[tuple[ast.expr, ast.expr | None]]:
    """Each assigned target with its value (tuple unpacking pairs up when the shapes agree)."""
    for target in targets:
        if isinstance(target, (ast.Tuple, ast.List)):
            values = value.elts if isinstance(value, (ast.Tuple, ast.List)) and \
                len(value.elts) == len(target.elts) else [None] * len(target.elts)
            for element, element_value in zip(target.elts, values):
                yield from pairs([element], element_value)
        else:
            yield target, value


def kind_of(value: ast.expr) -> str | None:
    """flag, container, optional (None or an object) or constant, from an assigned value."""
    if isinstance(value, ast.Constant):
        return "optional" if value.value is None else "flag" if isinstance(value.value, bool) else "constant"
    if isinstance(value, (ast.Compare, ast.UnaryOp)) and not isinstance(getattr(value, "op", None), ast.USub):
        return "flag"
    if isinstance(value, (ast.List, ast.Dict, ast.Set, ast.ListComp, ast.DictComp, ast.SetComp)) or \
            isinstance(value, ast.Call) and callee_name(value) in CONTAINER_TYPES:
        return "container"
    return "optional" if shape_of(value, lambda _e: None) == "object" else None


def shape_of(value: ast.expr, qualified: Callable[[ast.expr], str | None]) -> str | None:
    """empty or nonempty for a container literal (or an empty container constructor), object
    for what holds a value (a call, a name, an attribute), None when not known."""
    if isinstance(value, (ast.List, ast.Tuple, ast.Set)):
        return "nonempty" if value.elts else "empty"
    if isinstance(value, ast.Dict):
        return "nonempty" if value.keys else "empty"
    if isinstance(value, ast.Call):
        callee = qualified(value.func) or callee_name(value)
        if callee.rsplit(".", 1)[-1] in CONTAINER_TYPES:
            return None if value.args else "empty"
        return None if callee in SCALAR_CALLS else "object"
    return "object" if isinstance(value, (ast.Name, ast.Attribute, ast.Subscript)) else None


def callee_name(call: ast.Call) -> str:
    """The last name of a call's callee (`f` of `a.b.f()`)."""
    func = call.func
    return func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""


def running(expr: ast.expr) -> bool | None:
    """The value of a test while the node runs: rospy.is_shutdown() is False, rclpy.ok() and a
    true constant are True; None for anything else."""
    if isinstance(expr, ast.Constant):
        return bool(expr.value)
    if isinstance(expr, ast.UnaryOp) and isinstance(expr.op, ast.Not):
        inner = running(expr.operand)
        return None if inner is None else not inner
    if isinstance(expr, ast.Call) and not expr.args:
        name = callee_name(expr)
        return False if name == "is_shutdown" else True if name == "ok" else None
    return None


def periodic(test: ast.expr) -> bool:
    """An unbounded loop: `while not rospy.is_shutdown()`, `while rclpy.ok()`, `while True`
    (also combined with further conditions by `and`)."""
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And):
        return any(running(v) is True for v in test.values)
    return running(test) is True


def breaks(body: list[ast.stmt]) -> bool:
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


def is_docstring(stmt: ast.stmt) -> bool:
    """A string literal statement."""
    return isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant) and isinstance(stmt.value.value, str)
