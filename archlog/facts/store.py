"""The fact store: rows per relation, unknown values, export to CSV/JSON and to clingo."""

from __future__ import annotations

import contextlib
import csv
import json
from collections import defaultdict
from collections.abc import Iterable, Iterator
from pathlib import Path

import clingo

from archlog.facts.schema import BY_NAME, RELATIONS
from archlog.values import Unknown

Cell = str | int | Unknown
_ARITY: dict[str, int] = {name: rel.arity for name, rel in BY_NAME.items()}  # (looked up once per row added)


class FactStore:
    """Rows of every relation in `archlog.facts.schema`, checked against their arity."""

    def __init__(self) -> None:
        self._rows: dict[str, dict[tuple[Cell, ...], None]] = defaultdict(dict)  # rows in order, once each
        self._unknowns: dict[Unknown, int] = {}
        self._by_number: dict[int, Unknown] = {}
        self._locations: dict[str, tuple[str, int, int]] = {}
        self._counters: dict[str, int] = defaultdict(int)
        self._nul: set[str] = set()  # relations with a NUL character in a string

    def new_id(self, prefix: str) -> str:
        """A fresh id such as 'p1' (ports) or 'e1' (elements)."""
        self._counters[prefix] += 1
        return f"{prefix}{self._counters[prefix]:05d}"

    def add(self, relation: str, *row: Cell) -> None:
        if len(row) != _ARITY[relation]:
            raise ValueError(f"{relation} takes {_ARITY[relation]} columns, got {len(row)}")
        rows = self._rows[relation]
        if row in rows:
            return
        rows[row] = None
        if relation == "location":
            self._locations.setdefault(str(row[0]), (str(row[1]), int(str(row[2])), int(str(row[3]))))
        for cell in row:
            if type(cell) is str or isinstance(cell, str):  # (the first test is the quick one, for most cells)
                if "\0" in cell:
                    self._nul.add(relation)
            elif isinstance(cell, Unknown) and cell not in self._unknowns:
                self._unknowns[cell] = len(self._unknowns) + 1
                self._by_number[self._unknowns[cell]] = cell
                self.add("unknown_value", cell, cell.expr, cell.file, cell.line)

    def rows(self, relation: str) -> list[tuple[Cell, ...]]:
        return list(self._rows.get(relation, ()))

    def read_back(self, relation: str) -> Iterator[tuple[Cell, ...]]:
        """The rows of a relation as clingo holds them, in order: a string is cut at a NUL
        character, so rows that differ only after one are one row."""
        rows = self._rows.get(relation, {})
        cut: set[tuple[Cell, ...]] = set()
        for row in list(rows):
            if any(type(cell) is str and "\0" in cell for cell in row):
                row = tuple(cell.split("\0", 1)[0] if type(cell) is str else cell for cell in row)
                if row in rows or row in cut:
                    continue
                cut.add(row)
            yield row

    def has_nul(self, relation: str) -> bool:
        """Whether a string of the relation holds a NUL character (clingo cuts it there)."""
        return relation in self._nul

    def count(self, relation: str) -> int:
        return len(self._rows.get(relation, ()))

    def locate(self, ident: str, file: str, line: int, column: int = 0) -> None:
        if ident not in self._locations:
            self.add("location", ident, file, line, column)

    def location(self, ident: str) -> tuple[str, int, int] | None:
        return self._locations.get(ident)

    def from_term(self, symbol: clingo.Symbol) -> Cell:
        """The Python value of a clingo term produced from this store."""
        if symbol.type == clingo.SymbolType.String:
            return symbol.string
        if symbol.type == clingo.SymbolType.Number:
            return symbol.number
        if symbol.name == "unknown" and len(symbol.arguments) == 1:
            return self._by_number.get(symbol.arguments[0].number, Unknown(str(symbol), "", 0))
        return str(symbol)

    # -- conversion ---------------------------------------------------------------------
    def term(self, cell: Cell) -> clingo.Symbol:
        if isinstance(cell, Unknown):
            return clingo.Function("unknown", [clingo.Number(self._unknowns[cell])])
        if isinstance(cell, int):
            return clingo.Number(cell)
        return clingo.String(cell)

    @staticmethod
    def plain(cell: Cell) -> str | int:
        """A CSV- and JSON-friendly form: an unknown is written `?(expr)` (`unknown_value` has its place)."""
        return str(cell) if isinstance(cell, Unknown) else cell

    def program(self, relations: Iterable[str] | None = None) -> str:
        """The rows of these relations (default: all) as clingo facts, one program text."""
        return "".join(self.text(name, self._rows.get(name, ())) for name in (self._rows if relations is None else
                                                                             relations))

    def text(self, relation: str, rows: Iterable[tuple[Cell, ...]]) -> str:
        """Rows of a relation as clingo facts: clingo parses them, with no Python call per fact (a
        string is cut at a NUL character, as clingo.String cuts it)."""
        rows = rows if isinstance(rows, list) else list(rows)
        with contextlib.suppress(TypeError):  # a number or an unknown: written cell by cell below
            # most relations hold plain strings only: joined at once, then checked for escapes
            text = "".join([relation + '("' + '","'.join(row) + '").\n' for row in rows])  # type: ignore[arg-type]
            quotes = 2 * BY_NAME[relation].arity * len(rows)
            if text.count('"') == quotes and text.count("\n") == len(rows) and "\\" not in text and "\0" not in text:
                return text
        head = relation + "("
        return "".join([head + ",".join(map(self._text, row)) + ").\n" for row in rows])

    def _text(self, cell: Cell) -> str:
        if type(cell) is str:  # most cells: a plain string needs no escapes
            if '"' in cell or "\\" in cell or "\n" in cell or "\0" in cell:
                cell = cell.split("\0", 1)[0].replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
            return '"' + cell + '"'
        if isinstance(cell, Unknown):
            return f"unknown({self._unknowns[cell]})"
        if isinstance(cell, int):
            return str(int(cell))
        return self._text(str(cell))  # a str subclass

    def export(self, directory: Path, fmt: str) -> list[Path]:
        """Write one file per relation (every relation of the schema, even when empty)."""
        directory.mkdir(parents=True, exist_ok=True)
        written = []
        for rel in RELATIONS:
            rows = self._rows.get(rel.name, {})
            path = directory / f"{rel.name}.{fmt}"
            header = [c.name for c in rel.columns]
            if fmt == "csv":
                with path.open("w", newline="", encoding="utf-8") as fh:
                    writer = csv.writer(fh)
                    writer.writerow(header)
                    for row in rows:
                        writer.writerow(map(self.plain, row))
            else:
                data = [dict(zip(header, map(self.plain, row))) for row in rows]
                path.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
            written.append(path)
        return written
