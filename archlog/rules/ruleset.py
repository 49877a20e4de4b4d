"""Rule files: Datalog (clingo syntax) with a metadata header per rule in `%!` comment lines.

    %! id: AL101
    %! name: topic-type-mismatch
    %! severity: error
    %! finding: type_mismatch(topic, sub, sub_node, sub_type, pub, pub_node, pub_type)
    %! location: sub
    %! related: [pub]
    %! message: "{sub_node} subscribes to {topic} as {sub_type} ..."
    type_mismatch(T, S, SN, ST, P, PN, PT) :- ...

A file without a header holds shared derived relations (a library, like prelude.lp).
Rule files may come from the workspace under analysis, so they may not embed scripts (`#script`,
which clingo would run as Python or Lua) nor read other files (`#include`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from archlog import sandbox
from archlog.diagnostics import SEVERITIES

BUILTIN = Path(__file__).resolve().parent / "builtin"
REQUIRED = ("id", "name", "severity", "finding", "location", "message", "summary")
OPTIONAL = ("related", "description", "help", "tags", "precision", "lists", "url", "fix")
FIX_KINDS = ("remap", "rename")  # what a rule's `fix` edits: a node's remaps, a name where it is set
KEYS = REQUIRED + OPTIONAL  # a closed set: any other key is an error (docs/writing-rules.md documents each)
PRECISIONS = ("high", "medium", "low")
_HEAD = re.compile(r"^\s*(\w+)\s*\(([^()]*)\)\s*$")
_FORBIDDEN = re.compile(r"#(script|include)\b")  # anywhere, comments and strings too: clingo never sees it


class RuleError(Exception):
    """A rule file that cannot be used, with file:line."""

    def __init__(self, file: str, line: int, message: str, column: int = 1) -> None:
        super().__init__(f"{file}:{line}:{column}: {message}")
        self.file, self.line, self.column, self.message = file, line, column, message


@dataclass
class Rule:
    id: str
    name: str
    severity: str
    summary: str
    message: str
    predicate: str
    columns: list[str]
    location: str
    related: list[str]
    description: str = ""
    help: str = ""
    url: str = ""  # a page about the rule (SARIF helpUri, JSON `url`); shipped rules link docs/rules.md
    tags: list[str] = field(default_factory=list)
    precision: str = "high"
    file: str = ""
    line: int = 0
    # name -> (relation, column): the second arguments of the relation's binary rows whose first
    # argument is the finding's value in that column, listed in the finding (e.g. nodes silenced)
    lists: dict[str, tuple[str, str]] = field(default_factory=dict)
    # list name -> the phrase it renders as ("{}" is the list), or nothing when the list is empty
    list_phrases: dict[str, str] = field(default_factory=dict)
    # metadata key -> its line in the file (errors about a key point at it)
    lines: dict[str, int] = field(default_factory=dict)
    # `fix: {remap: [node, from, to], safe: BOOL}`: the columns of the node whose launch element gets
    # `<remap from= to=/>` (archlog check --fix), and whether --fix applies it without --unsafe-fixes;
    # `fix: {rename: [at, from, to], ...}`: the name `from` renamed to `to` on the line of the column
    # `at` (where the configuration sets a parameter)
    fix: tuple[str, str, str] | None = None
    fix_safe: bool = False
    fix_kind: str = "remap"


@dataclass
class Program:
    """A piece of rule text with where it came from (for mapping engine errors back)."""

    text: str
    file: str
    first_line: int


@dataclass
class RuleSet:
    rules: list[Rule] = field(default_factory=list)
    programs: list[Program] = field(default_factory=list)

    def add_file(self, path: Path) -> None:
        try:
            text = sandbox.read_text(path, "config")
        except sandbox.Refused as exc:
            raise RuleError(str(path), 1, f"rule file not read: {exc}") from None
        rules, programs = parse_rule_file(text, str(path))
        known = {r.id for r in self.rules}
        for rule in rules:
            if rule.id in known:
                raise RuleError(rule.file, rule.lines.get("id", rule.line), f"rule id {rule.id} is defined twice")
            known.add(rule.id)
        self.rules += rules
        self.programs += programs


def load_rules(paths: list[Path], builtin: bool = True) -> RuleSet:
    """The shipped rules (prelude first) followed by the user's files or folders."""
    ruleset = RuleSet()
    files = sorted(BUILTIN.glob("*.lp"), key=lambda p: (p.name != "prelude.lp", p.name)) if builtin else []
    for path in paths:
        files += sorted(path.glob("*.lp")) if path.is_dir() else [path]
    for path in files:
        ruleset.add_file(path)
    return ruleset


def parse_rule_file(text: str, file: str) -> tuple[list[Rule], list[Program]]:
    forbidden = _FORBIDDEN.search(text)
    if forbidden:
        line = text.count("\n", 0, forbidden.start()) + 1
        raise RuleError(file, line, f"rule files may not contain {forbidden.group()} (archlog runs no code and "
                        "reads no file a rule file names)", forbidden.start() - text.rfind("\n", 0, forbidden.start()))
    lines = text.splitlines()
    rules: list[Rule] = []
    programs: list[Program] = []
    i = 0
    while i < len(lines):
        start = i
        header: list[str] = []
        while i < len(lines) and lines[i].startswith("%!"):
            header.append(lines[i][2:].removeprefix(" "))
            i += 1
        body_start = i
        while i < len(lines) and not lines[i].startswith("%!"):
            i += 1
        programs.append(Program("\n".join(lines[body_start:i]), file, body_start + 1))
        if header:
            rules.append(_rule(header, file, start + 1))
    return rules, programs


def _yaml_error(exc: yaml.MarkedYAMLError, file: str, line: int) -> RuleError:
    """One line at the header line YAML points at (the problem, and where what it concerns began)."""
    mark = exc.problem_mark or exc.context_mark
    context = exc.context_mark
    where = f" ({exc.context} on line {line + context.line})" if exc.context and context and \
        (mark is None or context.line != mark.line) else ""
    what = f"{exc.problem or exc.context or 'not valid'}{where}"
    return RuleError(file, line + (mark.line if mark else 0), f"metadata is not valid YAML: {what}",
                     (mark.column if mark else 0) + len("%! ") + 1)


def _rule(header: list[str], file: str, line: int) -> Rule:
    """One rule's metadata; every error is reported at the file line of the key it concerns."""
    loader = yaml.SafeLoader("\n".join(header))
    try:
        node = loader.get_single_node()
        meta = loader.construct_document(node) if node is not None else {}
    except yaml.MarkedYAMLError as exc:
        raise _yaml_error(exc, file, line) from None
    finally:
        loader.dispose()
    if not isinstance(meta, dict) or not isinstance(node, yaml.MappingNode):
        raise RuleError(file, line, "metadata must be `key: value` lines")
    lines: dict[str, int] = {}
    for key_node, _value in node.value:
        key, at = key_node.value, line + key_node.start_mark.line
        if not isinstance(key_node, yaml.ScalarNode) or key not in KEYS:
            raise RuleError(file, at, f"unknown metadata key '{key}' (known keys: {', '.join(KEYS)})")
        if key in lines:
            raise RuleError(file, at, f"metadata key '{key}' is given twice (first on line {lines[key]})")
        lines[key] = at

    def fail(key: str, message: str) -> RuleError:
        return RuleError(file, lines.get(key, line), message)

    missing = [k for k in REQUIRED if k not in meta]
    if missing:
        raise RuleError(file, line, f"metadata lacks {', '.join(missing)}")
    for key in ("id", "name", "summary", "message", "description", "help", "precision", "url"):
        if key in meta and not isinstance(meta[key], (str, int, float)):
            raise fail(key, f"`{key}` must be a single value")
    for key in ("related", "tags"):
        if not isinstance(meta.get(key) or [], list) or not all(isinstance(v, str) for v in meta.get(key) or []):
            raise fail(key, f"`{key}` must be a list such as [a, b]")
    head = _HEAD.match(str(meta["finding"]))
    if not head:
        raise fail("finding", "`finding` must look like predicate(col1, col2, ...)")
    columns = [c.strip() for c in head.group(2).split(",") if c.strip()]
    related = meta.get("related") or []
    for key, cols in (("location", [meta["location"]]), ("related", related)):
        for col in cols:
            if col not in columns:
                raise fail(key, f"location column '{col}' is not a column of {head.group(1)}")
    if meta["severity"] not in SEVERITIES:
        raise fail("severity", f"severity must be one of {', '.join(SEVERITIES)}")
    precision = str(meta.get("precision", "high"))
    if precision not in PRECISIONS:
        raise fail("precision", f"precision must be one of {', '.join(PRECISIONS)}")
    if not isinstance(meta.get("lists") or {}, dict):
        raise fail("lists", "`lists` must be a mapping such as {name: relation(column)}")
    lists, phrases = {}, {}
    for name, spec in (meta.get("lists") or {}).items():
        if isinstance(spec, dict):
            if set(spec) != {"of", "text"} or "{}" not in str(spec["text"]):
                raise fail("lists", f"list '{name}' as a mapping must be {{of: relation(column), text: \"... {{}} ...\"}}")
            phrases[str(name)] = str(spec["text"])
            spec = spec["of"]
        match = _HEAD.match(str(spec))
        if not match or match.group(2).strip() not in columns:
            raise fail("lists", f"list '{name}' must look like relation(column), with a column of {head.group(1)}")
        lists[str(name)] = (match.group(1), match.group(2).strip())
    fix = meta.get("fix")
    kinds = [k for k in FIX_KINDS if isinstance(fix, dict) and k in fix]
    if fix is not None and not (isinstance(fix, dict) and len(kinds) == 1 and set(fix) <= {*kinds, "safe"}
                                and isinstance(fix[kinds[0]], list) and len(fix[kinds[0]]) == 3
                                and all(c in columns for c in fix[kinds[0]]) and isinstance(fix.get("safe", False), bool)):
        raise fail("fix", "`fix` must be {remap: [node, from, to], safe: true|false} or {rename: [at, from, to], "
                   f"safe: true|false}} with columns of {head.group(1)}")
    try:
        str(meta["message"]).format(**dict.fromkeys([*columns, *lists], ""))
    except (KeyError, IndexError, ValueError, AttributeError) as exc:
        raise fail("message", f"message template uses an unknown column: {exc}") from None
    return Rule(
        id=str(meta["id"]), name=str(meta["name"]), severity=meta["severity"], summary=str(meta["summary"]),
        message=str(meta["message"]), predicate=head.group(1), columns=columns, location=meta["location"],
        related=list(related), description=str(meta.get("description", "")).strip(),
        help=str(meta.get("help", "")).strip(), url=str(meta.get("url", "")).strip(), tags=list(meta.get("tags") or []),
        precision=precision, file=file, line=line, lists=lists, list_phrases=phrases, lines=lines,
        fix=tuple(fix[kinds[0]]) if fix else None, fix_safe=bool(fix and fix.get("safe", False)),
        fix_kind=kinds[0] if fix else "remap",
    )
