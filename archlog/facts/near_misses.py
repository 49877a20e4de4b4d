"""near_name facts: the near-miss names a broken link may explain, searched from the side that waits.

A link is broken where someone waits on a name nothing provides: a subscriber on a topic nobody
publishes, a service client on a service nobody serves, an action client on an action nobody
serves (a required input is a subscriber). Each such name is measured against every name of that
kind's providers. A publisher nobody hears is measured only against what AL102 pairs it with: the
connected topics (published and subscribed) that a subscriber of a compatible message type (the
same, or either unknown) uses. Everything else -- a publisher or a server nobody needs, the
infrastructure every node has (dynamic_reconfigure, diagnostics, ROS 2's /rosout and parameter
services) -- stays out of the pair search, which is what makes its cost follow the broken links
rather than the ports.
"""

from __future__ import annotations

from collections import defaultdict

from archlog.diagnostics import DiagnosticSink
from archlog.facts.compose import NAMED_PORTS
from archlog.facts.similarity import namespace_steps, near_names, too_long
from archlog.facts.store import FactStore
from archlog.values import Unknown

WAITERS = (("subscriber", "publisher"), ("service_client", "service_server"), ("action_client", "action_server"))
Typed = dict[str, set[str | None]]  # a name and the types its ports use (None: unknown)


def add_near_names(store: FactStore, threshold: float, diagnostics: DiagnosticSink | None = None) -> None:
    """near_name facts (both directions), with their near_scope rows, for the pairs a broken link
    may explain (the module's docstring says which). A name too long to compare is noted (once, at
    its first port) when `diagnostics` is given."""
    first_port: dict[str, str] = {}
    used: dict[str, Typed] = {rel: defaultdict(set) for rel in NAMED_PORTS}
    builtin = {row[0] for row in store.rows("infrastructure_port")}  # the client library's own ports
    for rel in NAMED_PORTS:
        for port, _node, name, type_ in store.rows(rel):
            if isinstance(name, str) and port not in builtin:
                first_port.setdefault(name, str(port))
                used[rel][name].add(None if isinstance(type_, Unknown) else str(type_))
    for name, port in first_port.items():
        if diagnostics is not None and (why := too_long(name)) is not None:
            file, line, _column = store.location(port) or ("", 0, 0)
            diagnostics.add(file, line, "name-too-long", f"name {name[:60]}... has {why}; no near miss is looked for",
                            "note")
    found: dict[tuple[str, str], float] = {}
    for waiter, provider in WAITERS:
        waiting = used[waiter].keys() - used[provider].keys()
        found |= {(a, b): score for a, b, score in near_names(waiting, used[provider], threshold)}
    found |= {(a, b): score for a, b, score in _unheard(used["publisher"], used["subscriber"], threshold)}
    for (a, b), score in sorted(found.items()):
        store.add("near_name", a, b, round(score * 1000))
        store.add("near_name", b, a, round(score * 1000))
        store.add("near_scope", a, b, namespace_steps(a, b))
        store.add("near_scope", b, a, namespace_steps(b, a))


def _unheard(published: Typed, subscribed: Typed, threshold: float) -> list[tuple[str, str, float]]:
    """Near pairs of a topic published to nobody and a connected topic a subscriber of a compatible
    type uses, searched per publisher type."""
    targets: dict[str | None, set[str]] = defaultdict(set)  # subscriber type -> connected topics
    for name, types in subscribed.items():
        if name in published:
            for type_ in types:
                targets[type_].add(name)
    queries: dict[str | None, set[str]] = defaultdict(set)
    for name, types in published.items():
        if name not in subscribed:
            for type_ in types:
                queries[type_].add(name)
    found = []
    for type_, names in queries.items():
        against = set().union(*targets.values()) if type_ is None else targets.get(type_, set()) | targets[None]
        if against:
            found += near_names(names, against, threshold)
    return found
