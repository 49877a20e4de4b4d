"""roslaunch substitution args: $(arg) $(find) $(env) $(optenv) $(anon) $(dirname) $(eval).

The grammar follows roslaunch 1.15: `$(cmd words)` cannot nest (a `$` inside is an error), an
unterminated `$(` stays literal, `find` is resolved after the others, and `$(eval expr)` applies
only when it is the whole value. `$(eval)` is interpreted over Python's AST with roslaunch's
names (args, true/false, arg/find/env/optenv/anon/dirname, math, a few pure builtins) by the
restricted evaluator of archlog.extract.launch.evaluate; nothing from the project is ever executed.
Expansion spends characters from the budget (archlog.budget) for what substitutions build.
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from archlog import budget, sandbox
from archlog.extract.launch import conditions
from archlog.extract.launch.evaluate import BUILTINS, MATH, restricted_eval
from archlog.extract.launch.model import SubstitutionError, UnknownArg, Unresolved


@dataclass
class SubstContext:
    """What substitutions can see: the current file's args, package lookup and environment (the
    variables the run was given, archlog.sandbox; never the environment archlog itself runs in).

    `anon` holds the $(anon) names of this scope (roslaunch keeps them next to the args, so a
    group or node copies them and an include starts afresh); `serial` numbers them uniquely."""

    args: dict[str, str | UnknownArg]
    find: Callable[[str], Path | None]
    file: Path
    anon: dict[str, str] = field(default_factory=dict)
    env: dict[str, str] = field(default_factory=lambda: dict(sandbox.current().env))
    serial: Iterator[int] = field(default_factory=lambda: itertools.count(1))

    def arg(self, name: str) -> str:
        if name not in self.args:
            raise SubstitutionError(f"arg '{name}' is not defined")
        value = self.args[name]
        if isinstance(value, UnknownArg):
            trial = conditions.given(name, value)
            if trial is None:
                raise Unresolved(f"arg '{name}' is unknown ({value.reason})")
            return trial
        return value

    def find_pkg(self, name: str) -> str:
        path = self.find(name)
        if path is None:
            raise Unresolved(f"package '{name}' not found")
        return str(path)

    def getenv(self, name: str, default: str | None = None) -> str:
        if name in self.env:
            return self.env[name]
        if (shell := sandbox.shell_value(name)) is not None:  # --env-from-shell
            return shell
        sandbox.not_given(name, defaulted=bool(default))  # $(optenv X) alone: no default written
        if default is None:
            raise Unresolved(f"environment variable {name} is not given")
        return default

    def anonymous(self, name: str) -> str:
        if name not in self.anon:
            self.anon[name] = f"{name}_anon{next(self.serial)}"
        return self.anon[name]

    def dirname(self) -> str:
        return os.path.abspath(os.path.dirname(str(self.file)))

    def child(self, args: dict[str, str | UnknownArg] | None = None, file: Path | None = None) -> SubstContext:
        """A copy for a group or node scope; with `args`, a fresh scope for an included file."""
        fresh = args is not None
        return SubstContext(args if args is not None else dict(self.args), self.find, file or self.file,
                            {} if fresh else dict(self.anon), self.env, self.serial)


def substitute(text: str, ctx: SubstContext) -> str:
    """Resolve every substitution in `text` as roslaunch does."""
    if "$(" not in text:
        return text
    if text.startswith("$(eval ") and text.endswith(")"):
        return _eval(text[7:-1], ctx)
    text = _pass(text, ctx, ("env", "optenv", "dirname", "anon", "arg"))
    return _pass(text, ctx, ("find",))


_VALID = ("find", "env", "optenv", "dirname", "anon", "arg")


def _pass(text: str, ctx: SubstContext, commands: tuple[str, ...]) -> str:
    resolved = text
    for inner in _collect(text):
        words = [w for w in inner.split(" ") if w]
        if not words or words[0] not in _VALID:
            raise SubstitutionError(f"unknown substitution command $({inner})")
        if words[0] in commands:
            placeholder = f"$({inner})"
            if words[0] == "find":
                resolved = _find(resolved, placeholder, words[1:], ctx)
            else:
                value = _one(words[0], words[1:], ctx)
                budget.charge("characters", resolved.count(placeholder) * len(value))
                resolved = resolved.replace(placeholder, value)
    return resolved


def _collect(text: str) -> list[str]:
    """The insides of `$(...)` in order; a `$` or `(` inside one is an error, as in roslaunch."""
    found: list[str] = []
    state = "out"
    buffer: list[str] = []
    for char in text:
        if char == "$":
            if state in ("in", "open"):
                raise SubstitutionError(f"'$' cannot be inside a substitution arg: {text}")
            state = "dollar"
        elif char == "(":
            if state == "dollar":
                state = "open"
                continue
            if state != "out":
                raise SubstitutionError(f"'(' cannot be inside a substitution arg: {text}")
        elif char == ")":
            if state == "in":
                found.append("".join(buffer))
                buffer = []
            state = "out"
        elif state == "dollar":
            state = "out"
        elif state == "open":
            state = "in"
        if state == "in":
            buffer.append(char)
    return found


def _one(command: str, words: list[str], ctx: SubstContext) -> str:
    if command == "arg":
        if len(words) != 1:
            raise SubstitutionError("$(arg) takes exactly one name")
        return ctx.arg(words[0])
    if command == "env":
        if len(words) != 1:
            raise SubstitutionError("$(env) takes exactly one variable")
        return ctx.getenv(words[0])
    if command == "optenv":
        if not words:
            raise SubstitutionError("$(optenv) needs a variable")
        return ctx.getenv(words[0], " ".join(words[1:]))
    if command == "anon":
        if len(words) != 1:
            raise SubstitutionError("$(anon) takes exactly one name")
        return ctx.anonymous(words[0])
    return ctx.dirname()


def _find(resolved: str, placeholder: str, words: list[str], ctx: SubstContext) -> str:
    """$(find pkg) joined with the path that follows it up to a space (executables and share files
    alike); one leading separator of that path is dropped."""
    if len(words) != 1:
        raise SubstitutionError("$(find) takes exactly one package")
    before, _, after = resolved.partition(placeholder)
    path, space, rest = after.partition(" ")
    path = path.replace("\\", "/")
    path = path[1:] if path.startswith("/") else path
    base = ctx.find_pkg(words[0])
    return before + (os.path.join(base, path) if path else base) + space + rest


def auto_value(text: str) -> object:
    """roslaunch's 'auto' conversion: float with a '.', int without '_', true/false, else text."""
    number = _number(text)
    if number is not None:
        return number
    lowered = text.lower()
    if lowered in ("true", "false"):
        return lowered == "true"
    return text


def _number(text: str) -> int | float | None:
    try:
        if "." in text:
            return float(text)
        return None if "_" in text else int(text)
    except ValueError:
        return None


def _eval(expr: str, ctx: SubstContext) -> str:
    functions: dict[str, object] = {
        **MATH,
        "arg": lambda name: auto_value(ctx.arg(name)), "find": ctx.find_pkg, "env": ctx.getenv,
        "optenv": lambda n, d="": ctx.getenv(n, d), "anon": ctx.anonymous, "dirname": ctx.dirname,
        "true": True, "false": False, "True": True, "False": False,
    }

    def lookup(name: str) -> object:
        """roslaunch's order: its functions and math, then the args (auto-typed), then builtins."""
        if name in functions:
            return functions[name]
        if name in ctx.args or name not in BUILTINS:
            return auto_value(ctx.arg(name))
        return BUILTINS[name]

    result = restricted_eval(expr, lookup)
    try:
        return str(result)
    except ValueError as exc:  # an integer with more digits than Python converts
        raise SubstitutionError(f"$(eval) {exc}") from None

