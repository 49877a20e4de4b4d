"""Which code of an executable's linked libraries runs: a call graph over the functions of the
workspace's code (by qualified name, so that overloads and template specialisations are one),
walked from the executable's own files. A library port counts only when the function making it
is reached (tf's library defines TransformListener, whose subscribers a static transform
publisher, which never builds one, does not have).

Conservative where the code does not say: a class named in reached code may be constructed
(`make_shared<T>`, `new T`), its constructor builds its members and bases and hands the object
to code that may call its virtual methods and `operator()`; a function whose address is taken
is called; a call clang could not resolve reaches every function of its name; what a file's
global variables run (a plugin's registration) is reached; and an executable whose reached code
includes a function of a file that does not compile (its calls may be lost), or whose graph is
over the budget, keeps every port."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

import clang.cindex as ci

from archlog.extract.cpp.callers import overridden
from archlog.extract.cpp.clang_ast import K, qualified

_FUNCTIONS = (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR, K.DESTRUCTOR, K.FUNCTION_TEMPLATE,
              K.CONVERSION_FUNCTION)
_CLASSES = (K.CLASS_DECL, K.STRUCT_DECL, K.CLASS_TEMPLATE, K.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)
_SCOPES = (K.NAMESPACE, K.LINKAGE_SPEC, K.UNEXPOSED_DECL)
_CURSOR_CAP = 400_000  # cursors one file's graph visits
_REACH_CAP = 50_000  # functions one executable's walk visits
_ARGS = re.compile(r"<[^<>]*>")
ANY = "?"  # prefix of a call clang could not resolve, by its name only


@dataclass
class CallGraph:
    """One file's part of the graph: each function's callees (functions, constructors, classes as
    `C::C`, unresolved names as `?name`), what runs before main (global variables), the functions
    the file itself defines, the function each of its ports is made in (by the port's file, line
    and column), whether its functions may lack calls (`unsure`: the file does not compile) and
    whether the graph is cut short (`partial`: over the cursor budget)."""

    calls: dict[str, set[str]] = field(default_factory=dict)
    static: set[str] = field(default_factory=set)
    own: set[str] = field(default_factory=set)
    ports: dict[tuple[str, int, int], str] = field(default_factory=dict)
    unsure: bool = False
    partial: bool = False


class Functions:
    """Where the functions of a file and of the workspace headers it includes are."""

    def __init__(self) -> None:
        self.spans: dict[str, list[tuple[int, int, str]]] = {}  # file -> (start, end offset, function)

    def around(self, cursor: ci.Cursor) -> str | None:
        """The innermost function around a cursor."""
        if cursor.location.file is None:
            return None
        at = cursor.extent.start.offset
        inside = [(end - start, name) for start, end, name in self.spans.get(cursor.location.file.name, [])
                  if start <= at <= end]
        return min(inside)[1] if inside else None


def function_name(decl: ci.Cursor) -> str:
    """A function's key: its qualified name without template arguments."""
    name = qualified(decl)
    while (reduced := _ARGS.sub("", name)) != name:
        name = reduced
    return name


def _constructor(cls: ci.Cursor) -> str:
    name = function_name(cls)
    return f"{name}::{name.rsplit('::', 1)[-1]}"


def build(root: ci.Cursor, source: str, workspace_header: Callable[[ci.Cursor], bool]) -> tuple[CallGraph, Functions]:
    """The graph of a file's code and of the workspace headers it includes, and where its
    functions are."""
    builder = _Builder(CallGraph(), Functions(), source)
    for top in root.get_children():
        if top.location.file is not None and (top.location.file.name == source or workspace_header(top)):
            builder.declaration(top)
    builder.graph.partial = builder.visited > _CURSOR_CAP
    return builder.graph, builder.functions


@dataclass
class _Builder:
    graph: CallGraph
    functions: Functions
    source: str
    visited: int = 0

    def declaration(self, cursor: ci.Cursor) -> None:
        """A namespace-scope or class-scope declaration."""
        self.visited += 1
        if self.visited > _CURSOR_CAP:
            return
        kind = cursor.kind
        if kind in _SCOPES:
            for child in cursor.get_children():
                self.declaration(child)
        elif kind in _CLASSES and cursor.is_definition():
            self.klass(cursor)
        elif kind in _FUNCTIONS and cursor.is_definition():
            self.function(cursor)
        elif kind == K.VAR_DECL:  # a global or static member: built before main
            self.graph.static |= self.type_constructors(cursor.type)
            self.graph.static.update(*(self.references(c) for c in _code(cursor)))

    def klass(self, cls: ci.Cursor) -> None:
        """A class's constructor builds its bases and members and may hand the object to code
        that calls its virtual methods, operator() or destructor."""
        name = function_name(cls)
        ctor = _constructor(cls)
        callees = self.graph.calls.setdefault(ctor, set())
        callees.add(f"{name}::~{name.rsplit('::', 1)[-1]}")
        for child in cls.get_children():
            if child.kind == K.CXX_BASE_SPECIFIER:
                callees |= self.type_constructors(child.type)
            elif child.kind == K.FIELD_DECL:
                callees |= self.type_constructors(child.type)
                callees.update(*(self.references(c) for c in _code(child)))
            elif child.kind in (K.CXX_METHOD, K.CONVERSION_FUNCTION, K.DESTRUCTOR, K.FUNCTION_TEMPLATE) and \
                    (child.is_virtual_method() or child.spelling == "operator()"):
                callees.add(function_name(child))
            if child.kind in _FUNCTIONS or child.kind in _CLASSES or child.kind == K.VAR_DECL:
                self.declaration(child)

    def function(self, function: ci.Cursor) -> None:
        name = function_name(function)
        callees = self.graph.calls.setdefault(name, set())
        for base in overridden(function):  # a call of the base's method may run this one
            self.graph.calls.setdefault(function_name(base), set()).add(name)
        callees.update(*(self.references(c) for c in _code(function)))
        file = function.location.file.name if function.location.file is not None else ""
        self.functions.spans.setdefault(file, []).append((function.extent.start.offset, function.extent.end.offset,
                                                          name))
        if file == self.source:
            self.graph.own.add(name)

    def references(self, code: ci.Cursor) -> set[str]:
        """What a piece of code calls, constructs or takes the address of."""
        found: set[str] = set()
        for cursor in code.walk_preorder():
            self.visited += 1
            if self.visited > _CURSOR_CAP:
                break
            kind, ref = cursor.kind, cursor.referenced
            if kind in (K.CALL_EXPR, K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and ref is not None and ref.kind in _FUNCTIONS:
                found.add(function_name(ref))
            elif kind in (K.CALL_EXPR, K.MEMBER_REF_EXPR, K.DECL_REF_EXPR, K.OVERLOADED_DECL_REF) and \
                    (ref is None or ref.kind == K.OVERLOADED_DECL_REF) and (name := _spelled(cursor)):
                found.add(ANY + name)  # dependent on a template argument, or not declared
            elif kind in (K.TYPE_REF, K.TEMPLATE_REF) and ref is not None and ref.kind in _CLASSES:
                found.add(_constructor(ref))
        return found

    def type_constructors(self, type_: ci.Type) -> set[str]:
        """The constructors of a member or base of class type (a pointer builds nothing)."""
        decl = type_.get_canonical().get_declaration()
        return {_constructor(decl)} if decl.kind in _CLASSES else set()


def _spelled(cursor: ci.Cursor) -> str:
    """The name an unresolved reference spells (`t.run` of a template's `t`: run)."""
    if cursor.spelling or cursor.kind == K.CALL_EXPR:
        return cursor.spelling
    words = [t.spelling for t in cursor.get_tokens() if t.kind == ci.TokenKind.IDENTIFIER]
    return words[-1] if words else ""


def _code(cursor: ci.Cursor) -> list[ci.Cursor]:
    """A declaration's children that run: not its parameters nor the types it is declared with."""
    return [c for c in cursor.get_children() if c.kind not in (K.PARM_DECL, K.TYPE_REF, K.NAMESPACE_REF,
                                                               K.TEMPLATE_REF)]


def reached(graphs: Iterable[CallGraph], roots: set[str]) -> set[str] | None:
    """The functions reached from `roots` and from what global variables run, or None when the
    graph cannot tell (a reached function of a file that does not compile, over the budget)."""
    graphs = list(graphs)
    if any(g.partial for g in graphs):
        return None
    unsure = {f for g in graphs if g.unsure for f in g.own}
    calls: dict[str, set[str]] = {}
    by_name: dict[str, set[str]] = {}
    for graph in graphs:
        for caller, callees in graph.calls.items():
            calls.setdefault(caller, set()).update(callees)
            by_name.setdefault(caller.rsplit("::", 1)[-1], set()).add(caller)
    pending = list(roots | {s for g in graphs for s in g.static})
    seen: set[str] = set()
    while pending:
        name = pending.pop()
        if name in seen:
            continue
        if len(seen) >= _REACH_CAP or name in unsure:
            return None
        seen.add(name)
        pending += by_name.get(name[len(ANY):], set()) if name.startswith(ANY) else calls.get(name, set())
    return seen
