"""Behavior facts of one node instance: how each publish call is reached (timer, loop, callback,
start-up), the state conditions on the way, and the callbacks that set that state."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable

from archlog.extract.summary import Guard, NodeSummary, Publish, Site
from archlog.facts.store import FactStore
from archlog.values import Unknown, Value

Sites = dict[Site, list[tuple[str, str]]]  # a port's site -> (kind, port id) of the ports made there
_SOURCE_KINDS = ("subscriber", "service_server", "action_server", "timer")


def add_behavior(store: FactStore, node: str, summary: NodeSummary, sites: Sites,
                 bind: Callable[[Value], str | Unknown]) -> None:
    """publish_call / publish_trigger / publish_guard / loop_period / state_write / decided facts; ports are
    found by their site among those the instance has (a port absent from this configuration, for
    example behind a parameter condition, takes its publish calls with it); `bind` evaluates a
    value (a loop period read from a parameter) for this instance."""
    calls: dict[tuple[str, int, Site | None], list[Publish]] = defaultdict(list)
    for publish in summary.publishes:
        calls[(publish.file, publish.line, publish.publisher)].append(publish)
    for (file, line, publisher), paths in calls.items():
        pubs = _ports(sites, publisher, ("publisher",)) if publisher else ["none"]
        for pub in pubs:
            call = store.new_id("c")
            store.locate(call, file, line)
            store.add("publish_call", call, node, pub)
            for path in paths:
                for source in _ports(sites, path.source, _SOURCE_KINDS) if path.source else ["none"]:
                    store.add("publish_trigger", call, path.trigger, source)
                if path.trigger == "loop" and path.period is not None:
                    store.add("loop_period", call, bind(path.period))
            if all(p.decided for p in paths) and len({frozenset((g.var, g.value) for g in p.guards) for p in paths}) == 1:
                store.add("decided", call)
            for guard in _common_guards(paths):
                gid = store.new_id("g")
                store.locate(gid, guard.file, guard.line)
                store.add("publish_guard", call, guard.var, guard.value, gid)
    for write in summary.writes:
        wid = store.new_id("w")
        store.locate(wid, write.file, write.line)
        for source in _ports(sites, write.source, _SOURCE_KINDS) if write.source else ["none"]:
            store.add("state_write", wid, node, write.var, write.value, source)
        if write.decided:
            store.add("decided", wid)


def _ports(sites: Sites, site: Site, kinds: tuple[str, ...]) -> list[str]:
    return [pid for kind, pid in sites.get(site, []) if kind in kinds]


def _common_guards(paths: list[Publish]) -> list[Guard]:
    """The guards on every path to a call (a guard on one path only does not hold the call back)."""
    common = {(g.var, g.value) for g in paths[0].guards}
    for path in paths[1:]:
        common &= {(g.var, g.value) for g in path.guards}
    return [g for g in paths[0].guards if (g.var, g.value) in common]
