"""Several rclpy nodes in one program: each rclpy Node subclass the program constructs is a node of
its own (the ports its methods create are its), and so is the node of the code outside such
classes (rclpy.create_node, rospy.init_node). The first node named is the program's summary; the
others run in the same process (NodeSummary.others)."""

from __future__ import annotations

from dataclasses import dataclass, replace

from archlog.extract.summary import NodeSummary, Port, Site
from archlog.values import Value

OUTSIDE = ""
"""The owner of code outside any rclpy Node subclass."""


@dataclass
class Part:
    """What the program's code says about one of its nodes."""

    name: Value | None = None
    file: str = ""
    line: int = 0
    namespace: Value = ""
    infrastructure: tuple[str, ...] = ()
    without: tuple[str, ...] = ()


class Nodes:
    """The nodes of one program by owner (a Node subclass's name, or OUTSIDE), and the owner of each port."""

    def __init__(self) -> None:
        self.parts: dict[str, Part] = {}
        self.owners: dict[Port, str] = {}

    def part(self, owner: str) -> Part:
        return self.parts.setdefault(owner, Part())

    def split(self, summary: NodeSummary) -> NodeSummary:
        """The summary of the first named node, with the other named nodes in `others`; ports of an
        owner that names no node go to the first node."""
        named = [owner for owner, part in self.parts.items() if part.name is not None]
        if not named:
            return summary
        first = named[0]
        nodes = {owner: self._summary(summary, owner) for owner in named}
        for port in summary.ports:
            owner = self.owners.get(port, first)
            nodes[owner if owner in nodes else first].ports.append(port)
        for node in nodes.values():
            sites = {Site(p.file, p.line) for p in node.ports}
            node.publishes = [p for p in summary.publishes if p.publisher in sites or
                              (p.publisher is None and node is nodes[first])]
            node.writes = [w for w in summary.writes if w.source in sites or (w.source is None and node is nodes[first])]
        main = nodes.pop(first)
        main.incomplete = summary.incomplete
        main.others = list(nodes.values())
        return main

    def _summary(self, summary: NodeSummary, owner: str) -> NodeSummary:
        part = self.parts[owner]
        return replace(summary, default_name=part.name, name_file=part.file, name_line=part.line,
                       namespace=part.namespace, infrastructure=part.infrastructure, without=part.without, ports=[],
                       publishes=[], writes=[], others=[])
