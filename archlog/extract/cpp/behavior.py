"""Behavior of a C++ node (roscpp and rclcpp), one file at a time: how each publish call is
reached and under which state conditions, and which callbacks set that state (summary.py's
Publish and StateWrite).

The file's functions and lambdas (index.py) form a call graph: calls, virtual methods by name
up the class hierarchy, lambdas run where they are written or called, functions handed to threads
or as reply callbacks. Its roots are the callbacks of the ports the walker found (subscribers,
services, actions, timers, and callbacks registered later on such an object), other registered
callbacks (with no port), main(), onInit() and lifecycle transitions, and constructors nothing in
the file calls. A publish call is reached along every path from a root; each function on the way
adds the state conditions that dominate the path in it and the endless loop it runs in
(paths.py, periods.py, state.py). Publisher objects are followed from the call that
made them through assignments, members, containers, function returns and arguments.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field, replace

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import SKIP, CursorKey, K, strip, written_args
from archlog.extract.cpp.index import ACCESSORS, DEFINITIONS, FUNCTIONS, THREADS, FileIndex, Function, Host, Store
from archlog.extract.cpp.paths import Paths, running
from archlog.extract.cpp.periods import Periods
from archlog.extract.cpp.state import (
    Conditions,
    StateVar,
    assigned_value,
    initial_value,
    method_value,
    object_of,
    operands,
    state_var,
)
from archlog.extract.summary import Guard, Port, Publish, Site, StateWrite
from archlog.values import Value

SOURCE_KINDS = {"subscriber": "callback", "service_server": "callback", "action_server": "callback",
                "timer": "timer"}
STARTUP = ("onInit", "on_configure", "on_activate")
_MAX_WAYS = 24


@dataclass(frozen=True)
class Way:
    """One way execution reaches a point: what started it, and the guards met on the way; an
    unknown way names the functions it enters by (their USRs: another file may call them)."""

    trigger: str
    source: Site | None = None
    period: Value | None = None
    guards: tuple[Guard, ...] = ()
    entry: tuple[str, ...] = ()


@dataclass
class FileBehavior:
    """What one file says about behavior: its publish calls and state writes; those reached in an
    unknown way with the functions that way enters (`open`); and the ways this file calls
    functions it does not define (`calls`, by USR). link_files() joins the files of a node."""

    publishes: list[Publish] = field(default_factory=list)
    writes: list[StateWrite] = field(default_factory=list)
    open: list[tuple[Publish | StateWrite, tuple[str, ...]]] = field(default_factory=list)
    calls: list[tuple[str, Way]] = field(default_factory=list)


def read_behavior(host: Host, cursors: list[ci.Cursor], port_calls: dict[ci.Cursor, list[str]],
                  named: list[tuple[str, Port]], text: bytes | None = None) -> FileBehavior:
    """The behavior of one file; `port_calls` maps each call that made a port to the kinds of the
    ports it made, `named` gives ports read from the tokens with the names in their arguments
    (callbacks among them); `text`: the file's text when its AST is incomplete."""
    behavior = _Behavior(host, port_calls)
    behavior.index.read(cursors)
    behavior.link()
    behavior.link_named(named)
    if text is not None:
        behavior.link_text(text)
    found = FileBehavior()
    behavior.publishes(found)
    behavior.writes(found)
    behavior.calls_out(found)
    return found


def link_files(files: list[FileBehavior]) -> tuple[list[Publish], list[StateWrite]]:
    """The publish calls and writes of a node's files, where a call or write one file reaches
    in an unknown way is reached the ways other files call the function it is in."""
    calls: dict[str, list[Way]] = {}
    for file in files:
        for usr, way in file.calls:
            calls.setdefault(usr, []).append(way)
    linked = [found for file in files for item, entry in file.open for found in _relink(item, entry, calls)]
    publishes = [p for file in files for p in file.publishes] + [p for p in linked if isinstance(p, Publish)]
    writes = [w for file in files for w in file.writes] + [w for w in linked if isinstance(w, StateWrite)]
    return sorted(_unique(publishes), key=lambda p: (p.file, p.line)), _unique(writes)


def _relink(item: Publish | StateWrite, entry: tuple[str, ...], calls: dict[str, list[Way]],
            depth: int = 0) -> list[Publish | StateWrite]:
    """An item reached in an unknown way, reached instead the ways other files call its entry
    (again through unknown ways, a few levels)."""
    ways = [w for usr in entry for w in calls.get(usr, [])]
    if not ways or depth > 4:
        return [item]
    found: list[Publish | StateWrite] = []
    for way in ways:
        if isinstance(item, StateWrite):
            source = way.source if way.trigger in ("callback", "timer") else None
            linked: Publish | StateWrite = replace(item, source=source)
        else:
            linked = replace(item, trigger=way.trigger, source=way.source, guards=_joined(way.guards, item.guards),
                             period=way.period if way.trigger == "loop" else item.period)
        found += _relink(linked, way.entry, calls, depth + 1) if way.trigger == "unknown" else [linked]
    return found


class _Behavior:
    def __init__(self, host: Host, port_calls: dict[ci.Cursor, list[str]]) -> None:
        self.host = host
        self.ports = {call: Site(host.shown(call), call.location.line) for call in port_calls}
        self.kinds: dict[Site, set[str]] = {}
        for call, kinds in port_calls.items():
            self.kinds.setdefault(self.ports[call], set()).update(kinds)
        self.index = FileIndex(host.key, self.ports.keys())
        self.vars: dict[str, StateVar] = {}
        self.conditions = Conditions(running, self.targets)
        self.paths = Paths(host, self.conditions, Periods(host, self.index.flows, self.passed), self.vars)
        self.roots: dict[CursorKey, list[tuple[str, Site | None]]] = {}
        self.edges: dict[CursorKey, list[ci.Cursor]] = {}  # function -> points where it runs besides its calls
        # function -> (thread launch, its first argument)
        self.launches: dict[CursorKey, list[tuple[ci.Cursor, int]]] = {}
        self.usrs: dict[CursorKey, str] = {}  # function id -> USR, for callbacks another file may define
        self._overrides: dict[CursorKey, list[Function]] | None = None
        self._reach: dict[CursorKey, list[Way]] = {}

    # -- the call graph ---------------------------------------------------------------------
    def link(self) -> None:
        """Roots (callbacks) and the points where lambdas and handed-off functions run."""
        index = self.index
        for call, site in self.ports.items():
            sources = [SOURCE_KINDS[k] for k in self.kinds[site] if k in SOURCE_KINDS]
            for fid in self.callbacks(written_args(call)):  # a publisher's: a connection callback
                self.roots.setdefault(fid, []).append((sources[0], site) if sources else ("callback", None))
        for call in index.registrations:
            obj = object_of(call)
            sites: list[Site | None] = [s for s in self.sites(obj) if self.kinds[s] & SOURCE_KINDS.keys()] \
                if obj is not None else []
            for fid in self.callbacks(written_args(call)):
                for registrar in sites or [None]:
                    trigger = "timer" if registrar is not None and "timer" in self.kinds[registrar] else "callback"
                    self.roots.setdefault(fid, []).append((trigger, registrar))
        for call in index.handoffs:
            args = written_args(call)
            for fid in self.callbacks(args):
                self.edges.setdefault(fid, []).append(call)
            if call.spelling in THREADS and args and (target := self.callbacks(args[:1])):
                member = strip(args[0]).kind == K.UNARY_OPERATOR  # &Class::method, this, arguments...
                self.launches.setdefault(target[0], []).append((call, 2 if member else 1))
        for call in index.invocations:
            for fid in self.callbacks(operands(call)[:1]):
                self.edges.setdefault(fid, []).append(call)
        for lam in index.lambdas:
            fid = index.lambda_id(lam)
            if fid not in self.roots and fid not in self.edges:
                self.edges[fid] = [lam]  # runs where it is written (std algorithms, a helper taking it)

    def link_named(self, named: list[tuple[str, Port]]) -> None:
        """Functions named in the arguments of a port read from the tokens are its callbacks."""
        for name, port in named:
            if port.kind in SOURCE_KINDS:
                for function in self.index.functions:
                    if function.cursor.spelling == name and function.cursor.kind in FUNCTIONS:
                        self.roots.setdefault(function.id, []).append((SOURCE_KINDS[port.kind],
                                                                      Site(port.file, port.line)))

    def link_text(self, text: bytes) -> None:
        """Calls the AST lost (the file does not compile): a function of the file nothing runs is
        called where another function's text names it followed by `(`, and is a callback where
        it is named after `&` (handed to something)."""
        for function in self.index.functions:
            cursor = function.cursor
            if function.file != self.host.source or cursor.kind not in FUNCTIONS or cursor.spelling == "main" or \
                    self.roots.get(function.id) or self.callers(function):
                continue
            named = rb"(&\s*(?:\w+\s*::\s*)*)?\b%s\s*(\()?" % re.escape(cursor.spelling.encode())
            for match in re.finditer(named, text):
                offset = match.start()
                caller = self.index.enclosing_offset(function.file, offset)
                if caller is None or caller.id == function.id or not (match.group(1) or match.group(2)):
                    continue
                if match.group(1):
                    self.roots.setdefault(function.id, []).append(("callback", None))
                else:
                    self.edges.setdefault(function.id, []).append(_innermost(caller.cursor, offset))

    def callbacks(self, exprs: Iterable[ci.Cursor], depth: int = 0) -> list[CursorKey]:
        """The functions and lambdas arguments pass: `&C::cb`, `cb`, a lambda, std::bind(...), a
        local variable holding one of these."""
        found: list[CursorKey] = []
        for expr in exprs:
            expr = strip(expr)
            kind = expr.kind
            if kind == K.LAMBDA_EXPR:
                found.append(self.index.lambda_id(expr))
            elif kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR):
                ref = expr.referenced
                if ref is not None and ref.kind in FUNCTIONS:
                    found.append(self.host.key(ref.canonical))
                    self.usrs[found[-1]] = ref.get_usr()
                elif ref is not None and ref.kind == K.VAR_DECL and depth < 4 and \
                        ref.semantic_parent is not None and ref.semantic_parent.kind in DEFINITIONS:
                    found += self.callbacks(self.index.flows.get(self.host.key(ref), []), depth + 1)
            elif kind == K.CALL_EXPR and depth < 6:
                found += self.callbacks(expr.get_arguments(), depth + 1)
            elif depth < 6:
                found += self.callbacks([c for c in expr.get_children() if c.kind not in SKIP], depth + 1)
        return found

    def callers(self, function: Function) -> list[ci.Cursor]:
        """The points where a function runs: its calls, calls of the methods it overrides, and
        the points recorded for lambdas and handed-off functions."""
        found = list(self.host.call_sites.get(function.id, [])) + self.edges.get(function.id, [])
        for base in self.overridden(function):
            found += self.host.call_sites.get(base, [])
        return found

    def overridden(self, function: Function) -> list[CursorKey]:
        """The ids of the virtual methods of base classes a method overrides."""
        return [self.host.key(m.canonical) for m in self.bases(function)]

    def bases(self, function: Function) -> list[ci.Cursor]:
        """The virtual methods of base classes a method overrides (by name)."""
        cursor = function.cursor
        if cursor.kind != K.CXX_METHOD or not cursor.is_virtual_method():
            return []
        found: list[ci.Cursor] = []
        queue, seen = [cursor.semantic_parent], set[CursorKey]()
        while queue and len(seen) < 16:
            cls = queue.pop()
            definition = cls.get_definition() if cls is not None else None
            if definition is None or self.host.key(definition) in seen:
                continue
            seen.add(self.host.key(definition))
            for child in definition.get_children():
                if child.kind == K.CXX_BASE_SPECIFIER and child.referenced is not None:
                    base = child.referenced.get_definition() or child.referenced
                    queue.append(base)
                    found += [m for m in base.get_children()
                              if m.kind == K.CXX_METHOD and m.spelling == cursor.spelling and m.is_virtual_method()]
        return found

    def targets(self, call: ci.Cursor) -> list[ci.Cursor]:
        """The definitions a call may run: for a virtual method, the overrides in the most derived
        classes of the file that override it, else the method itself."""
        ref = call.referenced
        if ref is None or ref.kind not in (K.CXX_METHOD, K.FUNCTION_DECL):
            return []
        if self._overrides is None:
            self._overrides = {}
            for function in self.index.functions:
                for base in self.overridden(function):
                    self._overrides.setdefault(base, []).append(function)
        below = self._overrides.get(self.host.key(ref.canonical), [])
        leaves = [f.cursor for f in below if not self._overrides.get(f.id)]
        definition = ref.get_definition()
        return leaves or ([definition] if definition is not None else [])

    def reach(self, function: Function, stack: tuple = ()) -> list[Way]:
        """Every way execution enters a function, merged by (trigger, source, period)."""
        if function.id in self._reach:
            return self._reach[function.id]
        if function.id in stack or len(stack) > 12:
            return []
        ways: list[Way] = []
        for fid in [function.id, *self.overridden(function)]:
            ways += [Way(trigger, site) for trigger, site in self.roots.get(fid, [])]
        cursor = function.cursor
        if (cursor.kind == K.FUNCTION_DECL and cursor.spelling == "main") or \
                (cursor.kind == K.CXX_METHOD and cursor.spelling in STARTUP):
            ways.append(Way("startup"))
        for point in self.callers(function):
            caller = self.index.enclosing(point)
            if caller is None:  # a global's initializer
                ways.append(Way("startup"))
                continue
            ways += [self.extend(way, caller, point) for way in self.reach(caller, (*stack, function.id))]
        if not ways and cursor.kind == K.CONSTRUCTOR:
            ways.append(Way("startup"))
        elif not ways:  # called from another file, maybe
            entry = (cursor.get_usr(), *(m.get_usr() for m in self.bases(function)))
            ways.append(Way("unknown", entry=entry if cursor.kind != K.LAMBDA_EXPR else ()))
        merged = _merge(ways)
        self._reach[function.id] = merged
        return merged

    def extend(self, way: Way, function: Function, point: ci.Cursor) -> Way:
        """A way into `function`, carried on to `point` inside it: the guards there, and the
        endless loop around it (for a way not started by a callback)."""
        guards, loop_period, in_loop = self.paths.at(function.id, function.cursor, point)
        if in_loop and way.trigger in ("startup", "unknown", "loop"):
            return Way("loop", None, loop_period, _joined(way.guards, guards))
        return replace(way, guards=_joined(way.guards, guards))

    def ways_to(self, point: ci.Cursor) -> list[Way]:
        function = self.index.enclosing(point)
        if function is None:
            return [Way("startup")]
        return _merge([self.extend(way, function, point) for way in self.reach(function)])

    # -- objects made by ports ------------------------------------------------------------------
    def sites(self, expr: ci.Cursor, depth: int = 0, seen: set | None = None) -> list[Site]:
        """The ports whose objects can flow into an expression (a publisher, a subscriber...)."""
        seen = set() if seen is None else seen
        expr = strip(expr)
        if depth > 10:
            return []
        if expr in self.ports:
            return [self.ports[expr]]
        kind = expr.kind
        if kind == K.CALL_EXPR:
            if expr.spelling in ACCESSORS:
                inner = object_of(expr) or next(iter(operands(expr)), None)
                return self.sites(inner, depth + 1, seen) if inner is not None else []
            ref = expr.referenced
            if ref is not None and ref.kind in FUNCTIONS and (returned := self.returns(ref)):
                return _unique(s for r in returned for s in self.sites(r, depth + 1, seen))
            return _unique(s for a in expr.get_arguments() for s in self.sites(a, depth + 1, seen))
        if kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR, K.MEMBER_REF):
            decl = expr.referenced
            decl_key = self.host.key(decl)
            if decl is None or decl_key in seen:
                return []
            seen.add(decl_key)
            values = self.passed(decl) if decl.kind == K.PARM_DECL else self.index.flows.get(decl_key, [])
            return _unique(s for v in values for s in self.sites(v, depth + 1, seen))
        if kind == K.LAMBDA_EXPR:
            return []
        return _unique(s for c in expr.get_children() if c.kind not in SKIP for s in self.sites(c, depth + 1, seen))

    def passed(self, param: ci.Cursor) -> list[ci.Cursor]:
        """The arguments of a parameter at the function's calls and thread launches in the file."""
        function = param.semantic_parent
        if function is None:
            return []
        params = [c for c in function.get_children() if c.kind == K.PARM_DECL]
        index = next((i for i, p in enumerate(params) if p == param), -1)
        fid = self.host.key(function.canonical)
        calls = [(call, 0) for call in self.host.call_sites.get(fid, [])] + self.launches.get(fid, [])
        return [args[first + index] for call, first in calls if index >= 0
                and first + index < len(args := written_args(call))]

    def returns(self, function: ci.Cursor) -> list[ci.Cursor]:
        """What a function of this file (or of a header it uses) returns."""
        definition = function.get_definition()
        if definition is None or self.host.key(definition.canonical) not in self.index.by_id:
            return []
        return [e for c in definition.walk_preorder() if c.kind == K.RETURN_STMT for e in c.get_children()]

    # -- results ------------------------------------------------------------------------------
    def publishes(self, found: FileBehavior) -> None:
        for call in self.index.publishes:
            obj = object_of(call)
            sites: list[Site | None] = [s for s in self.sites(obj) if "publisher" in self.kinds[s]] \
                if obj is not None else []
            for way in self.ways_to(call):
                for site in sites or [None]:
                    publish = Publish(site, self.host.shown(call), call.location.line, way.trigger, way.source,
                                      way.guards, way.period if way.trigger == "loop" else None)
                    found.open.append((publish, way.entry)) if way.entry else found.publishes.append(publish)

    def writes(self, found: FileBehavior) -> None:
        """Writes to members and globals, by the callbacks (or start-up code) that make them, and
        the initial values of every state variable met."""
        set_at_startup: set[str] = set()
        for store in self.index.stores:
            var = state_var(store.target)
            value = _store_value(var, store) if var is not None else None
            if var is None or value is None:
                continue
            self.vars.setdefault(var.name, var)
            function = self.index.enclosing(store.at)
            ways = self.reach(function) if function is not None else [Way("startup")]
            choices = [(v, ways) for v in _alternatives(var, store)] or [(value, ways)]
            for value, ways in self.passed_values(var, store, function) or choices:
                if any(w.trigger == "startup" for w in ways):
                    set_at_startup.add(var.name)
                for way in ways:
                    write = StateWrite(var.name, value, way.source if way.trigger in ("callback", "timer") else None,
                                       self.host.shown(store.at), store.at.location.line)
                    found.open.append((write, way.entry)) if way.entry else found.writes.append(write)
        for name, var in self.vars.items():
            value = initial_value(var)
            if value is None and name not in set_at_startup:
                value = "?"  # no initializer, and no start-up code here sets it
            if value is not None:
                found.writes.append(StateWrite(name, value, None, self.host.shown(var.decl), var.decl.location.line))

    def calls_out(self, found: FileBehavior) -> None:
        """The ways this file runs functions of the workspace it does not define: calls, and
        callbacks and threads it hands them to."""
        for call in self.index.calls:
            ref = call.referenced
            if self.host.key(ref.canonical) not in self.index.by_id and self.host.workspace_code(ref):
                found.calls += [(ref.get_usr(), way) for way in self.ways_to(call)]
        for fid, usr in self.usrs.items():
            if fid not in self.index.by_id:
                found.calls += [(usr, Way(trigger, site)) for trigger, site in self.roots.get(fid, [])]
                found.calls += [(usr, way) for point in self.edges.get(fid, []) for way in self.ways_to(point)]

    def passed_values(self, var: StateVar, store: Store, function: Function | None) -> list[tuple[str, list[Way]]]:
        """`mode_ = mode` in a function that is no callback (`setMode(Mode::kAuto)`): the value
        each call in the file passes, with the ways to that call."""
        value = strip(store.value) if store.op == "=" and store.value is not None else None
        param = value.referenced if value is not None and value.kind == K.DECL_REF_EXPR else None
        if param is None or param.kind != K.PARM_DECL or function is None or self.roots.get(function.id):
            return []
        params = [c for c in function.cursor.get_children() if c.kind == K.PARM_DECL]
        index = next((i for i, p in enumerate(params) if p == param), -1)
        found = []
        for call in self.host.call_sites.get(function.id, []) if index >= 0 else []:
            args = written_args(call)
            found.append((assigned_value(var, args[index]) if index < len(args) else "?", self.ways_to(call)))
        return found


def _innermost(top: ci.Cursor, offset: int) -> ci.Cursor:
    """The innermost cursor below `top` whose extent holds an offset."""
    node = top
    for _ in range(200):
        child = next((c for c in node.get_children() if c.extent.start.offset <= offset < c.extent.end.offset), None)
        if child is None:
            return node
        node = child
    return node


def _store_value(var: StateVar, store: Store) -> str | None:
    if store.op == "=":
        return assigned_value(var, _constructor_argument(store.value) if store.value is not None else None)
    if store.op in ("?", "ref", "port"):
        return "?"
    return method_value(var, store.op, [store.value] if store.value is not None else [])


def _alternatives(var: StateVar, store: Store) -> list[str]:
    """`mode_ = c ? A : B`: each branch's value."""
    value = strip(store.value) if store.op == "=" and store.value is not None else None
    if value is None or value.kind != K.CONDITIONAL_OPERATOR:
        return []
    return _unique(assigned_value(var, branch) for branch in list(value.get_children())[1:])


def _constructor_argument(expr: ci.Cursor) -> ci.Cursor | None:
    """`x` in a member initializer `member_(x)` (a constructor call with one argument); None for
    `member_()` (default construction)."""
    inner = strip(expr)
    for _ in range(4):
        if inner.kind != K.CALL_EXPR or inner.referenced is None or inner.referenced.kind != K.CONSTRUCTOR:
            break
        args = written_args(inner)
        if not args:
            return None
        if len(args) != 1:
            return inner
        inner = strip(args[0])
    return inner


def _merge(ways: list[Way]) -> list[Way]:
    """One way per (trigger, source, period, entry), with the guards common to all that were
    merged."""
    merged: dict[CursorKey, Way] = {}
    for way in ways:
        key = (way.trigger, way.source, way.period, way.entry)
        if key in merged:
            common = {(g.var, g.value) for g in way.guards}
            kept = tuple(g for g in merged[key].guards if (g.var, g.value) in common)
            merged[key] = replace(way, guards=kept)
        elif len(merged) < _MAX_WAYS:
            merged[key] = way
    return list(merged.values())


def _joined(first: tuple[Guard, ...], then: tuple[Guard, ...]) -> tuple[Guard, ...]:
    """Guards met one after the other (each condition once)."""
    known = {(g.var, g.value) for g in first}
    return first + tuple(g for g in then if (g.var, g.value) not in known)


def _unique(items: Iterable) -> list:
    return list(dict.fromkeys(items))
