"""PyYAML's safe loader within the expansion budget (archlog.budget).

Aliases make a small file stand for a huge tree ("billion laughs"): each alias is counted at the
size of what it expands to (elements, characters of scalars, nesting), so consumers that walk the
expanded tree stay within the budget. Nesting is checked while composing, before PyYAML's
recursive composer can run out of stack. A recursive alias (an anchor used inside itself) would
expand forever and crosses the depth limit. A loader spends from the budget of the unit being
read when it is made (outside one, from a budget of its own: one per file). `where` is the line
the loader was at when it stopped.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import yaml

from archlog import budget

_Size = tuple[int, int, int]  # elements, characters, height of a node's expanded tree


class BoundedLoader(yaml.SafeLoader):
    """A SafeLoader that spends, as it composes, from the budget current when it was made."""

    def __init__(self, stream: Any) -> None:
        super().__init__(stream)
        self.where = 1
        self._budget = budget.current()
        self._depth = 0
        self._sizes: dict[int, _Size] = {}

    def compose_node(self, parent: yaml.Node | None, index: Any) -> yaml.Node | None:
        event = self.peek_event()
        self.where = event.start_mark.line + 1
        limits = self._budget
        limits.check("depth", self._depth + 1)
        self._depth += 1
        try:
            node = super().compose_node(parent, index)
        finally:
            self._depth -= 1
        if node is None:
            return None
        if isinstance(event, yaml.AliasEvent):
            if id(node) not in self._sizes:  # used inside its own anchor: endless
                raise budget.BudgetExceeded("depth", limits.limits["depth"])
            elements, characters, height = self._sizes[id(node)]
        else:
            elements, characters, height = self._measure(node)
            self._sizes[id(node)] = (elements, characters, height)
            elements, characters = 1, characters if isinstance(node, yaml.ScalarNode) else 0
        limits.charge("elements", elements)
        limits.charge("characters", characters)
        limits.check("depth", self._depth + height)
        return node

    def _measure(self, node: yaml.Node) -> _Size:
        """The expanded size of a node whose children are composed (and measured) already."""
        if isinstance(node, yaml.ScalarNode):
            return 1, len(node.value), 1
        children = [n for pair in node.value for n in pair] if isinstance(node, yaml.MappingNode) else node.value
        sizes = [self._sizes[id(child)] for child in children]
        return (1 + sum(s[0] for s in sizes), sum(s[1] for s in sizes), 1 + max((s[2] for s in sizes), default=0))


@contextmanager
def crossing_in(loader: BoundedLoader, shown: str) -> Iterator[None]:
    """A limit crossed while `loader` reads the file `shown` is crossed at the loader's line there
    (the expansion of an alias is refused there as a whole, before it is built)."""
    try:
        yield
    except (budget.BudgetExceeded, RecursionError, MemoryError) as exc:
        raise budget.crossed(shown, loader.where, exc) from None


def load(text: str, loader: type[BoundedLoader] = BoundedLoader) -> object:
    """The document in `text`, read within the budget; raises yaml.YAMLError or BudgetExceeded."""
    return yaml.load(text, Loader=loader)
