"""Query results as text, JSON or CSV. Tables are plain aligned columns written a page at a time,
never cut to a terminal's width: the first rows appear before the last are read."""

from __future__ import annotations

import csv
import json
from collections.abc import Iterable
from itertools import islice
from typing import IO

from archlog.facts.store import Cell
from archlog.queries.session import Result
from archlog.rules.engine import render

PAGE = 50  # rows per write; column widths come from the header and the first page


def write_table(columns: list[str], rows: Iterable[tuple[Cell, ...]], out: IO[str]) -> int:
    """Write a header and the rows, flushing after each page; returns the number of rows written
    (a KeyboardInterrupt while writing leaves the rows written so far on the screen)."""
    source = iter(rows)
    page = [list(map(render, row)) for row in islice(source, PAGE)]
    widths = [max([len(name)] + [len(cells[i]) for cells in page]) for i, name in enumerate(columns)]

    def line(cells: list[str]) -> str:
        return "  ".join(cell.ljust(width) for cell, width in zip(cells, widths)).rstrip() + "\n"

    out.write(line(columns) + line(["-" * width for width in widths]))
    count = 0
    while page:
        out.write("".join(map(line, page)))
        out.flush()
        count += len(page)
        page = [list(map(render, row)) for row in islice(source, PAGE)]
    return count


def plural(count: int, word: str = "result") -> str:
    return f"{count} {word}{'s' if count != 1 else ''}"


def print_result(result: Result, fmt: str, out: IO[str]) -> None:
    """A query result, sorted (numbers, strings, then unknowns), as a table, JSON or CSV."""
    ordered = result.sorted_rows()
    rows = [list(map(render, row)) for row in ordered]
    if fmt == "json":
        out.write(json.dumps([dict(zip(result.columns, row)) for row in rows], indent=2) + "\n")
    elif fmt == "csv":
        writer = csv.writer(out)
        writer.writerow(result.columns)
        writer.writerows(rows)
    elif not result.columns:
        out.write(("true" if rows else "false") + "\n")
    else:
        write_table(result.columns, ordered, out)
        out.write(plural(len(rows)) + "\n")
