"""Call-site summaries across the files of one executable: a function's parameter that no call in
its own file gives a value (a NodeHandle or a name handed to a constructor or function defined in
another file, tf2_ros's BufferServer, a nodelet's childInit) stays a `FromCaller` unknown while
the file is read; each file records the handle and name arguments of its calls, and once every
file is read the unknown takes the value all call sites agree on."""

from __future__ import annotations

import ctypes
from dataclasses import dataclass, replace

import clang.cindex as ci

from archlog.extract.summary import LoadedNodelet, Port
from archlog.values import Alternatives, Concat, ParamRef, Unknown, Value, concat

Sites = dict[str, list[tuple[Value | None, ...]]]
"""function (USR) -> the arguments of each call (None: not a handle or a name)"""
_DEPTH = 6  # a value handed on through this many functions at most


@dataclass(frozen=True)
class FromCaller(Unknown):
    """Parameter `index` of `functions` (the USRs of a function and of those it overrides): its value
    comes from a call in another file of the executable."""

    functions: tuple[str, ...] = ()
    index: int = 0


def settled_ports(ports: list[Port], sites: Sites) -> list[Port]:
    """Ports whose names, handles, defaults and conditions take their callers' values."""
    return list(dict.fromkeys(_settled(port, sites) for port in ports))  # once each, in order (not quadratic)


def _settled(port: Port, sites: Sites) -> Port:
    condition = port.condition and (settle(port.condition[0], sites), port.condition[1])
    also = tuple((settle(value, sites), wanted) for value, wanted in port.also)
    return replace(port, name=settle(port.name, sites), handle_ns=settle(port.handle_ns, sites),
                   default=None if port.default is None else settle(port.default, sites), condition=condition,
                   also=also)


def settled_loads(loads: list[LoadedNodelet], sites: Sites) -> list[LoadedNodelet]:
    return [replace(n, plugin=settle(n.plugin, sites), name=settle(n.name, sites)) for n in loads]


def settle(value: Value, sites: Sites, depth: int = 0) -> Value:
    """`value` with each FromCaller replaced by what every call site passes (when they agree)."""
    if depth > _DEPTH:
        return value
    if isinstance(value, FromCaller):
        passed = {args[value.index] for usr in value.functions for args in sites.get(usr, [])
                  if len(args) > value.index}
        agreed = passed.pop() if len(passed) == 1 else None
        return value if agreed is None else settle(agreed, sites, depth + 1)
    if isinstance(value, Concat):
        return concat(*(settle(p, sites, depth) for p in value.parts))
    if isinstance(value, Alternatives):
        return Alternatives(tuple(settle(o, sites, depth) for o in value.options), value.every)
    if isinstance(value, ParamRef):
        return replace(value, name=settle(value.name, sites, depth), default=settle(value.default, sites, depth),
                       handle_ns=settle(value.handle_ns, sites, depth))
    return value


def merged_sites(parts: list[Sites]) -> Sites:
    sites: Sites = {}
    for part in parts:
        for usr, calls in part.items():
            sites[usr] = list(dict.fromkeys([*sites.get(usr, []), *calls]))
    return sites


def function_keys(function: ci.Cursor) -> tuple[str, ...]:
    """The USRs of a function and of the methods it overrides, transitively (a virtual call names
    the base class's method)."""
    keys: list[str] = []
    pending = [function]
    while pending and len(keys) < 16:
        cursor = pending.pop()
        usr = cursor.canonical.get_usr()
        if usr and usr not in keys:
            keys.append(usr)
            pending += overridden(cursor)
    return tuple(keys)


def overridden(method: ci.Cursor) -> list[ci.Cursor]:
    """clang_getOverriddenCursors, which the Python bindings do not wrap."""
    if method.kind != ci.CursorKind.CXX_METHOD:
        return []
    lib = ci.conf.lib
    if not getattr(lib.clang_getOverriddenCursors, "argtypes", None):
        lib.clang_getOverriddenCursors.argtypes = [ci.Cursor, ctypes.POINTER(ctypes.POINTER(ci.Cursor)),
                                                   ctypes.POINTER(ctypes.c_uint)]
        lib.clang_getOverriddenCursors.restype = None
        lib.clang_disposeOverriddenCursors.argtypes = [ctypes.POINTER(ci.Cursor)]
        lib.clang_disposeOverriddenCursors.restype = None
    found = ctypes.POINTER(ci.Cursor)()
    count = ctypes.c_uint(0)
    lib.clang_getOverriddenCursors(method, ctypes.byref(found), ctypes.byref(count))
    cursors = [ci.Cursor.from_buffer_copy(found[i]) for i in range(count.value)]
    for cursor in cursors:
        cursor._tu = method._tu  # what the bindings' cursors keep, so that their unit outlives them
    if count.value:
        lib.clang_disposeOverriddenCursors(found)
    return cursors
