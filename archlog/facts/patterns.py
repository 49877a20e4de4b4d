"""may_name facts: the names in use that an unknown name with known parts (`unknown_pattern`) might be.

Found through two sorted indexes (of the names, and of the names reversed), so the cost grows with
the patterns and the names that fit them, not with their product."""

from __future__ import annotations

from bisect import bisect_left

from archlog.facts.compose import NAMED_PORTS
from archlog.facts.store import FactStore


def add_name_fits(store: FactStore) -> None:
    """A may_name row for each unknown name with known parts and each name a port or a remap uses that
    starts with its known prefix and ends with its known suffix."""
    patterns = store.rows("unknown_pattern")
    if not patterns:
        return
    used = {row[2] for rel in NAMED_PORTS for row in store.rows(rel)} | {row[2] for row in store.rows("remap")}
    names = sorted(n for n in used if isinstance(n, str))
    ends = sorted(n[::-1] for n in names)
    for unknown, prefix, suffix in patterns:
        start, end = str(prefix), str(suffix)
        (a, b), (c, d) = _bounds(names, start), _bounds(ends, end[::-1])
        if b - a <= d - c:
            fits = [n for n in names[a:b] if n.endswith(end)]
        else:
            fits = [n[::-1] for n in ends[c:d] if n[::-1].startswith(start)]
        for name in sorted(fits):
            store.add("may_name", unknown, name)


def _bounds(ordered: list[str], start: str) -> tuple[int, int]:
    """Where the strings of a sorted list that start with `start` begin and end."""
    return bisect_left(ordered, start), bisect_left(ordered, start + chr(0x10FFFF))
