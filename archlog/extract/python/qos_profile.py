"""QoS profiles of rclpy publishers and subscriptions: a depth, a preset, a QoSProfile(...) call,
or a variable holding one with the attributes set on it before the call."""

from __future__ import annotations

import ast
from fractions import Fraction

from archlog.extract.python.fold import ValueFolder
from archlog.extract.python.index import Function, arg, in_scope, is_self_attr
from archlog.extract.qos import DURATIONS, Qos, number, preset_name, seconds_text

_BRANCHING = (ast.If, ast.For, ast.While, ast.Try, ast.AsyncFor, ast.Match)


class QosReader:
    """The QoS of a publisher or subscription, folded with the file's values."""

    def __init__(self, folder: ValueFolder) -> None:
        self.folder = folder

    def facts(self, expr: ast.expr | None, scope: Function | None) -> tuple[tuple[str, str], ...]:
        """QoS policies from a depth, a preset, a QoSProfile(...) call, or a variable holding one
        (with the attributes set on it before the call)."""
        return self.qos_value(expr, 0, scope, expr.lineno).facts() if expr is not None else ()

    def qos_value(self, expr: ast.expr, depth: int, scope: Function | None, line: int) -> Qos:
        """The profile an expression gives, read in `scope`."""
        text = ast.unparse(expr)
        if depth > 8:
            return Qos.unknown(text)
        name = self.folder.qualified(expr)
        if name and (preset := preset_name(name)) and not (isinstance(expr, ast.Name) and self.assigned(expr, scope)):
            return Qos.preset(preset)
        if isinstance(expr, ast.Call):
            func = self.folder.qualified(expr.func) or ""
            if func.endswith("QoSProfile"):
                return self.qos_profile(expr, scope)
            if func in ("copy.copy", "copy.deepcopy") and expr.args:
                return self.qos_value(expr.args[0], depth + 1, scope, line)
            if func.endswith("QoSPresetProfiles.get_from_short_key") and expr.args and \
                    isinstance(expr.args[0], ast.Constant) and (preset := preset_name(
                        f"QoSPresetProfiles.{str(expr.args[0].value).upper()}")):
                return Qos.preset(preset)
        if isinstance(expr, ast.Name) and (assigned := self.assigned(expr, scope)):
            module_level = [e for e in self.folder.module_assigns.get(expr.id, []) if isinstance(e, ast.expr)]
            where = None if assigned == module_level else scope
            qos = self.one_qos([(value, where) for value in assigned], depth, line, text)
            for target, value, conditional in self.attribute_sets(expr.id, where, line):
                self.qos_set(qos, target, value, where)
                if conditional:
                    qos.set(target, None, ast.unparse(value))
            return qos
        if isinstance(expr, ast.Name) and scope is not None and expr.id in [a.arg for a in scope.node.args.args +
                                                                            scope.node.args.kwonlyargs]:
            passed = [(e, caller) for e, caller in self.folder.arguments(scope, expr.id) if e is not None]
            return self.one_qos(passed, depth, line, text) if passed else Qos.unknown(text)
        if is_self_attr(expr) and scope is not None and scope.cls and \
                (values := self.folder.class_attrs.get(scope.cls, {}).get(expr.attr)):
            last = values[-1]
            return self.qos_value(last, depth + 1, self.folder.attr_scope.get(id(last), scope), line) \
                if isinstance(last, ast.expr) else Qos.unknown(text)
        folded = self.folder.value(expr, scope=scope)
        if isinstance(folded, str) and number(folded) is not None:
            qos = Qos.preset("default")
            qos.initialise("keep_last", folded, text)
            return qos
        return Qos.unknown(text)

    def one_qos(self, sources: list[tuple[ast.expr, Function | None]], depth: int, line: int, text: str) -> Qos:
        """The QoS several expressions agree on (if/else branches, call sites), else unknown."""
        found = [self.qos_value(e, depth + 1, where, getattr(e, "lineno", line)) for e, where in sources]
        if found and all(q.facts() == found[0].facts() for q in found):
            return found[0].copy()
        return Qos.unknown(text)

    def assigned(self, expr: ast.Name, scope: Function | None) -> list[ast.expr]:
        """The values assigned to a name, in its function or else at module level."""
        found = scope.assigns.get(expr.id) if scope is not None else None
        found = found if found else self.folder.module_assigns.get(expr.id, [])
        return [e for e in found if isinstance(e, ast.expr)]

    def attribute_sets(self, variable: str, scope: Function | None, line: int) -> list[tuple[str, ast.expr, bool]]:
        """`variable.policy = value` statements before `line`, in the function (or module), and
        whether they run only under a condition (in an if, a loop, a try)."""
        body = scope.node.body if scope is not None else self.folder.tree.body
        conditional = {id(n) for block in in_scope(body) if isinstance(block, _BRANCHING)
                       for child in ast.iter_child_nodes(block) for n in in_scope([child])}
        return [(target.attr, node.value, id(node) in conditional) for node in in_scope(body)
                if isinstance(node, ast.Assign) and node.lineno < line for target in node.targets
                if isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name)
                and target.value.id == variable]

    def qos_profile(self, call: ast.Call, scope: Function | None) -> Qos:
        """QoSProfile(history=..., depth=..., reliability=..., ...): rmw's default profile for
        what is not given; a depth without a history means keep_last."""
        qos = Qos.preset("default")
        given = {kw.arg for kw in call.keywords}
        if "depth" in given and "history" not in given:
            qos.set("history", "keep_last", ast.unparse(call))
        for kw in call.keywords:
            if kw.arg is not None:
                self.qos_set(qos, kw.arg, kw.value, scope)
        return qos

    def qos_set(self, qos: Qos, policy: str, value: ast.expr, scope: Function | None) -> None:
        """One policy from a QoSProfile keyword or an attribute assignment."""
        text = ast.unparse(value)
        if policy in DURATIONS:
            seconds = self.seconds(value, scope)
            qos.apply(policy, seconds_text(seconds) if seconds is not None else None, text)
        elif policy == "depth":
            depth = self.folder.value(value, scope=scope)
            qos.apply("depth", depth if isinstance(depth, str) and number(depth) is not None else None, text)
        else:
            qos.apply(policy, self.folder.qualified(value) or text, text)

    def seconds(self, expr: ast.expr, scope: Function | None) -> Fraction | None:
        """Seconds of rclpy's Duration(seconds=..., nanoseconds=...) (also builtin_interfaces'
        Duration(sec=..., nanosec=...)); None when not known."""
        if not (isinstance(expr, ast.Call) and (self.folder.qualified(expr.func) or "").endswith("Duration")):
            if isinstance(expr, ast.Name) and (assigned := self.assigned(expr, scope)):
                return self.seconds(assigned[-1], scope)
            return None
        total = Fraction(0)
        for index, (keyword, alias, scale) in enumerate((("seconds", "sec", 1), ("nanoseconds", "nanosec", 10 ** 9))):
            part = arg(expr, index, keyword) or next((kw.value for kw in expr.keywords if kw.arg == alias), None)
            if part is None:
                continue
            value = self.folder.value(part, scope=scope)
            amount = number(value) if isinstance(value, str) else None
            if amount is None:
                return None
            total += amount / scale
        return total

