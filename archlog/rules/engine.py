"""Run rule files over a fact store with clingo and turn derived tuples into findings."""

from __future__ import annotations

import difflib
import hashlib
import re
import time
from dataclasses import dataclass, field
from typing import NamedTuple

import clingo
import clingo.ast

from archlog.facts.schema import BY_NAME, RELATIONS
from archlog.facts.store import Cell, FactStore
from archlog.rules import loading
from archlog.rules.functions import FUNCTIONS, NAMES
from archlog.rules.loading import Position, Signature, atoms, positive
from archlog.rules.ruleset import Program, Rule, RuleError, RuleSet

SUBJECT_KINDS = {"node": "nodes", "topic": "topics", "service": "services", "action": "actions",
                 "param": "parameters", "type": "types"}
_SPAN = re.compile(r"<(?:block|string)>:(\d+):(\d+)(?:-\d+(?::\d+)?)?:\s*")

_HINTS = {
    "unsafe": "every variable must occur in a positive body literal (not only under `not` or in a comparison)",
    "syntax error": "check parentheses and commas, and end each rule with a period",
}
_FACT_SIGNATURES = {(r.name, r.arity) for r in RELATIONS}


@dataclass(frozen=True)
class Location:
    file: str
    line: int
    column: int = 0


@dataclass
class Finding:
    rule: Rule
    values: dict[str, Cell]
    message: str
    location: Location
    related: list[Location]
    unsure: bool  # one of the lists the rule calls `unsure` is not empty: the finding is a note
    subjects: dict[str, list[str]] = field(default_factory=dict)
    suppression: tuple[str, str] | None = None  # (kind: inSource | external, justification)

    @property
    def severity(self) -> str:
        """The rule's severity (as the configuration sets it), or `note` when unsure."""
        return "note" if self.unsure else self.rule.severity

    @property
    def tag(self) -> str:
        """The rule id, and the severity when it is not the rule's: `AL201 [note]`."""
        return self.rule.id if self.severity == self.rule.severity else f"{self.rule.id} [{self.severity}]"

    @property
    def fingerprint(self) -> str:
        """Stable across line moves: the rule and the resolved names involved."""
        key = self.rule.id + "|" + "|".join(f"{k}={v}" for k, v in sorted(self.subjects.items()))
        return hashlib.sha256(key.encode()).hexdigest()[:32]


def render(value: Cell) -> str:
    """A cell as text; an unknown is written `?(expr)`."""
    return str(value)


class Engine:
    """Grounds the rule programs with the facts; a stratified program yields only facts."""

    def __init__(self, ruleset: RuleSet) -> None:
        self.ruleset = ruleset
        self.declared = check(ruleset)
        self.reads = loading.reads_of(p.text for p in ruleset.programs)
        self.timings: dict[str, float] = {}  # seconds of the last run's phases

    def run(self, store: FactStore) -> tuple[clingo.Control, list[Finding]]:
        ctl = self.ground(store)
        return ctl, self.findings(ctl, store)

    def ground(self, store: FactStore) -> clingo.Control:
        return self.start(store).ctl

    def start(self, store: FactStore) -> loading.Grounded:
        """The rules grounded with the facts they read (`loading`); other relations load on demand."""
        if self.reads is None:
            grounded = loading.Grounded(store)
            grounded.load(BY_NAME)
            grounded.ctl.add("base", [], self.declared + "\n".join(p.text for p in self.ruleset.programs))
            grounded.ground("base")
        else:
            listed = {relation for rule in self.ruleset.rules for relation, _column in rule.lists.values()}
            kept = {rule.predicate for rule in self.ruleset.rules} | listed
            grounded = loading.ground(store, self.reads, self.declared, listed, kept)
        ctl = grounded.ctl
        clock = time.perf_counter()
        stratified = ctl.solve().satisfiable and ctl.statistics["problem"]["lp"]["bodies"] == 0
        self.timings = {"to-clingo": grounded.timings["to-clingo"],
                        "ground": grounded.timings["ground"] + time.perf_counter() - clock}
        if stratified:
            return grounded  # every atom is a fact
        for atom in ctl.symbolic_atoms:
            if not atom.is_fact:
                name = atom.symbol.name
                program = next((p for p in self.ruleset.programs if name in {s[0] for s in _parse(p)[0]}), None)
                raise RuleError(program.file if program else "<rules>", program.first_line if program else 0,
                                f"rules are not stratified: {name} depends on itself through `not` (hint: define "
                                "the negated relation without the one that negates it)")
        return grounded

    def findings(self, ctl: clingo.Control, store: FactStore) -> list[Finding]:
        clock = time.perf_counter()
        result = []
        listed: dict[str, dict[clingo.Symbol, set[str]]] = {}  # relation -> first argument -> rendered seconds
        for rule in self.ruleset.rules:
            for atom in ctl.symbolic_atoms.by_signature(rule.predicate, len(rule.columns)):
                values = {c: store.from_term(a) for c, a in zip(rule.columns, atom.symbol.arguments)}
                shown: list[str] = []
                unsure = False
                for name, (relation, column) in rule.lists.items():
                    if relation not in listed:
                        listed[relation] = _binary_rows(ctl, relation, store)
                    items = listed[relation].get(atom.symbol.arguments[rule.columns.index(column)], set())
                    values[name] = _list_text(", ".join(sorted(items)), rule.list_phrases.get(name))
                    shown += sorted(items)
                    unsure = unsure or (bool(items) and name in rule.unsure)
                result.append(_finding(rule, values, store, shown, unsure))
        self.timings["findings"] = time.perf_counter() - clock
        return sorted(result, key=lambda f: (f.location.file, f.location.line, f.rule.id, f.message))


def _binary_rows(ctl: clingo.Control, relation: str, store: FactStore) -> dict[clingo.Symbol, set[str]]:
    """The rows of a binary relation, by first argument (a finding's list reads one key of them)."""
    rows: dict[clingo.Symbol, set[str]] = {}
    for row in ctl.symbolic_atoms.by_signature(relation, 2):
        first, second = row.symbol.arguments
        rows.setdefault(first, set()).add(render(store.from_term(second)))
    return rows


def _list_text(joined: str, phrase: str | None) -> str:
    """A list value: the items, or "none"; with a phrase, the phrase around them, or nothing."""
    if phrase is None:
        return joined or "none"
    return phrase.replace("{}", joined) if joined else ""


def _finding(rule: Rule, values: dict[str, Cell], store: FactStore, listed: list[str], unsure: bool) -> Finding:
    """A finding; listed items that are located ids (ports, elements) are related locations too."""
    def locate(column: str) -> Location:
        found = store.location(str(values[column]))
        return Location(*found) if found else Location("", 0, 0)

    subjects: dict[str, list[str]] = {}
    for column, value in values.items():
        kind = column.rsplit("_", 1)[-1]
        if kind in SUBJECT_KINDS:
            bucket = subjects.setdefault(SUBJECT_KINDS[kind], [])
            if render(value) not in bucket:
                bucket.append(render(value))
    message = rule.message.format(**{k: render(v) for k, v in values.items()})
    related = [found for found in map(locate, rule.related) if found.file]  # an optional column may hold `none`
    also = [Location(*found) for item in listed if (found := store.location(item))]
    return Finding(rule, values, message, locate(rule.location), related + also, unsure, subjects)


# -- checking rule programs ---------------------------------------------------------------
def check(ruleset: RuleSet) -> str:
    """Reject syntax errors, unknown relations and @functions, wrong arities, unsafe variables,
    findings that no rule derives and location columns that hold no element, each at its rule
    file:line:column. Returns the `#defined` preamble."""
    parsed = [(program, _parse(program)) for program in ruleset.programs]
    facts = {r.name: r.arity for r in RELATIONS}
    heads = {sig for _p, found in parsed for sig in found.heads}
    for program, found in parsed:
        for (name, arity), pos in found.heads.items():
            if name in facts and facts[name] != arity:
                raise RuleError(program.file, program.first_line + pos[0] - 1,
                                f"{name} is a fact relation with {facts[name]} columns (hint: rules may not add "
                                "facts; derive a relation of your own)", pos[1])
    known = set(facts.items()) | heads
    for program, found in parsed:
        for (name, arity), pos in found.body:
            if (name, arity) not in known:
                raise RuleError(program.file, program.first_line + pos[0] - 1, unknown_relation(name, arity, known),
                                pos[1])
        for name, pos in found.functions:
            if name not in NAMES:
                raise RuleError(program.file, program.first_line + pos[0] - 1, unknown_function(name), pos[1])
    declared = "".join(f"#defined {n}/{a}. " for n, a in sorted(known)) + "\n"
    for program in ruleset.programs:
        _safety(program, declared)
    types = column_types([rule for program in ruleset.programs for rule in rules_of(program)])
    for rule in ruleset.rules:
        if (rule.predicate, len(rule.columns)) not in heads:
            raise RuleError(rule.file, rule.lines.get("finding", rule.line), f"no rule derives the finding "
                            f"{rule.predicate}/{len(rule.columns)} (hint: the `finding:` header must name the head of "
                            "a rule below it, with as many columns)")
        check_locations(rule, types.get((rule.predicate, len(rule.columns)), []))
    return declared


def unknown_relation(name: str, arity: int, known: set[Signature]) -> str:
    """Why a relation cannot be used, with the nearest known spelling."""
    arities = sorted(a for n, a in known if n == name)
    if arities:
        return f"{name} takes {arities[0]} columns, not {arity} (hint: use _ for the columns you do not need)"
    close = difflib.get_close_matches(name, sorted({n for n, _a in known if not n.startswith("__")}), 1, 0.7)
    suggestion = f"did you mean {close[0]}/{min(a for n, a in known if n == close[0])}?" if close else \
        "docs/facts.md lists the relations"
    return f"unknown relation {name}/{arity} (hint: {suggestion})"


def unknown_function(name: str) -> str:
    close = difflib.get_close_matches(name, NAMES, 1, 0.6)
    return f"unknown function @{name} (hint: {f'did you mean @{close[0]}? ' if close else ''}the functions rules may " \
        f"call are {', '.join('@' + n for n in NAMES)}; docs/writing-rules.md describes them)"


def column_types(rules: list[clingo.ast.AST]) -> dict[Signature, list[str | None]]:
    """The column types (`id`, `name`, ...) of every relation, derived ones inferred from the fact
    columns their rules' head variables come from; None where the rules disagree or tell nothing."""
    types: dict[Signature, list[str | None]] = {(r.name, r.arity): [c.type for c in r.columns] for r in RELATIONS}
    shapes = [(defined, [atom for literal in rule.body if (atom := positive(literal)) is not None])
              for rule in rules if (defined := positive(rule.head)) is not None and defined[0] not in _FACT_SIGNATURES]
    seen: dict[Signature, list[set[str]]] = {}
    changed = True
    while changed:
        changed = False
        for (sig, head), body in shapes:
            bound: dict[object, set[str]] = {}  # the types the body's positive atoms give its variables
            for relation, columns in body:
                for column, type_ in zip(columns, types.get(relation, [])):
                    if column is not None and column[0] == "var" and type_ is not None:
                        bound.setdefault(column[1], set()).add(type_)
            slots = seen.setdefault(sig, [set() for _ in head])
            for slot, column in zip(slots, head):
                new = bound.get(column[1], set()) if column is not None and column[0] == "var" else set()
                if not new <= slot:
                    slot |= new
                    changed = True
            types[sig] = [next(iter(slot)) if len(slot) == 1 else None for slot in slots]
    return types


def check_locations(rule: Rule, types: list[str | None]) -> None:
    """A finding's location (and related) columns must hold elements with a location: ids."""
    ids = [c for c, t in zip(rule.columns, types) if t == "id"]
    for key, columns in (("location", [rule.location]), ("related", rule.related)):
        for column in columns:
            type_ = types[rule.columns.index(column)] if types else None
            if type_ is not None and type_ != "id":
                hint = f"a column such as {', '.join(ids)}" if ids else "add a port or element id column"
                raise RuleError(rule.file, rule.lines.get(key, rule.line), f"{key} column '{column}' holds a "
                                f"{type_}, which has no file and line (hint: name a column that holds a port or "
                                f"element id: {hint})")


class Parsed(NamedTuple):
    """What a program uses: the relations its rules define and use, and the @functions it calls."""

    heads: dict[Signature, Position]
    body: list[tuple[Signature, Position]]
    functions: list[tuple[str, Position]]


def _parse(program: Program) -> Parsed:
    parsed = Parsed({}, [], [])
    statements, messages = loading.parse(program.text)
    if messages is not None:
        raise _error(program, list(messages))
    for statement in statements:
        if statement.ast_type == clingo.ast.ASTType.Rule:
            for sig, pos in atoms(statement.head, parsed.functions):
                parsed.heads.setdefault(sig, pos)
            for literal in statement.body:
                parsed.body.extend(atoms(literal, parsed.functions))
    return parsed


def rules_of(program: Program) -> list[clingo.ast.AST]:
    """The rules of a program (already checked), as clingo ASTs."""
    return [s for s in loading.parse(program.text)[0] if s.ast_type == clingo.ast.ASTType.Rule]


def _safety(program: Program, declared: str) -> None:
    messages: list[str] = []
    ctl = clingo.Control(["--warn=none"], logger=lambda _c, m: messages.append(m))
    ctl.add("base", [], declared + program.text)
    try:
        ctl.ground([("base", [])], context=FUNCTIONS)
    except RuntimeError:
        raise _error(program, messages, line_offset=-1) from None


_INTERNALS = ((re.compile(r"\[#inc_base\];|#inc_base;?"), ""), (re.compile(r"#Anon\d+|#p\b"), "_"),
              (re.compile(r"#p_(\w+)"), r"\1"), (re.compile(r"#b\((\w+)\)"), r"\1"))
_UNSAFE = re.compile(r"<(?:block|string)>:(\d+):(\d+)(?:-\d+(?::\d+)?)?: note: '(\w+)' is unsafe")


def _error(program: Program, messages: list[str], line_offset: int = 0) -> RuleError:
    """clingo's complaint in archlog's words, at the rule file's line and column."""
    notes = [note for m in messages for note in _UNSAFE.finditer(m)]
    if notes:
        line, column = int(notes[0].group(1)), int(notes[0].group(2))
        variables = ", ".join(dict.fromkeys(m.group(3) for m in notes))
        detail = f"unsafe variable{'s' if ',' in variables else ''} {variables} (hint: {_HINTS['unsafe']})"
        return RuleError(program.file, program.first_line + line - 1 + line_offset, detail, column)
    text = " ".join(m.strip().replace("\n", " ") for m in messages[:1]) or "rule program rejected"
    match = _SPAN.search(text)
    detail = _SPAN.sub("", text).removeprefix("error: ")
    for pattern, replacement in _INTERNALS:
        detail = pattern.sub(replacement, detail)
    hint = next((h for needle, h in _HINTS.items() if needle in detail), "")
    detail += f" (hint: {hint})" if hint else ""
    if not match:
        return RuleError(program.file, program.first_line, detail)
    line = program.first_line + int(match.group(1)) - 1 + line_offset
    return RuleError(program.file, line, detail, int(match.group(2)))
