"""A query session: facts extracted once, rules grounded once, then queries, rules defined on
the fly and explanations run incrementally against them (clingo keeps the grounded state)."""

from __future__ import annotations

import re
import time
from dataclasses import dataclass, field

import clingo
import clingo.ast

from archlog.config import Config
from archlog.facts.schema import BY_NAME
from archlog.facts.store import Cell, FactStore
from archlog.rules.engine import Engine, Finding, Signature, _parse, _safety
from archlog.rules.ruleset import Program, RuleError, RuleSet, parse_rule_file


class QueryError(Exception):
    """A query or an on-the-fly rule that clingo rejects, or that names an unknown relation."""


@dataclass
class Result:
    columns: list[str]
    rows: list[tuple[Cell, ...]]
    seconds: float = 0.0


@dataclass
class Explanation:
    """Why an atom holds: the rule that derived it and the atoms of that rule's body."""

    atom: str
    rule: str | None = None
    location: tuple[str, int, int] | None = None
    children: list[Explanation] = field(default_factory=list)

    def as_dict(self) -> dict:
        return {"atom": self.atom, "rule": self.rule,
                "location": None if self.location is None else
                {"file": self.location[0], "line": self.location[1], "column": self.location[2]},
                "because": [c.as_dict() for c in self.children]}

    def lines(self, indent: str = "") -> list[str]:
        where = f"  [{self.location[0]}:{self.location[1]}]" if self.location else ""
        how = f"  (by {self.rule})" if self.rule else "  (fact)"
        out = [f"{indent}{self.atom}{how}{where}"]
        for child in self.children:
            out += child.lines(indent + "  ")
        return out


class Session:
    def __init__(self, store: FactStore, ruleset: RuleSet, config: Config | None = None) -> None:
        self.store, self.ruleset, self.config = store, ruleset, config or Config()
        self.engine = Engine(ruleset)
        start = time.perf_counter()
        self.ctl = self.engine.ground(store)
        self.ground_seconds = time.perf_counter() - start
        self.disabled: set[str] = set()
        self.parts = 0
        self.extra: list[Program] = []
        self._known_cache: set[Signature] | None = None

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
        """(name, arity, number of tuples, 'fact' or 'derived') of everything grounded."""
        counts: dict[Signature, int] = {}
        for atom in self.ctl.symbolic_atoms:
            sig = (atom.symbol.name, len(atom.symbol.arguments))
            counts[sig] = counts.get(sig, 0) + 1
        signatures = {(r.name, r.arity) for r in BY_NAME.values()} | set(counts)
        return sorted((n, a, counts.get((n, a), 0), "fact" if n in BY_NAME else "derived")
                      for n, a in signatures if not n.startswith("__"))

    # -- queries and rules ----------------------------------------------------------------
    def query(self, goal: str) -> Result:
        """All bindings of the variables of `goal` (a conjunction of literals, clingo syntax)."""
        start = time.perf_counter()
        body = goal.strip().rstrip(".").strip()
        variables = _variables(body)
        self.parts += 1
        head = f"__q{self.parts}"
        text = f"{head}({', '.join(variables)}) :- {body}." if variables else f"{head} :- {body}."
        self._add(Program(text, "<query>", 1))
        atoms = self.ctl.symbolic_atoms.by_signature(head, len(variables))
        rows = sorted(tuple(self.store.from_term(a) for a in atom.symbol.arguments) for atom in atoms)
        return Result(variables, rows, time.perf_counter() - start)

    def define(self, text: str, file: str = "<repl>") -> list[str]:
        """Add rules (and rule metadata headers) on the fly; returns the predicates they define."""
        rules, programs = parse_rule_file(text, file)
        for program in programs:
            self._add(program)
        self.ruleset.rules += rules
        self.ruleset.programs += programs
        return sorted({name for p in programs for name, _a in _parse(p)[0]})

    def _add(self, program: Program) -> None:
        """Check one new program (syntax, relations, safety) and ground it on top of the rest."""
        try:
            heads, body = _parse(program)
            known = self._known() | set(heads)
            missing = [f"{n}/{a}" for (n, a), _pos in body if (n, a) not in known]
            if missing:
                raise QueryError(f"unknown relation {missing[0]} (see :relations)")
            _safety(program, "".join(f"#defined {n}/{a}. " for n, a in sorted(known)) + "\n")
        except RuleError as exc:
            raise QueryError(f"{exc.message} (line {exc.line}, column {exc.column})") from None
        self.parts += 1
        part = f"p{self.parts}"
        self.ctl.add(part, [], program.text)
        self.ctl.ground([(part, [])])
        self.extra.append(program)
        self._known_cache = None

    def _known(self) -> set[Signature]:
        if self._known_cache is None:
            self._known_cache = {(r.name, r.arity) for r in BY_NAME.values()} | \
                {sig for p in self.ruleset.programs + self.extra for sig in _parse(p)[0]}
        return self._known_cache

    # -- explanations ---------------------------------------------------------------------
    def explain(self, atom: clingo.Symbol, depth: int = 4) -> Explanation:
        """The rule that derives `atom` and, recursively, the atoms it used (facts at the leaves)."""
        node = Explanation(str(atom), location=self._location(atom))
        if atom.name in BY_NAME or depth == 0:
            return node
        for program in self.ruleset.programs + self.extra:
            for rule in _rules(program):
                if rule.head.ast_type != clingo.ast.ASTType.Literal:
                    continue
                head = rule.head.atom.symbol
                if head.ast_type != clingo.ast.ASTType.Function or head.name != atom.name or \
                        len(head.arguments) != len(atom.arguments):
                    continue
                body = self._instantiate(rule, atom)
                if body is not None:
                    node.rule = f"{program.file}:{program.first_line + rule.location.begin.line - 1}"
                    node.children = [self.explain(b, depth - 1) for b in body]
                    return node
        return node

    def _instantiate(self, rule: clingo.ast.AST, atom: clingo.Symbol) -> list[clingo.Symbol] | None:
        """The positive body atoms of one grounding of `rule` whose head is `atom`, if any."""
        literals = [_name_anonymous(str(lit.atom), i) for i, lit in enumerate(rule.body)
                    if lit.ast_type == clingo.ast.ASTType.Literal and lit.sign == clingo.ast.Sign.NoSign
                    and lit.atom.ast_type == clingo.ast.ASTType.SymbolicAtom]
        body_text = ", ".join(_name_anonymous(str(lit), i) for i, lit in enumerate(rule.body))
        bindings = ", ".join(f"{arg} = {value}" for arg, value in zip(rule.head.atom.symbol.arguments, atom.arguments))
        variables = _variables(", ".join(literals))  # not an aggregate's own variables (unsafe outside it)
        self.parts += 1
        head = f"__why{self.parts}"
        text = f"{head}({', '.join(variables)}) :- {body_text}{', ' if bindings else ''}{bindings}."
        try:
            self.ctl.add(f"w{self.parts}", [], text)
            self.ctl.ground([(f"w{self.parts}", [])])
        except RuntimeError:
            return None
        solution = next(iter(self.ctl.symbolic_atoms.by_signature(head, len(variables))), None)
        if solution is None:
            return None
        values = dict(zip(variables, solution.symbol.arguments))
        return [clingo.parse_term(_substitute(text, values)) for text in literals]

    def _location(self, atom: clingo.Symbol) -> tuple[str, int, int] | None:
        for arg in atom.arguments:
            if arg.type == clingo.SymbolType.String and (found := self.store.location(arg.string)):
                return found
        return None


def _rules(program: Program) -> list[clingo.ast.AST]:
    found: list[clingo.ast.AST] = []
    clingo.ast.parse_string(program.text, lambda s: found.append(s) if s.ast_type == clingo.ast.ASTType.Rule else None)
    return found


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


def _substitute(text: str, values: dict[str, clingo.Symbol]) -> str:
    """Replace variables in a rendered atom by their values, leaving string literals alone."""
    return _outside_strings(text, lambda piece: re.sub(r"\b([A-Z]\w*)\b",
                                                       lambda m: str(values.get(m.group(1), m.group(0))), piece))
