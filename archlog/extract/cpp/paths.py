"""Inside one C++ function (behavior.py): the state conditions that dominate a point (the
if/else branches and loops around it, early returns, finished wait loops and switch cases before
it) and the endless loop it runs in (`while (ros::ok())`, `for (;;)`, `do ... while (true)`)."""

from __future__ import annotations

import re

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import CursorKey, K, binary_operator, strip, unary_operator
from archlog.extract.cpp.index import Host
from archlog.extract.cpp.periods import Periods
from archlog.extract.cpp.state import Conditions, StateVar, state_var
from archlog.extract.summary import Guard
from archlog.values import Value

_RUNNING = ("ok",)
_STOPPED = ("isShuttingDown", "is_shutdown", "isShutdown")
_ENDLESS_FOR = re.compile(r"(?:\w+(?:::|\.|->))*ok\(\)|true|1|")
_BRANCHING = (K.IF_STMT, K.CONDITIONAL_OPERATOR, K.WHILE_STMT, K.DO_STMT, K.FOR_STMT, K.CXX_FOR_RANGE_STMT)
Atoms = list[tuple[tuple[StateVar, str], ci.Cursor]]  # what a condition requires, and the condition
Local = tuple[tuple[Guard, ...], Value | None, bool]


def running(expr: ci.Cursor) -> bool:
    """ros::ok(), rclcpp::ok(), nh.ok(), !ros::isShuttingDown(), true: holds while the node runs."""
    expr = strip(expr)
    if expr.kind == K.CALL_EXPR:
        return expr.spelling in _RUNNING
    if expr.kind == K.UNARY_OPERATOR and unary_operator(expr) == "!":
        inner = strip(next(expr.get_children()))
        return inner.kind == K.CALL_EXPR and inner.spelling in _STOPPED
    if expr.kind in (K.CXX_BOOL_LITERAL_EXPR, K.INTEGER_LITERAL):
        return "".join(t.spelling for t in expr.get_tokens()) not in ("false", "0", "")
    return False


class Paths:
    """What holds at a point of a function; `vars` collects the state variables met."""

    def __init__(self, host: Host, conditions: Conditions, periods: Periods, vars: dict[str, StateVar]) -> None:
        self.host, self.conditions, self.periods, self.vars = host, conditions, periods, vars
        self._memo: dict[CursorKey, Local] = {}

    def at(self, fid: CursorKey, function: ci.Cursor, point: ci.Cursor) -> Local:
        """The guards that dominate `point` in `function`, and the endless loop it runs in (its
        period, and whether there is one)."""
        memo = (fid, point.extent.start.offset, point.extent.end.offset)
        if memo in self._memo:
            return self._memo[memo]
        path = _path(function, point)
        atoms: Atoms = []
        loop: ci.Cursor | None = None
        for index, node in enumerate(path):
            child = path[index + 1] if index + 1 < len(path) else point
            kind = node.kind
            children = list(node.get_children()) if kind in _BRANCHING else []
            if kind in (K.IF_STMT, K.CONDITIONAL_OPERATOR) and len(children) >= 2 and child != children[0]:
                atoms += [(a, children[0]) for a in self.conditions.atoms(children[0], child == children[1])]
            elif kind == K.WHILE_STMT and len(children) == 2 and child == children[1]:
                atoms += [(a, children[0]) for a in self.conditions.atoms(children[0], True)]
                loop = node if self.endless(children[0]) else loop
            elif kind == K.DO_STMT and len(children) == 2 and child == children[0]:
                loop = node if self.endless(children[1]) else loop
            elif kind == K.FOR_STMT and children and child == children[-1]:
                loop = node if _endless_for(node) else loop
            elif kind == K.CXX_FOR_RANGE_STMT and len(children) >= 3 and child == children[-1]:
                var = state_var(children[1])
                atoms += [((var, "nonempty"), children[1])] if var is not None else []
            elif kind == K.COMPOUND_STMT:
                atoms += self.before(node, child, path[index - 1] if index else None)
        guards: list[Guard] = []
        for (var, value), cond in atoms:
            self.vars.setdefault(var.name, var)
            if all((g.var, g.value) != (var.name, value) for g in guards):
                guards.append(Guard(var.name, value, self.host.shown(cond), cond.location.line))
        result = (tuple(guards), self.periods.of(loop) if loop is not None else None, loop is not None)
        self._memo[memo] = result
        return result

    def endless(self, cond: ci.Cursor) -> bool:
        """A loop condition that holds as long as the node runs, possibly and a state condition
        (`ros::ok() && running_`; not `i < n && ros::ok()`)."""
        cond = strip(cond)
        if cond.kind == K.BINARY_OPERATOR and binary_operator(cond) == "&&":
            parts = list(cond.get_children())
            return any(self.endless(c) for c in parts) and \
                all(self.endless(c) or self.conditions.atoms(c, True) for c in parts)
        return running(cond)

    def before(self, block: ci.Cursor, child: ci.Cursor, parent: ci.Cursor | None) -> Atoms:
        """What the statements of a block before `child` establish: `if (c) return;` leaves
        not-c, a finished wait loop `while (!c) ...` leaves c, a switch case its value."""
        atoms: Atoms = []
        label: ci.Cursor | None = None
        for stmt in block.get_children():
            if stmt == child:
                break
            if stmt.kind in (K.CASE_STMT, K.DEFAULT_STMT):
                label = stmt
            if stmt.kind == K.IF_STMT:
                parts = list(stmt.get_children())
                then_exits = len(parts) >= 2 and _exits(parts[1])
                else_exits = len(parts) == 3 and _exits(parts[2])
                if then_exits != else_exits:
                    atoms += [(a, parts[0]) for a in self.conditions.atoms(parts[0], else_exits)]
            elif stmt.kind == K.WHILE_STMT:
                parts = list(stmt.get_children())
                if len(parts) == 2 and not any(c.kind == K.BREAK_STMT for c in parts[1].walk_preorder()):
                    atoms += [(a, parts[0]) for a in self.conditions.atoms(parts[0], False)]
        if parent is not None and parent.kind == K.SWITCH_STMT:
            label = child if child.kind in (K.CASE_STMT, K.DEFAULT_STMT) else label
            if label is not None and _exits_before(block, label):
                atoms += self.case(parent, label)
        return atoms

    def case(self, switch: ci.Cursor, label: ci.Cursor) -> Atoms:
        """`switch (mode_) { case Mode::AUTO: ... }`: mode_ is AUTO (one label, no fall-through)."""
        parts = list(label.get_children()) if label.kind == K.CASE_STMT else []
        cond = next(switch.get_children(), None)
        if len(parts) < 2 or parts[1].kind == K.CASE_STMT or cond is None:
            return []
        return [(a, cond) for a in self.conditions.compare("==", cond, parts[0])]


def _path(top: ci.Cursor, target: ci.Cursor) -> list[ci.Cursor]:
    """The cursors from `top` down to `target`'s parent (empty when it is not below `top`)."""
    start, end = target.extent.start.offset, target.extent.end.offset
    path, node = [], top
    for _ in range(200):
        path.append(node)
        child = next((c for c in node.get_children()
                      if c.extent.start.offset <= start and end <= c.extent.end.offset), None)
        if child is None or child == target:
            return path if child is not None else []
        node = child
    return []


def _endless_for(loop: ci.Cursor) -> bool:
    """`for (;;)` or a for loop whose condition is ros::ok()."""
    words = [t.spelling for t in loop.get_tokens()]
    if "(" not in words:
        return False
    depth, parts, current = 0, list[str](), list[str]()
    for word in words[words.index("(") + 1:]:
        if word == ")" and depth == 0:
            break
        depth += word in ("(", "[", "{")
        depth -= word in (")", "]", "}")
        if word == ";" and depth == 0:
            parts.append("".join(current))
            current = []
        else:
            current.append(word)
    return len(parts) >= 2 and bool(_ENDLESS_FOR.fullmatch(parts[1]))


def _exits(stmt: ci.Cursor) -> bool:
    """A statement after which the code that follows does not run (return, continue, break, throw)."""
    kind = stmt.kind
    if kind in (K.RETURN_STMT, K.CONTINUE_STMT, K.BREAK_STMT, K.CXX_THROW_EXPR):
        return True
    if kind == K.COMPOUND_STMT:
        children = list(stmt.get_children())
        return bool(children) and _exits(children[-1])
    if kind == K.IF_STMT:
        parts = list(stmt.get_children())
        return len(parts) == 3 and _exits(parts[1]) and _exits(parts[2])
    if kind in (K.CALL_EXPR, K.UNEXPOSED_EXPR):
        inner = strip(stmt)
        return inner.kind == K.CXX_THROW_EXPR or (inner.kind == K.CALL_EXPR and inner.spelling in
                                                   ("exit", "abort", "_exit", "quick_exit"))
    return False


def _exits_before(block: ci.Cursor, label: ci.Cursor) -> bool:
    """The statement before a case label leaves the switch (no fall-through into it)."""
    previous = None
    for stmt in block.get_children():
        if stmt == label:
            break
        previous = stmt
    if previous is None:
        return True
    while previous.kind in (K.CASE_STMT, K.DEFAULT_STMT) and (parts := list(previous.get_children())):
        previous = parts[-1]
    return _exits(previous)
