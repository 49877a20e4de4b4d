"""The function definitions of a C++ file, as the rclcpp readers ask about them."""

from __future__ import annotations

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import K


class Definitions:
    """A file's constructors and the spans of its function definitions (filled by read())."""

    def __init__(self) -> None:
        self.constructors: list[ci.Cursor] = []
        self.function_spans: list[tuple[int, int]] = []

    def read(self, cursors: list[ci.Cursor]) -> None:
        definitions = [c for c in cursors if c.kind in (K.CONSTRUCTOR, K.CXX_METHOD, K.FUNCTION_DECL,
                                                         K.FUNCTION_TEMPLATE) and c.is_definition()]
        self.constructors = [c for c in definitions if c.kind == K.CONSTRUCTOR]
        self.function_spans = [(c.extent.start.offset, c.extent.end.offset) for c in definitions]

    def base_init(self, call: ci.Cursor) -> bool:
        """A call in a constructor's initializer list (a base class initializer)."""
        return any(call.extent.start.offset >= c.extent.start.offset and call.extent.end.offset <= c.extent.end.offset
                   and call.extent.start.offset < body.extent.start.offset
                   for c in self.constructors for body in c.get_children() if body.kind == K.COMPOUND_STMT)

    def member_initializer(self, decl: ci.Cursor) -> ci.Cursor | None:
        """The expression a member is initialised with in a constructor's initializer list."""
        for ctor in self.constructors:
            children = list(ctor.get_children())
            for member, init in zip(children, children[1:]):
                if member.kind == K.MEMBER_REF and member.referenced == decl:
                    return init
        return None

    def same_function(self, a: ci.Cursor, b: ci.Cursor) -> bool:
        """Whether two cursors are in the same function definition of this file."""
        def owner(cursor: ci.Cursor) -> int:
            return next((i for i, (start, end) in enumerate(self.function_spans)
                         if start <= cursor.extent.start.offset <= end), -1)
        return owner(a) == owner(b)
