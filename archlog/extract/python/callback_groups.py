"""Whether an rclpy timer's callback runs at the timer's period: rclpy's own callback groups let it run
each time; a group of the program's own (a CallbackGroup subclass deciding `can_execute`) may hold it
back, so its period says nothing of when the callback runs."""

from __future__ import annotations

import ast

STANDARD = frozenset({"MutuallyExclusiveCallbackGroup", "ReentrantCallbackGroup"})


def standard_group(expr: ast.expr | None, tree: ast.Module) -> bool:
    """The `callback_group` argument is absent, None, or one of rclpy's groups (made there, or every
    assignment of the name or attribute passed makes one)."""
    if expr is None or isinstance(expr, ast.Constant) and expr.value is None:
        return True
    if isinstance(expr, ast.Call):
        return _named(expr.func) in STANDARD
    name = expr.id if isinstance(expr, ast.Name) else expr.attr if isinstance(expr, ast.Attribute) else None
    values = [node.value for node in ast.walk(tree) if isinstance(node, ast.Assign)
              for target in node.targets if name is not None and _named(target) == name]
    return bool(values) and all(isinstance(v, ast.Call) and _named(v.func) in STANDARD for v in values)


def _named(expr: ast.expr) -> str | None:
    return expr.id if isinstance(expr, ast.Name) else expr.attr if isinstance(expr, ast.Attribute) else None
