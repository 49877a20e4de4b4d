"""Functions that create a port named by one of their parameters (wrapper summaries).

A factory such as `make_server<ActionT>(node, name, ...)` that hands `name` on, through other
functions, constructors (`std::make_shared<Server<ActionT>>(node, name)`, a delegating
constructor) and a member initialised from it, to `rclcpp_action::create_server<ActionT>(...,
name_, ...)` creates one port per call: the name is the one each call site passes. Inside templates
libclang gives these calls no referenced declaration, so the summaries are read from the tokens of
the definitions: callees are matched by name (and qualifier) and by how many arguments they take.
The walker then makes one port at each call site of a wrapper (walker.py `wrapped`)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import CursorKey, K, qualified
from archlog.extract.cpp.rclcpp.api import ENTITIES, FACTORIES, NODE_CLASSES

DEPTH = 6  # a name handed on through this many functions at most
_CALLABLE = (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR, K.FUNCTION_TEMPLATE)
_SCOPES = (K.NAMESPACE, K.CLASS_DECL, K.STRUCT_DECL, K.CLASS_TEMPLATE, K.LINKAGE_SPEC,
           K.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)
_CLASSES = (K.CLASS_DECL, K.STRUCT_DECL, K.CLASS_TEMPLATE, K.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)
_OPEN, _CLOSE = "([{", ")]}"
Token = tuple[str, int]  # spelling, line


@dataclass(frozen=True)
class Wrapper:
    """Parameter `index` of a function names a port of `kind`; `type_` is the interface as the
    innermost rclcpp call writes it (None: a template parameter, the call site's template argument
    says it); `base` is the file and line of that rclcpp call."""

    index: int
    kind: str
    type_: str | None
    base: tuple[str, int]


@dataclass(frozen=True)
class Call:
    """A call as written: callee name, its qualifier, the first template argument, the arguments."""

    name: str
    scope: str
    template: str
    args: tuple[tuple[str, ...], ...]
    line: int


@dataclass
class Definition:
    """A function or constructor definition of the workspace, as tokens."""

    key: CursorKey
    name: str  # a constructor: its class's name
    qualified: str
    file: str
    params: list[str]
    names: list[bool]  # whether each parameter can hold a name (a string, or a template parameter's type)
    required: int  # parameters without a default value
    template_params: set[str]
    members: dict[str, int] = field(default_factory=dict)  # member -> the parameter that initialises it
    calls: list[Call] = field(default_factory=list)
    constructor: bool = False
    method: bool = False  # a member function (not a constructor)

    def accepts(self, call: Call) -> bool:
        if not self.required <= len(call.args) <= len(self.params):
            return False
        return not call.scope or call.scope == "std" or self.qualified.endswith(f"{call.scope}::{self.name}")

    def parameter_of(self, arg: tuple[str, ...]) -> int | None:
        """The parameter an argument is (directly, or through a member initialised from it)."""
        name = _bare(arg)
        if name is None:
            return None
        index = self.params.index(name) if name in self.params else self.members.get(name)
        return index if index is not None and self.names[index] else None


@dataclass
class Summaries:
    """The wrappers by definition, and the definitions read, by name (to match calls by tokens)."""

    wrappers: dict[CursorKey, set[Wrapper]]
    by_name: dict[str, list[Definition]]


Key = Callable[[ci.Cursor], CursorKey]
Shown = Callable[[ci.Cursor], str]


def definitions(root: ci.Cursor, readable: Callable[[ci.Cursor], bool]) -> list[ci.Cursor]:
    """The function and constructor definitions of the files `readable(cursor)` accepts."""
    found: list[ci.Cursor] = []
    pending = [c for c in root.get_children() if c.location.file is not None and readable(c)]
    while pending and len(found) < 20000:
        cursor = pending.pop()
        if cursor.kind in _CALLABLE and cursor.is_definition():
            found.append(cursor)
        elif cursor.kind in _SCOPES:
            pending += cursor.get_children()
    return found


def summaries(cursors: list[ci.Cursor], key: Key, shown: Shown) -> Summaries:
    """The wrappers among the definitions, each with the parameters that name its ports."""
    defs = [d for c in cursors if (d := _definition(c, key, shown)) is not None]
    by_name: dict[str, list[Definition]] = {}
    for d in defs:
        by_name.setdefault(d.name, []).append(d)
    constructors: dict[str, list[Definition]] = {}
    for d in defs:
        if d.constructor:
            constructors.setdefault(_owner(d), []).append(d)
    found: dict[CursorKey, set[Wrapper]] = {}
    for _ in range(DEPTH + 1):
        added = False
        for d in defs:
            for arg, new in _named(d, found, by_name):
                for target, index in _namers(d, arg, constructors):
                    wrapper = Wrapper(index, *new)
                    if wrapper not in found.setdefault(target.key, set()):
                        found[target.key].add(wrapper)
                        added = True
        if not added:
            break
    return Summaries(found, by_name)


def _named(d: Definition, found: dict[CursorKey, set[Wrapper]], by_name: dict[str, list[Definition]]) \
        -> Iterator[tuple[tuple[str, ...], tuple[str, str | None, tuple[str, int]]]]:
    """The arguments of `d`'s calls that name a port, each with the port's kind, type and rclcpp call:
    the name argument of an rclcpp call, and the argument a wrapper already found names one with."""
    for call in d.calls:
        base = _port_call(call)
        if base is not None and base[1] < len(call.args):
            type_ = None if call.template in d.template_params or not call.template else call.template
            yield call.args[base[1]], (base[0], type_, (d.file, call.line))
    for call, callee in _callees(d, by_name):
        for wrapper in list(found.get(callee.key, ())):
            if wrapper.index < len(call.args):
                type_ = wrapper.type_
                if type_ is None and call.template and call.template not in d.template_params:
                    type_ = call.template  # the template argument this call gives
                yield call.args[wrapper.index], (wrapper.kind, type_, wrapper.base)


def _namers(d: Definition, arg: tuple[str, ...], constructors: dict[str, list[Definition]]) \
        -> Iterator[tuple[Definition, int]]:
    """The definitions and parameters whose value `arg` is: a parameter of `d` (or a member its own
    initialisers set from one), else a member of `d`'s class that a constructor of the class sets
    from its parameter (the port is made in another method, with what the constructor kept)."""
    index = d.parameter_of(arg)
    if index is not None:
        yield d, index
        return
    member = _bare(arg)
    for constructor in constructors.get(_owner(d), []) if member is not None else []:
        index = constructor.members.get(member or "")
        if constructor is not d and index is not None and constructor.names[index]:
            yield constructor, index


def _owner(d: Definition) -> str:
    """The class a method or constructor belongs to (its qualified name's scope)."""
    return d.qualified.rpartition("::")[0]


def _bare(arg: tuple[str, ...]) -> str | None:
    """The one name an argument is (`x`, `this->x`, `std::move(x)`, `(x)`), None if it is more."""
    if arg[:2] == ("this", "->"):
        arg = arg[2:]
    if len(arg) == 4 and arg[:3] == ("std", "::", "move"):
        arg = arg[3:]
    if len(arg) == 3 and arg[0] == "(" and arg[2] == ")":
        arg = arg[1:2]
    return arg[0] if len(arg) == 1 else None


def _callees(d: Definition, by_name: dict[str, list[Definition]]) -> Iterator[tuple[Call, Definition]]:
    for written in d.calls:
        call, candidates = _targets(written, by_name)
        yield from ((call, c) for c in candidates if c is not d and c.accepts(call))


def _targets(call: Call, by_name: dict[str, list[Definition]]) -> tuple[Call, list[Definition]]:
    """The definitions a call may run, by name: for std::make_shared<Class<T>>(...) Class's
    constructors, with the call rewritten as one of them (template argument T)."""
    if call.name not in FACTORIES:
        return call, by_name.get(call.name, [])
    name = call.template.split("<")[0].split("::")[-1]
    call = Call(name, "", _first_argument(call.template.partition("<")[2].rstrip(">")), call.args, call.line)
    return call, [c for c in by_name.get(name, []) if c.constructor]


def written_wrappers(cursor: ci.Cursor, summaries: Summaries) -> Iterator[tuple[Wrapper, str]]:
    """The wrappers a call without a declaration (a dependent call, inside a template) runs, matched
    by its tokens as calls inside definitions are; each with the template argument the call gives."""
    tokens = [(t.spelling, t.location.line) for t in cursor.get_tokens()]
    calls = _calls(tokens)
    if not calls:
        return
    at = next(i for i, (word, _line) in enumerate(tokens) if word == calls[0].name)
    on_object = at > 0 and tokens[at - 1][0] in ("->", ".")  # `node->f(...)`: a method, not a free function
    call, candidates = _targets(calls[0], summaries.by_name)
    for callee in candidates:
        if callee.accepts(call) and (callee.method or not on_object):
            yield from ((w, w.type_ or call.template) for w in summaries.wrappers.get(callee.key, ()))


def _port_call(call: Call) -> tuple[str, int] | None:
    """An rclcpp call creating a port: its kind and the position of its name argument."""
    if call.scope == "rclcpp_action" and call.name in ("create_server", "create_client"):
        interfaces = len(call.args) >= (8 if call.name == "create_server" else 5)  # the node-interfaces overload
        return ("action_server" if call.name == "create_server" else "action_client"), 4 if interfaces else 1
    if call.name in ENTITIES and not call.name.startswith("create_generic"):
        if call.scope == "rclcpp":  # rclcpp::create_publisher(node, topic, ...)
            return ENTITIES[call.name], 1
        if not call.scope or call.scope in NODE_CLASSES:  # node->create_publisher(topic, ...), Base::create_...
            return ENTITIES[call.name], 0
    return None


def _definition(cursor: ci.Cursor, key: Key, shown: Shown) -> Definition | None:
    tokens = [(t.spelling, t.location.line) for t in cursor.get_tokens()]
    name = cursor.spelling.split("<")[0]
    spellings = [t for t, _ in tokens]
    start = next((i for i in range(len(spellings) - 1) if spellings[i] == name and spellings[i + 1] == "("), None)
    if start is None:
        return None
    close = _matching(spellings, start + 1)
    if close is None:
        return None
    params = [c for c in cursor.get_children() if c.kind == K.PARM_DECL]
    parent = cursor.semantic_parent
    templates = {c.spelling for c in [*cursor.get_children(), *(parent.get_children() if parent else [])]
                 if c.kind == K.TEMPLATE_TYPE_PARAMETER}
    d = Definition(key(cursor), name, qualified(cursor), shown(cursor),
                   [p.spelling for p in params], [_name_type(p.type.spelling, templates) for p in params],
                   sum(1 for p in params if "=" not in [t.spelling for t in p.get_tokens()]), templates,
                   constructor=cursor.kind == K.CONSTRUCTOR or
                   (cursor.kind == K.FUNCTION_TEMPLATE and parent is not None and name == parent.spelling))
    d.method = not d.constructor and parent is not None and parent.kind in _CLASSES
    body = next((i for i in range(close + 1, len(spellings)) if spellings[i] == "{"), len(spellings))
    if close + 1 < len(spellings) and spellings[close + 1] == ":":
        body = _initialisers(d, tokens, close + 2)
    d.calls += _calls(tokens[body:])
    for i in range(body, len(spellings) - 3):  # member_ = parameter;
        if spellings[i + 1] == "=" and spellings[i + 3] == ";" and spellings[i + 2] in d.params and \
                spellings[i - 1] in ("{", ";", "}", ">"):
            d.members.setdefault(spellings[i], d.params.index(spellings[i + 2]))
    return d


def _name_type(spelling: str, templates: set[str]) -> bool:
    """A parameter type that can hold a port's name: a string, a character pointer, or a template
    parameter (not a duration, a callback or a number handed on beside the name)."""
    bare = spelling.replace("const ", "").replace("&", "").replace("*", "").strip()
    return "string" in spelling or "char" in spelling or bare in templates


def _initialisers(d: Definition, tokens: list[Token], at: int) -> int:
    """Read a constructor's initialiser list from `at`: members initialised from a parameter and
    calls of other constructors (delegating, base classes); the index of the body's brace."""
    spellings = [t for t, _ in tokens]
    while at < len(spellings):
        opening = next((i for i in range(at, len(spellings)) if spellings[i] in "({"), None)
        if opening is None:
            return len(spellings)
        close = _matching(spellings, opening)
        if close is None:
            return len(spellings)
        target = spellings[at:opening]
        args = _split(tokens[opening + 1:close])
        d.calls += _calls(tokens[opening + 1:close])
        if len(target) == 1 and len(args) == 1 and (index := d.parameter_of(args[0])) is not None:
            d.members[target[0]] = index
        elif target:
            head = [t for t in target if t.isidentifier()]
            d.calls.append(Call(head[0] if head else "", "", "", args, tokens[at][1]))
        if close + 1 < len(spellings) and spellings[close + 1] == ",":
            at = close + 2
        else:
            return close + 1
    return len(spellings)


def _calls(tokens: list[Token]) -> list[Call]:
    """Every `name(...)` and `name<...>(...)` among the tokens, with its arguments."""
    spellings = [t for t, _ in tokens]
    closing = _pairs(spellings)
    found: list[Call] = []
    for i, word in enumerate(spellings):
        if not word.isidentifier() or i + 1 >= len(spellings):
            continue
        after, template = i + 1, ""
        if spellings[after] == "<" and (end := _angle_end(spellings, after)) is not None:
            template = _first_argument("".join(spellings[after + 1:end + 1])[:-1])
            after = end + 1
        if after >= len(spellings) or spellings[after] != "(" or (close := closing.get(after)) is None:
            continue
        scope: list[str] = []
        j = i
        while j >= 2 and spellings[j - 1] == "::" and spellings[j - 2].isidentifier():
            scope.insert(0, spellings[j - 2])
            j -= 2
        found.append(Call(word, "::".join(scope), template, _split(tokens[after + 1:close]), tokens[i][1]))
    return found


def _split(tokens: list[Token]) -> tuple[tuple[str, ...], ...]:
    """Arguments at the top level of a token list (template argument lists kept whole)."""
    spellings = [t for t, _ in tokens]
    args: list[tuple[str, ...]] = []
    depth, start, i = 0, 0, 0
    while i < len(spellings):
        word = spellings[i]
        if word == "<" and i and spellings[i - 1].isidentifier() and (end := _angle_end(spellings, i)) is not None:
            i = end
        elif word in _OPEN:
            depth += 1
        elif word in _CLOSE:
            depth -= 1
        elif word == "," and depth == 0:
            args.append(tuple(spellings[start:i]))
            start = i + 1
        i += 1
    if spellings:
        args.append(tuple(spellings[start:]))
    return tuple(args)


def _pairs(spellings: list[str]) -> dict[int, int]:
    """The index of the bracket closing each bracket that is closed, in one pass (a search per
    call from each opening bracket was quadratic in the unclosed ones)."""
    opened: list[int] = []
    pairs: dict[int, int] = {}
    for i, word in enumerate(spellings):
        if word in _OPEN:
            opened.append(i)
        elif word in _CLOSE and opened:
            pairs[opened.pop()] = i
    return pairs


def _matching(spellings: list[str], at: int) -> int | None:
    """The index of the bracket closing the one at `at`."""
    depth = 0
    for i in range(at, len(spellings)):
        if spellings[i] in _OPEN:
            depth += 1
        elif spellings[i] in _CLOSE:
            depth -= 1
            if depth == 0:
                return i
    return None


def _angle_end(spellings: list[str], at: int) -> int | None:
    """The `>` closing a template argument list opened at `at` (None: a comparison, not a list)."""
    depth = 0
    for i in range(at, min(len(spellings), at + 64)):
        word = spellings[i]
        if word in (";", "{", "}", "&&", "||", "=", "return"):
            return None
        depth += word == "<"
        depth -= 2 if word == ">>" else word == ">"
        if depth <= 0:
            return i if depth == 0 else None  # `>>` closing an enclosing list too: this one is inside it
    return None


def _first_argument(template: str) -> str:
    """`A` of `A,B` (a template argument list's first argument, as text)."""
    depth = 0
    for i, char in enumerate(template):
        depth += char == "<"
        depth -= char == ">"
        if char == "," and depth == 0:
            return template[:i]
    return template
