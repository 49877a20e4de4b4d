"""Run rule files over a fact store with clingo and turn derived tuples into findings."""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field

import clingo
import clingo.ast

from archlog.facts.schema import RELATIONS
from archlog.facts.store import Cell, FactStore
from archlog.rules.ruleset import Program, Rule, RuleError, RuleSet
from archlog.values import Unknown

SUBJECT_KINDS = {"node": "nodes", "topic": "topics", "service": "services", "action": "actions",
                 "param": "parameters", "type": "types"}
_SPAN = re.compile(r"<(?:block|string)>:(\d+):(\d+)(?:-\d+(?::\d+)?)?:\s*")

Signature = tuple[str, int]
_HINTS = {
    "unsafe": "every variable must occur in a positive body literal (not only under `not` or in a comparison)",
    "syntax error": "check parentheses and commas, and end each rule with a period",
}
Position = tuple[int, int]


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
    subjects: dict[str, list[str]] = field(default_factory=dict)
    suppression: tuple[str, str] | None = None  # (kind: inSource | external, justification)

    @property
    def severity(self) -> str:
        return self.rule.severity

    @property
    def fingerprint(self) -> str:
        """Stable across line moves: the rule and the resolved names involved."""
        key = self.rule.id + "|" + "|".join(f"{k}={v}" for k, v in sorted(self.subjects.items()))
        return hashlib.sha256(key.encode()).hexdigest()[:32]


def render(value: Cell) -> str:
    return f"?({value.expr})" if isinstance(value, Unknown) else str(value)


class Engine:
    """Grounds the rule programs with the facts; a stratified program yields only facts."""

    def __init__(self, ruleset: RuleSet) -> None:
        self.ruleset = ruleset
        self.declared = check(ruleset)

    def run(self, store: FactStore) -> tuple[clingo.Control, list[Finding]]:
        ctl = self.ground(store)
        return ctl, self.findings(ctl, store)

    def ground(self, store: FactStore) -> clingo.Control:
        ctl = clingo.Control(["--warn=none"])
        ctl.add("base", [], self.declared + "\n".join(p.text for p in self.ruleset.programs))
        with ctl.backend() as backend:
            for symbol in store.symbols():
                backend.add_rule([backend.add_atom(symbol)])
        ctl.ground([("base", [])])
        for atom in ctl.symbolic_atoms:
            if not atom.is_fact:
                name = atom.symbol.name
                program = next((p for p in self.ruleset.programs if name in {s[0] for s in _parse(p)[0]}), None)
                raise RuleError(program.file if program else "<rules>", program.first_line if program else 0,
                                f"rules are not stratified: {name} depends on itself through `not` (hint: define "
                                "the negated relation without the one that negates it)")
        return ctl

    def findings(self, ctl: clingo.Control, store: FactStore) -> list[Finding]:
        result = []
        listed: dict[str, dict[clingo.Symbol, set[str]]] = {}  # relation -> first argument -> rendered seconds
        for rule in self.ruleset.rules:
            for atom in ctl.symbolic_atoms.by_signature(rule.predicate, len(rule.columns)):
                values = {c: store.from_term(a) for c, a in zip(rule.columns, atom.symbol.arguments)}
                for name, (relation, column) in rule.lists.items():
                    if relation not in listed:
                        listed[relation] = _binary_rows(ctl, relation, store)
                    items = listed[relation].get(atom.symbol.arguments[rule.columns.index(column)], set())
                    values[name] = _list_text(", ".join(sorted(items)), rule.list_phrases.get(name))
                result.append(_finding(rule, values, store))
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


def _finding(rule: Rule, values: dict[str, Cell], store: FactStore) -> Finding:
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
    return Finding(rule, values, message, locate(rule.location), related, subjects)


# -- checking rule programs ---------------------------------------------------------------
def check(ruleset: RuleSet) -> str:
    """Reject syntax errors, unknown relations, wrong arities, unsafe variables and findings
    that no rule derives, each at its rule file:line:column. Returns the `#defined` preamble."""
    parsed = [(program, _parse(program)) for program in ruleset.programs]
    facts = {r.name: r.arity for r in RELATIONS}
    heads = {sig for _p, (h, _b) in parsed for sig in h}
    for program, (program_heads, _body) in parsed:
        for (name, arity), pos in program_heads.items():
            if name in facts and facts[name] != arity:
                raise RuleError(program.file, program.first_line + pos[0] - 1,
                                f"{name} is a fact relation with {facts[name]} columns (hint: rules may not add "
                                "facts; derive a relation of your own)", pos[1])
    known = set(facts.items()) | heads
    names = {name for name, _a in known}
    for program, (_heads, body) in parsed:
        for (name, arity), pos in body:
            if (name, arity) in known:
                continue
            line = program.first_line + pos[0] - 1
            if name in names:
                arities = sorted(a for n, a in known if n == name)
                raise RuleError(program.file, line, f"{name} takes {arities[0]} columns, not {arity} (hint: use _ "
                                "for the columns you do not need)", pos[1])
            raise RuleError(program.file, line, f"unknown relation {name}/{arity} (hint: docs/facts.md lists the "
                            "relations; a typo?)", pos[1])
    declared = "".join(f"#defined {n}/{a}. " for n, a in sorted(known)) + "\n"
    for program in ruleset.programs:
        _safety(program, declared)
    for rule in ruleset.rules:
        if (rule.predicate, len(rule.columns)) not in heads:
            raise RuleError(rule.file, rule.lines.get("finding", rule.line), f"no rule derives the finding "
                            f"{rule.predicate}/{len(rule.columns)} (hint: the `finding:` header must name the head of "
                            "a rule below it, with as many columns)")
    return declared


def _parse(program: Program) -> tuple[dict[Signature, Position], list[tuple[Signature, Position]]]:
    heads: dict[Signature, Position] = {}
    body: list[tuple[Signature, Position]] = []
    messages: list[str] = []

    def visit(statement: clingo.ast.AST) -> None:
        if statement.ast_type == clingo.ast.ASTType.Rule:
            for sig, pos in _atoms(statement.head):
                heads.setdefault(sig, pos)
            for literal in statement.body:
                body.extend(_atoms(literal))

    try:
        clingo.ast.parse_string(program.text, visit, logger=lambda _c, m: messages.append(m))
    except RuntimeError:
        raise _error(program, messages) from None
    return heads, body


def _atoms(node: clingo.ast.AST) -> list[tuple[Signature, Position]]:
    found = []
    if node.ast_type == clingo.ast.ASTType.SymbolicAtom and node.symbol.ast_type == clingo.ast.ASTType.Function:
        begin = node.symbol.location.begin
        found.append(((node.symbol.name, len(node.symbol.arguments)), (begin.line, begin.column)))
    for key in node.child_keys:
        child = getattr(node, key)
        for item in child if isinstance(child, (list, clingo.ast.ASTSequence)) else [child]:
            if isinstance(item, clingo.ast.AST):
                found.extend(_atoms(item))
    return found


def _safety(program: Program, declared: str) -> None:
    messages: list[str] = []
    ctl = clingo.Control(["--warn=none"], logger=lambda _c, m: messages.append(m))
    ctl.add("base", [], declared + program.text)
    try:
        ctl.ground([("base", [])])
    except RuntimeError:
        raise _error(program, messages, line_offset=-1) from None


def _error(program: Program, messages: list[str], line_offset: int = 0) -> RuleError:
    text = " ".join(m.strip().replace("\n", " ") for m in messages) or "rule program rejected"
    match = _SPAN.search(text)
    if not match:
        return RuleError(program.file, program.first_line, text)
    line = program.first_line + int(match.group(1)) - 1 + line_offset
    detail = _SPAN.sub("", text)
    hint = next((h for needle, h in _HINTS.items() if needle in detail), "")
    return RuleError(program.file, line, detail + (f" (hint: {hint})" if hint else ""), int(match.group(2)))
