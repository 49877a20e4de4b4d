"""YAML loaders bounded in what a document may make: PyYAML composes nodes recursively, so a
deeply nested document ends in a RecursionError, and an alias shares its anchor's node, so a few
lines of aliases of aliases stand for billions of nodes once a reader walks them. Past the
budget's `depth`, or past its `elements` counted through aliases, a `yaml.composer.ComposerError`
at the offending line is raised, which the readers already report as malformed YAML."""

from __future__ import annotations

import yaml

from archlog import budget


class DepthLimited:
    """Mixin for a PyYAML loader (put before the loader class)."""

    _depth = 0
    _through_aliases = 0

    def compose_node(self, parent: yaml.Node | None, index: object) -> yaml.Node | None:
        limits = budget.current().limits
        event = self.peek_event()  # type: ignore[attr-defined]
        if self._depth >= limits["depth"]:
            raise self._refused(f"nested deeper than {limits['depth']} levels", "depth", event)
        if isinstance(event, yaml.AliasEvent) and event.anchor in self.anchors:  # type: ignore[attr-defined]
            self._through_aliases += _size(self.anchors[event.anchor], limits["elements"])  # type: ignore[attr-defined]
            if self._through_aliases > limits["elements"]:
                raise self._refused(f"aliases stand for more than {limits['elements']} elements", "elements", event)
        self._depth += 1
        try:
            return super().compose_node(parent, index)  # type: ignore[misc]
        finally:
            self._depth -= 1

    @staticmethod
    def _refused(why: str, kind: str, event: yaml.Event) -> yaml.composer.ComposerError:
        return yaml.composer.ComposerError(None, None, f"{why} (raise [budget] {kind} in archlog.toml to allow more)",
                                           event.start_mark)


def _size(node: yaml.Node, limit: int) -> int:
    """Nodes under `node`, aliases counted as often as they are used (without recursion), up to
    just past `limit`."""
    total, pending = 0, [node]
    while pending:
        current = pending.pop()
        total += 1
        if isinstance(current, yaml.SequenceNode):
            pending += current.value
        elif isinstance(current, yaml.MappingNode):
            pending += [part for pair in current.value for part in pair]
        if total > limit:
            break
    return total


class SafeLoader(DepthLimited, yaml.SafeLoader):
    """yaml.SafeLoader with the limits."""
