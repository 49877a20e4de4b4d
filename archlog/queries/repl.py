"""`archlog repl`: extraction runs once, then queries, rules and explanations interactively."""

from __future__ import annotations

import csv
import json
import os
import shlex
import time
from pathlib import Path

import clingo
from prompt_toolkit import PromptSession
from prompt_toolkit.completion import WordCompleter
from prompt_toolkit.history import FileHistory
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from archlog.analysis import Analysis
from archlog.extract.cpp.cache import cache_dir
from archlog.facts.schema import BY_NAME, DERIVED_BY_NAME
from archlog.queries.session import QueryError, Result, Session
from archlog.queries.table import plural, write_table
from archlog.rules.engine import Finding, render
from archlog.rules.ruleset import RuleError

HELP = """\
Type a goal to query it, e.g.  publisher(P, N, T, _), not subscribed(T)
Type a rule (with :-) to define it, e.g.  fan_in(T, C) :- subscribed(T), C = #count { N : publisher(_, N, T, _) }.
A line with unbalanced parentheses, or ending in ',' or ':-', continues on the next line.
Commands:
  :relations             relations with arity, number of tuples, fact or derived
  :schema REL            columns of a relation
  :rules                 rules with severity and whether they are enabled
  :enable ID | :disable ID
  :findings              findings of the enabled rules, numbered
  :explain N | ATOM      why finding N (or an atom, e.g. subscribed("/scan")) holds; add --json for JSON
  :load FILE             load a rule file
  :time                  show query timing on/off
  :export FILE           write the last result (.csv or .json)
  :help | :quit          (Ctrl-C cancels the line or stops a listing; Ctrl-D ends the session)"""


class Repl:
    def __init__(self, session: Session, analysis: Analysis, console: Console) -> None:
        self.session, self.analysis, self.console = session, analysis, console
        self.timing = False
        self.last: Result | None = None
        self.numbered: list[Finding] = []

    def words(self) -> list[str]:
        """Completion candidates: relations, rule ids, commands, and the names in the facts."""
        names = {str(c) for rows in (self.session.store.rows(r) for r in ("node", "publisher", "subscriber"))
                 for row in rows for c in row[:3] if isinstance(c, str) and c.startswith("/")}
        commands = [":relations", ":schema", ":rules", ":enable", ":disable", ":findings", ":explain", ":load",
                    ":time", ":export", ":help", ":quit"]
        relations = [r[0] for r in self.session.relations()] + [name for name, _arity in self.session.waiting()]
        return sorted(set(relations) | {r.id for r in self.session.ruleset.rules}
                      | {f'"{n}"' for n in names}) + commands

    # -- dispatch -------------------------------------------------------------------------
    def handle(self, text: str) -> bool:
        """Run one input; False to stop."""
        text = text.strip()
        if not text:
            return True
        try:
            if text.startswith(":"):
                return self.command(text)
            if ":-" in text:
                defined = self.session.define(text if text.endswith(".") else text + ".")
                self.console.print(f"defined: {', '.join(defined)}")
            else:
                self.show(self.session.query(text))
        except (QueryError, RuleError) as exc:
            self.console.print(f"[red]error:[/] {escape(str(exc))}")
        return True

    def command(self, text: str) -> bool:
        name, _, rest = text.partition(" ")
        try:  # an atom to explain keeps its quotes
            args = rest.split() if name == ":explain" else shlex.split(rest)
        except ValueError as exc:
            self.console.print(f"[red]error:[/] {escape(str(exc))}")
            return True
        if name in (":quit", ":q", ":exit"):
            return False
        handler = getattr(self, "cmd_" + name[1:], None)
        if handler is None:
            self.console.print(f"[red]unknown command {name}[/] (:help lists them)")
        else:
            handler(args)
        return True

    # -- commands -------------------------------------------------------------------------
    def cmd_help(self, _args: list[str]) -> None:
        self.console.print(HELP, markup=False)

    def cmd_relations(self, _args: list[str]) -> None:
        table = Table("relation", "arity", "tuples", "kind")
        for name, arity, count, kind in self.session.relations():
            table.add_row(name, str(arity), str(count), kind)
        for name, arity in self.session.waiting():
            table.add_row(name, str(arity), "when queried", "derived")
        self.console.print(table)

    def cmd_schema(self, args: list[str]) -> None:
        relation = (BY_NAME.get(args[0]) or DERIVED_BY_NAME.get(args[0])) if args else None
        if relation is None:
            self.console.print("schema of a fact relation: :schema publisher (derived relations: docs/facts.md, or "
                               "their rule file)")
            return
        where = f" (derived in {relation.source})" if relation.source else ""
        self.console.print(f"{relation.name}: {relation.doc}{where}", markup=False)
        for column in relation.columns:
            self.console.print(f"  {column.name} ({column.type}): {column.doc}", markup=False)

    def cmd_rules(self, _args: list[str]) -> None:
        table = Table("id", "name", "severity", "enabled")
        for rule in self.session.ruleset.rules:
            table.add_row(rule.id, rule.name, rule.severity, "no" if rule.id in self.session.disabled else "yes")
        self.console.print(table)

    def cmd_enable(self, args: list[str]) -> None:
        self.session.disabled.difference_update(args)
        self.console.print(f"enabled {', '.join(args)}")

    def cmd_disable(self, args: list[str]) -> None:
        self.session.disabled.update(args)
        self.console.print(f"disabled {', '.join(args)}")

    def cmd_findings(self, _args: list[str]) -> None:
        self.numbered = self.session.findings()
        for number, finding in enumerate(self.numbered, 1):
            loc = finding.location
            self.console.print(f"{number}. {finding.rule.id} {loc.file}:{loc.line} {finding.message}", markup=False)
        self.console.print(f"{len(self.numbered)} finding{'s' if len(self.numbered) != 1 else ''}")

    def cmd_explain(self, args: list[str]) -> None:
        as_json = "--json" in args
        target = " ".join(a for a in args if a != "--json")
        if target.isdigit():
            self.numbered = self.numbered or self.session.findings()
            index = int(target) - 1
            if not 0 <= index < len(self.numbered):
                self.console.print(f"no finding {target} (:findings lists them)")
                return
            finding = self.numbered[index]
            terms = [self.session.store.term(finding.values[column]) for column in finding.rule.columns]
            atom = clingo.Function(finding.rule.predicate, terms)
        else:
            try:
                atom = clingo.parse_term(target.rstrip("."))
            except RuntimeError:
                self.console.print('explain a finding number or an atom such as subscribed("/scan")', markup=False)
                return
        tree = self.session.explain(atom)
        if as_json:
            self.console.print_json(json.dumps(tree.as_dict()))
        else:
            self.console.print("\n".join(tree.lines()), markup=False)

    def cmd_load(self, args: list[str]) -> None:
        for path in map(Path, args):
            try:
                defined = self.session.define(path.read_text(encoding="utf-8"), str(path))
            except OSError as exc:
                self.console.print(f"[red]error:[/] cannot read {path}: {exc.strerror}")
                continue
            self.console.print(f"loaded {path}: {', '.join(defined)}")

    def cmd_time(self, _args: list[str]) -> None:
        self.timing = not self.timing
        self.console.print(f"timing {'on' if self.timing else 'off'}")

    def cmd_export(self, args: list[str]) -> None:
        if self.last is None or not args:
            self.console.print("run a query first, then :export FILE.csv or FILE.json")
            return
        path = Path(args[0])
        rows = [list(map(render, row)) for row in self.last.rows]
        if path.suffix == ".json":
            path.write_text(json.dumps([dict(zip(self.last.columns, row)) for row in rows], indent=1) + "\n")
        else:
            with path.open("w", newline="") as fh:
                csv.writer(fh).writerows([self.last.columns, *rows])
        self.console.print(f"wrote {len(rows)} rows to {path}")

    def show(self, result: Result) -> None:
        """Rows as they are read, a page at a time (Ctrl-C stops the listing, not the session)."""
        self.last = result
        start = time.perf_counter()
        if result.columns:
            try:
                summary = plural(write_table(result.columns, result, self.console.file))
            except KeyboardInterrupt:
                self.console.print("interrupted")
                return
        else:
            summary = "true" if result.rows else "false"
        took = result.seconds + time.perf_counter() - start
        self.console.print(summary + (f" in {took * 1000:.1f} ms (grounded in {result.seconds * 1000:.1f} ms)"
                                      if self.timing else ""))


def complete_input(lines: list[str]) -> bool:
    """Whether the text typed so far is a whole input: a :command, or a goal or rule with balanced
    parentheses that does not end in ',' or ':-'."""
    text = "\n".join(lines).strip()
    return text.startswith(":") or text.count("(") <= text.count(")") and not text.endswith((",", ":-", ";"))


def run_repl(session: Session, analysis: Analysis) -> None:
    console = Console(no_color=bool(os.environ.get("NO_COLOR")), soft_wrap=True, highlight=False)
    repl = Repl(session, analysis, console)
    prompt: PromptSession[str] = PromptSession(history=FileHistory(str(cache_dir() / "repl_history")),
                           completer=WordCompleter(repl.words(), WORD=True))
    facts = sum(count for _n, _a, count, kind in session.relations() if kind == "fact")
    findings = len(session.findings())
    console.print(f"archlog repl: {len(analysis.config.nodes)} nodes, {facts} facts, {findings} finding"
                  f"{'s' if findings != 1 else ''}. :help lists the commands.", highlight=False)
    while True:
        lines: list[str] = []
        try:
            while True:
                lines.append(prompt.prompt("archlog> " if not lines else "     ...> "))
                if complete_input(lines):
                    break
            if not repl.handle("\n".join(lines)):
                break
        except KeyboardInterrupt:  # Ctrl-C cancels the line being typed or the running input
            console.print("interrupted (Ctrl-D or :quit ends the session)")
        except EOFError:
            break
