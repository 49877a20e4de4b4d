"""Which facts clingo parses, and when. Parsing fact text is most of the cost of handing facts to
clingo, so a row is given to it only when a rule can read it, or when asked for:

- the rules are grounded stratum by stratum (a relation after every relation it reads);
- before a stratum, each of its rules is given the rows of the fact relations it reads, unless a
  relation of a positive body atom of the rule is already known to be empty (then the rule derives
  nothing, like AL401's `remap_user` guarding its read of `location`);
- a relation read only in positive body atoms gets only the rows that can join with the other fact
  relations of that body (same value where they share a variable, the constant it is written with),
  that no fact of a relation the body negates rules out (`node(N, ...), not node_source(N, _)`),
  and, joined with itself under `E1 < E2` (or `>`, `!=`), that share their key with another row;
- a relation read only under a plain `not` gets the rows that can match the rows clingo has of the
  positive fact atoms binding its variables;
- every other row (of a relation no rule reads, or rows no join can use) when a query, an
  on-the-fly rule or an explanation names its relation (`Grounded.load`); so are the rules of a
  derived relation no other rule reads (`opaque_may_use`).

The first stratum's rows reach clingo as a ground program (aspif), which it reads faster than it
parses facts; that is possible only before anything is grounded.
"""

from __future__ import annotations

import functools
import operator
import tempfile
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass

import clingo
import clingo.ast

from archlog.facts.schema import BY_NAME
from archlog.facts.store import Cell, FactStore
from archlog.rules.functions import FUNCTIONS

Signature = tuple[str, int]
Position = tuple[int, int]
FACTS = {(r.name, r.arity) for r in BY_NAME.values()}
_PLAIN = (clingo.ast.ASTType.Rule, clingo.ast.ASTType.Comment)
_DIFFERENT = (clingo.ast.ComparisonOperator.LessThan, clingo.ast.ComparisonOperator.GreaterThan,
              clingo.ast.ComparisonOperator.NotEqual)
Column = tuple[str, object] | None  # ("var", a variable's name), ("=", a constant) or None (anything)


@dataclass(frozen=True)
class Reads:
    """One rule: the relations it defines and reads, its positive body atoms (signature and column
    patterns), its plainly negated atoms, the relations it reads otherwise (in aggregates and
    conditions, under `not not`) and its comparisons of two variables by <, > or !=."""

    rule: clingo.ast.AST
    heads: frozenset[Signature]
    reads: frozenset[Signature]
    atoms: tuple[tuple[Signature, tuple[Column, ...]], ...]
    negated: tuple[tuple[Signature, tuple[Column, ...]], ...]
    loose: frozenset[Signature]
    differ: frozenset[tuple[str, str]]

    @property
    def guards(self) -> set[Signature]:
        return {sig for sig, _pattern in self.atoms}


@functools.lru_cache(maxsize=1024)
def parse(text: str) -> tuple[tuple[clingo.ast.AST, ...], tuple[str, ...] | None]:
    """A rule program's statements, parsed once; or clingo's messages about why it cannot be."""
    found: list[clingo.ast.AST] = []
    messages: list[str] = []
    try:
        clingo.ast.parse_string(text, found.append, logger=lambda _code, message: messages.append(message))
    except RuntimeError:
        return (), tuple(messages)
    return tuple(found), None


def reads_of(texts: Iterable[str]) -> list[Reads] | None:
    """The rules of (valid) rule program texts, in order; None when a text holds other statements
    than rules (`#const`, `#show`, a `#program` part), which are then grounded as written, at once."""
    statements = [statement for text in texts for statement in parse(text)[0]]
    if any(s.ast_type not in _PLAIN and s.ast_type != clingo.ast.ASTType.Program for s in statements) or \
            sum(s.ast_type == clingo.ast.ASTType.Program and s.name != "base" for s in statements):
        return None
    found = []
    for statement in statements:
        if statement.ast_type != clingo.ast.ASTType.Rule:
            continue
        atoms = [atom for literal in statement.body if (atom := positive(literal)) is not None]
        negated = [atom for literal in statement.body if (atom := _negated(literal))]
        loose = [sig for literal in statement.body if positive(literal) is None and _negated(literal) is None
                 for sig in _signatures(literal)]
        heads = _signatures(statement.head)
        found.append(Reads(statement, frozenset(heads), frozenset(heads + loose + [sig for sig, _p in atoms + negated]),
                           tuple(atoms), tuple(negated), frozenset(loose), frozenset(_differ(statement.body))))
    return found


def atoms(node: clingo.ast.AST, functions: list[tuple[str, Position]]) -> list[tuple[Signature, Position]]:
    """The atoms under a node; the @functions it calls are added to `functions`."""
    found = []
    if node.ast_type == clingo.ast.ASTType.SymbolicAtom and node.symbol.ast_type == clingo.ast.ASTType.Function:
        begin = node.symbol.location.begin
        found.append(((node.symbol.name, len(node.symbol.arguments)), (begin.line, begin.column)))
    elif node.ast_type == clingo.ast.ASTType.Function and node.external:
        begin = node.location.begin
        functions.append((node.name, (begin.line, begin.column)))
    for key in node.child_keys:
        child = getattr(node, key)
        for item in child if isinstance(child, (list, clingo.ast.ASTSequence)) else [child]:
            if isinstance(item, clingo.ast.AST):
                found.extend(atoms(item, functions))
    return found


def _signatures(node: clingo.ast.AST) -> list[Signature]:
    """The relations of every atom under a node (not @functions)."""
    return [sig for sig, _position in atoms(node, [])]


def positive(literal: clingo.ast.AST, sign: int = clingo.ast.Sign.NoSign) -> tuple[Signature, tuple[Column, ...]] | None:
    """A positive body atom (or, with `sign`, a negated one): its relation and, per column,
    ("var", name), ("=", a constant) or None."""
    if literal.ast_type != clingo.ast.ASTType.Literal or literal.sign != sign or \
            literal.atom.ast_type != clingo.ast.ASTType.SymbolicAtom:
        return None
    symbol = literal.atom.symbol
    if symbol.ast_type != clingo.ast.ASTType.Function or symbol.external:
        return None
    return (symbol.name, len(symbol.arguments)), tuple(map(_column, symbol.arguments))


def _negated(literal: clingo.ast.AST) -> tuple[Signature, tuple[Column, ...]] | None:
    """A plainly negated atom whose arguments are variables (`_` too) and constants."""
    found = positive(literal, clingo.ast.Sign.Negation)
    if found is None or any(column is None and term.ast_type != clingo.ast.ASTType.Variable
                            for column, term in zip(found[1], literal.atom.symbol.arguments)):
        return None
    return found


def _differ(body: Iterable[clingo.ast.AST]) -> Iterable[tuple[str, str]]:
    """The pairs of variables a body compares by <, > or != (both orders): they hold different values."""
    for literal in body:
        atom = literal.atom if literal.ast_type == clingo.ast.ASTType.Literal else None
        if atom is None or literal.sign != clingo.ast.Sign.NoSign or atom.ast_type != clingo.ast.ASTType.Comparison or \
                len(atom.guards) != 1 or atom.guards[0].comparison not in _DIFFERENT:
            continue
        left, right = atom.term, atom.guards[0].term
        if left.ast_type == right.ast_type == clingo.ast.ASTType.Variable and "_" not in (left.name, right.name):
            yield left.name, right.name
            yield right.name, left.name


def _column(term: clingo.ast.AST) -> Column:
    if term.ast_type == clingo.ast.ASTType.Variable and term.name != "_":
        return "var", term.name
    if term.ast_type == clingo.ast.ASTType.SymbolicTerm and term.symbol.type == clingo.SymbolType.String:
        return "=", term.symbol.string
    if term.ast_type == clingo.ast.ASTType.SymbolicTerm and term.symbol.type == clingo.SymbolType.Number:
        return "=", term.symbol.number
    return None


class Grounded:
    """A clingo control with the rules grounded, and the fact rows given to it so far."""

    def __init__(self, store: FactStore) -> None:
        self.ctl = clingo.Control(["--warn=none"])
        self.store = store
        self.loaded: set[str] = set()  # relations given whole
        self.timings = {"to-clingo": 0.0, "ground": 0.0}
        self._given: dict[str, set[int]] = {}  # rows (indexes) given of the other relations
        self.later: dict[str, list[Reads]] = {}  # derived relation -> its rules, not grounded yet
        self.values = Values(store)
        self._parts = 0

    def load(self, relations: Iterable[str]) -> None:
        """Give clingo every row it lacks of these fact relations, and ground the rules of these
        derived relations that wait to be named (other names are ignored)."""
        relations = list(relations)
        self.give({name: None for name in relations if name in BY_NAME})
        for name in relations:
            if name in self.later:
                rules = self.later.pop(name)
                self.add_stratum(rules, lambda sig: sig not in _heads(rules))  # noqa: B023 (called at once)

    def lacks(self, relation: str) -> bool:
        """Whether clingo lacks rows of a fact relation or the rules of a derived one."""
        return (relation in BY_NAME and relation not in self.loaded) or relation in self.later

    def add_stratum(self, rules: list[Reads], complete: Callable[[Signature], bool], whole: Iterable[str] = (),
                    preamble: str = "") -> None:
        """Ground rules that read only relations clingo has whole (`complete`) besides those they
        define, with the fact rows they can read (and every row of the fact relations `whole`)."""
        clock = time.perf_counter()  # choosing rows is part of handing facts to clingo
        wanted: dict[str, set[int] | None] = {name: None for name in whole if name in BY_NAME}
        active = [rule for rule in rules if not any(self.empty(sig) for sig in rule.guards if complete(sig))]
        for rule in active:  # (a rule a relation it joins is empty for derives nothing)
            for name, _arity in rule.reads & FACTS:
                if name not in self.loaded and wanted.get(name, ()) is not None:
                    _want(wanted, name, _joining(self.values, rule, name))
        changed = True
        while changed:  # negated rows: those that can match what clingo will have (which they may add to)
            changed = False
            for rule in active:
                for (name, arity), pattern in rule.negated:
                    if (name, arity) in FACTS and name not in self.loaded and wanted.get(name, ()) is not None:
                        rows = _blocking(self.values, rule, name, pattern, lambda a: self.present(a, wanted))
                        changed |= _want(wanted, name, rows)
        self.timings["to-clingo"] += time.perf_counter() - clock
        self.give(wanted)
        self.add_rules([rule.rule for rule in rules], preamble)

    def give(self, rows: dict[str, set[int] | None]) -> None:
        """Give clingo these rows (indexes; None: all) of fact relations, those it lacks."""
        text: list[str] = []
        clock = time.perf_counter()
        for name, wanted in sorted(rows.items()):
            if name in self.loaded:
                continue
            every = self.store.rows(name)
            given = self._given.pop(name, set())
            if wanted is None and not given:
                text.append(self.store.text(name, every))
                self.loaded.add(name)
                continue
            new = [i for i in (range(len(every)) if wanted is None else sorted(wanted)) if i not in given]
            text.append(self.store.text(name, [every[i] for i in new]))
            given.update(new)
            if len(given) == len(every):
                self.loaded.add(name)
            else:
                self._given[name] = given
        facts = "".join(text)
        if facts and not self._parts and facts.isascii() and _load_ground(self.ctl, facts):  # nothing grounded yet
            self.timings["to-clingo"] += time.perf_counter() - clock
        elif facts:
            part = self._part()
            self.ctl.add(part, [], facts)
            self.timings["to-clingo"] += time.perf_counter() - clock
            self.ground(part)

    def present(self, relation: str, wanted: dict[str, set[int] | None]) -> set[int] | None:
        """The rows clingo has of a fact relation once these are given too (None: all)."""
        if relation in self.loaded or wanted.get(relation, ()) is None:
            return None
        return self._given.get(relation, set()) | (wanted.get(relation) or set())

    def given(self, relation: str) -> int:
        """How many rows of a fact relation clingo has."""
        return self.store.count(relation) if relation in self.loaded else len(self._given.get(relation, ()))

    def add_rules(self, rules: list[clingo.ast.AST], preamble: str = "") -> None:
        """Ground rules on top of what is grounded (they may read only relations grounded before
        them or defined among themselves)."""
        part = self._part()
        if preamble:
            self.ctl.add(part, [], preamble)
        with clingo.ast.ProgramBuilder(self.ctl) as builder:
            begin = clingo.ast.Position("<rules>", 1, 1)
            builder.add(clingo.ast.Program(clingo.ast.Location(begin, begin), part, []))
            for rule in rules:
                builder.add(rule)
        self.ground(part)

    def ground(self, part: str) -> None:
        clock = time.perf_counter()
        self.ctl.ground([(part, [])], context=FUNCTIONS)
        self.timings["ground"] += time.perf_counter() - clock

    def empty(self, signature: Signature) -> bool:
        """Whether a relation has no rows (a fact relation in the store, a derived one in clingo)."""
        if signature in FACTS:
            return self.store.count(signature[0]) == 0
        return next(iter(self.ctl.symbolic_atoms.by_signature(*signature)), None) is None

    def _part(self) -> str:
        self._parts += 1
        return f"__part{self._parts}"


def _load_ground(ctl: clingo.Control, facts: str) -> bool:
    """Give clingo facts (`relation(...).` lines, ASCII) as a ground program in its aspif format,
    which it reads faster than it parses them (only before anything is grounded, and only from a
    file): each fact is a term shown unconditionally. The next `ground` call adds them. False when
    no temporary file can be written (then they are to be parsed)."""
    terms = facts.split(").\n")[:-1]
    try:
        with tempfile.NamedTemporaryFile("w", encoding="ascii", prefix="archlog-", suffix=".aspif") as file:
            file.write("asp 1 0 0\n" + "".join([f"4 {len(term) + 1} {term}) 0\n" for term in terms]) + "0\n")
            file.flush()
            ctl.load(file.name)
    except OSError:
        return False
    return True


def ground(store: FactStore, rules: list[Reads], preamble: str, listed: set[str], kept: set[str]) -> Grounded:
    """Ground the rules stratum by stratum, each with the fact rows it can read (see the module).
    `listed` are relations findings list (read from clingo, whole). The rules of a relation no
    other rule reads and not `kept` (findings, lists) wait until it is named (`Grounded.load`)."""
    grounded = Grounded(store)
    read = {sig for rule in rules for sig in rule.reads - rule.heads} | {sig for sig in _heads(rules) if sig[0] in kept}
    for rule in rules:
        if len(rule.heads) == 1 and not rule.heads & read:
            grounded.later.setdefault(next(iter(rule.heads))[0], []).append(rule)
    eager = [rule for rule in rules if len(rule.heads) != 1 or rule.heads & read]
    levels = _levels(eager)
    for level in sorted(set(levels.values())) or [1]:  # the first stratum with the listed relations and the preamble
        grounded.add_stratum([rule for rule in eager if levels[id(rule)] == level],
                             lambda sig: sig in FACTS or levels.get(sig, level) < level,  # noqa: B023 (called at once)
                             *((listed, preamble) if level == min(levels.values(), default=1) else ((), "")))
    return grounded


def _heads(rules: list[Reads]) -> set[Signature]:
    return {sig for rule in rules for sig in rule.heads}


class Values:
    """The values in columns of fact relations, each set computed once."""

    def __init__(self, store: FactStore) -> None:
        self.store = store
        self._sets: dict[tuple[str, tuple[int, ...], tuple[tuple[int, object], ...]], set[object]] = {}
        self._spread: dict[tuple[str, tuple[int, ...], int], set[object]] = {}
        self._rows: dict[str, list[tuple[Cell, ...]]] = {}

    def rows(self, relation: str) -> list[tuple[Cell, ...]]:
        if relation not in self._rows:
            self._rows[relation] = self.store.rows(relation)
        return self._rows[relation]

    def of(self, relation: str, columns: tuple[int, ...], constants: tuple[tuple[int, object], ...] = ()) \
            -> set[object]:
        """The values (a tuple per row, or the value for one column) of these columns, in the rows
        that hold these constants (column, value)."""
        key = (relation, columns, constants)
        if key not in self._sets:
            rows = self.rows(relation)
            for column, value in constants:
                rows = [row for row in rows if row[column] == value]
            self._sets[key] = set(map(operator.itemgetter(*columns), rows))
        return self._sets[key]

    def spread(self, relation: str, columns: tuple[int, ...], apart: int) -> set[object]:
        """The values of these columns that two rows with different values in column `apart` share."""
        key = (relation, columns, apart)
        if key not in self._spread:
            seen: dict[object, Cell] = {}
            found = self._spread[key] = set()
            for row in self.rows(relation):
                value = operator.itemgetter(*columns)(row)
                if seen.setdefault(value, row[apart]) != row[apart]:
                    found.add(value)
        return self._spread[key]

    def column(self, relation: str, column: int, rows: set[int] | None) -> set[object]:
        """The values of a column in these rows (None: all)."""
        if rows is None:
            return self.of(relation, (column,))
        every = self.rows(relation)
        return {every[i][column] for i in rows}

    def has_nul(self, relation: str) -> bool:
        """Whether a string of the relation holds a NUL character: clingo cuts it there, so values
        that differ here may be equal there."""
        return self.store.has_nul(relation)


def _want(wanted: dict[str, set[int] | None], relation: str, rows: set[int] | None) -> bool:
    """Add rows (None: all) to those wanted of a relation; whether that added any."""
    before = wanted.get(relation, set())
    if before is None or (rows is not None and rows <= before):
        return False
    wanted[relation] = None if rows is None else rows | before
    return True


def _joining(values: Values, rule: Reads, relation: str) -> set[int] | None:
    """The rows of a fact relation that the rule's body can use (None: all): read only in positive
    atoms (and plain negations), a row must match an atom's constants and, for every other fact
    relation of the body, share the values of their common variables with one of its rows (with
    another one, joined with itself where the body compares the two atoms' values of a column by <,
    > or !=), and must not match a fact of a relation the body negates on its variables (relations
    with a NUL in a string are not filtered, nor used as filters)."""
    if any(name == relation for name, _arity in rule.loose):
        return None
    found: set[int] = set()
    for index, ((name, _arity), pattern) in enumerate(rule.atoms):
        if name != relation:
            continue
        tests: list[tuple[Callable[[tuple[Cell, ...]], object], set[object], bool]] = [
            (operator.itemgetter(column), {spec[1]}, True) for column, spec in enumerate(pattern)
            if spec and spec[0] == "="]
        variables = {spec[1]: column for column, spec in enumerate(pattern) if spec and spec[0] == "var"}
        for other, ((guard, _arity), guard_pattern) in enumerate(rule.atoms):
            shared = [(variables[spec[1]], column) for column, spec in enumerate(guard_pattern)
                      if spec and spec[0] == "var" and spec[1] in variables]
            if other != index and (guard, len(guard_pattern)) in FACTS and shared and not values.has_nul(guard):
                theirs = tuple(column for _mine, column in shared)
                apart = [column for column, (mine, spec) in enumerate(zip(pattern, guard_pattern))
                         if guard == relation and mine and spec and mine[0] == spec[0] == "var" and
                         (mine[1], spec[1]) in rule.differ]
                allowed = values.spread(guard, theirs, apart[0]) if apart else values.of(guard, theirs)
                tests.append((operator.itemgetter(*(mine for mine, _theirs in shared)), allowed, True))
        for (guard, arity), guard_pattern in rule.negated:
            bound = [(column, spec[1]) for column, spec in enumerate(guard_pattern) if spec and spec[0] == "var"]
            if (guard, arity) in FACTS and bound and all(var in variables for _c, var in bound) and \
                    not values.has_nul(guard):
                blocked = values.of(guard, tuple(column for column, _var in bound), _constants(guard_pattern))
                tests.append((operator.itemgetter(*(variables[var] for _c, var in bound)), blocked, False))
        if not tests or values.has_nul(relation):
            return None
        every = values.rows(relation)
        rows: Iterable[int] = range(len(every))
        for key, allowed, inside in tests:
            rows = [i for i in rows if (key(every[i]) in allowed) is inside]
        found.update(rows)
    return found


def _blocking(values: Values, rule: Reads, relation: str, pattern: tuple[Column, ...],
              present: Callable[[str], set[int] | None]) -> set[int] | None:
    """The rows of a fact relation the rule negates (`not relation(...)`) that can match the rows
    clingo has (`present`, None: all) of the positive fact atoms binding the atom's variables, and
    its constants (None: all)."""
    if any(name == relation for name, _arity in rule.loose) or values.has_nul(relation):
        return None
    tests: list[tuple[int, set[object]]] = [(column, {value}) for column, value in _constants(pattern)]
    for column, spec in enumerate(pattern):
        if not spec or spec[0] != "var":
            continue
        bound = [values.column(name, position, present(name)) for (name, arity), atom in rule.atoms
                 if (name, arity) in FACTS and not values.has_nul(name)
                 for position, other in enumerate(atom) if other == spec]
        if not bound:
            return None  # bound by a derived relation only
        tests.append((column, set.intersection(*bound)))
    every = values.rows(relation)
    rows: Iterable[int] = range(len(every))
    for column, allowed in tests:
        rows = [i for i in rows if every[i][column] in allowed]
    return set(rows)


def _constants(pattern: tuple[Column, ...]) -> tuple[tuple[int, object], ...]:
    return tuple((column, spec[1]) for column, spec in enumerate(pattern) if spec and spec[0] == "=")


def _levels(rules: list[Reads]) -> dict[object, int]:
    """The stratum of each rule (by id) and derived relation: 1 + the highest stratum of the
    derived relations its rules read, outside its own cycle (a cycle's relations share one)."""
    defined = {sig for rule in rules for sig in rule.heads}
    depends: dict[Signature, set[Signature]] = {sig: set() for sig in defined}
    for rule in rules:
        for head in rule.heads:
            depends[head] |= (rule.reads & defined) | rule.heads
    component = _components(depends)
    level: dict[int, int] = {}

    def of(comp: int) -> int:
        if comp not in level:
            members = [sig for sig, c in component.items() if c == comp]
            level[comp] = 1 + max((of(component[d]) for m in members for d in depends[m] if component[d] != comp),
                                  default=0)
        return level[comp]

    levels: dict[object, int] = {sig: of(component[sig]) for sig in defined}
    for rule in rules:
        levels[id(rule)] = levels[next(iter(rule.heads))] if rule.heads else \
            1 + max((levels[d] for d in rule.reads & defined), default=0)
    return levels


def _components(graph: dict[Signature, set[Signature]]) -> dict[Signature, int]:
    """Strongly connected components (Tarjan, iterative): relation -> component number."""
    index: dict[Signature, int] = {}
    low: dict[Signature, int] = {}
    component: dict[Signature, int] = {}
    stack: list[Signature] = []
    for root in graph:
        if root in index:
            continue
        index[root] = low[root] = len(index)
        stack.append(root)
        work = [(root, iter(sorted(graph[root])))]
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child not in component:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                number = index[node]
                while True:
                    member = stack.pop()
                    component[member] = number
                    if member == node:
                        break
    return component
