"""What the rclcpp readers need of the C++ walker that drives them (roscpp._Walker)."""

from __future__ import annotations

from typing import Protocol

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import CursorKey
from archlog.extract.cpp.result import FileResult
from archlog.extract.summary import ParamSpec
from archlog.values import Unknown, Value


class WalkContext(Protocol):
    """The walker of one file: its result, its shown name, values of expressions, and the
    file's calls by callee, parameter variables and bound arguments."""

    file: str
    result: FileResult
    spans: list[tuple[int, int]] | None
    call_sites: dict[CursorKey, list[ci.Cursor]]
    param_vars: dict[CursorKey, Value]
    bindings: dict[CursorKey, ci.Cursor]

    def key(self, decl: ci.Cursor | None) -> CursorKey: ...
    def in_main(self, cursor: ci.Cursor) -> bool: ...
    def shown(self, cursor: ci.Cursor) -> str: ...
    def value(self, expr: ci.Cursor, depth: int = 0) -> Value: ...
    def unknown(self, cursor: ci.Cursor, why: str = "") -> Unknown: ...
    def add(self, kind: str, call: ci.Cursor, name: Value, type_: Value, handle: Value, default: Value | None = None,
            queue: Value | None = None, qos: tuple[tuple[str, str], ...] = (), *, param: ParamSpec | None = None
            ) -> None: ...
