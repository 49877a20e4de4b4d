"""Generated docs are up to date with the fact schema and rule metadata."""

from __future__ import annotations

from archlog.docs import DOCS, GENERATED


def test_generated_docs_are_fresh() -> None:
    for name, make in GENERATED.items():
        assert (DOCS / name).read_text() == make(), f"docs/{name} is stale: run `python -m archlog.docs`"
