"""The scopes of a file as the behavior walk sees them: every function, method and lambda with
its frame, local and global names, class hierarchy, and the state variables a name stands for."""

from __future__ import annotations

import ast
from dataclasses import replace

from archlog.extract.python.behavior.paths import Frame, FunctionNode
from archlog.extract.python.behavior.syntax import parameters_of
from archlog.extract.python.fold import ValueFolder
from archlog.extract.python.index import Function, in_scope, is_self_attr, record_assigns
from archlog.extract.summary import Port, Site

SOURCE_KINDS = ("subscriber", "service_server", "action_server", "timer")


class Scopes:
    """One file's scopes and names, on top of the index and values of its port extraction."""

    def __init__(self, folder: ValueFolder, ports: list[Port]) -> None:
        self.folder, self.file = folder, folder.file
        self.sites = {kind: {Site(p.file, p.line) for p in ports if p.kind == kind}
                      for kind in ("publisher", *SOURCE_KINDS)}
        self.returned: dict[int, list[ast.expr]] = {}
        self.module = Frame(None)
        self.module_nodes = in_scope(folder.tree.body)
        self.scopes: list[tuple[Frame, list[ast.AST]]] = []
        self.functions = {id(f.node): f for f in folder.functions.values()}
        self.owner: dict[int, str] = {id(f.node): f.cls for f in folder.functions.values() if f.cls}
        self.frames: dict[int, Frame] = {}  # function -> its frame when not called
        self.names: dict[int, tuple[set[str], set[str]]] = {}  # function -> (local names, declared global)
        self.nested: dict[int, dict[str, ast.FunctionDef | ast.AsyncFunctionDef]] = {}
        self.subclasses: dict[str, list[str]] = {}
        for cls, bases in folder.class_bases.items():
            for base in bases:
                if base in folder.class_attrs:
                    self.subclasses.setdefault(base, []).append(cls)
        self._scan(self.module_nodes, self.module)
        self.global_values: dict[str, list[tuple[ast.expr, Frame]]] = {
            name: [(e, self.module) for e in values if isinstance(e, ast.expr)]
            for name, values in folder.module_assigns.items()}
        for frame, nodes in self.scopes:
            for node in nodes:
                if isinstance(node, ast.Assign) and frame.func is not None:
                    for target in node.targets:
                        if isinstance(target, ast.Name) and target.id in self.local_names(frame.func)[1]:
                            self.global_values.setdefault(target.id, []).append((node.value, frame))
        self.instantiated = {n.func.id for n in ast.walk(folder.tree) if isinstance(n, ast.Call)
                             and isinstance(n.func, ast.Name) and n.func.id in folder.class_attrs}
        self.kinds: dict[str, set[str]] = {}

    def _scan(self, nodes: list[ast.AST], frame: Frame) -> None:
        """Every function, method and lambda with its frame when not called from anywhere."""
        nested: dict[str, ast.FunctionDef | ast.AsyncFunctionDef] = {}
        for node in nodes:
            if isinstance(node, ast.ClassDef):
                for item in node.body:
                    if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        self.owner[id(item)] = node.name
                        self._add_scope(Frame(item, node.name))
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                outer = frame if frame.func is not None else None
                if not isinstance(node, ast.Lambda) and outer is not None:
                    nested[node.name] = node
                self._add_scope(Frame(node, frame.cls, outer=outer))
        if frame.func is not None:
            self.nested[id(frame.func)] = nested

    def _add_scope(self, frame: Frame) -> None:
        """One function's names, assignments and frame; then the functions nested in it."""
        func = frame.func
        assert func is not None
        nodes = in_scope([func.body] if isinstance(func, ast.Lambda) else func.body)
        declared = {name for n in nodes if isinstance(n, ast.Global) for name in n.names}
        stores = {n.id for n in nodes if isinstance(n, ast.Name) and isinstance(n.ctx, (ast.Store, ast.Del))}
        nonlocal_ = {name for n in nodes if isinstance(n, ast.Nonlocal) for name in n.names}
        self.names[id(func)] = ((stores | nonlocal_ | set(parameters_of(func))) - declared, declared)
        if id(func) not in self.functions and not isinstance(func, ast.Lambda):
            function = Function(func, frame.cls)
            record_assigns(func.body, function.assigns, nested=True)
            self.functions[id(func)] = function
        self.scopes.append((frame, nodes))
        self.frames[id(func)] = frame
        self._scan(nodes, frame)

    def function(self, frame: Frame | None) -> Function | None:
        """The index's function for a frame (a lambda's is its enclosing function's)."""
        while frame is not None and frame.func is not None:
            if id(frame.func) in self.functions:
                return self.functions[id(frame.func)]
            frame = frame.outer
        return None

    def canonical(self, function: Function | None, cls: str | None = None) -> Frame:
        """The frame of a function not reached through a call (its parameters come from every call site)."""
        if function is None:
            return Frame(None, cls)
        frame = self.frames.get(id(function.node)) or Frame(function.node, function.cls)
        return replace(frame, cls=cls or frame.cls)

    def returns(self, func: FunctionNode) -> list[ast.expr]:
        """What a function returns (its return statements' values, a lambda's body)."""
        if isinstance(func, ast.Lambda):
            return [func.body]
        if id(func) not in self.returned:
            self.returned[id(func)] = [r.value for r in in_scope(func.body) if isinstance(r, ast.Return) and r.value]
        return self.returned[id(func)]

    def local_names(self, func: FunctionNode) -> tuple[set[str], set[str]]:
        """A function's local names (parameters, assigned, nonlocal) and those it declares global."""
        return self.names.get(id(func), (set(parameters_of(func)), set()))

    def lineage(self, cls: str) -> list[str]:
        """A class and its bases defined in the file."""
        found = [cls]
        for name in found:
            found += [b for b in self.folder.class_bases.get(name, [])
                      if b in self.folder.class_attrs and b not in found]
        return found

    def descendants(self, cls: str) -> list[str]:
        """The subclasses of a class defined in the file (all levels)."""
        found = [cls]
        for name in found:
            found += [s for s in self.subclasses.get(name, []) if s not in found]
        return found[1:]

    # -- state variables ------------------------------------------------------------------
    def state_var(self, expr: ast.AST, frame: Frame) -> str | None:
        """`Class.attr` for `self.attr` (the class at the root of its hierarchy in the file), the
        name of a module variable; None for locals, parameters and anything else."""
        if is_self_attr(expr) and frame.cls:
            return f"{self.lineage(frame.cls)[-1]}.{expr.attr}"
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

