"""Resolution on a path: the expressions a name or attribute may hold, the calls that made an
object, the classes it is an instance of, the functions a callee may be, and argument binding."""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import replace

from archlog.extract.python.behavior.paths import Frame, FunctionNode, Target
from archlog.extract.python.behavior.scopes import Scopes
from archlog.extract.python.behavior.syntax import annotations_of, defaults_of, parameters_of
from archlog.extract.python.fold import ValueFolder
from archlog.extract.summary import Port, Site


class Resolver(Scopes):
    """What expressions hold and which functions calls run, memoised per expression and frame."""

    def __init__(self, folder: ValueFolder, ports: list[Port]) -> None:
        super().__init__(folder, ports)
        self.arguments: dict[tuple[int, str], list[tuple[ast.expr, Frame]]] = {}
        self.resolved: dict[tuple[str, int, Frame], list] = {}  # memo of origins, callables, classes_of

    def values(self, name: str, frame: Frame) -> list[tuple[ast.expr, Frame]]:
        """The expressions a name may hold, each with the frame to read it in."""
        while frame is not None and frame.func is not None:
            bound = frame.bound(name)
            if bound is not None:
                return [bound]
            if name in parameters_of(frame.func):
                default = defaults_of(frame.func).get(name)
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

    def passed(self, func: FunctionNode, name: str) -> list[tuple[ast.expr, Frame]]:
        """What the call sites in the file pass for a parameter (its default when they do not)."""
        key = (id(func), name)
        if key not in self.arguments:
            function = self.functions.get(id(func))
            self.arguments[key] = [(e, self.canonical(caller)) for e, caller in
                                   (self.folder.arguments(function, name) if function else []) if e is not None]
        return self.arguments[key]

    def attribute_values(self, expr: ast.Attribute, frame: Frame, depth: int) -> list[tuple[ast.expr, Frame]]:
        """The values assigned to an attribute of `self` or of an instance of a class of the file."""
        found: list[tuple[ast.expr, Frame]] = []
        for cls in self.classes_of(expr.value, frame, depth):
            for owner in self.lineage(cls) + self.descendants(cls):
                for value in self.folder.class_attrs.get(owner, {}).get(expr.attr, []):
                    if isinstance(value, ast.expr):
                        found.append((value, self.canonical(self.folder.attr_scope.get(id(value)), cls)))
        return found

    def memo(self, compute: Callable[[ast.expr, Frame, int], list], expr: ast.expr, frame: Frame,
             depth: int) -> list:
        """A resolution computed once per expression and frame (near the top of a resolution,
        where the depth limit does not cut it short)."""
        if depth > 2:
            return compute(expr, frame, depth)
        key = (compute.__name__, id(expr), frame)
        if key not in self.resolved:
            self.resolved[key] = compute(expr, frame, depth)
        return self.resolved[key]

    def classes_of(self, expr: ast.expr, frame: Frame, depth: int = 0) -> list[str]:
        """The classes of the file an object may be an instance of."""
        return self.memo(self._classes_of, expr, frame, depth)

    def _classes_of(self, expr: ast.expr, frame: Frame, depth: int) -> list[str]:
        if isinstance(expr, ast.Name) and expr.id == "self" and frame.cls:
            return [frame.cls]
        found = list(dict.fromkeys(c.func.id for c, _f in self.origins(expr, frame, depth + 1)
                                   if isinstance(c.func, ast.Name) and c.func.id in self.folder.class_attrs))
        if not found and isinstance(expr, ast.Name) and frame.func is not None and \
                (annotation := annotations_of(frame.func).get(expr.id)) is not None:
            name = annotation.value if isinstance(annotation, ast.Constant) else ast.unparse(annotation)
            found = [name] if name in self.folder.class_attrs else []  # a parameter annotated with a class of the file
        return found

    def origins(self, expr: ast.expr, frame: Frame, depth: int = 0) -> list[tuple[ast.Call, Frame]]:
        """The calls that may have made the object an expression holds: a constructor, or what a
        function of the file returns."""
        return self.memo(self._origins, expr, frame, depth)

    def _origins(self, expr: ast.expr, frame: Frame, depth: int) -> list[tuple[ast.Call, Frame]]:
        if depth > 10:
            return []
        if isinstance(expr, ast.Call):
            if isinstance(expr.func, ast.Name) and expr.func.id in self.folder.class_attrs:
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

    def callables(self, expr: ast.expr, frame: Frame, depth: int = 0) -> list[Target]:
        """The functions of the file a callee expression may be: methods (with overrides in
        subclasses), module and nested functions, lambdas, functools.partial, constructors, and
        callables stored in attributes."""
        return self.memo(self._callables, expr, frame, depth)

    def _callables(self, expr: ast.expr, frame: Frame, depth: int) -> list[Target]:
        if depth > 10:
            return []
        if isinstance(expr, ast.Lambda):
            return [Target(expr, frame.cls, frame)]
        if isinstance(expr, ast.Call) and (self.folder.qualified(expr.func) or "").endswith("partial") and expr.args:
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
        scope: Frame | None = frame
        while scope is not None and scope.func is not None:
            nested = self.nested.get(id(scope.func), {})
            if name in nested:
                return [Target(nested[name], scope.cls, scope)]
            if scope.bound(name) or name in self.local_names(scope.func)[0]:
                return [t for e, f in self.values(name, scope) for t in self.callables(e, f, depth + 1)]
            scope = scope.outer
        if (None, name) in self.folder.functions:
            return [Target(self.folder.functions[(None, name)].node, None, None)]
        if name in self.folder.class_attrs:
            return self.methods([name], "__init__", name)
        return [t for e, f in self.global_values.get(name, []) for t in self.callables(e, f, depth + 1)]

    def methods(self, classes: list[str], name: str, cls: str | None, overrides: bool = True) -> list[Target]:
        """A method as found from the classes upward, and its overrides in subclasses of the file."""
        found: list[Target] = []
        for start in classes:
            for owner in self.lineage(start):
                if (owner, name) in self.folder.functions:
                    found.append(Target(self.folder.functions[(owner, name)].node, cls, None, True))
                    break
            for sub in self.descendants(start) if overrides else []:
                if (sub, name) in self.folder.functions:
                    found.append(Target(self.folder.functions[(sub, name)].node, sub, None, True))
        return list({id(t.func): t for t in found}.values())

    def is_thread(self, cls: str) -> bool:
        """A threading.Thread subclass (its start() runs its run())."""
        return any(base == "threading.Thread" for c in self.lineage(cls) for base in self.folder.class_bases.get(c, []))

    def owner_class(self, frame: Frame) -> str | None:
        """The class whose method the frame runs (through closures)."""
        while frame is not None and frame.func is not None:
            if id(frame.func) in self.owner:
                return self.owner[id(frame.func)]
            frame = frame.outer  # type: ignore[assignment]
        return None

    def bind(self, target: Target, call: ast.Call | None, frame: Frame,
             extra: list[tuple[ast.expr, Frame]] | None = None) -> Frame:
        """The callee's frame: partial's arguments, then the call's; `extra` (callback_args)
        binds the last parameters."""
        return self.bind_arguments(target, call.args if call else [], call.keywords if call else [], frame, extra)

    def bind_arguments(self, target: Target, passed: list[ast.expr], keywords: list[ast.keyword], frame: Frame,
                       extra: list[tuple[ast.expr, Frame]] | None = None) -> Frame:
        """The callee's frame from positional and keyword arguments (up to a *starred one)."""
        params = parameters_of(target.func, positional=True)
        if target.method and params:
            params = params[1:]
        positional = list(target.preset)
        for given in passed:
            if isinstance(given, ast.Starred):
                break
            positional.append((given, frame))
        args = [(p, e, f) for p, (e, f) in zip(params, positional)]
        args += [(kw.arg, kw.value, frame) for kw in keywords if kw.arg]
        if extra and len(params) > len(positional):
            args += [(p, e, f) for p, (e, f) in zip(params[len(params) - len(extra):], extra)]
        return Frame(target.func, target.cls, tuple(args), target.outer, True)

    def publisher_sites(self, expr: ast.expr, frame: Frame) -> list[Site]:
        """The publisher ports (rospy/rclpy publishers, tf broadcasters) an object may be."""
        return list(dict.fromkeys(s for c, _f in self.origins(expr, frame)
                                  if (s := Site(self.file, c.lineno)) in self.sites["publisher"]))
