"""Where a finding lands in code review: a file of the analysed repository.

A finding about a port of a node without source is located in its YAML model (a file archlog
ships, or one outside the repository), which GitHub and GitLab cannot show on a change. Such a
finding is moved to where the user configured the node: the remap that gave the port its name,
else the parameter that names it, else the node's launch element (`<node>`, `Node(...)`). The
model's line becomes the first related location, labelled as such.

A finding of a name rule (tagged `names`: a near miss) about a port whose name is the value of a
parameter the configuration sets (`<param name="scan_topic" value="scna"/>`) is where that value
is written: the parameter's line, with the code that reads it as the first related location.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from archlog.facts.compose import NAMED_PORTS
from archlog.rules.engine import Finding, Location
from archlog.system.node_models import BUILTIN_DIR

OWNED = (*NAMED_PORTS, "param_read", "param_write", "timer")  # relations whose rows are (port, node, ...)


def shipped(file: str) -> bool:
    """A file of archlog's own models."""
    return bool(file) and Path(file).resolve().is_relative_to(BUILTIN_DIR)


class Relocator:
    """The configuration location of each port and node instance of one fact store."""

    def __init__(self, store) -> None:
        self.store = store
        self.owner: dict[str, tuple[str, str]] = {}  # port -> (node, resolved name or '')
        for rel in OWNED:
            for port, node, *rest in store.rows(rel):
                self.owner[str(port)] = (str(node), str(rest[0]) if rel != "timer" else "")
        self.remaps: dict[tuple[str, str], str] = {(str(n), str(to)): str(e) for e, n, _f, to in store.rows("remap")}
        self.name_param = {str(port): str(param) for port, param in store.rows("port_name_param")}
        self.param_elem = {str(param): str(elem) for param, _value, elem in store.rows("param")}
        self.node_elem = {str(name): str(elem) for name, _pkg, _exe, elem in store.rows("node")}

    def _where(self, ident: str) -> Location | None:
        found = self.store.location(ident)
        return Location(*found) if found else None

    def configured(self, port: str) -> tuple[Location, str] | None:
        """Where the user configured the port (or node instance) `port`, and what that place is."""
        node, name = self.owner.get(port, (port, ""))
        candidates = [(self.remaps.get((node, name)), f"the remap that names {name}"),
                      (self.param_elem.get(self.name_param.get(port, "")), f"the parameter that names {name}"),
                      (self.node_elem.get(node), f"node {node} is declared here")]
        for elem, what in candidates:
            where = self._where(elem) if elem else None
            if where is not None and where.file:
                return where, what
        return None

    def finding(self, finding: Finding, foreign: Callable[[str], bool]) -> tuple[Finding, str]:
        """The finding located in the repository when it is located in a foreign file, and the
        label of the location it leaves (empty when it stays)."""
        if not foreign(finding.location.file):
            return finding, ""
        subjects = [str(finding.values.get(finding.rule.location, ""))] + finding.subjects.get("nodes", [])
        for subject in subjects:
            found = self.configured(subject)
            if found is not None and not foreign(found[0].file):
                node = self.owner.get(subject, (subject, ""))[0]
                return replace(finding, location=found[0], related=[finding.location, *finding.related]), \
                    f"declared in the model of {node}"
        return finding, ""


    def named_by_parameter(self, finding: Finding) -> tuple[Finding, str]:
        """A name rule's finding on a port a configured parameter names, located at that parameter."""
        port = str(finding.values.get(finding.rule.location, ""))
        param = self.name_param.get(port)
        elem = self.param_elem.get(param) if param is not None and "names" in finding.rule.tags else None
        where = self._where(elem) if elem else None
        if where is None or not where.file:
            return finding, ""
        return replace(finding, location=where, related=[finding.location, *finding.related]), \
            f"the code that reads the name from parameter {param}"


def relocate(findings: list[Finding], store, foreign: Callable[[str], bool]) -> tuple[list[Finding], dict]:
    """Each finding located in the repository (a name rule's at the parameter that names its port);
    the labels of the locations they left, by (file, line, column)."""
    mover = Relocator(store)
    foreign = functools.cache(foreign)  # asked once per file, not once per finding
    moved, labels = [], {}
    for found in findings:
        finding, label = mover.named_by_parameter(found)
        if label:
            labels[(found.location.file, found.location.line, found.location.column)] = label
        new, label = mover.finding(finding, foreign)
        moved.append(new)
        if label:
            labels[(finding.location.file, finding.location.line, finding.location.column)] = label
    return sorted(moved, key=lambda f: (f.location.file, f.location.line, f.rule.id, f.message)), labels
