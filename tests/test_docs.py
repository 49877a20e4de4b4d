"""Generated docs are up to date with the fact schema and rule metadata (`pytest --update-goldens`
regenerates them, as `python -m archlog.docs` does)."""

from __future__ import annotations

from support.goldens import compare_text

from archlog.docs import DOCS, GENERATED


def test_generated_docs_are_fresh(update_goldens: bool) -> None:
    for name, make in GENERATED.items():
        diff = compare_text(DOCS / name, make(), update_goldens)
        assert not diff, f"docs/{name} is stale: run `python -m archlog.docs`\n{diff}"
