"""Behavior fingerprint: every fact, finding and diagnostic of every corpus system, as one JSON file.

    python bench/fingerprint.py OUT.json [--compare BEFORE.json] [--systems corpus/ros1/CASE/buggy ...]

Run before and after a change that must not change behavior (a refactoring): the two files are
equal when nothing changed; `--compare` prints the systems and relations that differ.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from archlog.analysis import analyse
from archlog.facts.schema import BY_NAME
from archlog.rules.engine import Engine, render
from archlog.rules.ruleset import load_rules

ROOT = Path(__file__).resolve().parent.parent


def system(variant: Path) -> dict[str, list]:
    case = json.loads((variant / "case.json").read_text())
    analysis = analyse([variant], case.get("launch", []), case.get("args", {}),
                       [variant / m for m in case.get("models", [])])
    store = analysis.store
    _ctl, findings = Engine(load_rules([])).run(store)
    result: dict[str, list] = {
        relation: sorted(json.dumps([store.plain(c) for c in row]) for row in store.rows(relation))
        for relation in sorted(BY_NAME)}
    result["findings"] = sorted(f"{f.rule.id} {f.location.file}:{f.location.line}:{f.location.column} "
                                f"{render(next(iter(f.values.values())))}: {f.message}" for f in findings)
    result["diagnostics"] = sorted(str(d) for d in analysis.diagnostics.items)
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output", type=Path)
    parser.add_argument("--compare", type=Path, help="a fingerprint to compare with")
    parser.add_argument("--systems", nargs="+", type=Path, help="only these systems (corpus/ros1/topic_typo/buggy...)")
    options = parser.parse_args()
    variants = [ROOT / v for v in options.systems] if options.systems else \
        sorted(p.parent for p in (ROOT / "corpus").glob("*/*/*/case.json"))
    prints = {str(v.relative_to(ROOT)): system(v) for v in variants}
    options.output.write_text(json.dumps(prints, indent=1, sort_keys=True))
    print(f"{len(prints)} systems, {sum(len(rows) for p in prints.values() for rows in p.values())} rows")
    if options.compare:
        before = json.loads(options.compare.read_text())
        differ = [(name, key) for name in sorted(set(before) | set(prints))
                  for key in sorted(set(before.get(name, {})) | set(prints.get(name, {})))
                  if before.get(name, {}).get(key) != prints.get(name, {}).get(key)]
        for name, key in differ:
            print(f"differs: {name} {key}")
        print("identical" if not differ else f"{len(differ)} differences")
        sys.exit(1 if differ else 0)


if __name__ == "__main__":
    main()
