"""Which code of a translation unit the C++ walker reads: the file's own, the definitions in the
workspace's headers that it uses (transitively), and for a nodelet class only its methods."""

from __future__ import annotations

from collections.abc import Callable

import clang.cindex as ci

from archlog.extract.cpp.cache import cache_dir
from archlog.extract.cpp.clang_ast import CursorKey, K, qualified
from archlog.extract.cpp.stubs import API_DIR

_CALLABLE = (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR, K.FUNCTION_TEMPLATE)


class Scope:
    """The file read, the workspace folders whose headers' code is read, and the class read alone."""

    def __init__(self, source: str, workspace: tuple[str, ...], cls: str | None) -> None:
        self.source, self.cls = source, cls
        self.workspace = tuple(folder.rstrip("/") + "/" for folder in workspace)

    def header_code(self, cursors: list[ci.Cursor], key: Callable[[ci.Cursor | None], CursorKey]) -> list[ci.Cursor]:
        """The cursors of definitions in the workspace's own headers that the file's code uses
        (base class constructors, inline methods), and of the methods those use or register as
        callbacks, transitively."""
        found: list[ci.Cursor] = []
        seen: set[CursorKey] = set()
        pending = [c.referenced for c in cursors if c.kind == K.CALL_EXPR]
        while pending and len(seen) < 4000:
            decl = pending.pop()
            if decl is None or (decl_key := key(decl.canonical)) in seen:
                continue
            seen.add(decl_key)
            definition = decl.get_definition()
            if definition is None or not self.workspace_header(definition):
                continue
            body = list(definition.walk_preorder())
            found += body
            pending += [c.referenced for c in body if c.kind in (K.CALL_EXPR, K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)
                        and c.referenced is not None and c.referenced.kind in _CALLABLE]
        return found

    def workspace_header(self, definition: ci.Cursor) -> bool:
        """A definition in a header of the workspace (not the file itself, not a generated header
        or one of archlog's stand-ins)."""
        file = definition.location.file
        if file is None or file.name == self.source or not file.name.startswith(self.workspace):
            return False
        return not file.name.startswith((str(cache_dir()), str(API_DIR)))

    def relevant(self, cursors: list[ci.Cursor]) -> tuple[list[ci.Cursor], list[tuple[int, int]] | None]:
        """All cursors, or for a nodelet class only those inside its methods and free functions
        (with the spans of their lines)."""
        if self.cls is None:
            return cursors, None
        kept: list[ci.Cursor] = []
        spans: list[tuple[int, int]] = []
        for cursor in cursors:
            if cursor.kind in (K.CXX_METHOD, K.CONSTRUCTOR, K.FUNCTION_DECL) and cursor.is_definition():
                owner = cursor.semantic_parent
                if cursor.kind == K.FUNCTION_DECL or qualified(owner) == self.cls:
                    kept += list(cursor.walk_preorder())
                    spans.append((cursor.extent.start.line, cursor.extent.end.line))
        return kept, spans
