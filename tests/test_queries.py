"""Queries, rules and fixtures as a rule writer uses them: unknown values, functions, namespaces,
streaming results, explanations, and test-rules errors."""

from __future__ import annotations

import io
import json
import subprocess
import sys
from pathlib import Path

import clingo
import pytest
from conftest import CORPUS, CORPUS_BEHAVIOR, ROOT, load_case

from archlog.analysis import analyse
from archlog.facts.namespaces import add_namespaces
from archlog.facts.store import FactStore
from archlog.queries.session import QueryError, Session
from archlog.queries.table import PAGE, print_result, write_table
from archlog.rules.ruleset import load_rules
from archlog.values import Unknown


def archlog(*args: str | Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=ROOT, timeout=300)


def store_with_unknowns() -> FactStore:
    store = FactStore()
    store.add("node", "/robot1/base", "pkg", "base", "e1")
    store.add("param_read", "p1", "/robot1/base", "/robot1/base/rate", Unknown("no default", "base.py", 4))
    store.add("param_read", "p2", "/robot1/base", "/robot1/base/frame", Unknown("a default", "base.py", 5))
    store.add("param_read", "p3", "/robot1/base", "/speed", "1.0")
    store.add("subscriber", "p4", "/robot1/base", Unknown("topic + '/x'", "base.py", 7), "std_msgs/String")
    store.add("param", "/robot1/base/rate", "10", "e2")
    store.add("param", "/use_sim_time", "true", "e3")
    return store


def test_unknowns_sort_after_strings_and_are_written_one_way(tmp_path: Path) -> None:
    session = Session(store_with_unknowns(), load_rules([]))
    result = session.query("unknown_value(U, E, F, L)")
    assert [row[1] for row in result.sorted_rows()] == ["a default", "no default", "topic + '/x'"]
    mixed = session.query("param_read(_, _, _, D)").sorted_rows()  # strings before unknowns in one column
    assert [str(row[0]) for row in mixed] == ["1.0", "?(a default)", "?(no default)"]
    out = io.StringIO()
    print_result(session.query("param_read(P, N, X, D)"), "csv", out)
    assert "p1,/robot1/base,/robot1/base/rate,?(no default)" in out.getvalue()
    out = io.StringIO()
    print_result(session.query("param_read(P, _, _, D)"), "json", out)
    assert {"P": "p2", "D": "?(a default)"} in json.loads(out.getvalue())
    store_with_unknowns().export(tmp_path, "csv")
    assert "?(topic + '/x')" in (tmp_path / "subscriber.csv").read_text()
    store_with_unknowns().export(tmp_path, "json")
    assert json.loads((tmp_path / "param_read.json").read_text())[0]["default"] == "?(no default)"
    tree = session.explain(clingo.parse_term('param_read("p1", "/robot1/base", "/robot1/base/rate", unknown(1))'))
    assert tree.atom == 'param_read("p1", "/robot1/base", "/robot1/base/rate", ?(no default))'


def test_the_query_command_sorts_unknown_values() -> None:
    """`archlog query` on a system with several unknown values (it used to end in a TypeError)."""
    variant = CORPUS_BEHAVIOR / "wait_first_pose" / "buggy"
    launch = [a for f in load_case(variant)["launch"] for a in ("--launch", f)]
    result = archlog("query", variant, *launch, "unknown_value(U, E, F, L)")
    assert result.returncode == 0, result.stderr
    assert "?(" in result.stdout and "internal error" not in result.stderr


def test_functions_on_names() -> None:
    session = Session(FactStore(), load_rules([]))

    def value(expr: str) -> list[str]:
        return [str(row[0]) for row in session.query(f"X = {expr}").rows]

    assert value('@parent("/a/b/c")') == ["/a/b"] and value('@parent("/c")') == ["/"] and value('@parent("/")') == []
    assert value('@basename("/a/b/c")') == ["c"] and value('@segments("/a/b/c")') == ["3"]
    assert value('@prefix("/a/b/c", 2)') == ["/a/b"] and value('@suffix("/a/b/c", 2)') == ["b/c"]
    assert value('@prefix("/a", 3)') == [] and value('@prefix(3, 1)') == []  # out of range, not a name
    assert value('@starts_with("/robot1/scan", "/robot")') == ["1"] and value('@ends_with("/a/scan", "x")') == ["0"]
    assert value('@lower("/Robot")') == ["/robot"] and value("@parent(unknown(1))") == []
    misspelled = {'X = @segment("/a")': "unknown function @segment .*did you mean @segments",
                  "publishr(P, N, T, Ty)": "unknown relation publishr/4 .*did you mean publisher/4"}
    for goal, message in misspelled.items():
        with pytest.raises(QueryError, match=message):
            session.query(goal)


def test_namespace_relations() -> None:
    store = store_with_unknowns()
    add_namespaces(store)
    assert store.rows("node_namespace") == [("/robot1/base", "/robot1")]
    assert ("/robot1/base/rate", "/robot1/base") in store.rows("name_namespace")
    assert ("/speed", "/") in store.rows("name_namespace")
    assert dict(store.rows("param_scope")) == {"/robot1/base/frame": "/robot1/base", "/robot1/base/rate": "/robot1/base",
                                               "/speed": "global", "/use_sim_time": "global"}
    variant = CORPUS / "wrong_namespace" / "buggy"
    facts = analyse([variant], load_case(variant)["launch"], {}, []).store
    assert ("/robot1/laser", "/robot1") in facts.rows("node_namespace")
    assert ("/robot1/scan", "/robot1") in facts.rows("name_namespace")
    assert ("/robot1/laser/rate", "/robot1/laser") in facts.rows("param_scope")


def test_results_stream_and_a_new_query_reads_the_rest_first() -> None:
    store = FactStore()
    for i in range(3 * PAGE):
        store.add("publisher", f"p{i:04d}", f"/n{i}", f"/t{i}", "std_msgs/String")
    session = Session(store, load_rules([]))
    first = session.query("publisher(P, N, T, Ty)")
    assert [row for _i, row in zip(range(2), first)] == [("p0000", "/n0", "/t0", "std_msgs/String"),
                                                        ("p0001", "/n1", "/t1", "std_msgs/String")]
    session.query("published(T)")  # grounds more: the first result is read to its end before
    assert len(first.rows) == 3 * PAGE and first.rows[-1][0] == f"p{3 * PAGE - 1:04d}"

    def rows_then_interrupt():
        yield from first.rows[:PAGE + 1]
        raise KeyboardInterrupt

    out = io.StringIO()
    with pytest.raises(KeyboardInterrupt):
        write_table(["P", "N", "T", "Ty"], rows_then_interrupt(), out)
    assert out.getvalue().count("\n") == 2 + PAGE  # the header and the first page were written before


def test_piped_query_tables_keep_their_full_width(tmp_path: Path) -> None:
    variant = CORPUS / "topic_typo" / "buggy"
    result = archlog("query", variant, "--launch", "waypoint_nav/launch/follow_waypoints.launch",
                     "location(P, F, L, C), publisher(P, N, T, Ty)")
    assert result.returncode == 0, result.stderr
    widest = max((line for line in result.stdout.splitlines() if "src/waypoint_nav/" in line), key=len)
    assert len(widest) > 80 and "…" not in result.stdout


def test_explaining_a_behavior_finding_shows_its_rule_and_reasons() -> None:
    variant = CORPUS_BEHAVIOR / "wait_first_pose" / "buggy"
    session = Session(analyse([variant], load_case(variant)["launch"], {}, []).store, load_rules([]))
    finding = next(f for f in session.findings() if f.rule.id == "AL601")
    atom = clingo.Function(finding.rule.predicate,
                           [session.store.term(finding.values[c]) for c in finding.rule.columns])
    tree = session.explain(atom).as_dict()
    rule_file = ROOT / "archlog" / "rules" / "builtin" / "AL601_required_input_unreachable.lp"
    heads = [n for n, line in enumerate(rule_file.read_text().splitlines(), 1) if line.startswith("starved_root(")]
    assert tree["rule"].endswith(tuple(f"{rule_file.name}:{n}" for n in heads))
    reasons = {(c["atom"], c["kind"]) for c in tree["because"]}
    assert any(kind == "derived" and atom.startswith("starved_input(") for atom, kind in reasons)
    assert ('not has_candidate("p00017")', "absent") in reasons  # a `not` condition, shown as such

    def below(node: dict) -> set[tuple[str, str]]:
        return {(node["atom"], node["kind"])} | {pair for child in node["because"] for pair in below(child)}

    assert ('not published("/odom_pose")', "absent") in below(tree)  # why the input is starved, further down


def test_test_rules_reports_bad_fixtures_and_runs_only_the_given_rules(tmp_path: Path) -> None:
    cases = tmp_path / "tests"
    for name, text in (("bad_relation", '{\n "publisher": [],\n "subscribr": []\n}\n'),
                       ("bad_row", '{\n "publisher": [["p1", "/a", "/t"]]\n}\n'),
                       ("bad_json", '{\n "publisher": [["p1" "/a"]]\n}\n')):
        (cases / name).mkdir(parents=True)
        (cases / name / "facts.json").write_text(text)
    result = archlog("test-rules", tmp_path)
    assert result.returncode == 1 and "internal error" not in result.stderr
    assert f"{cases / 'bad_relation' / 'facts.json'}:3: unknown fact relation 'subscribr' (did you mean " \
           "subscriber?)" in result.stdout
    assert f"{cases / 'bad_row' / 'facts.json'}:2: publisher row 1: expected 4" in result.stdout
    assert f"{cases / 'bad_json' / 'facts.json'}:2: not valid JSON" in result.stdout
    for name in ("bad_relation", "bad_row", "bad_json"):
        (cases / name / "facts.json").unlink()
        (cases / name).rmdir()
    (tmp_path / "mine.lp").write_text(
        '%! id: MY1\n%! name: mine\n%! severity: note\n%! summary: s\n%! finding: lonely(topic, pub)\n'
        '%! location: pub\n%! message: "{topic} is published once"\n'
        "lonely(T, P) :- publisher(P, _, T, _), #count { Q : publisher(Q, _, T, _) } = 1.\n")
    (cases / "mine").mkdir()
    (cases / "mine" / "facts.json").write_text(json.dumps({"publisher": [["p1", "/a", "/t", "x/Y"]],
                                                           "service_client": [["p2", "/a", "/srv", "t/T"]],
                                                           "location": [["p1", "a.py", 3, 1], ["p2", "a.py", 4, 1]]}))
    updated = archlog("test-rules", tmp_path, "--update")
    assert updated.returncode == 0
    assert f"wrote {cases / 'mine' / 'findings.expected'} (2 findings)" in updated.stdout  # AL201 and MY1
    assert "1 case, all passed; 1 file written" in updated.stdout
    assert archlog("test-rules", tmp_path, "--only").returncode == 1  # AL201's finding is no longer expected
    only = archlog("test-rules", tmp_path, "--only", "--update")
    assert "(1 finding)" in only.stdout
    assert (cases / "mine" / "findings.expected").read_text() == "MY1 a.py:3 /t: /t is published once\n"


def test_a_rule_defined_in_a_session_names_a_located_column() -> None:
    session = Session(store_with_unknowns(), load_rules([]))
    header = ('%! id: MY2\n%! name: n\n%! severity: note\n%! summary: s\n%! finding: reads(node, port)\n'
              '%! location: {}\n%! message: "{{node}}"\n')
    with pytest.raises(QueryError, match=r"location column 'node' holds a name, .*\(line 6\)"):
        session.define(header.format("node") + "reads(N, P) :- param_read(P, N, _, _).\n")
    assert session.define(header.format("port").replace("MY2", "MY3") + "reads(N, P) :- param_read(P, N, _, _).\n")


def test_test_rules_checks_every_rule_even_without_cases(tmp_path: Path) -> None:
    """`test-rules` loads and checks the folder's rules as `check --rules` does: a rule reading an
    unknown relation fails at its line even with no case; a good rule without cases is "nothing
    tested", never "all passed" (issue 31)."""
    header = '%! id: MY2\n%! name: mine\n%! severity: note\n%! summary: s\n%! finding: lonely(topic, pub)\n' \
             '%! location: pub\n%! message: "{topic}"\n'
    (tmp_path / "mine.lp").write_text(header + "lonely(T, P) :- publishr(P, _, T, _).\n")
    broken = archlog("test-rules", tmp_path)
    assert broken.returncode == 1 and "internal error" not in broken.stderr
    assert f"{tmp_path / 'mine.lp'}:8:" in broken.stdout and "publishr" in broken.stdout
    assert "all passed" not in broken.stdout
    (tmp_path / "mine.lp").write_text(header + "lonely(T, P) :- publisher(P, _, T, _).\n")
    empty = archlog("test-rules", tmp_path)
    assert empty.returncode == 0
    assert "1 rule, 0 cases, nothing tested" in empty.stdout
