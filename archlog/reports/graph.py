"""Graph views of the recovered architecture: DOT, SVG (Graphviz) and one self-contained HTML page.

Elements are node instances, topics, services, actions and the parameters nodes read (with
where the configuration sets them); namespaces are clusters; elements a
finding names are coloured by severity (the other side of a finding, `other_*` and `candidate`
columns, only gets a dashed outline), and a near miss (any finding's `other_topic` or candidate)
is drawn as a dashed edge between the two names. `focus` keeps what is within N edges of one
element, and the near-miss partner of everything it keeps. Infrastructure (GROUPS: tf,
dynamic_reconfigure, rosout, ROS 2 built-in ports, leaf topics) and parameters are left out
unless asked for or named by a finding, as rqt_graph does; the HTML page holds the layout
without them and the one with everything, and toggles between them, with a legend and a list of
the findings.
"""

from __future__ import annotations

import difflib
import html
import json
import re
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import networkx as nx

from archlog import names
from archlog.facts.store import Cell, FactStore
from archlog.rules.engine import Finding, render

KINDS = {"n": "node", "t": "topic", "s": "service", "a": "action", "p": "parameter"}
PREFIX = {"node": "n", "topic": "t", "service": "s", "action": "a", "param": "p"}  # a finding's column kind
SHAPES = {"n": "box", "t": "ellipse", "s": "diamond", "a": "hexagon", "p": "note"}
COLOURS = {"error": "#d62728", "warning": "#ff7f0e", "note": "#1f77b4"}
NEAR_MISS = "near miss?"
OTHER_SIDE = "#555555"  # the outline of an element that is the other side of a finding
# what is hidden unless asked for: group -> message/service type prefixes (ROS 1 and ROS 2 spellings)
GROUPS = {"tf": ("tf2_msgs/TFMessage", "tf/tfMessage"),
          "dynamic_reconfigure": ("dynamic_reconfigure/",),
          "rosout": ("rosgraph_msgs/Log", "rcl_interfaces/Log"),
          "built-in": (), "leaf topics": (), "parameters": ()}
INFRASTRUCTURE = [g for g in GROUPS if g != "parameters"]
PORTS = {  # relation -> (element kind, edge direction: node->element or element->node, style)
    "publisher": ("t", "out", "solid"), "subscriber": ("t", "in", "solid"),
    "service_server": ("s", "in", "solid"), "service_client": ("s", "out", "dashed"),
    "action_server": ("a", "in", "solid"), "action_client": ("a", "out", "dashed"),
}


@dataclass
class Graph:
    graph: nx.MultiDiGraph = field(default_factory=nx.MultiDiGraph)
    # each unsuppressed finding: rule, severity, message, where (file:line) and the elements it names
    findings: list[dict] = field(default_factory=list)
    focused: set[str] = field(default_factory=set)  # the elements --focus named: drawn even if parameters are not

    def element(self, ident: str, label: str, where: str | None = None) -> None:
        if ident not in self.graph:
            namespace = names.namespace_of(label) if label.startswith("/") else "?"
            self.graph.add_node(ident, label=label, kind=KINDS[ident[0]], namespace=namespace, places=[],
                                severity=None, findings=[], other=False,
                                group="parameters" if ident[0] == "p" else None)
        if where and where not in self.graph.nodes[ident]["places"]:
            self.graph.nodes[ident]["places"].append(where)


def _group(type_: str, built_in: bool) -> str | None:
    """The infrastructure group of a port of this type."""
    plain = type_.replace("/msg/", "/").replace("/srv/", "/")
    found = next((group for group, prefixes in GROUPS.items() if plain.startswith(prefixes or ("\0",))), None)
    return found or ("built-in" if built_in else None)


def build(store: FactStore, findings: list[Finding]) -> Graph:
    g = Graph()
    for name, pkg, exe, elem in store.rows("node"):
        g.element(f"n:{name}", str(name), _where(store, elem, f"{pkg}/{exe}"))
    built_in = {str(port) for port, _group in store.rows("infrastructure_port")}
    groups: dict[str, set[str | None]] = {}  # element -> the groups of its ports
    port_element: dict[str, str] = {}
    for relation, (kind, direction, style) in PORTS.items():
        for port, node, name, type_ in store.rows(relation):
            target = f"{kind}:{render(name)}"
            g.element(f"n:{node}", str(node))
            g.element(target, render(name), _where(store, port, f"{relation.replace('_', ' ')} {render(type_)}"))
            ends = (f"n:{node}", target) if direction == "out" else (target, f"n:{node}")
            g.graph.add_edge(*ends, style=style, label="")
            groups.setdefault(target, set()).add(_group(render(type_), str(port) in built_in))
            port_element[str(port)] = target
    for ident, found in groups.items():
        sides = {"in" for _edge in g.graph.in_edges(ident)} | {"out" for _edge in g.graph.out_edges(ident)}
        only = found.pop() if len(found) == 1 else None
        g.graph.nodes[ident]["group"] = only or ("leaf topics" if ident[0] == "t" and len(sides) == 1 else None)
    for port, node, name, default in store.rows("param_read"):
        target = f"p:{render(name)}"
        g.element(target, render(name), _where(store, port, f"read by {node} (default {render(default)})"))
        g.graph.add_edge(target, f"n:{node}", style="dotted", label="")
    for name, value, elem in store.rows("param"):
        if f"p:{name}" in g.graph:
            g.element(f"p:{name}", str(name), _where(store, elem, f"set to {render(value)}"))
    for finding in findings:
        if finding.suppression is not None:
            continue
        named = []
        for ident, other in _named(finding, port_element):
            if ident in g.graph and ident not in named:
                named.append(ident)
                data = g.graph.nodes[ident]
                data["findings"].append(f"{finding.rule.id} {finding.message}")
                if other:
                    data["other"] = True
                elif data["severity"] is None or finding.severity == "error":
                    data["severity"] = finding.severity
        loc = finding.location
        g.findings.append({"rule": finding.rule.id, "severity": finding.severity, "message": finding.message,
                           "where": f"{loc.file}:{loc.line}" if loc.file else "", "elements": named})
        near = f"t:{finding.values['other_topic']}" if "other_topic" in finding.values \
            else port_element.get(str(finding.values.get("candidate")), "")
        a = f"t:{finding.values.get('topic')}"
        if a in g.graph and near in g.graph and near != a:
            g.graph.add_edge(a, near, style="dashed", label=NEAR_MISS, colour=COLOURS[finding.severity])
    return g


def _named(finding: Finding, port_element: dict[str, str]) -> list[tuple[str, bool]]:
    """The elements a finding names, each with whether it is the finding's other side (a column
    `other_*`, or `candidate`: a port whose topic is offered)."""
    found = []
    for column, value in finding.values.items():
        other = column.startswith("other_") or column == "candidate"
        kind = column.rsplit("_", 1)[-1]
        if column == "candidate" and str(value) in port_element:
            found.append((port_element[str(value)], True))
        elif kind in PREFIX:
            found.append((f"{PREFIX[kind]}:{render(value)}", other))
    return found


def focus(g: Graph, element: str, depth: int) -> Graph:
    """What is within `depth` edges of an element (given by resolved name), with the near-miss
    partner of each topic kept; a ValueError names the nearest names when none is `element`."""
    matches = [n for n, d in g.graph.nodes(data=True) if d["label"] == element]
    if not matches:
        labels = sorted({d["label"] for _n, d in g.graph.nodes(data=True)})
        near = difflib.get_close_matches(element, labels, n=3, cutoff=0.6)
        raise ValueError(f"no node, topic, service, action or parameter named {element}"
                         + (f"; did you mean {' or '.join(near)}?" if near else ""))
    keep: set[str] = set()
    undirected = nx.Graph(g.graph)
    for start in matches:
        keep |= set(nx.single_source_shortest_path_length(undirected, start, cutoff=depth))
    keep |= {b for a, b, d in g.graph.edges(data=True) if a in keep and _near_miss(d)}
    keep |= {a for a, b, d in g.graph.edges(data=True) if b in keep and _near_miss(d)}
    kept = Graph(g.graph.subgraph(keep).copy())
    kept.findings = [f for f in g.findings if set(f["elements"]) & keep]
    kept.focused = set(matches)
    return kept


def _near_miss(edge: dict) -> bool:
    return edge["label"] == NEAR_MISS


def shown(g: Graph, groups: set[str]) -> Graph:
    """The graph with the elements of `groups` and of no group; an element a finding names or
    --focus kept is always shown, and a focused graph hides only parameters."""
    named = {ident for finding in g.findings for ident in finding["elements"]}
    hidden = {"parameters"} - groups if g.focused else set(GROUPS) - groups
    return Graph(g.graph.subgraph([n for n, d in g.graph.nodes(data=True)
                                   if d["group"] not in hidden or n in named or n in g.focused]).copy(),
                 g.findings, g.focused)


def to_dot(g: Graph) -> str:
    lines = ["digraph archlog {", '  graph [rankdir=LR, fontname="Helvetica", fontsize=10];',
             '  node [fontname="Helvetica", fontsize=10]; edge [fontname="Helvetica", fontsize=9];']
    by_namespace: dict[str, list[str]] = {}
    for ident, data in g.graph.nodes(data=True):
        by_namespace.setdefault(data["namespace"], []).append(ident)
    for index, (namespace, members) in enumerate(sorted(by_namespace.items())):
        cluster = namespace not in ("/", "?")
        if cluster:
            lines.append(f'  subgraph cluster_{index} {{ label={_q(namespace)}; style=rounded; color="#999999";')
        for ident in sorted(members):
            data = g.graph.nodes[ident]
            colour = COLOURS.get(data["severity"], OTHER_SIDE if data["other"] else "#444444")
            width = 2.5 if data["severity"] else 1.5 if data["other"] else 1
            other = ", style=dashed" if data["other"] and not data["severity"] else ""
            tooltip = "\n".join(data["places"] + data["findings"])
            lines.append(f'    {_q(ident)} [label={_q(data["label"])}, shape={SHAPES[ident[0]]}, color={_q(colour)}, '
                         f'penwidth={width}{other}, tooltip={_q(tooltip)}, id={_q(ident)}];')
        if cluster:
            lines.append("  }")
    for index, (a, b, data) in enumerate(g.graph.edges(data=True)):
        colour = data.get("colour", "#666666")
        lines.append(f'  {_q(a)} -> {_q(b)} [style={data["style"]}, color={_q(colour)}, label={_q(data["label"])}, '
                     f'id={_q("edge " + json.dumps([a, b, index]))}];')  # the page hides edges by their ends
    lines.append("}")
    return "\n".join(lines) + "\n"


def to_svg(dot: str) -> str:
    executable = shutil.which("dot")
    if executable is None:
        raise RuntimeError("Graphviz is not installed (the `dot` command): install it for svg and html output")
    result = subprocess.run([executable, "-Tsvg"], input=dot, capture_output=True, text=True, timeout=300, check=False)
    if result.returncode != 0:
        raise RuntimeError(f"Graphviz failed: {result.stderr.strip()[:300]}")
    return result.stdout[result.stdout.find("<svg"):]


def draw(g: Graph, fmt: str, title: str, groups: set[str] | None = None) -> str:
    """The graph as `dot` or `svg` (with the hidden `groups` asked for) or `html` (the layout
    without any hidden group and the one with all, toggled)."""
    if fmt == "dot":
        return to_dot(shown(g, groups or set()))
    if fmt == "svg":
        return to_svg(to_dot(shown(g, groups or set())))
    return to_html(g, to_svg(to_dot(shown(g, set()))), to_svg(to_dot(shown(g, set(GROUPS)))), title)


def to_html(g: Graph, svg: str, svg_with_all: str, title: str) -> str:
    """One offline page: the layout without the hidden groups, the one with them all (each group
    toggled on its own), a legend and the findings list."""
    always = set(shown(g, set()).graph)  # drawn whatever is toggled
    elements = {ident: {"label": d["label"], "kind": d["kind"], "places": d["places"], "findings": d["findings"],
                        "group": None if ident in always else d["group"]} for ident, d in g.graph.nodes(data=True)}
    parts = {"TITLE": html.escape(title), "LEGEND": legend(), "SVG": svg, "SVG_WITH_PARAMETERS": svg_with_all,
             "ELEMENTS": _script_json(elements), "FINDINGS": _script_json(g.findings),
             "GROUPS": _script_json(INFRASTRUCTURE)}
    template = (Path(__file__).with_name("graph.html")).read_text(encoding="utf-8")
    return re.sub(r"__([A-Z_]+)__", lambda m: parts[m.group(1)], template)  # one pass: no part is read again


def legend() -> str:
    """The legend of the HTML page: each shape's kind, each colour's severity, the edge styles."""
    icons = {
        "box": '<rect x="2" y="3" width="20" height="12"/>', "ellipse": '<ellipse cx="12" cy="9" rx="10" ry="6"/>',
        "diamond": '<polygon points="12,2 22,9 12,16 2,9"/>', "hexagon": '<polygon points="6,3 18,3 22,9 18,15 6,15 2,9"/>',
        "note": '<polygon points="2,3 17,3 22,8 22,15 2,15"/>',
    }
    items = [f'<span class="key"><svg width="24" height="18" fill="none" stroke="#444">{icons[SHAPES[k]]}</svg>'
             f"{kind}</span>" for k, kind in KINDS.items()]
    items += [f'<span class="key"><span class="swatch" style="border-color:{colour}"></span>{severity}</span>'
              for severity, colour in COLOURS.items()]
    items += ['<span class="key">&#8594; publishes, serves</span>', '<span class="key">&#8674; client, near miss?</span>',
              '<span class="key">&#8230; parameter read</span>']
    return "".join(items)


def _script_json(value: object) -> str:
    return json.dumps(value).replace("</", "<\\/")


def _where(store: FactStore, ident: Cell, what: str) -> str:
    place = store.location(str(ident))
    return f"{place[0]}:{place[1]} {what}" if place else what


def _q(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
