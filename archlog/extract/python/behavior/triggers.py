"""Behavior of rospy and rclpy nodes: how each publish call is reached (a timer, an unbounded
loop, the callback of a subscriber, service or action, start-up code), the state conditions on
the way, and the assignments to that state.

Paths are followed from entries (registered callbacks, module code, `main`, constructors)
through calls to the file's own functions, binding arguments at each call: a publisher passed as
an argument resolves per path, and a caller's guards and loop hold in its callees. Built on the
index and values of the port extraction (python/node.py). Nothing is imported or run.
"""

from __future__ import annotations

import ast
from dataclasses import replace

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python.behavior.paths import Context, Frame
from archlog.extract.python.behavior.scopes import SOURCE_KINDS
from archlog.extract.python.behavior.syntax import NO_INDEX
from archlog.extract.python.behavior.walk import BUDGET, PUBLISH_METHODS, Walk
from archlog.extract.python.fold import ValueFolder
from archlog.extract.python.index import arg
from archlog.extract.summary import TRIGGERS, Port, Publish, Site, StateWrite

# calls that register a callback: qualified name (or rclpy Node method) -> (trigger, (index, keyword) of callbacks)
_REGISTRATIONS: dict[str, tuple[str, tuple[tuple[int, str], ...]]] = {
    "rospy.Subscriber": ("callback", ((2, "callback"),)),
    "rospy.Service": ("callback", ((2, "handler"),)),
    "rospy.Timer": ("timer", ((1, "callback"),)),
    "actionlib.SimpleActionServer": ("callback", ((2, "execute_cb"),)),
    "actionlib.ActionServer": ("callback", ((2, "goal_cb"), (3, "cancel_cb"))),
    "rclpy.action.ActionServer": ("callback", ((3, "execute_callback"), (NO_INDEX, "goal_callback"),
                                               (NO_INDEX, "handle_accepted_callback"), (NO_INDEX, "cancel_callback"))),
}
_RCLPY_REGISTRATIONS = {"create_subscription": ("callback", ((2, "callback"),)),
                        "create_service": ("callback", ((2, "callback"),)),
                        "create_timer": ("timer", ((1, "callback"),))}
_LATER_REGISTRATIONS = {"registerCallback", "register_goal_callback", "register_preempt_callback"}


def recover_behavior(folder: ValueFolder, ports: list[Port],
                     diagnostics: DiagnosticSink) -> tuple[list[Publish], list[StateWrite]]:
    """The publish calls of a file whose ports were read with `folder` (after its walk), one per
    way each is reached, and the assignments to the state variables their guards test."""
    if not any(port.kind == "publisher" for port in ports):
        return [], []  # publishes nothing of its own (not a node, or a library handed its publishers)
    behavior = Behavior(folder, ports)
    behavior.run()
    if behavior.budget <= 0:
        diagnostics.add(folder.file, 1, "python-behavior",
                        f"more than {BUDGET} paths through the file's functions: the triggers of some publish calls "
                        "are not recovered", "note")
    tested = {g.var for p in behavior.publishes for g in p.guards}
    order = {t: i for i, t in enumerate(TRIGGERS)}
    publishes = sorted(behavior.publishes, key=lambda p: (
        p.line, order[p.trigger], p.source.line if p.source else 0, p.publisher.line if p.publisher else 0,
        [(g.var, g.value, g.line) for g in p.guards], str(p.period)))
    writes = sorted((w for w in behavior.writes if w.var in tested),
                    key=lambda w: (w.line, w.var, w.value, w.source.line if w.source else 0))
    return publishes, writes


class Behavior(Walk):
    """One file: its scopes and state variables, then the walk from every entry."""

    def run(self) -> None:
        """Register callbacks, walk module code, then main and constructors, then the rest."""
        for frame, nodes in [(self.module, self.module_nodes), *self.scopes]:
            for node in nodes:
                if isinstance(node, ast.Call):
                    self.register(node, frame)
        self.walk(self.folder.tree.body, self.module, Context("startup", None))
        for startup in (True, False):  # main and constructors run at start-up; the rest: unknown
            for frame, _nodes in self.scopes:
                func = frame.func
                if id(func) in self.reached:
                    continue
                name = getattr(func, "name", "")
                if startup == ((name == "main" and frame.cls is None and frame.outer is None) or name == "__init__"):
                    self.enter(replace(frame, called=True), Context("startup" if startup else "unknown", None))
        walked = {p.line for p in self.publishes}
        for frame, nodes in [(self.module, self.module_nodes), *self.scopes]:  # past the budget or the depth
            for node in nodes:
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
                        node.func.attr in PUBLISH_METHODS and node.lineno not in walked and \
                        not self.callables(node.func, frame) and (sites := self.publish_sites(node, frame)):
                    self.publish(node, Context("unknown", None), sites)

    def register(self, call: ast.Call, frame: Frame, exact: bool = False) -> None:
        """A call that registers callbacks: each callback is an entry with the port's site. In a
        base class, it registers once for each class of the file made from it (then `exact`)."""
        name = self.folder.qualified(call.func) or ""
        method = call.func.attr if isinstance(call.func, ast.Attribute) else ""
        spec = _REGISTRATIONS.get(name) or _RCLPY_REGISTRATIONS.get(method)
        if frame.cls and not exact and (spec or method in _LATER_REGISTRATIONS):
            concrete = [c for c in [frame.cls, *self.descendants(frame.cls)] if c in self.instantiated]
            if concrete and concrete != [frame.cls]:
                for cls in concrete:
                    self.register(call, replace(frame, cls=cls), exact=True)
                return
        if spec:
            site = Site(self.file, call.lineno)
            if not any(site in self.sites[k] for k in SOURCE_KINDS):
                return
            extra = arg(call, 3, "callback_args") if name == "rospy.Subscriber" else None
            for index, keyword in spec[1]:
                callback = arg(call, index, keyword)
                if callback is not None:
                    self.start(callback, frame, spec[0], site, [(extra, frame)] if extra is not None else [])
        elif method in _LATER_REGISTRATIONS and call.args:
            for site in self.port_sites(call.func.value, frame):  # type: ignore[attr-defined]
                trigger = "timer" if site in self.sites["timer"] else "callback"
                self.start(call.args[0], frame, trigger, site, [(a, frame) for a in call.args[1:]])

    def port_sites(self, expr: ast.expr, frame: Frame) -> list[Site]:
        """The source ports an object stands for: a subscriber, an action server, or the
        subscribers a message_filters synchronizer joins."""
        sites: list[Site] = []
        for origin, where in self.origins(expr, frame):
            site = Site(self.file, origin.lineno)
            if any(site in self.sites[k] for k in SOURCE_KINDS):
                sites.append(site)
            elif (self.folder.qualified(origin.func) or "").endswith("Synchronizer") and origin.args:
                inputs = origin.args[0]
                elements = _members(inputs) if not isinstance(inputs, ast.Name) else \
                    [e for value, _f in self.values(inputs.id, where) for e in _members(value)]
                sites += [s for e in elements for s in self.port_sites(e, where)]
        return list(dict.fromkeys(sites))

    def start(self, callback: ast.expr, frame: Frame, trigger: str, site: Site,
              extra: list[tuple[ast.expr, Frame]]) -> None:
        """Walk each function a callback expression may be, from its registration."""
        for target in self.callables(callback, frame):
            self.enter(self.bind(target, None, frame, extra), Context(trigger, site))



def _members(sequence: ast.AST) -> list[ast.expr]:
    """The element expressions of a literal list or tuple, or the one of a comprehension."""
    if isinstance(sequence, (ast.List, ast.Tuple)):
        return sequence.elts
    return [sequence.elt] if isinstance(sequence, (ast.ListComp, ast.GeneratorExp)) else []
