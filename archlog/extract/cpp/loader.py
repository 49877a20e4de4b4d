"""nodelet::Loader::load(name, type, remappings, argv) in an executable's own code: the nodelets a
standalone executable runs in its process (image_proc, stereo_image_proc), read once per call
site of the function that loads them, with the remappings the map holds at that point."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Protocol

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import CursorKey, K, written_args
from archlog.extract.summary import LoadedNodelet
from archlog.values import Value

LOADER = "nodelet::Loader"
_FUNCTIONS = (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR)


class LoaderContext(Protocol):
    """What reading a load needs of the walker."""

    kept: list[ci.Cursor]
    bindings: dict[CursorKey, ci.Cursor]
    call_sites: dict[CursorKey, list[ci.Cursor]]

    def key(self, decl: ci.Cursor | None) -> CursorKey: ...
    def value(self, expr: ci.Cursor, depth: int = 0) -> Value: ...
    def shown(self, cursor: ci.Cursor) -> str: ...


def loaded_nodelets(ctx: LoaderContext, call: ci.Cursor, args: list[ci.Cursor]) -> list[LoadedNodelet]:
    """One LoadedNodelet per call site of the function the load is in (its parameters bound to
    that site's arguments), or one when it is not called from this file (main)."""
    function = _enclosing(ctx.kept, call)
    sites = ctx.call_sites.get(ctx.key(function.canonical), []) if function is not None else []
    params = [ctx.key(p) for p in function.get_arguments()] if function is not None else []
    found = []
    for site in sites or [None]:
        with _bound(ctx, dict(zip(params, written_args(site))) if site is not None else {}):
            remaps = tuple((ctx.value(k), ctx.value(v)) for k, v in _entries(function, args[2], call)) \
                if function is not None and len(args) > 2 else ()
            found.append(LoadedNodelet(ctx.value(args[1]), ctx.value(args[0]), remaps, ctx.shown(call),
                                       call.location.line))
    return list(dict.fromkeys(found))


@contextmanager
def _bound(ctx: LoaderContext, bindings: dict[CursorKey, ci.Cursor]) -> Iterator[None]:
    saved, ctx.bindings = ctx.bindings, bindings
    try:
        yield
    finally:
        ctx.bindings = saved


def _enclosing(cursors: list[ci.Cursor], call: ci.Cursor) -> ci.Cursor | None:
    """The innermost function definition that contains the call."""
    at, file = call.extent.start.offset, call.location.file.name if call.location.file else None
    around = [c for c in cursors if c.kind in _FUNCTIONS and c.is_definition() and c.location.file is not None
              and c.location.file.name == file and c.extent.start.offset <= at <= c.extent.end.offset]
    return max(around, key=lambda c: c.extent.start.offset, default=None)


def _entries(function: ci.Cursor, map_expr: ci.Cursor, call: ci.Cursor) -> list[tuple[ci.Cursor, ci.Cursor]]:
    """(key, value) of `map[key] = value` on the map variable before the call in the function,
    each `map.clear()` emptying it (read in source order: straight-line code)."""
    var = _variable(map_expr)
    if var is None:
        return []
    entries: dict[str, tuple[ci.Cursor, ci.Cursor]] = {}
    for cursor in function.walk_preorder():
        if cursor.kind != K.CALL_EXPR or cursor.extent.start.offset >= call.extent.start.offset:
            continue
        children = list(cursor.get_children())
        if cursor.spelling == "clear" and children and _variable(children[0]) == var:
            entries.clear()
        elif cursor.spelling == "operator=" and len(children) == 3 and children[0].spelling == "operator[]" \
                and _variable(children[0]) == var:
            key = list(children[0].get_children())[-1]
            entries[" ".join(t.spelling for t in key.get_tokens())] = (key, children[-1])
    return list(entries.values())


def _variable(expr: ci.Cursor) -> ci.Cursor | None:
    """The variable an expression names first (the map of `map[k]`, `map.clear()`, `map`)."""
    found = next((c for c in expr.walk_preorder() if c.kind == K.DECL_REF_EXPR and c.referenced is not None
                  and c.referenced.kind in (K.VAR_DECL, K.PARM_DECL)), None)
    return found.referenced if found is not None else None
