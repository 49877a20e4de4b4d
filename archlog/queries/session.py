"""A query session: facts extracted once, rules grounded once, then queries, rules defined on
the fly and explanations run incrementally against them (clingo keeps the grounded state)."""

from __future__ import annotations

import re
import time
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import clingo
import clingo.ast

from archlog.config import Config
from archlog.facts.schema import BY_NAME
from archlog.facts.store import Cell, FactStore
from archlog.rules.engine import (
    Engine,
    Finding,
    Signature,
    _parse,
    _safety,
    check_locations,
    column_types,
    rules_of,
    unknown_function,
    unknown_relation,
)
from archlog.rules.functions import FUNCTIONS, NAMES
from archlog.rules.loading import FACTS
from archlog.rules.ruleset import BUILTIN, Program, RuleError, RuleSet, parse_rule_file
from archlog.values import order


class QueryError(Exception):
    """A query or an on-the-fly rule that clingo rejects, or that names an unknown relation."""


class Result:
    """The bindings of a query's variables, converted as they are read: the first rows can be
    shown before the last are converted. Iterating again replays the rows read so far."""

    def __init__(self, columns: list[str], source: Iterable[tuple[Cell, ...]], seconds: float = 0.0) -> None:
        self.columns, self.seconds = columns, seconds  # seconds: until the first row could be read
        self._source: Iterator[tuple[Cell, ...]] = iter(source)
        self._read: list[tuple[Cell, ...]] = []

    def __iter__(self) -> Iterator[tuple[Cell, ...]]:
        index = 0
        while index < len(self._read) or self._more():
            yield self._read[index]
            index += 1

    def _more(self) -> bool:
        row = next(self._source, None)
        if row is not None:
            self._read.append(row)
        return row is not None

    @property
    def rows(self) -> list[tuple[Cell, ...]]:
        """Every row, in the order clingo grounded them."""
        return self.read_all()

    def read_all(self) -> list[tuple[Cell, ...]]:
        """Read the rows not read yet; every row."""
        self._read.extend(self._source)
        return self._read

    def sorted_rows(self) -> list[tuple[Cell, ...]]:
        return sorted(self.rows, key=lambda row: tuple(map(order, row)))


@dataclass
class Explanation:
    """Why an atom holds: the rule that derived it and the literals of that rule's body, or that it
    is a fact. `kind` is fact, derived (by `rule`), absent (a `not` condition: no such atom),
    condition (a comparison or aggregate that held) or false (the atom does not hold)."""

    atom: str
    kind: str = "fact"
    rule: str | None = None
    location: tuple[str, int, int] | None = None
    children: list[Explanation] = field(default_factory=list)

    def as_dict(self) -> dict:
        return {"atom": self.atom, "kind": self.kind, "rule": self.rule,
                "location": None if self.location is None else
                {"file": self.location[0], "line": self.location[1], "column": self.location[2]},
                "because": [c.as_dict() for c in self.children]}

    def lines(self, indent: str = "") -> list[str]:
        where = f"  [{self.location[0]}:{self.location[1]}]" if self.location else ""
        how = {"fact": "  (fact)", "absent": "  (none exists)", "condition": "  (holds)", "false": "  (does not hold)",
               "derived": f"  (by {self.rule})" if self.rule else "  (derived; reasons not shown)"}[self.kind]
        out = [f"{indent}{self.atom}{how}{where}"]
        for child in self.children:
            out += child.lines(indent + "  ")
        return out


class Session:
    def __init__(self, store: FactStore, ruleset: RuleSet, config: Config | None = None) -> None:
        self.store, self.ruleset, self.config = store, ruleset, config or Config()
        self.engine = Engine(ruleset)
        start = time.perf_counter()
        self.grounded = self.engine.start(store)
        self.ctl = self.grounded.ctl
        self.ground_seconds = time.perf_counter() - start
        self.disabled: set[str] = set()
        self.parts = 0
        self.extra: list[Program] = []
        self._known_cache: set[Signature] | None = None
        self._open: Result | None = None  # the last query's result, read lazily from the grounded atoms

    def _finish_open(self) -> None:
        """Read the rest of the last result before grounding more (which invalidates its atoms)."""
        if self._open is not None:
            self._open.read_all()
            self._open = None

    # -- findings -------------------------------------------------------------------------
    def findings(self) -> list[Finding]:
        rules = {r.id: r for r in self.config.adjust(self.ruleset.rules) if r.id not in self.disabled}
        result = []
        for finding in self.engine.findings(self.ctl, self.store):
            if finding.rule.id in rules:
                finding.rule = rules[finding.rule.id]
                result.append(finding)
        return result

    # -- relations ------------------------------------------------------------------------
    def relations(self) -> list[tuple[str, int, int, str]]:
        """(name, arity, number of tuples, 'fact' or 'derived') of every fact relation (loaded into
        clingo or not) and of everything derived so far (`waiting` names the other derived ones)."""
        counts = {(r.name, r.arity): self.store.count(r.name) for r in BY_NAME.values()}
        waiting = set(self.waiting())
        for name, arity, _positive in self.ctl.symbolic_atoms.signatures:
            if (name, arity) not in counts and (name, arity) not in waiting:
                counts[(name, arity)] = sum(1 for _ in self.ctl.symbolic_atoms.by_signature(name, arity))
        return sorted((n, a, count, "fact" if n in BY_NAME else "derived")
                      for (n, a), count in counts.items() if not n.startswith("__"))

    def waiting(self) -> list[tuple[str, int]]:
        """(name, arity) of the derived relations whose rules are grounded when first named (in a
        query, a rule or an explanation): no other rule reads them."""
        return sorted({sig for rules in self.grounded.later.values() for rule in rules for sig in rule.heads})

    # -- queries and rules ----------------------------------------------------------------
    def query(self, goal: str) -> Result:
        """All bindings of the variables of `goal` (a conjunction of literals, clingo syntax)."""
        start = time.perf_counter()
        body = goal.strip().rstrip(".").strip()
        variables = _variables(body)
        whole = _whole_relation(body)
        if whole is not None and whole in FACTS:  # a fact relation, all columns: the store's rows
            return Result(variables, self.store.read_back(whole[0]), time.perf_counter() - start)
        if whole is not None and whole in self._known():  # a derived relation, all columns: read it as it is
            self._finish_open()
            self._load([whole[0]])
            atoms = self.ctl.symbolic_atoms.by_signature(*whole)
        else:
            self.parts += 1
            head = f"__q{self.parts}"
            text = f"{head}({', '.join(variables)}) :- {body}." if variables else f"{head} :- {body}."
            self._add(Program(text, "<query>", 1))
            atoms = self.ctl.symbolic_atoms.by_signature(head, len(variables))
        self._open = Result(variables, (tuple(map(self.store.from_term, atom.symbol.arguments)) for atom in atoms),
                            time.perf_counter() - start)
        return self._open

    def define(self, text: str, file: str = "<repl>") -> list[str]:
        """Add rules (and rule metadata headers) on the fly; returns the predicates they define."""
        rules, programs = parse_rule_file(text, file)
        for program in programs:
            self._add(program)
        types = column_types([rule for p in self.ruleset.programs + self.extra for rule in rules_of(p)])
        for rule in rules:
            try:
                check_locations(rule, types.get((rule.predicate, len(rule.columns)), []))
            except RuleError as exc:
                raise QueryError(f"{exc.message} (line {exc.line})") from None
        self.ruleset.rules += rules
        self.ruleset.programs += programs
        return sorted({name for p in programs for name, _a in _parse(p)[0]})

    def _add(self, program: Program) -> None:
        """Check one new program (syntax, relations, safety) and ground it on top of the rest."""
        try:
            parsed = _parse(program)
            known = self._known() | set(parsed.heads)
            missing = [sig for sig, _pos in parsed.body if sig not in known]
            if missing:
                raise QueryError(unknown_relation(*missing[0], known))
            for name, _pos in parsed.functions:
                if name not in NAMES:
                    raise QueryError(unknown_function(name))
            _safety(program, "".join(f"#defined {n}/{a}. " for n, a in sorted(known)) + "\n")
        except RuleError as exc:
            raise QueryError(f"{exc.message} (line {exc.line}, column {exc.column})") from None
        self._load(name for (name, _arity), _pos in parsed.body)
        self._finish_open()
        self.parts += 1
        part = f"p{self.parts}"
        self.ctl.add(part, [], program.text)
        self.ctl.ground([(part, [])], context=FUNCTIONS)
        self.extra.append(program)
        self._known_cache = self._known() | set(parsed.heads)

    def _load(self, relations: Iterable[str]) -> None:
        """Give clingo the fact relations it lacks of these, and the rules of derived ones that wait
        to be named (grounding them ends the open result)."""
        missing = [name for name in relations if self.grounded.lacks(name)]
        if missing:
            self._finish_open()
            self.grounded.load(missing)

    def _known(self) -> set[Signature]:
        if self._known_cache is None:
            self._known_cache = {(r.name, r.arity) for r in BY_NAME.values()} | \
                {sig for p in self.ruleset.programs + self.extra for sig in _parse(p)[0]}
        return self._known_cache

    # -- explanations ---------------------------------------------------------------------
    def explain(self, atom: clingo.Symbol, depth: int = 4) -> Explanation:
        """The rule that derives `atom` and, recursively, what its body used (facts at the leaves)."""
        self._load([atom.name])
        if self.ctl.symbolic_atoms[atom] is None:
            return Explanation(self.show(atom), "false")
        if atom.name in BY_NAME:
            return Explanation(self.show(atom), location=self._location(atom))
        node = Explanation(self.show(atom), "derived", location=self._location(atom))
        if depth == 0:
            return node
        for program in self.ruleset.programs + self.extra:
            for rule in rules_of(program):
                if rule.head.ast_type != clingo.ast.ASTType.Literal:
                    continue
                head = rule.head.atom.symbol
                if head.ast_type != clingo.ast.ASTType.Function or head.name != atom.name or \
                        len(head.arguments) != len(atom.arguments):
                    continue
                body = self._instantiate(rule, atom)
                if body is not None:
                    node.rule = f"{_shown(program.file)}:{program.first_line + rule.location.begin.line - 1}"
                    node.children = [self.explain(b, depth - 1) if isinstance(b, clingo.Symbol) else b for b in body]
                    return node
        return node

    def show(self, symbol: clingo.Symbol) -> str:
        """A term as archlog writes values: strings quoted, an unknown as `?(expr)`."""
        if symbol.type == clingo.SymbolType.Function and symbol.arguments:
            if symbol.name == "unknown" and len(symbol.arguments) == 1:
                return str(self.store.from_term(symbol))
            return f"{symbol.name}({', '.join(map(self.show, symbol.arguments))})"
        return str(symbol)

    def _instantiate(self, rule: clingo.ast.AST, atom: clingo.Symbol) -> list[clingo.Symbol | Explanation] | None:
        """One grounding of `rule` whose head is `atom`: its positive body atoms, and its other
        literals (`not` conditions, comparisons, aggregates) as text with the values filled in."""
        literals = [_name_anonymous(str(lit.atom), i) if _is_positive_atom(lit) else str(lit)
                    for i, lit in enumerate(rule.body)]
        variables = _variables(str(rule.head))
        for literal, text in zip(rule.body, literals):
            if _is_positive_atom(literal):
                variables += [v for v in _variables(text) if v not in variables]
        bindings = [f"{arg} = {value}" for arg, value in zip(rule.head.atom.symbol.arguments, atom.arguments)]
        self.parts += 1
        head = f"__why{self.parts}"
        program = f"{head}({', '.join(variables)}) :- {', '.join(literals + bindings)}."
        self._finish_open()
        try:
            self.ctl.add(f"w{self.parts}", [], program)
            self.ctl.ground([(f"w{self.parts}", [])], context=FUNCTIONS)
        except RuntimeError:
            return None
        solution = next(iter(self.ctl.symbolic_atoms.by_signature(head, len(variables))), None)
        if solution is None:
            return None
        values = dict(zip(variables, solution.symbol.arguments))
        shown = {name: self.show(value) for name, value in values.items()}
        body: list[clingo.Symbol | Explanation] = []
        for literal, text in zip(rule.body, literals):
            if _is_positive_atom(literal):
                body.append(clingo.parse_term(_substitute(text, values)))
            else:
                absent = literal.ast_type == clingo.ast.ASTType.Literal and \
                    literal.atom.ast_type == clingo.ast.ASTType.SymbolicAtom
                shown_text = self._absent(literal, values) if absent else None
                body.append(Explanation(shown_text or _substitute(text, shown), "absent" if absent else "condition"))
        return body

    def _absent(self, literal: clingo.ast.AST, values: dict[str, clingo.Symbol]) -> str | None:
        """`not ATOM` written as atoms are, when the atom has no `_` left (else None)."""
        try:
            return "not " + self.show(clingo.parse_term(_substitute(str(literal.atom), values), lambda _c, _m: None))
        except RuntimeError:
            return None

    def _location(self, atom: clingo.Symbol) -> tuple[str, int, int] | None:
        for arg in atom.arguments:
            if arg.type == clingo.SymbolType.String and (found := self.store.location(arg.string)):
                return found
        return None


def _shown(file: str) -> str:
    """A shipped rule file relative to the folder holding the archlog package; others as given."""
    path = Path(file)
    return path.relative_to(BUILTIN.parents[2]).as_posix() if path.is_relative_to(BUILTIN) else file


def _is_positive_atom(literal: clingo.ast.AST) -> bool:
    return literal.ast_type == clingo.ast.ASTType.Literal and literal.sign == clingo.ast.Sign.NoSign and \
        literal.atom.ast_type == clingo.ast.ASTType.SymbolicAtom


def _whole_relation(body: str) -> Signature | None:
    """The relation of a goal that is a single atom with a distinct named variable in every column."""
    rules: list[clingo.ast.AST] = []
    clingo.ast.parse_string(f"__v :- {body}.", lambda s: rules.append(s) if s.ast_type == clingo.ast.ASTType.Rule
                            else None, logger=lambda _code, _message: None)
    if len(rules) != 1 or len(rules[0].body) != 1 or not _is_positive_atom(rules[0].body[0]):
        return None
    symbol = rules[0].body[0].atom.symbol
    if symbol.ast_type != clingo.ast.ASTType.Function or symbol.external:
        return None
    names = [a.name for a in symbol.arguments if a.ast_type == clingo.ast.ASTType.Variable and a.name[0] != "_"]
    return (symbol.name, len(names)) if len(names) == len(set(names)) == len(symbol.arguments) else None


def _variables(body: str) -> list[str]:
    """The named variables of a body, in order of first appearance."""
    seen: list[str] = []

    def collect(node: clingo.ast.AST) -> None:
        if node.ast_type == clingo.ast.ASTType.Variable and not node.name.startswith("_") and node.name not in seen:
            seen.append(node.name)
        for key in node.child_keys:
            child = getattr(node, key)
            for item in child if isinstance(child, (list, clingo.ast.ASTSequence)) else [child]:
                if isinstance(item, clingo.ast.AST):
                    collect(item)

    try:
        clingo.ast.parse_string(f"__v :- {body}.", lambda s: collect(s) if s.ast_type == clingo.ast.ASTType.Rule
                                else None, logger=lambda _code, _message: None)
    except RuntimeError:
        raise QueryError(f"not a valid goal: {body}") from None
    return seen


def _outside_strings(text: str, change) -> str:
    pieces = re.split(r'("(?:[^"\\]|\\.)*")', text)
    return "".join(piece if piece.startswith('"') else change(piece) for piece in pieces)


def _name_anonymous(text: str, literal: int) -> str:
    """Give each `_` of a body literal its own variable, so an explanation can show its value."""
    count = iter(range(1000))
    return _outside_strings(text, lambda piece: re.sub(r"(?<![\w])_(?![\w])",
                                                       lambda _m: f"Anon{literal}x{next(count)}", piece))


def _substitute(text: str, values: Mapping[str, object]) -> str:
    """Replace variables in a rendered atom by their values, leaving string literals alone."""
    return _outside_strings(text, lambda piece: re.sub(r"\b([A-Z]\w*)\b",
                                                       lambda m: str(values.get(m.group(1), m.group(0))), piece))
