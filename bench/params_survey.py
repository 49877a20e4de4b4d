"""Survey of the parameter rules (AL403-AL406) on real configurations: how many parameters a configuration
sets, how many reach a node whose parameter names archlog knows completely (the only ones AL403 judges),
how many have a declared type or bounds to check a value against, and every finding of the four rules.

    python bench/params_survey.py PATH... --launch FILE [--launch FILE...] [--arg NAME:=VALUE...] [--env NAME=VALUE...]

One configuration per run (the launch files together, as `archlog check`); prints a summary and each
finding (rule, file:line, message) so a reviewer can give each one a verdict.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from archlog.analysis import analyse  # noqa: E402
from archlog.rules.engine import Engine  # noqa: E402
from archlog.rules.ruleset import load_rules  # noqa: E402

RULES = ("AL403", "AL404", "AL405", "AL406")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--launch", action="append", default=[])
    parser.add_argument("--arg", action="append", default=[])
    parser.add_argument("--env", action="append", default=[], help="NAME=VALUE a launch file may read")
    options = parser.parse_args()
    args = dict(a.split(":=", 1) for a in options.arg)
    env = dict(e.split("=", 1) for e in options.env)
    clock = time.perf_counter()
    analysis = analyse(options.paths, options.launch, args, [], env=env)
    ctl, findings = Engine(load_rules([])).run(analysis.store)
    store = analysis.store
    unknown = {str(a.symbol.arguments[0].string) for a in ctl.symbolic_atoms.by_signature("params_unknown", 1)
               if a.symbol.arguments[0].type.name == "String"}
    nodes = {str(row[0]) for row in store.rows("node")}
    set_for = list(store.rows("param_of"))
    judged = [row for row in set_for if str(row[1]) not in unknown]
    typed_ports = {str(row[0]) for row in store.rows("param_type")}
    bounded_ports = {str(row[0]) for row in store.rows("param_bound")} | {str(row[0]) for row in store.rows("param_choice")}
    print(f"configuration: {' '.join(options.launch)} {' '.join(options.arg)} {' '.join(options.env)}")
    print(f"  parameters set: {len(list(store.rows('param')))} ({len(set_for)} for a node instance, "
          f"{len(judged)} for a node whose parameter names are all known)")
    print(f"  nodes: {len(nodes)}, parameter names all known: {len(nodes - unknown)}; "
          f"declarations: {len(list(store.rows('param_read')))}, typed: {len(typed_ports)}, bounded: {len(bounded_ports)}, "
          f"required: {len(list(store.rows('param_required')))}; places setting unknown parameters: "
          f"{len(list(store.rows('param_set_unknown')))}")
    dynamic = {str(row[0]) for row in store.rows("params_dynamic")}
    typed = {(str(row[1]), str(row[2])) for row in store.rows("param_read") if str(row[0]) in typed_ports}
    checked = [row for row in set_for if str(row[1]) not in dynamic and (str(row[1]), str(row[0])) in typed]
    print(f"  values whose type AL404 checks against a declaration: {len(checked)}; nodes with dynamic parameters: "
          f"{len(dynamic)}")
    ours = [f for f in findings if f.rule.id in RULES]
    print(f"  findings of {', '.join(RULES)}: {len(ours)}; all findings: {len(findings)}; "
          f"{time.perf_counter() - clock:.0f} s")
    for finding in ours:
        print(f"  {finding.rule.id} {finding.location.file}:{finding.location.line} {finding.message}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
