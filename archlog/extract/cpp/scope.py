"""Which code of a translation unit the C++ walker reads: the file's own, the definitions in the
workspace's headers that it uses (transitively), and for a nodelet class only its methods and
those of its base classes (the class as exported may be a typedef of the class defined)."""

from __future__ import annotations

from collections.abc import Callable

import clang.cindex as ci

from archlog.extract.cpp.cache import cache_dir
from archlog.extract.cpp.clang_ast import CursorKey, K, qualified
from archlog.extract.cpp.handles import METHODS
from archlog.extract.cpp.stubs import API_DIR

_CALLABLE = (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR, K.FUNCTION_TEMPLATE)


class Scope:
    """The file read, the workspace folders whose headers' code is read, and the class read alone
    (`cls`: "A" or, when other files found its bases, "A|ns::Base|..."); `classes` is the class
    with the bases this file knows of, once `relevant` has run."""

    def __init__(self, source: str, workspace: tuple[str, ...], cls: str | None) -> None:
        self.source, self.cls = source, cls
        self.workspace = tuple(folder.rstrip("/") + "/" for folder in workspace)
        self.classes: list[str] = cls.split("|") if cls else []
        self.members: list[ci.Cursor] = []  # the data members of those classes this file sees
        self.bound: dict[str, str] = {}  # a base class template's parameter -> the argument a class gives

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
            if definition is None or not self.workspace_header(definition) or \
                    (qualified(decl.semantic_parent), decl.spelling) in METHODS:  # an API the walker reads as such
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
        (with the spans of their lines), and those of the other functions they call, in the file
        or in the workspace's headers (a helper object's methods that subscribe on the handle
        the nodelet gave it)."""
        if self.cls is None:
            return cursors, None
        self.classes, self.members, inline = _with_bases(self.classes, cursors, self.bound)
        kept: list[ci.Cursor] = []
        spans: list[tuple[int, int]] = []
        seen: set[tuple[str, int, int]] = set()
        for cursor in cursors:
            if cursor.kind in (K.CXX_METHOD, K.CONSTRUCTOR, K.FUNCTION_DECL) and cursor.is_definition():
                owner = cursor.semantic_parent
                if cursor.kind == K.FUNCTION_DECL or qualified(owner) in self.classes:
                    kept += list(cursor.walk_preorder())
                    spans.append((cursor.extent.start.line, cursor.extent.end.line))
                    seen.add(_where(cursor))
        for method in inline:  # the classes' methods defined in their workspace headers, called or not
            if _where(method) not in seen and self.workspace_header(method):  # (virtual: called from elsewhere)
                kept += list(method.walk_preorder())
                seen.add(_where(method))
        return kept + _reached(kept, set(cursors)), spans


def _reached(kept: list[ci.Cursor], readable: set[ci.Cursor]) -> list[ci.Cursor]:
    """The cursors of the definitions (among `readable`) that the kept code calls, transitively."""
    seen = set(kept)
    found: list[ci.Cursor] = []
    pending = _callees(kept)
    while pending and len(found) < 40000:
        definition = pending.pop().get_definition()
        if definition is None or definition in seen or definition not in readable:
            continue
        body = list(definition.walk_preorder())
        seen.update(body)
        found += body
        pending += _callees(body)
    return found


def _callees(cursors: list[ci.Cursor]) -> list[ci.Cursor]:
    return [c.referenced for c in cursors if c.kind in (K.CALL_EXPR, K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)
            and c.referenced is not None and c.referenced.kind in _CALLABLE]


def _where(cursor: ci.Cursor) -> tuple[str, int, int]:
    loc = cursor.location
    return (loc.file.name if loc.file is not None else "", loc.line, loc.column)


def _pattern(definition: ci.Cursor | None) -> ci.Cursor | None:
    """The class template a class is an implicit instantiation of (a base `Base<T>`, whose cursor
    has no members of its own), else the class."""
    if definition is None or any(True for _ in definition.get_children()):
        return definition
    template = ci.conf.lib.clang_getSpecializedCursorTemplate(definition)
    return template if template is not None and template.kind == K.CLASS_TEMPLATE else definition


def _bind(base: ci.Type, bound: dict[str, str]) -> None:
    """Bind the parameters of the class template `base` instantiates to the types it is given."""
    template = _pattern(base.get_declaration().get_definition())
    if template is None or template.kind != K.CLASS_TEMPLATE:
        return
    parameters = [c.spelling for c in template.get_children() if c.kind == K.TEMPLATE_TYPE_PARAMETER]
    for i, parameter in enumerate(parameters[:max(base.get_num_template_arguments(), 0)]):
        argument = base.get_template_argument_type(i)
        if argument.kind != ci.TypeKind.INVALID:
            bound.setdefault(parameter, argument.get_canonical().spelling)


def _with_bases(classes: list[str], cursors: list[ci.Cursor], bound: dict[str, str]) \
        -> tuple[list[str], list[ci.Cursor], list[ci.Cursor]]:
    """The classes, the classes their typedefs in the file name, and all their base classes; the
    data members of the definitions found, and the methods defined inside them. A base that is a
    class template's instantiation is read as the template, its parameters bound (in `bound`) to
    the types the class gives."""
    found, members, defined = list(classes), list[ci.Cursor](), set[str]()
    inline: list[ci.Cursor] = []
    pending = [c.underlying_typedef_type.get_declaration() for c in cursors
               if c.kind in (K.TYPEDEF_DECL, K.TYPE_ALIAS_DECL) and qualified(c) in classes]
    pending += [c.referenced for c in cursors if c.kind in (K.CLASS_DECL, K.STRUCT_DECL, K.TYPE_REF)
                and c.referenced is not None and qualified(c.referenced) in classes]
    while pending and len(found) < 64:
        decl = pending.pop()
        definition = _pattern(decl.get_definition()) if decl is not None else None
        if definition is None:
            continue
        if (name := qualified(definition)) not in found:
            found.append(name)
        if name in defined:
            continue
        defined.add(name)
        members += [c for c in definition.get_children() if c.kind == K.FIELD_DECL]
        inline += [c for c in definition.get_children() if c.kind in (K.CXX_METHOD, K.CONSTRUCTOR)
                   and c.is_definition()]
        bases = [base.type for base in definition.get_children() if base.kind == K.CXX_BASE_SPECIFIER]
        for base in bases:
            _bind(base, bound)
        pending += [base.get_declaration() for base in bases]
    return found, members, inline
