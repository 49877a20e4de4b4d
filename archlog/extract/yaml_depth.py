"""YAML loaders that refuse nesting deeper than the budget's `depth`: PyYAML composes nodes
recursively, so a deeply nested document would end in a RecursionError. Past the limit a
`yaml.composer.ComposerError` at the offending line is raised, which the readers already report
as malformed YAML."""

from __future__ import annotations

import yaml

from archlog import budget


class DepthLimited:
    """Mixin for a PyYAML loader (put before the loader class)."""

    _depth = 0

    def compose_node(self, parent: yaml.Node | None, index: object) -> yaml.Node | None:
        limit = budget.current().limits["depth"]
        if self._depth >= limit:
            mark = self.peek_event().start_mark  # type: ignore[attr-defined]
            raise yaml.composer.ComposerError(None, None, f"nested deeper than {limit} levels "
                                              "(raise [budget] depth in archlog.toml to allow more)", mark)
        self._depth += 1
        try:
            return super().compose_node(parent, index)  # type: ignore[misc]
        finally:
            self._depth -= 1


class SafeLoader(DepthLimited, yaml.SafeLoader):
    """yaml.SafeLoader with the nesting limit."""
