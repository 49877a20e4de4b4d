"""A small CMakeLists.txt reader: commands with arguments, `set()` variables and `${VAR}` expansion."""

from __future__ import annotations

import re
from dataclasses import dataclass

_TOKEN = re.compile(
    r'#\[(?P<eq>=*)\[.*?\](?P=eq)\]|#[^\n]*|"(?:\\.|[^"\\])*"|\[(?P<beq>=*)\[.*?\](?P=beq)\]|[()]|[^\s()#"]+',
    re.S,
)
_VAR = re.compile(r"\$\{(\w+)\}")


@dataclass(frozen=True)
class Command:
    name: str
    args: tuple[str, ...]
    line: int


def commands(text: str, variables: dict[str, str] | None = None) -> list[Command]:
    """Parse CMake source into commands; arguments are expanded with the variables set so far
    (`variables`, if given, seeds them and receives the ones set)."""
    variables = {} if variables is None else variables
    result: list[Command] = []
    tokens = [(m.group(0), text.count("\n", 0, m.start()) + 1) for m in _TOKEN.finditer(text)]
    tokens = [t for t in tokens if not t[0].startswith("#")]
    i = 0
    while i < len(tokens):
        name, line = tokens[i]
        if i + 1 < len(tokens) and tokens[i + 1][0] == "(" and re.fullmatch(r"\w+", name):
            depth, j, args = 1, i + 2, []
            while j < len(tokens) and depth:
                tok = tokens[j][0]
                depth += tok == "("
                depth -= tok == ")"
                if depth and tok not in "()":
                    value = _expand(_unquote(tok), variables)
                    args.extend([value] if tok.startswith('"') else [a for a in value.split(";") if a])
                j += 1
            cmd = Command(name.lower(), tuple(args), line)
            _track(cmd, variables)
            result.append(cmd)
            i = j
        else:
            i += 1
    return result


def _unquote(tok: str) -> str:
    if tok.startswith('"') and tok.endswith('"'):
        return tok[1:-1]
    return tok


def _expand(value: str, variables: dict[str, str]) -> str:
    for _ in range(5):
        new = _VAR.sub(lambda m: variables.get(m.group(1), m.group(0)), value)
        if new == value:
            break
        value = new
    return value


def _track(cmd: Command, variables: dict[str, str]) -> None:
    if cmd.name == "project" and cmd.args:
        variables["PROJECT_NAME"] = cmd.args[0]
        variables.setdefault("PROJECT_SOURCE_DIR", variables.get("CMAKE_CURRENT_SOURCE_DIR", ""))
    elif cmd.name == "set" and cmd.args:
        values = [a for a in cmd.args[1:] if a not in ("CACHE", "PARENT_SCOPE", "FORCE")]
        if "CACHE" in cmd.args:
            values = values[:1]
        variables[cmd.args[0]] = ";".join(values)
