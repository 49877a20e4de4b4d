"""The index of a Python source: its imports, functions and classes, assignments and call sites.

Built once per file by a walk over its ast; shared by the port extraction (node.py) and the
behavior recovery (behavior/). Nothing is imported or run.
"""

from __future__ import annotations

import ast
import heapq
from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TypeGuard

_SELF = "self."  # the key of self.method() calls (no class is named so)

Assigned = ast.expr | ast.AugAssign | ast.For | ast.With
"""What a name is assigned: a value, or the statement that assigns it otherwise (`+=`, a loop or with target)."""


@dataclass
class Function:
    """A function or method of the file, with the values assigned to its local names."""

    node: ast.FunctionDef | ast.AsyncFunctionDef
    cls: str | None
    assigns: dict[str, list[Assigned]] = field(default_factory=dict)


class FileIndex:
    """A module's names: import aliases, module and class assignments, functions and call sites."""

    def __init__(self, tree: ast.Module) -> None:
        self.tree = tree
        self.aliases: dict[str, str] = {}
        self.conditional: dict[str, list[str]] = {}  # a name several imports bind to different things
        self.module_assigns: dict[str, list[Assigned]] = {}
        self.class_attrs: dict[str, dict[str, list[Assigned]]] = {}
        self.attr_scope: dict[int, Function] = {}
        self.class_bases: dict[str, list[str]] = {}
        self.functions: dict[tuple[str | None, str], Function] = {}
        # call sites in walk order: (None, function), (class, "__init__"), (_SELF, method) for self.method()
        self.calls: dict[tuple[str | None, str], list[tuple[int, ast.Call]]] = {}
        self.class_of: dict[int, str | None] = {}  # id of a function node -> its class
        self.owners: dict[int, Function] | None = None  # id of a node -> the function it is in
        self.declared: dict[str, ast.expr] = {}
        self._index()

    def _index(self) -> None:
        """Aliases, assignments, functions, class attributes, declared parameters and call sites."""
        bound: dict[str, list[str]] = {}
        for node in ast.walk(self.tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    bound.setdefault(a.asname or a.name.split(".")[0], []).append(
                        a.name if a.asname else a.name.split(".")[0])
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                for a in node.names:
                    bound.setdefault(a.asname or a.name, []).append(f"{node.module}.{a.name}")
        for alias, targets in bound.items():
            self.aliases[alias] = targets[-1]
            if len(set(targets)) > 1:  # imported under conditions: which one runs is not known statically
                self.conditional[alias] = list(dict.fromkeys(targets))
        record_assigns(self.tree.body, self.module_assigns, nested=True)
        for node in self.tree.body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                self._function(node, None)
            elif isinstance(node, ast.ClassDef):
                self.class_bases[node.name] = [self.qualified(b) or "" for b in node.bases]
                attrs = self.class_attrs.setdefault(node.name, {})
                record_assigns(node.body, attrs, nested=False)
                for item in node.body:
                    if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        self._function(item, node.name)
                        for sub in ast.walk(item):
                            if isinstance(sub, (ast.Assign, ast.AnnAssign)):
                                for target in sub.targets if isinstance(sub, ast.Assign) else [sub.target]:
                                    if is_self_attr(target) and sub.value is not None:
                                        attrs.setdefault(target.attr, []).append(sub.value)
                                        self.attr_scope[id(sub.value)] = self.functions[(node.name, item.name)]
                            elif isinstance(sub, ast.AugAssign) and is_self_attr(sub.target):
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
        """Index one function or method with its local assignments."""
        function = Function(node, cls)
        self.class_of[id(node)] = cls
        record_assigns(node.body, function.assigns, nested=True)
        self.functions[(cls, node.name)] = function

    def qualified(self, expr: ast.expr) -> str | None:
        """The dotted name of a name or attribute, its first part resolved through the imports (None when
        that part is bound by several imports to different things: which one runs is not known)."""
        if isinstance(expr, ast.Name):
            return None if expr.id in self.conditional else self.aliases.get(expr.id, expr.id)
        if isinstance(expr, ast.Attribute):
            base = self.qualified(expr.value)
            return f"{base}.{expr.attr}" if base else None
        return None


    def arguments(self, scope: Function, name: str) -> list[tuple[ast.expr | None, Function | None]]:
        """What each call site in the file passes for a parameter (its default when it passes
        nothing), with the caller's scope; the default alone when no call site is in the file."""
        args = scope.node.args
        positional = [a.arg for a in args.args]
        if scope.cls and positional and positional[0] in ("self", "cls"):
            positional = positional[1:]
        defaults = dict(zip([a.arg for a in args.args][len(args.args) - len(args.defaults):], args.defaults))
        defaults.update({a.arg: d for a, d in zip(args.kwonlyargs, args.kw_defaults) if d is not None})
        found: list[tuple[ast.expr | None, Function | None]] = []
        for call in self.call_sites(scope.cls, scope.node.name):
            passed = next((kw.value for kw in call.keywords if kw.arg == name), None)
            if passed is None and name in positional and positional.index(name) < len(call.args):
                passed = call.args[positional.index(name)]
            found.append((passed if passed is not None else defaults.get(name), self.function_of(call)))
        if not found and name in defaults:
            found.append((defaults[name], scope))
        return found

    def function_of(self, node: ast.AST) -> Function | None:
        """The function a node is in (None at module or class level)."""
        if self.owners is None:  # indexed once, at the first question
            self.owners = {}
            for function in self.functions.values():
                for sub in ast.walk(function.node):
                    self.owners.setdefault(id(sub), function)
        return self.owners.get(id(node))


def arg(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
    """A call's argument by keyword, else by position; None when not passed."""
    for kw in call.keywords:
        if kw.arg == keyword:
            return kw.value
    return call.args[index] if len(call.args) > index else None


def is_self_attr(expr: ast.AST) -> TypeGuard[ast.Attribute]:
    """`self.name`."""
    return isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) and expr.value.id == "self"


def in_scope(body: Iterable[ast.AST]) -> list[ast.AST]:
    """The nodes of a block, descending into if/for/while/with/try but not into nested scopes."""
    found: list[ast.AST] = []
    pending: deque[ast.AST] = deque(body)
    while pending:
        node = pending.popleft()
        found.append(node)
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            pending.extend(ast.iter_child_nodes(node))
    return found


def record_assigns(body: list[ast.stmt], into: dict[str, list[Assigned]], nested: bool) -> None:
    """Record `name = expr` (and `name += ...`, loop and with targets as further values) in a
    block; `nested` also reads its if/for/while/with/try bodies (not nested functions)."""
    nodes = in_scope(body) if nested else list(body)
    for node in nodes:
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    into.setdefault(target.id, []).append(node.value)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.value is not None:
            into.setdefault(node.target.id, []).append(node.value)
        elif isinstance(node, ast.AugAssign) and isinstance(node.target, ast.Name):
            into.setdefault(node.target.id, []).append(node)
        elif isinstance(node, (ast.For, ast.With)):
            bound: list[ast.expr | None] = [node.target] if isinstance(node, ast.For) else \
                [i.optional_vars for i in node.items]
            for name in bound:
                if isinstance(name, ast.Name):
                    into.setdefault(name.id, []).append(node)
