"""The REPL driven as a person would: in a pseudo-terminal, typing queries and commands."""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

import pexpect
import pytest
from conftest import CORPUS, ROOT

ANSI = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]|\r")
WORKSPACE = CORPUS / "topic_typo" / "buggy"
LAUNCH = "waypoint_nav/launch/follow_waypoints.launch"


@pytest.fixture
def repl(tmp_path: Path):
    env = dict(os.environ, NO_COLOR="1", TERM="xterm", PROMPT_TOOLKIT_NO_CPR="1")
    child = pexpect.spawn(sys.executable, ["-m", "archlog", "repl", str(WORKSPACE), "--launch", LAUNCH], env=env,
                          cwd=str(ROOT), encoding="utf-8", timeout=60, dimensions=(60, 200))
    child.expect("lists the commands")
    yield child
    child.sendline(":quit")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0


def screen(child: pexpect.spawn) -> str:
    return ANSI.sub("", child.before or "")


def test_queries_commands_and_explanations(repl: pexpect.spawn, tmp_path: Path) -> None:
    repl.sendline(":relations")
    repl.expect(r"subscriber\s*\S*\s*4\s*\S*\s*\d+\s*\S*\s*fact")
    repl.expect(r"opaque_may_use\s*\S*\s*2\s*\S*\s*when queried")  # no rule reads it: grounded when named
    repl.sendline("subscriber(_, N, T, _),")  # an open line continues
    repl.expect(r"\.\.\.>")
    repl.sendline("not published(T)")
    repl.expect("1 result")
    assert "/rover/pure_pursuit" in screen(repl) and "/rover/base_waypoint" in screen(repl)
    repl.sendline(":findings")
    repl.expect("1 finding")
    assert "1. AL102 src/waypoint_nav/src/pure_pursuit.cpp:45" in screen(repl)
    repl.sendline(":explain 1")
    repl.expect(r"near_name\(.*\(fact\)")
    text = screen(repl)
    assert "by " in text and "AL102_near_miss_topic.lp" in text and "src/waypoint_nav/src/pure_pursuit.cpp:45" in text
    repl.sendline(":explain --json 1")
    repl.expect(r'"because"')
    repl.sendline('many_pubs(T) :- publisher(_, N, T, _), publisher(_, M, T, _), N != M.')
    repl.expect("defined: many_pubs")
    repl.sendline(":time")
    repl.expect("timing on")
    repl.sendline("publisher(P, N, T, Ty)")
    repl.expect(r"(\d+) results in ([\d.]+) ms")
    export = tmp_path / "pubs.csv"
    repl.sendline(f":export {export}")
    repl.expect("wrote")
    assert export.read_text().startswith("P,N,T,Ty\n")
    repl.sendline(":disable AL102")
    repl.expect("disabled AL102")
    repl.sendline(":findings")
    repl.expect("0 findings")
    repl.sendline("nope(X)")
    repl.expect("unknown relation nope/1")


def test_ctrl_c_cancels_the_line_or_the_query_and_keeps_the_session(repl: pexpect.spawn) -> None:
    repl.sendline("fan_in(T, C) :- subscribed(T), C = #count { N : publisher(_, N, T, _) }.")
    repl.expect("defined: fan_in")
    repl.send("subscriber(_, N,")  # a partial line, then Ctrl-C
    repl.sendintr()
    repl.expect("interrupted")
    repl.sendline("subscriber(_, N, T, _),")  # a partial input over two lines, then Ctrl-C
    repl.expect(r"\.\.\.>")
    repl.sendintr()
    repl.expect("interrupted")
    repl.sendline("location(A, _, _, _), location(B, _, _, _), location(C, _, _, _), location(D, _, _, _)")
    repl.expect(r"p\d{5}")
    repl.sendintr()
    repl.expect("interrupted")
    repl.sendline("fan_in(T, C)")  # the rule defined before survives, and so does the grounded state
    repl.expect(r"(\d+) results?")
    assert "/rover/base_waypoint" in screen(repl) and "/rover/odom" in screen(repl)


def test_explain_parses_atoms_and_shows_not_conditions(repl: pexpect.spawn) -> None:
    repl.sendline(':explain subscribed("/rover/odom")')
    repl.expect(r"subscriber\(.*\(fact\)")
    text = screen(repl)
    assert 'subscribed("/rover/odom")  (by ' in text and "prelude.lp" in text
    repl.sendline(':explain dangling_sub("p00014", "/rover/pure_pursuit", "/rover/base_waypoint", "nav_msgs/Path")')
    repl.expect(r"optional_input.*\(none exists\)")
    text = screen(repl)
    assert 'not published("/rover/base_waypoint")  (none exists)' in text
    assert re.search(r'dangling_sub\(.*\)  \(by .*prelude\.lp:\d+\)', text)  # derived, not labelled a fact
    repl.sendline(':explain subscribed("/nowhere")')
    repl.expect(r'subscribed\("/nowhere"\)  \(does not hold\)')
    repl.sendline(":explain subscribed(")
    repl.expect("explain a finding number or an atom")
