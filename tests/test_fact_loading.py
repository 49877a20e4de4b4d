"""Fact relations reach clingo only when something can read them (archlog/rules/loading.py): the
findings are those of grounding every fact, and every relation stays available to queries, rules
defined on the fly, user rule files and explanations."""

from __future__ import annotations

from pathlib import Path

import clingo
import pytest
from conftest import CORPUS, load_case

from archlog.analysis import analyse
from archlog.facts.schema import BY_NAME
from archlog.facts.store import FactStore
from archlog.queries.session import Session
from archlog.rules import loading
from archlog.rules.engine import Engine, Finding
from archlog.rules.functions import FUNCTIONS
from archlog.rules.ruleset import RuleSet, load_rules

HEADER = """%! id: USR9
%! name: early-publisher
%! severity: warning
%! summary: a publisher declared in the first lines of its file
%! finding: early(topic, port)
%! location: port
%! message: "{topic} is published early"
"""


def corpus_store(name: str) -> FactStore:
    variant = CORPUS / name / "buggy"
    case = load_case(variant)
    return analyse([variant], case["launch"], case.get("args", {}), []).store


def every_fact(engine: Engine, store: FactStore) -> list[Finding]:
    """The findings of the rules grounded together with every fact relation, as one program."""
    ctl = clingo.Control(["--warn=none"])
    ctl.add("base", [], engine.declared + "\n".join(p.text for p in engine.ruleset.programs) + store.program())
    ctl.ground([("base", [])], context=FUNCTIONS)
    return engine.findings(ctl, store)


def shown(findings: list[Finding]) -> list[tuple[str, str, int, str]]:
    return [(f.rule.id, f.location.file, f.location.line, f.message) for f in findings]


@pytest.mark.parametrize("name", ["misplaced_remap", "unused_remap_duplicate", "unread_topic_param"])
def test_findings_are_those_of_grounding_every_fact(name: str) -> None:
    store, engine = corpus_store(name), Engine(load_rules([]))
    grounded = engine.start(store)
    lazy = engine.findings(grounded.ctl, store)
    assert lazy and shown(lazy) == shown(every_fact(engine, store))
    assert "name_namespace" not in grounded.loaded  # no rule reads it


def test_a_guarded_relation_loads_only_when_its_guard_holds() -> None:
    """AL401 reads `location` only for remaps that no node uses (its guard `remap_user`)."""
    engine = Engine(load_rules([]))
    misplaced = engine.start(corpus_store("misplaced_remap"))
    assert "location" in misplaced.loaded
    assert any("declared before the remap" in f.message or "outside the remap's scope" in f.message
               for f in engine.findings(misplaced.ctl, misplaced.store) if f.rule.id == "AL401")
    store = FactStore()
    store.add("node", "/a", "pkg", "a", "e1")
    store.locate("e1", "a.launch", 3)
    store.add("publisher", "p1", "/a", "/x", "std_msgs/String")
    assert "location" not in engine.start(store).loaded


def test_a_relation_only_a_query_names_is_queryable() -> None:
    store = corpus_store("misplaced_remap")
    session = Session(store, load_rules([]))
    assert "name_namespace" not in session.grounded.loaded and store.count("name_namespace")
    rows = session.query("name_namespace(T, NS)").rows  # the whole relation, read from the store
    assert rows == store.rows("name_namespace") and "name_namespace" not in session.grounded.loaded
    joined = session.query('name_namespace(T, NS), subscriber(_, _, T, _), NS != "/"').rows
    assert joined and all(row[1] != "/" for row in joined)
    counts = {name: count for name, _arity, count, kind in session.relations() if kind == "fact"}
    assert counts["name_namespace"] == store.count("name_namespace")


def test_rules_defined_on_the_fly_and_explanations_load_what_they_read() -> None:
    store = corpus_store("include_missing_remap")
    session = Session(store, load_rules([]))
    assert "included_through" not in session.grounded.loaded
    rule = HEADER.replace("USR9", "USR8").replace("early(topic, port)", "nested(node, elem, include)") \
        .replace("location: port", "location: elem").replace("{topic} is published early", "{node} is included")
    assert session.define(rule + "nested(N, E, F) :- node(N, _, _, E), included_through(E, F, _).\n") == ["nested"]
    expected = {(n, f) for n, _p, _x, e in store.rows("node") for e2, f, _d in store.rows("included_through") if e2 == e}
    assert expected and {(f.values["node"], f.values["include"]) for f in session.findings()
                         if f.rule.id == "USR8"} == expected
    session = Session(store, load_rules([]))
    first = store.rows("node_namespace")[0]
    atom = clingo.Function("node_namespace", [store.term(cell) for cell in first])
    assert session.explain(atom).kind == "fact"


def test_a_user_rule_reading_location_works(tmp_path: Path) -> None:
    path = tmp_path / "early.lp"
    path.write_text(HEADER + "early(T, P) :- publisher(P, _, T, _), location(P, _, L, _), L < 10.\n")
    store = FactStore()
    for port, line in (("p1", 4), ("p2", 40)):
        store.add("publisher", port, "/a", f"/topic{line}", "std_msgs/String")
        store.locate(port, "a.py", line, 1)
    engine = Engine(load_rules([path], builtin=False))
    grounded = engine.start(store)
    assert "location" in grounded.loaded
    assert shown(engine.findings(grounded.ctl, store)) == [("USR9", "a.py", 4, "/topic4 is published early")]


def test_rows_no_join_can_use_are_given_when_a_query_asks() -> None:
    """`remap_used` joins `port_source_name` with `remap` on the remapped name: only the ports whose
    source name a remap names reach clingo, until a query joins the relation (a query of the whole
    relation reads the store's rows)."""
    store = FactStore()
    store.add("node", "/a", "pkg", "a", "e1")
    store.add("publisher", "p1", "/a", "/out", "std_msgs/String")
    store.add("subscriber", "p2", "/a", "/y", "std_msgs/String")
    store.add("port_source_name", "p1", "/out")
    store.add("port_source_name", "p2", "/in")
    store.add("remap", "e2", "/a", "/in", "/y")
    session = Session(store, load_rules([]))
    assert session.grounded.given("port_source_name") == 1
    assert session.query("unused_remap(F, E, T, W)").rows == []  # the remap is used: p2's name is remapped
    assert sorted(session.query("port_source_name(P, F)").rows) == [("p1", "/out"), ("p2", "/in")]  # the store's
    assert session.grounded.given("port_source_name") == 1
    assert session.query("port_source_name(P, F), publisher(P, _, _, _)").rows == [("p1", "/out")]
    assert session.grounded.given("port_source_name") == 2


def test_rule_files_with_other_statements_are_grounded_with_every_fact(tmp_path: Path) -> None:
    """A `#const` (or `#show`) is grounded as written, in one program with every fact."""
    path = tmp_path / "early.lp"
    path.write_text(HEADER + "#const limit = 10.\nearly(T, P) :- publisher(P, _, T, _), location(P, _, L, _), L < limit.\n")
    store = FactStore()
    store.add("publisher", "p1", "/a", "/topic4", "std_msgs/String")
    store.locate("p1", "a.py", 4, 1)
    store.add("name_namespace", "/topic4", "/")
    engine = Engine(load_rules([path], builtin=False))
    grounded = engine.start(store)
    assert {"location", "name_namespace"} <= grounded.loaded
    assert shown(engine.findings(grounded.ctl, store)) == [("USR9", "a.py", 4, "/topic4 is published early")]


def test_a_whole_fact_relation_reads_as_clingo_holds_it() -> None:
    """clingo cuts a string at a NUL character: the store's rows are read back the same way."""
    store = FactStore()
    for name in ("/a\0b", "/a", "/c\0d", "/c\0e"):
        store.add("name_namespace", name, "/")
    session = Session(store, load_rules([]))
    whole = session.query("name_namespace(T, NS)").rows
    assert whole == [("/a", "/"), ("/c", "/")]
    assert sorted(session.query('name_namespace(T, NS), NS = "/"').rows) == whole  # given to clingo


def every_atom(engine: Engine, store: FactStore) -> set[str]:
    ctl = clingo.Control(["--warn=none"])
    ctl.add("base", [], engine.declared + "\n".join(p.text for p in engine.ruleset.programs) + store.program())
    ctl.ground([("base", [])], context=FUNCTIONS)
    return {str(a.symbol) for a in ctl.symbolic_atoms if a.symbol.name not in BY_NAME}


def _nodes_a_b_c_c() -> FactStore:
    store = FactStore()
    for name, elem, source in (("/a", "e1", "cpp"), ("/b", "e2", None), ("/c", "e3", "model"), ("/c", "e4", "model")):
        store.add("node", name, "pkg", name[1:], elem)
        store.locate(elem, "a.launch", int(elem[1:]))
        if source:
            store.add("node_source", name, source)
    store.add("publisher", "p1", "/a", "/x", "std_msgs/String")
    return store


def test_rows_a_negated_fact_rules_out_are_not_given() -> None:
    """`opaque_node(N) :- node(N, ...), not node_source(N, _)` needs only the nodes without a source
    (the rules without AL301, which reads every named node once). Every derived atom is that of
    grounding every fact."""
    store = _nodes_a_b_c_c()
    every = load_rules([])
    engine = Engine(RuleSet([r for r in every.rules if r.id != "AL301"],
                            [p for p in every.programs if not Path(p.file).name.startswith("AL301")]))
    grounded = engine.start(store)
    assert grounded.given("node") == 1  # /b
    grounded.load(list(grounded.later))
    atoms = {str(a.symbol) for a in grounded.ctl.symbolic_atoms if a.symbol.name not in BY_NAME}
    assert 'opaque_node("/b")' in atoms and atoms == every_atom(engine, store)


def test_each_later_node_of_a_name_is_paired_with_the_first_only() -> None:
    """AL301 pairs each later instance of a name with the first one (n - 1 findings, and no
    grounding of every pair: 4,096 instances of one name would be 8 million pairs)."""
    store = _nodes_a_b_c_c()
    engine = Engine(load_rules([]))
    grounded = engine.start(store)
    grounded.load(list(grounded.later))
    atoms = {str(a.symbol) for a in grounded.ctl.symbolic_atoms if a.symbol.name not in BY_NAME}
    assert 'duplicate_node("/c","e4","e3","a second node with the same name shuts the first one down")' in atoms
    assert not [a for a in atoms if a.startswith('duplicate_node("/a"') or a.startswith('duplicate_node("/b"')]
    assert atoms == every_atom(engine, store)


def test_a_negated_fact_gets_the_rows_other_rules_give_its_positive_atom() -> None:
    """AL301 gives clingo both rows of the twice-named /c; the opaque_node rule then sees them too,
    so the node_source rows of /c must be there for its `not`."""
    store = FactStore()
    for elem in ("e1", "e2"):
        store.add("node", "/c", "pkg", "c", elem)
        store.locate(elem, "a.launch", int(elem[1:]))
    store.add("node_source", "/c", "model")
    engine = Engine(load_rules([]))
    grounded = engine.start(store)
    assert grounded.given("node_source") == 1
    assert not any(True for _ in grounded.ctl.symbolic_atoms.by_signature("opaque_node", 1))


def incomplete_store(opaque: int) -> FactStore:
    """`opaque` incomplete nodes and one complete one, each with a publisher of msgs/T on its own topic."""
    store = FactStore()
    for i in range(opaque + 1):
        node = f"/n{i}"
        store.add("node", node, "pkg", "exe", f"e{i}")
        store.add("node_source", node, "model")
        if i < opaque:
            store.add("node_incomplete", node, "generated")
        store.add("publisher", f"p{i}", node, f"/t{i}", "msgs/T")
    return store


@pytest.mark.parametrize("opaque", [1, 2])
def test_opaque_near_by_type_names_another_opaque_node(opaque: int) -> None:
    """A name of type T is near an opaque node using T other than its port's node: with one opaque
    node, not for that node's own port; with two, for every port."""
    store = incomplete_store(opaque)
    session = Session(store, load_rules([]))
    near = set(session.query("opaque_near(T, N)").rows)
    everyone = {(f"/t{i}", f"/n{i}") for i in range(opaque + 1)}
    assert near == (everyone - {("/t0", "/n0")} if opaque == 1 else everyone)
    assert near == {(t, n) for t, n in everyone for m, t2 in session.query("opaque_may_use(M, T)").rows
                    if t2 == t and m != n}


def test_opaque_may_use_is_grounded_when_named() -> None:
    """No rule reads opaque_may_use (it can hold every name of a type for every opaque node using
    it): it is grounded when a query, a rule defined on the fly or an explanation names it."""
    store = incomplete_store(3)
    engine = Engine(load_rules([]))
    assert "opaque_may_use" in engine.start(store).later
    session = Session(store, load_rules([]))
    assert len(session.query("opaque_may_use(M, T)").rows) == 3 * 4
    assert "opaque_may_use" not in session.grounded.later
    session = Session(store, load_rules([]))
    assert session.query('opaque_may_use("/n0", T), T != "/t0"').rows
    session = Session(store, load_rules([]))
    assert session.explain(clingo.Function("opaque_may_use", [clingo.String("/n0"), clingo.String("/t1")])).kind == \
        "derived"
    session = Session(store, load_rules([]))
    assert ("opaque_may_use", 2) in session.waiting()
    assert "opaque_may_use" not in {name for name, _arity, _count, _kind in session.relations()}  # not grounded
    session.query("opaque_may_use(M, T)")
    assert ("opaque_may_use", "derived", 12) in {(name, kind, count) for name, _a, count, kind in session.relations()}


@pytest.mark.parametrize("fallback", ["no temporary file", "non-ASCII"])
def test_facts_are_parsed_when_they_cannot_be_read_as_a_ground_program(fallback: str,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    """The first stratum's facts reach clingo as a ground program through a temporary file; without
    one, or with a fact that is not ASCII, they are parsed as text, with the same result."""
    store, engine = corpus_store("misplaced_remap"), Engine(load_rules([]))
    if fallback == "non-ASCII":
        store.add("publisher", "p_é", "/nœud", "/caméra", "std_msgs/String")
    else:
        def refuse(*_args: object, **_kwargs: object) -> None:
            raise OSError("read-only")
        monkeypatch.setattr("archlog.rules.loading.tempfile.NamedTemporaryFile", refuse)
    grounded = engine.start(store)
    grounded.load(list(grounded.later))
    assert {str(a.symbol) for a in grounded.ctl.symbolic_atoms if a.symbol.name not in BY_NAME} == \
        every_atom(engine, store)
    assert shown(engine.findings(grounded.ctl, store)) == shown(every_fact(engine, store))


def test_a_negated_atom_with_a_computed_argument_filters_nothing() -> None:
    """`not near_name(B, A, D + 1)` is false only for that distance: the rows of near_name are not
    filtered by the other rows of the pair, whatever their distance."""
    store = FactStore()
    store.add("near_name", "/a", "/b", 1)
    store.add("near_name", "/b", "/a", 5)
    text = "odd(A) :- near_name(A, B, D), not near_name(B, A, D + 1).\n"
    grounded = loading.ground(store, loading.reads_of([text]) or [], "", set(), {"odd"})
    assert sorted(str(a.symbol) for a in grounded.ctl.symbolic_atoms if a.symbol.name == "odd") == \
        ['odd("/a")', 'odd("/b")']
