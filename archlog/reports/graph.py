"""Graph views of the recovered architecture: DOT, SVG (Graphviz) and one self-contained HTML page.

Elements are node instances, topics, services, actions and the parameters nodes read (with
where the configuration sets them); namespaces are clusters; elements a
finding names are coloured by severity, and a near miss is drawn as a dashed edge between the
two names. `focus` keeps what is within N edges of one element, and the near-miss partner of
everything it keeps. Parameters are left out of DOT and SVG unless asked for; the HTML page holds
both layouts and toggles between them, with a legend and a list of the findings.
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
SHAPES = {"n": "box", "t": "ellipse", "s": "diamond", "a": "hexagon", "p": "note"}
COLOURS = {"error": "#d62728", "warning": "#ff7f0e", "note": "#1f77b4"}
NEAR_MISS = "near miss?"
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
                                severity=None, findings=[])
        if where and where not in self.graph.nodes[ident]["places"]:
            self.graph.nodes[ident]["places"].append(where)


def build(store: FactStore, findings: list[Finding]) -> Graph:
    g = Graph()
    for name, pkg, exe, elem in store.rows("node"):
        g.element(f"n:{name}", str(name), _where(store, elem, f"{pkg}/{exe}"))
    for relation, (kind, direction, style) in PORTS.items():
        for port, node, name, type_ in store.rows(relation):
            target = f"{kind}:{render(name)}"
            g.element(f"n:{node}", str(node))
            g.element(target, render(name), _where(store, port, f"{relation.replace('_', ' ')} {render(type_)}"))
            ends = (f"n:{node}", target) if direction == "out" else (target, f"n:{node}")
            g.graph.add_edge(*ends, style=style, label="")
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
        for kind, key in (("n", "nodes"), ("t", "topics"), ("s", "services"), ("a", "actions"), ("p", "parameters")):
            for name in finding.subjects.get(key, []):
                ident = f"{kind}:{name}"
                if ident in g.graph:
                    named.append(ident)
                    data = g.graph.nodes[ident]
                    data["findings"].append(f"{finding.rule.id} {finding.message}")
                    if data["severity"] is None or finding.severity == "error":
                        data["severity"] = finding.severity
        loc = finding.location
        g.findings.append({"rule": finding.rule.id, "severity": finding.severity, "message": finding.message,
                           "where": f"{loc.file}:{loc.line}" if loc.file else "", "elements": named})
        if finding.rule.id == "AL102":
            a, b = f"t:{finding.values['topic']}", f"t:{finding.values['other_topic']}"
            if a in g.graph and b in g.graph:
                g.graph.add_edge(a, b, style="dashed", label=NEAR_MISS, colour=COLOURS[finding.severity])
    return g


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


def without_parameters(g: Graph) -> Graph:
    """The graph without parameter elements (but the one focused on)."""
    return Graph(g.graph.subgraph([n for n in g.graph if not n.startswith("p:") or n in g.focused]).copy(),
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
            colour = COLOURS.get(data["severity"], "#444444")
            width = 2.5 if data["severity"] else 1
            tooltip = "\n".join(data["places"] + data["findings"])
            lines.append(f'    {_q(ident)} [label={_q(data["label"])}, shape={SHAPES[ident[0]]}, color={_q(colour)}, '
                         f'penwidth={width}, tooltip={_q(tooltip)}, id={_q(ident)}];')
        if cluster:
            lines.append("  }")
    for a, b, data in g.graph.edges(data=True):
        colour = data.get("colour", "#666666")
        lines.append(f'  {_q(a)} -> {_q(b)} [style={data["style"]}, color={_q(colour)}, label={_q(data["label"])}];')
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


def draw(g: Graph, fmt: str, title: str, parameters: bool = False) -> str:
    """The graph as `dot`, `svg` (both with parameters only when asked) or `html` (both layouts)."""
    shown = g if parameters else without_parameters(g)
    if fmt == "dot":
        return to_dot(shown)
    if fmt == "svg":
        return to_svg(to_dot(shown))
    return to_html(g, to_svg(to_dot(without_parameters(g))), to_svg(to_dot(g)), title)


def to_html(g: Graph, svg: str, svg_with_parameters: str, title: str) -> str:
    """One offline page: the layout without parameters, the one with them (toggled), a legend and
    the findings list."""
    elements = {ident: {"label": d["label"], "kind": d["kind"], "places": d["places"], "findings": d["findings"]}
                for ident, d in g.graph.nodes(data=True)}
    parts = {"TITLE": html.escape(title), "LEGEND": legend(), "SVG": svg, "SVG_WITH_PARAMETERS": svg_with_parameters,
             "ELEMENTS": _script_json(elements), "FINDINGS": _script_json(g.findings)}
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
