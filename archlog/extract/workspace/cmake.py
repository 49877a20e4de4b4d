"""A small CMakeLists.txt reader: commands with `${VAR}` expansion, `set()`, `list(APPEND)`,
`foreach()` loops, and the package's own functions and macros expanded where they are called
(with `${ARGN}`, `${ARGV<n>}` and `cmake_parse_arguments`); the commands they run are located at
the call. Conditions are not evaluated (every branch is read). Each file spends from a budget
(`archlog.budget`): a step per command run and loop item, the characters of every expanded argument
and variable, so self-doubling variables, huge ranges and call fan-out stop at a limit."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from archlog import budget

# where a token starts: a bracket argument or comment opener, a comment, a quote, a parenthesis or an
# unquoted argument; bracket and quoted tokens are ended by `_Tokenizer` so that reading stays linear
_START = re.compile(r'#?\[(?P<eq>=*)\[|#|"|[()]|[^\s()#"]+')
_COMMENT = re.compile(r"#[^\n]*")
_UNQUOTED = re.compile(r'[^\s()#"]+')
_QUOTED = re.compile(r'"(?:\\.|[^"\\])*"', re.S)
_VAR = re.compile(r"\$\{(\w+)\}")


@dataclass(frozen=True)
class Command:
    name: str
    args: tuple[str, ...]
    line: int


@dataclass(frozen=True)
class _Raw:
    name: str
    args: tuple[tuple[str, bool], ...]  # (text, quoted)
    line: int


@dataclass(frozen=True)
class _Function:
    params: tuple[str, ...]
    body: tuple[_Raw, ...]
    macro: bool


_MAX_CALL_DEPTH = 8


class _Stopped(Exception):
    """A budget ran out while running the command at `line`."""

    def __init__(self, line: int, exceeded: budget.BudgetExceeded) -> None:
        super().__init__(str(exceeded))
        self.line, self.exceeded = line, exceeded


def commands(text: str, variables: dict[str, str] | None = None,
             on_budget: Callable[[int, str], None] | None = None) -> list[Command]:
    """Parse and interpret CMake source; `variables`, if given, seeds them and receives the ones set.
    When the budget runs out, `on_budget(line, message)` is told and the commands run so far are
    returned (without `on_budget`, `BudgetExceeded` is raised)."""
    variables = {} if variables is None else variables
    result: list[Command] = []
    try:
        with budget.scope():
            raws, stopped = _parse(text)
            _run(raws, variables, result, {}, None)
            if stopped is not None:
                raise stopped
    except _Stopped as stop:
        if on_budget is None:
            raise stop.exceeded from None
        on_budget(stop.line, str(stop.exceeded))
    return result


class _Tokenizer:
    """The tokens of a CMake text. A bracket `[==[` (or comment `#[==[`) ends at the first `]==]`
    after it; one never closed is read as an unquoted argument (a comment: to the end of the line).
    The search for a closer is remembered per number of `=` (and paid for in characters), and a
    quote that finds no end means no later quote does, so hostile text with many openers that never
    close is read in linear time. A search the budget cannot pay for is refused without spending,
    so that the commands before it still run."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.closers: dict[str, tuple[int, int]] = {}  # '=' run: (searched from, found at or -1)
        self.quotes_from = len(text) + 1  # from here on, no quote closes

    def tokens(self) -> tuple[list[tuple[str, int]], _Stopped | None]:
        """(token, line) of every token but comments; lines are counted from the previous token.
        When the budget runs out, the tokens before and where it stopped."""
        text, tokens, line, counted, pos = self.text, list[tuple[str, int]](), 1, 0, 0
        try:
            while (m := _START.search(text, pos)) is not None:
                line += text.count("\n", counted, m.start())
                counted = m.start()
                end = self._end(m)
                if end is None:
                    pos = m.start() + 1  # a quote never closed: skipped
                    continue
                if text[m.start()] != "#":
                    tokens.append((text[m.start():end], line))
                pos = end
        except budget.BudgetExceeded as exc:
            return tokens, _Stopped(line, exc)
        return tokens, None

    def _end(self, m: re.Match[str]) -> int | None:
        """Where the token starting at `m` ends (None: a quote that does not close)."""
        head, start = m.group(0), m.start()
        if m.group("eq") is not None:
            end = self._closer(m.group("eq"), m.end())
            if end >= 0:
                return end
            rest = (_COMMENT if head[0] == "#" else _UNQUOTED).match(self.text, start)
            return rest.end() if rest else m.end()  # both match wherever an opener does
        if head == "#":
            return m.end() + len(self.text[m.end():].partition("\n")[0])
        if head == '"':
            quoted = _QUOTED.match(self.text, start) if start < self.quotes_from else None
            if quoted is None:
                self.quotes_from = min(self.quotes_from, start)
                return None
            return quoted.end()
        return m.end()

    def _closer(self, eq: str, pos: int) -> int:
        """The end of the first `]eq]` at or after `pos`, or -1."""
        searched, found = self.closers.get(eq, (len(self.text) + 1, -1))
        if not searched <= pos <= (found if found >= 0 else len(self.text)):
            found = self.text.find(f"]{eq}]", pos)
            budget.charge("characters", (found if found >= 0 else len(self.text)) - pos)
            self.closers[eq] = (pos, found)
        return found + len(eq) + 2 if found >= 0 else -1


def _parse(text: str) -> tuple[list[_Raw], _Stopped | None]:
    """The commands of a text, and where the budget stopped reading it (None: it did not)."""
    tokens, stopped = _Tokenizer(text).tokens()
    raws, i = [], 0
    while i < len(tokens):
        name, line = tokens[i]
        if i + 1 < len(tokens) and tokens[i + 1][0] == "(" and re.fullmatch(r"\w+", name):
            depth, j, args = 1, i + 2, []
            while j < len(tokens) and depth:
                tok = tokens[j][0]
                depth += tok == "("
                depth -= tok == ")"
                if depth and tok not in "()":
                    quoted = tok.startswith('"') and tok.endswith('"')
                    args.append((tok[1:-1] if quoted else tok, quoted))
                j += 1
            raws.append(_Raw(name.lower(), tuple(args), line))
            i = j
        else:
            i += 1
    return raws, stopped


def _run(raws: Sequence[_Raw], variables: dict[str, str], out: list[Command],
         functions: dict[str, _Function], call_line: int | None, depth: int = 0) -> None:
    """Interpret commands; `call_line`: the line of the function call they run for."""
    i = 0
    try:
        while i < len(raws):
            i = _step(raws, i, variables, out, functions, call_line, depth)
    except budget.BudgetExceeded as exc:
        raise _Stopped(call_line or raws[i].line, exc) from None


def _step(raws: Sequence[_Raw], i: int, variables: dict[str, str], out: list[Command],
          functions: dict[str, _Function], call_line: int | None, depth: int) -> int:
    """Run the command at `i` (a whole block for function, macro and foreach); the index after it."""
    budget.spend("steps")
    raw = raws[i]
    if raw.name in ("function", "macro", "foreach"):
        end = _matching_end(raws, i)
        if raw.name == "foreach":
            _loop(raw, raws[i + 1:end], variables, out, functions, call_line, depth)
        else:
            head = _expand_args(raw.args, variables)
            if head:
                functions[head[0].lower()] = _Function(head[1:], tuple(raws[i + 1:end]), raw.name == "macro")
        return end + 1
    cmd = Command(raw.name, _expand_args(raw.args, variables), call_line or raw.line)
    if cmd.name in functions and depth < _MAX_CALL_DEPTH:
        _call(functions[cmd.name], cmd, variables, out, functions, depth)
    else:
        _track(cmd, variables)
        out.append(cmd)
    return i + 1


def _call(function: _Function, cmd: Command, variables: dict[str, str], out: list[Command],
          functions: dict[str, _Function], depth: int) -> None:
    """Run a function (in a copy of the variables) or a macro (in the caller's) with its arguments."""
    scope = variables if function.macro else dict(variables)
    arguments = list(cmd.args)
    scope.update(dict(zip(function.params, arguments)))
    scope.update({f"ARGV{n}": value for n, value in enumerate(arguments)})
    scope.update({"ARGN": ";".join(arguments[len(function.params):]), "ARGV": ";".join(arguments),
                  "ARGC": str(len(arguments))})
    _run(function.body, scope, out, functions, cmd.line, depth + 1)


def _matching_end(raws: Sequence[_Raw], start: int) -> int:
    opener = raws[start].name
    depth = 0
    for j in range(start, len(raws)):
        depth += raws[j].name == opener
        depth -= raws[j].name == f"end{opener}"
        if depth == 0:
            return j
    return len(raws) - 1


def _loop(head: _Raw, body: Sequence[_Raw], variables: dict[str, str], out: list[Command],
          functions: dict[str, _Function], call_line: int | None, depth: int) -> None:
    args = _expand_args(head.args, variables)
    if not args:
        return
    var, items = args[0], list(args[1:])
    if items[:1] == ["IN"]:
        items = items[1:]
        values: list[str] = []
        mode = ""
        for item in items:
            if item in ("LISTS", "ITEMS"):
                mode = item
            elif mode == "LISTS":
                values += [v for v in variables.get(item, "").split(";") if v]
            else:
                values.append(item)
        items = values
    elif items[:1] == ["RANGE"]:
        bounds = [int(b) for b in items[1:] if b.lstrip("-").isdigit()]
        start, stop = (0, bounds[0]) if len(bounds) == 1 else (bounds[0], bounds[1]) if bounds else (0, -1)
        budget.spend("steps", max(0, stop + 1 - start))  # before the items are built
        items = [str(n) for n in range(start, stop + 1)]
    for item in items:
        variables[var] = item
        _run(body, variables, out, functions, call_line, depth)


def _expand_args(args: tuple[tuple[str, bool], ...], variables: dict[str, str]) -> tuple[str, ...]:
    budget.spend("characters", sum(len(text) for text, _quoted in args))
    expanded: list[str] = []
    for text, quoted in args:
        value = _expand(text, variables)
        expanded.extend([value] if quoted else [a for a in value.split(";") if a])
    return tuple(expanded)


def _expand(value: str, variables: dict[str, str]) -> str:
    """`${VAR}` references replaced (five rounds, for values that name variables); each
    replacement is paid for before the new string is built."""
    if "${" not in value:
        return value
    for _ in range(5):
        new = _VAR.sub(lambda m: _lookup(m, variables), value)
        if new == value:
            break
        value = new
    return value


def _lookup(match: re.Match[str], variables: dict[str, str]) -> str:
    value = variables.get(match.group(1), match.group(0))
    budget.spend("characters", len(value))
    return value


def _track(cmd: Command, variables: dict[str, str]) -> None:
    if cmd.name == "project" and cmd.args:
        variables["PROJECT_NAME"] = cmd.args[0]
        variables.setdefault("PROJECT_SOURCE_DIR", variables.get("CMAKE_CURRENT_SOURCE_DIR", ""))
    elif cmd.name == "set" and cmd.args:
        # `${NAME}` left unexpanded in set(NAME ${NAME} ...) was unset: CMake reads it as nothing
        values = [a for a in cmd.args[1:] if a not in ("CACHE", "PARENT_SCOPE", "FORCE", f"${{{cmd.args[0]}}}")]
        if "CACHE" in cmd.args:
            values = values[:1]
        variables[cmd.args[0]] = ";".join(values)
    elif cmd.name == "list" and len(cmd.args) > 1 and cmd.args[0] == "APPEND":
        current = variables.get(cmd.args[1], "")
        budget.spend("characters", len(current))
        variables[cmd.args[1]] = ";".join([v for v in current.split(";") if v] + list(cmd.args[2:]))
    elif cmd.name == "cmake_parse_arguments" and len(cmd.args) >= 4:
        _parse_arguments(cmd.args, variables)


def _parse_arguments(args: tuple[str, ...], variables: dict[str, str]) -> None:
    """cmake_parse_arguments(PREFIX OPTIONS ONE_VALUE MULTI_VALUE args...), also with PARSE_ARGV N:
    sets PREFIX_KEYWORD for every keyword and PREFIX_UNPARSED_ARGUMENTS."""
    if args[0] == "PARSE_ARGV" and len(args) >= 6:
        start = int(args[1]) if args[1].isdigit() else 0
        count = int(variables.get("ARGC", "0") or 0)
        values = [variables.get(f"ARGV{n}", "") for n in range(start, count)]
        args = (*args[2:6], *values)
    prefix, options, single, multi = args[0], *(set(a.split(";")) - {""} for a in args[1:4])
    parsed: dict[str, list[str]] = {}
    unparsed: list[str] = []
    current: str | None = None
    for word in args[4:]:
        if word in options:
            parsed[word], current = ["TRUE"], None
        elif word in single | multi:
            parsed[word], current = [], word
        elif current is not None:
            parsed[current].append(word)
            current = None if current in single else current
        else:
            unparsed.append(word)
    for keyword in options:
        variables[f"{prefix}_{keyword}"] = "TRUE" if keyword in parsed else "FALSE"
    for keyword in single | multi:
        variables[f"{prefix}_{keyword}"] = ";".join(parsed.get(keyword, []))
    variables[f"{prefix}_UNPARSED_ARGUMENTS"] = ";".join(unparsed)
