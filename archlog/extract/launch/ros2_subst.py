"""ROS 2 launch substitutions: one representation for the XML/YAML `$(...)` syntax and for the
Python substitution classes, the launch context they read, and their static evaluation.

Substitutions nest (`$(find-pkg-share $(var pkg))`); `parse` follows launch's frontend grammar
(quoted arguments, backslash escapes). `perform` evaluates as launch does and raises `Unresolved`
for what depends on the machine or the run (an unset variable, a package that is not here, a
command's output) and `SubstitutionError` for what launch itself rejects. `$(eval)` goes through
the restricted evaluator of `evaluate.py`; nothing is executed.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from pathlib import Path

import yaml

from archlog import budget, sandbox
from archlog.extract.launch import bounded_yaml, conditions
from archlog.extract.launch.conditions import Guard
from archlog.extract.launch.evaluate import BUILTINS, MATH, restricted_eval
from archlog.extract.launch.model import Element, SubstitutionError, UnknownArg, Unresolved, read_file
from archlog.extract.launch.read import boolean


@dataclass(frozen=True)
class Text:
    """Literal text."""

    text: str


@dataclass(frozen=True)
class Call:
    """A substitution by its frontend name (`var`, `env`, `find-pkg-share`, `eval`...) with its
    arguments, each a concatenation of parts. Python-only classes get names of their own
    (`path-join`, `as-bool`) and `opaque` stands for a value archlog could not interpret."""

    name: str
    args: tuple[Parts, ...] = ()


@dataclass(frozen=True)
class Rewritten:
    """nav2_common's RewrittenYaml: a parameter file rewritten at launch (under `root_key`, with
    leaf parameters and values replaced). Only a parameter file can use it."""

    source: Parts
    root_key: Parts | None
    params: tuple[tuple[str, Parts], ...]
    values: tuple[tuple[str, Parts], ...]
    convert_types: bool = False


Subst = Text | Call | Rewritten
Parts = tuple[Subst, ...]


def text(value: str) -> Parts:
    return (Text(value),)


def opaque(reason: str) -> Parts:
    """Parts that cannot be performed; `reason` says why."""
    return (Call("opaque", (text(reason),)),)


# -- the launch context -------------------------------------------------------------------
@dataclass
class Context:
    """What launch's LaunchContext holds for one point of the description: the launch
    configurations (with launch_ros's `ros_namespace`, `ros_remaps` and `global_params` kept in
    them as launch does), the environment, the current file, and how it was reached."""

    configs: dict[str, object]
    env: dict[str, str | UnknownArg]
    file: Path
    find: Callable[[str], Path | None]
    serial: Iterator[int]
    condition: str | None = None
    guards: tuple[Guard | None, ...] = ()  # the undecided conditions' guards (conditions.py)
    chain: tuple[Element, ...] = ()  # the include Elements that led here, outermost first

    def scoped(self) -> Context:
        """A pushed copy (launch's PushLaunchConfigurations + PushEnvironment): the dictionaries
        are copied, the lists in them are shared, as in launch."""
        return replace(self, configs=dict(self.configs), env=dict(self.env))


# -- the frontend grammar -----------------------------------------------------------------
def parse(source: str) -> Parts:
    """Parse a frontend attribute (XML or YAML string) into parts, as launch's grammar does."""
    if "$(" not in source and "\\" not in source:
        return text(source)
    parser = _Parser(source)
    parts = parser.template(None)
    if parser.pos != len(source):
        raise parser.error("unexpected character")
    return parts


class _Parser:
    """Recursive descent over launch's substitution grammar. `quote` is the quoting context:
    None at the top level, or the quote character of the enclosing quoted argument."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.pos = 0

    def error(self, what: str) -> SubstitutionError:
        return SubstitutionError(f"invalid substitution syntax ({what} at column {self.pos + 1}): {self.source}")

    def at_subst(self) -> bool:
        return self.source.startswith("$(", self.pos)

    def template(self, quote: str | None) -> Parts:
        """Text and substitutions up to the end (or the closing `quote`)."""
        parts: list[Subst] = []
        buffer: list[str] = []
        while self.pos < len(self.source):
            char = self.source[self.pos]
            if quote is not None and char == quote:
                break
            if self.at_subst():
                _flush(buffer, parts)
                parts.append(self.substitution(quote))
            elif char == "\\" and self.pos + 1 < len(self.source):
                buffer.append(self.source[self.pos + 1])
                self.pos += 2
            else:
                buffer.append(char)
                self.pos += 1
        _flush(buffer, parts)
        return tuple(parts) or text("")

    def substitution(self, quote: str | None) -> Call:
        self.pos += 2
        start = self.pos
        while self.pos < len(self.source) and (self.source[self.pos].isalnum() or self.source[self.pos] in "_-"):
            self.pos += 1
        name = self.source[start:self.pos]
        if not name or not name[0].isalpha():
            raise self.error("expected a substitution name")
        args: list[Parts] = []
        while self.pos < len(self.source) and self.source[self.pos] == " ":
            while self.pos < len(self.source) and self.source[self.pos] == " ":
                self.pos += 1
            if self.pos < len(self.source) and self.source[self.pos] != ")":
                args.append(self.value(quote))
        if self.pos >= len(self.source) or self.source[self.pos] != ")":
            raise self.error("expected ')'")
        self.pos += 1
        return Call(name, tuple(args))

    def value(self, quote: str | None) -> Parts:
        """One argument: a quoted template (only where no quote encloses it) or unquoted parts."""
        char = self.source[self.pos]
        if quote is None and char in "'\"":
            self.pos += 1
            quoted = self.template(char)
            if self.pos >= len(self.source):
                raise self.error(f"unterminated {char}")
            self.pos += 1
            return quoted
        parts: list[Subst] = []
        buffer: list[str] = []
        stops = " ()" + ("'\"" if quote is None else quote)
        while self.pos < len(self.source):
            char = self.source[self.pos]
            if self.at_subst():
                _flush(buffer, parts)
                parts.append(self.substitution(quote))
            elif char == "\\" and self.pos + 1 < len(self.source):
                buffer.append(self.source[self.pos + 1])
                self.pos += 2
            elif char in stops:
                break
            else:
                buffer.append(char)
                self.pos += 1
        _flush(buffer, parts)
        if not parts:
            raise self.error("expected an argument")
        return tuple(parts)


def _flush(buffer: list[str], parts: list[Subst]) -> None:
    if buffer:
        parts.append(Text("".join(buffer)))
        buffer.clear()


# -- evaluation ---------------------------------------------------------------------------
def perform(parts: Parts, ctx: Context) -> str:
    """The string `parts` evaluate to in `ctx` (what substitutions bring in is charged to the budget
    before it is joined)."""
    pieces = [_perform_one(part, ctx) for part in parts]
    budget.charge("characters", sum(len(piece) for part, piece in zip(parts, pieces) if not isinstance(part, Text)))
    return "".join(pieces)


def describe(parts: Parts) -> str:
    """Parts written back in the frontend syntax (for messages and condition texts)."""
    out = []
    for part in parts:
        if isinstance(part, Text):
            out.append(part.text)
        elif isinstance(part, Rewritten):
            out.append(f"$(RewrittenYaml {describe(part.source)})")
        else:
            out.append("$(" + " ".join([part.name, *(describe(a) for a in part.args)]) + ")")
    return "".join(out)


def truth(parts: Parts, ctx: Context) -> bool:
    """A condition expression as launch's IfCondition reads it: true/1 or false/0, any case."""
    value = perform(parts, ctx).strip().lower()
    flag = boolean(value)
    if flag is not None:
        return flag
    raise SubstitutionError(f"condition {describe(parts)!r} is {value!r}, expected true, false, 1 or 0")


def typed_bool(value: str) -> bool:
    """A string coerced to bool as launch's typed substitutions do ('1'/'0' and YAML's booleans)."""
    loaded = yaml_value({"1": "true", "0": "false"}.get(value, value))
    if not isinstance(loaded, bool):
        raise SubstitutionError(f"{value!r} is not a boolean")
    return loaded


def yaml_value(value: str) -> object:
    """A performed string read with YAML rules, as launch reads parameter values (text that is
    not valid YAML stays text)."""
    if not value:
        return ""
    try:
        return bounded_yaml.load(value)
    except yaml.YAMLError:
        return value


def _perform_one(part: Subst, ctx: Context) -> str:
    if isinstance(part, Text):
        return part.text
    if isinstance(part, Rewritten):
        raise Unresolved(f"RewrittenYaml({describe(part.source)}) writes a temporary file at launch")
    handler = _HANDLERS.get(part.name)
    if handler is None:
        raise SubstitutionError(f"unknown substitution $({part.name})")
    low, high = _ARITY.get(part.name, (0, 99))
    if not low <= len(part.args) <= high:
        raise SubstitutionError(f"$({part.name}) takes {low} to {high} arguments, got {len(part.args)}")
    return handler(part.args, ctx)


def _var(args: tuple[Parts, ...], ctx: Context) -> str:
    name = perform(args[0], ctx)
    if name in ctx.configs:
        value = ctx.configs[name]
        if isinstance(value, UnknownArg):
            value = trial_value(name, value)
        return str(value)
    if len(args) > 1:
        return perform(args[1], ctx)
    raise Unresolved(f"launch configuration '{name}' is not set (not declared before its use, nor given)")


def trial_value(name: str, value: UnknownArg) -> str:
    """The value a condition's trial gives an unknown launch argument (conditions.py), else Unresolved."""
    given = conditions.given(name, value)
    if given is None:
        raise Unresolved(unknown_reason(name, value))
    return given


def unknown_reason(name: str, value: UnknownArg) -> str:
    """Why a launch argument is not known: the first unknown one in a chain of arguments."""
    return value.reason if value.reason.startswith("launch ") else f"launch argument '{name}' is not known " \
        f"({value.reason})"


def _env(args: tuple[Parts, ...], ctx: Context) -> str:
    name = perform(args[0], ctx)
    if name in ctx.env:
        value = ctx.env[name]
        if isinstance(value, UnknownArg):
            raise Unresolved(f"environment variable {name} is not known ({value.reason})")
        return value
    sandbox.not_given(name, defaulted=len(args) > 1)
    if len(args) > 1:
        return perform(args[1], ctx)
    raise Unresolved(f"environment variable {name} is not given")


def _find_share(args: tuple[Parts, ...], ctx: Context) -> str:
    name = perform(args[0], ctx)
    found = ctx.find(name)
    if found is None:
        raise Unresolved(f"package '{name}' not found")
    return str(found)


def _unknowable(what: str) -> Callable[[tuple[Parts, ...], Context], str]:
    def handler(args: tuple[Parts, ...], ctx: Context) -> str:
        words = " ".join(describe(a) for a in args)
        raise Unresolved(f"{what} is not known statically{': ' + words if words else ''}")
    return handler


def _eval(args: tuple[Parts, ...], ctx: Context) -> str:
    expr = perform(args[0], ctx)
    modules = [m.strip() for m in perform(args[1], ctx).split(",") if m.strip()] if len(args) > 1 else ["math"]
    if any(m != "math" for m in modules):
        raise Unresolved(f"$(eval) imports {', '.join(modules)}; only math is evaluated statically")
    names: dict[str, object] = dict(MATH) if modules else {}

    def lookup(name: str) -> object:
        if name in names:
            return names[name]
        if name in BUILTINS:
            return BUILTINS[name]
        raise SubstitutionError(f"$(eval {expr}): name '{name}' is not defined")

    return str(restricted_eval(expr, lookup))


def _anon(args: tuple[Parts, ...], ctx: Context) -> str:
    key = "anon" + perform(args[0], ctx)
    if key not in ctx.configs:
        ctx.configs[key] = f"{key[4:]}_anon{next(ctx.serial)}"
    return str(ctx.configs[key])


def _file_content(args: tuple[Parts, ...], ctx: Context) -> str:
    return read_file(perform(args[0], ctx), "config")


def _equals(args: tuple[Parts, ...], ctx: Context) -> str:
    left, right = perform(args[0], ctx), perform(args[1], ctx)
    if all(v.lower() in ("true", "false", "1", "0") for v in (left, right)):
        return str((left.lower() in ("true", "1")) == (right.lower() in ("true", "1"))).lower()
    try:
        return str(math.isclose(float(left), float(right))).lower()
    except ValueError:
        return str(left == right).lower()


def _bools(args: tuple[Parts, ...], ctx: Context) -> list[bool]:
    return [typed_bool(perform(a, ctx)) for a in args]


def _if_else(args: tuple[Parts, ...], ctx: Context) -> str:
    if typed_bool(perform(args[0], ctx)):
        return perform(args[1], ctx)
    return perform(args[2], ctx) if len(args) > 2 else ""


def _as_bool(args: tuple[Parts, ...], ctx: Context) -> str:
    """nav2_common's LaunchConfigAsBool: 'True' for true/1/yes/on, else 'False'."""
    return str(perform(args[0], ctx).strip().lower() in ("true", "1", "yes", "on"))


def _opaque(args: tuple[Parts, ...], ctx: Context) -> str:
    raise Unresolved(describe(args[0]) if args else "a value archlog cannot interpret")


_HANDLERS: dict[str, Callable[[tuple[Parts, ...], Context], str]] = {
    "var": _var,
    "env": _env,
    "find-pkg-share": _find_share,
    "find-pkg-prefix": _unknowable("the install prefix of a package"),
    "find-exec": _unknowable("the path of an executable"),
    "exec-in-pkg": _unknowable("the path of an executable"),
    "command": _unknowable("the output of a command"),
    "param": _unknowable("a parameter of a running node"),
    "log_dir": _unknowable("the log directory"),
    "launch_log_dir": _unknowable("the log directory"),
    "eval": _eval,
    "anon": _anon,
    "dirname": lambda args, ctx: os.path.dirname(os.path.abspath(ctx.file)),
    "filename": lambda args, ctx: os.path.abspath(ctx.file),
    "file-content": _file_content,
    "equals": _equals,
    "not-equals": lambda args, ctx: str(_equals(args, ctx) != "true").lower(),
    "not": lambda args, ctx: str(not _bools(args, ctx)[0]).lower(),
    "and": lambda args, ctx: str(all(_bools(args, ctx))).lower(),
    "or": lambda args, ctx: str(any(_bools(args, ctx))).lower(),
    "any": lambda args, ctx: str(any(_bools(args, ctx))).lower(),
    "all": lambda args, ctx: str(all(_bools(args, ctx))).lower(),
    "if": _if_else,
    "path-join": lambda args, ctx: os.path.join(*(perform(a, ctx) for a in args)) if args else "",
    "as-bool": _as_bool,
    "opaque": _opaque,
}
_ARITY = {
    "var": (1, 2), "env": (1, 2), "find-pkg-share": (1, 1), "eval": (1, 2), "anon": (1, 1), "dirname": (0, 0),
    "filename": (0, 0), "file-content": (1, 1), "equals": (2, 2), "not-equals": (2, 2), "not": (1, 1),
    "and": (2, 2), "or": (2, 2), "if": (2, 3), "as-bool": (1, 1),
}
