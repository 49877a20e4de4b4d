"""The fact store: rows per relation, unknown values, export to CSV/JSON and to clingo."""

from __future__ import annotations

import csv
import json
from collections import defaultdict
from pathlib import Path

import clingo

from archlog.facts.schema import BY_NAME, RELATIONS
from archlog.values import Unknown

Cell = str | int | Unknown


class FactStore:
    """Rows of every relation in `archlog.facts.schema`, checked against their arity."""

    def __init__(self) -> None:
        self._rows: dict[str, list[tuple[Cell, ...]]] = defaultdict(list)
        self._seen: set[tuple[str, tuple[Cell, ...]]] = set()
        self._unknowns: dict[Unknown, int] = {}
        self._counters: dict[str, int] = defaultdict(int)

    def new_id(self, prefix: str) -> str:
        """A fresh id such as 'p1' (ports) or 'e1' (elements)."""
        self._counters[prefix] += 1
        return f"{prefix}{self._counters[prefix]}"

    def add(self, relation: str, *row: Cell) -> None:
        rel = BY_NAME[relation]
        if len(row) != rel.arity:
            raise ValueError(f"{relation} takes {rel.arity} columns, got {len(row)}")
        key = (relation, row)
        if key in self._seen:
            return
        self._seen.add(key)
        self._rows[relation].append(row)
        for cell in row:
            if isinstance(cell, Unknown) and cell not in self._unknowns:
                self._unknowns[cell] = len(self._unknowns) + 1
                self.add("unknown_value", cell, cell.expr, cell.file, cell.line)

    def rows(self, relation: str) -> list[tuple[Cell, ...]]:
        return list(self._rows.get(relation, ()))

    def locate(self, ident: str, file: str, line: int, column: int = 0) -> None:
        self.add("location", ident, file, line, column)

    def location(self, ident: str) -> tuple[str, int, int] | None:
        for row in self._rows.get("location", ()):
            if row[0] == ident:
                return str(row[1]), int(row[2]), int(row[3])
        return None

    def unknown_id(self, value: Unknown) -> int:
        return self._unknowns[value]

    # -- conversion ---------------------------------------------------------------------
    def term(self, cell: Cell) -> clingo.Symbol:
        if isinstance(cell, Unknown):
            return clingo.Function("unknown", [clingo.Number(self._unknowns[cell])])
        if isinstance(cell, int):
            return clingo.Number(cell)
        return clingo.String(cell)

    def plain(self, cell: Cell) -> str | int | dict:
        """A JSON-friendly form: unknowns become {"unknown": expr, "file", "line"}."""
        if isinstance(cell, Unknown):
            return {"unknown": cell.expr, "file": cell.file, "line": cell.line}
        return cell

    def symbols(self) -> list[clingo.Symbol]:
        return [
            clingo.Function(name, [self.term(c) for c in row])
            for name, rows in self._rows.items()
            for row in rows
        ]

    def export(self, directory: Path, fmt: str) -> list[Path]:
        """Write one file per relation (every relation of the schema, even when empty)."""
        directory.mkdir(parents=True, exist_ok=True)
        written = []
        for rel in RELATIONS:
            rows = self._rows.get(rel.name, [])
            path = directory / f"{rel.name}.{fmt}"
            header = [c.name for c in rel.columns]
            if fmt == "csv":
                with path.open("w", newline="", encoding="utf-8") as fh:
                    writer = csv.writer(fh)
                    writer.writerow(header)
                    for row in rows:
                        writer.writerow([f"?{self._unknowns[c]}" if isinstance(c, Unknown) else c for c in row])
            else:
                data = [dict(zip(header, map(self.plain, row))) for row in rows]
                path.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
            written.append(path)
        return written
