"""Rule files: metadata, user rules loaded like shipped ones, and errors with file:line:column."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from archlog.facts.store import FactStore
from archlog.rules.engine import Engine
from archlog.rules.ruleset import RuleError, load_rules
from archlog.values import Unknown

HEADER = """%! id: {id}
%! name: test-rule
%! severity: warning
%! summary: test
%! finding: {finding}
%! location: {location}
%! message: "{message}"
"""


def rule_file(tmp_path: Path, body: str, finding: str = "hit(topic, port)", location: str = "port",
              message: str = "{topic}", rule_id: str = "USR1") -> Path:
    path = tmp_path / "user.lp"
    path.write_text(HEADER.format(id=rule_id, finding=finding, location=location, message=message) + body)
    return path


def small_store() -> FactStore:
    store = FactStore()
    for pid, node, topic in (("p1", "/a", "/x"), ("p2", "/b", "/x"), ("p3", "/c", "/y")):
        store.add("publisher", pid, node, topic, "std_msgs/String")
        store.locate(pid, f"{node[1:]}.py", 3, 5)
    store.add("subscriber", "p4", "/d", Unknown("f()", "d.py", 9), "std_msgs/String")
    return store


def test_user_rule_reuses_shipped_relations(tmp_path: Path) -> None:
    path = rule_file(tmp_path, "hit(T, P) :- publisher(P, N, T, _), publisher(Q, M, T, _), N != M, published(T).\n",
                     message="{topic} has several publishers")
    _ctl, findings = Engine(load_rules([path])).run(small_store())
    user = [f for f in findings if f.rule.id == "USR1"]
    assert [(f.message, f.location.file, f.location.line, f.location.column) for f in user] == [
        ("/x has several publishers", "a.py", 3, 5), ("/x has several publishers", "b.py", 3, 5)]
    assert user[0].subjects == {"topics": ["/x"]}


def test_unknown_values_never_join(tmp_path: Path) -> None:
    path = rule_file(tmp_path, "hit(T, P) :- subscriber(P, _, T, _), published(T).\n")
    _ctl, findings = Engine(load_rules([path])).run(small_store())
    assert [f for f in findings if f.rule.id == "USR1"] == []


def test_an_unsure_list_not_empty_makes_the_finding_a_note(tmp_path: Path) -> None:
    path = rule_file(tmp_path, "hit(T, P) :- publisher(P, _, T, _).\nblind(P, \"/c\") :- publisher(P, \"/a\", _, _).\n",
                     message="{topic}{unseen}")
    path.write_text(path.read_text().replace('%! message:', '%! lists: {unseen: {of: blind(port), text: " unless {}"}}\n'
                                             '%! unsure: [unseen]\n%! message:'))
    _ctl, findings = Engine(load_rules([path])).run(small_store())
    assert sorted((f.message, f.severity) for f in findings if f.rule.id == "USR1") == [
        ("/x", "warning"), ("/x unless /c", "note"), ("/y", "warning")]
    for finding in findings:  # a configured severity (archlog.toml [severity]) is the rule's; unsure stays a note
        finding.rule = replace(finding.rule, severity="error")
    assert sorted((f.tag, f.severity) for f in findings if f.rule.id == "USR1") == [
        ("USR1", "error"), ("USR1", "error"), ("USR1 [note]", "note")]


@pytest.mark.parametrize("body, line, column, words", [
    ("hit(T, P) :- publisher(P, _, T _).\n", 8, 32, "syntax error"),
    ("hit(T, P) :- publisher(P, _, T, _), not subscriber(Q, _, X, _).\n", 8, 52, "unsafe variables Q, X"),
    ("hit(T, P) :- publisher(P, _, T, _), no_such_relation(T).\n", 8, 37, "unknown relation no_such_relation/1"),
    ("hit(T, P) :- publisher(P, _, T, _), subscribd(T).\n", 8, 37, "(hint: did you mean subscribed/1?)"),
    ("hit(T, P) :- publisher(P, _, T, _), @parnt(T) = \"/\".\n", 8, 37, "unknown function @parnt (hint: did you "
     "mean @parent?"),
    ("hit(T, N) :- publisher(_, N, T, _).\n", 6, 1, "location column 'port' holds a name, which has no file"),
    ("hit(T, P) :- publisher(P, T).\n", 8, 14, "publisher takes 4 columns, not 2"),
    ("other(T, P) :- publisher(P, _, T, _).\n", 5, 1, "no rule derives the finding hit/2"),
    ("hit(T, P) :- publisher(P, _, T, _).\npublisher(T) :- hit(T, _).\n", 9, 1, "fact relation"),
])
def test_rule_errors_point_at_file_line_column(tmp_path: Path, body: str, line: int, column: int, words: str) -> None:
    path = rule_file(tmp_path, body)
    with pytest.raises(RuleError) as err:
        Engine(load_rules([path]))
    assert (err.value.file, err.value.line, err.value.column) == (str(path), line, column)
    assert words in err.value.message
    assert "#" not in err.value.message and "error:" not in err.value.message  # no clingo internals, no error: error:


def test_non_stratified_rules_are_rejected(tmp_path: Path) -> None:
    path = rule_file(tmp_path, "hit(T, P) :- publisher(P, _, T, _), not skip(T).\n"
                               "skip(T) :- publisher(_, _, T, _), not hit(T, _).\n")
    with pytest.raises(RuleError) as err:
        Engine(load_rules([path])).run(small_store())
    assert "not stratified" in err.value.message and err.value.file == str(path)


@pytest.mark.parametrize("change, line, words", [
    (("%! severity: warning", "%! severity: fatal"), 3, "severity must be one of"),
    (("%! location: port", "%! location: nowhere"), 6, "location column 'nowhere'"),
    (('%! message: "{topic}"', '%! message: "{missing}"'), 7, "unknown column"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! related: [elsewhere]'), 8, "location column 'elsewhere'"),
    (("%! finding: hit(topic, port)", "%! finding: hit"), 5, "`finding` must look like"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! precision: great'), 8, "precision must be one of"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! tags: topics'), 8, "`tags` must be a list"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! lists: {l: nope}'), 8, "list 'l' must look like"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! lists: {l: {of: hit(port)}}'), 8, "as a mapping must be"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! lists: {l: {of: hit(port), text: no list}}'), 8,
     "as a mapping must be"),
    (('%! message: "{topic}"', '%! message: "{topic}"\n%! unsure: [gone]'), 8, "`unsure` must be a list of the rule's"),
    (("%! summary: test\n", ""), 1, "metadata lacks summary"),
    (("%! summary: test\n", "%! summary: test\n%! sumary: typo\n"), 5, "unknown metadata key 'sumary'"),
    (("%! summary: test\n", "%! summary: test\n%! description: |\n%!   two\n%!   lines\n%! helps: x\n"), 8,
     "unknown metadata key 'helps'"),
    (("%! summary: test\n", "%! summary: test\n%! summary: again\n"), 5, "given twice (first on line 4)"),
    (("%! summary: test\n", "%! summary: [test\n"), 5, "not valid YAML: expected ',' or ']'"),
    (('%! message: "{topic}"', '%! message: "{topic}'), 7, "not valid YAML: found unexpected end of stream"),
])
def test_bad_metadata_is_reported_at_the_line_of_its_key(tmp_path: Path, change: tuple[str, str], line: int,
                                                          words: str) -> None:
    path = rule_file(tmp_path, "hit(T, P) :- publisher(P, _, T, _).\n")
    path.write_text(path.read_text().replace(*change))
    with pytest.raises(RuleError) as err:
        load_rules([path])
    assert words in err.value.message and (err.value.file, err.value.line) == (str(path), line)
    assert "\n" not in str(err.value) and "unicode string" not in str(err.value)


def test_header_errors_of_a_second_rule_point_into_it(tmp_path: Path) -> None:
    """Lines count from the top of the file, not from the header of the rule."""
    first = rule_file(tmp_path, "hit(T, P) :- publisher(P, _, T, _).\n").read_text()
    second = first.replace("USR1", "USR2").replace("hit", "hot").replace("%! severity: warning", "%! severity: loud")
    path = tmp_path / "two.lp"
    path.write_text(first + second)
    with pytest.raises(RuleError) as err:
        load_rules([path])
    assert (err.value.line, "severity must be one of" in err.value.message) == (8 + 3, True)
    path.write_text(first + first)
    with pytest.raises(RuleError) as err:
        load_rules([path])
    assert (err.value.line, "defined twice" in err.value.message) == (8 + 1, True)


def test_every_metadata_key_is_documented() -> None:
    from archlog.rules.ruleset import KEYS

    guide = (Path(__file__).resolve().parent.parent / "docs" / "writing-rules.md").read_text()
    header = guide[guide.index("## The metadata header"):guide.index("## Five worked rules")]
    assert [k for k in KEYS if f"%! {k}:" not in header] == []


def test_shipped_rules_have_complete_metadata() -> None:
    rules = load_rules([]).rules
    assert len(rules) >= 8 and len({r.id for r in rules}) == len(rules)
    for rule in rules:
        assert rule.description and rule.help and rule.tags and rule.summary
