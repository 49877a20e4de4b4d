"""A virtual method of the class read alone (a plugin or nodelet class), called on the object itself:
the expression its most derived override returns, when that override's body is one return statement
(`std::string getName() override {return "navigate";}` makes a base class's `getName()` that)."""

from __future__ import annotations

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import K, qualified, written_args
from archlog.extract.cpp.state import single_return


def override_return(call: ci.Cursor, kept: list[ci.Cursor], classes: list[str]) -> ci.Cursor | None:
    """The returned expression of the override that runs for `call`; None when the call is not a
    virtual method's without arguments on `this`, or no override among `classes` (the class read,
    then its bases) is a single return statement."""
    ref = call.referenced
    if ref is None or ref.kind != K.CXX_METHOD or not ref.is_virtual_method() or written_args(call) or \
            not _on_this(call):
        return None
    ranked = [(classes.index(owner), c) for c in kept
              if c.kind == K.CXX_METHOD and c.spelling == ref.spelling and c.is_definition()
              and (owner := qualified(c.semantic_parent)) in classes]
    if not ranked:
        return None
    most_derived = min(ranked, key=lambda pair: pair[0])[1]
    return single_return(most_derived)


def _on_this(call: ci.Cursor) -> bool:
    """`f()` or `this->f()` inside a method."""
    callee = next(call.get_children(), None)
    while callee is not None and callee.kind == K.UNEXPOSED_EXPR:
        callee = next(callee.get_children(), None)
    if callee is None or callee.kind != K.MEMBER_REF_EXPR:
        return False
    objects = [c for c in callee.get_children() if c.kind != K.TYPE_REF]
    return not objects or (len(objects) == 1 and objects[0].kind == K.CXX_THIS_EXPR)
