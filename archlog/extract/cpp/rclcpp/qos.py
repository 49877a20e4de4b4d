"""The QoS of rclcpp publishers and subscriptions: a depth, rclcpp::QoS(...) and its presets,
builder chains, rmw profiles, classes derived from rclcpp::QoS, and variables holding any of
these with the statements changing them."""

from __future__ import annotations

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import SKIP, K, qualified, strip, written_args
from archlog.extract.cpp.rclcpp.api import chain_root, default_argument, object_of, parameter_names, tokens
from archlog.extract.cpp.rclcpp.context import WalkContext
from archlog.extract.cpp.rclcpp.definitions import Definitions
from archlog.extract.cpp.rclcpp.durations import Durations
from archlog.extract.cpp.rclcpp.qos_changes import Mutation, QosChanges
from archlog.extract.qos import FIXED_SETTERS, PRESET_NAMES, Qos, number, seconds_text

_RMW_FIELDS = ("history", "depth", "reliability", "durability", "deadline", "lifespan", "liveliness",
               "liveliness_lease_duration")
_INTEGERS = (ci.TypeKind.INT, ci.TypeKind.UINT, ci.TypeKind.LONG, ci.TypeKind.ULONG, ci.TypeKind.LONGLONG,
             ci.TypeKind.ULONGLONG, ci.TypeKind.SHORT, ci.TypeKind.USHORT, ci.TypeKind.UCHAR, ci.TypeKind.SCHAR)


def derives_from_qos(cls: ci.Cursor | None, depth: int = 0) -> bool:
    """A class derived (directly or not) from rclcpp::QoS, other than rclcpp's own presets."""
    if cls is None or depth > 6 or qualified(cls).startswith("rclcpp::"):
        return False
    definition = cls.get_definition() or cls
    return any(qualified(base.referenced) == "rclcpp::QoS" or derives_from_qos(base.referenced, depth + 1)
               for base in definition.get_children() if base.kind == K.CXX_BASE_SPECIFIER and base.referenced)


def builtin_qos(partial: Qos) -> tuple[tuple[str, str], ...]:
    """A library's own QoS: rclcpp::QoS(depth) with the given changes."""
    qos = Qos.preset("default")
    qos.policies.update(partial.policies)
    return qos.facts()


class QosReader:
    """Reads the QoS argument of an entity: its policies, or what is unknown about them."""

    def __init__(self, ctx: WalkContext, durations: Durations, changes: QosChanges, definitions: Definitions) -> None:
        self.ctx, self.durations, self.changes, self.definitions = ctx, durations, changes, definitions

    def facts(self, expr: ci.Cursor | None, at: ci.Cursor, default: str | None = None) -> tuple[tuple[str, str], ...]:
        """The QoS facts of an entity's QoS argument (`default`: the preset when there is none)."""
        if expr is None:
            return Qos.preset(default).facts() if default else Qos.unknown(tokens(at)).facts()
        return self.qos_value(expr, 0).facts()

    def qos_value(self, expr: ci.Cursor, depth: int) -> Qos:
        """Read a QoS expression: a depth, rclcpp::QoS(...) and its presets, builder chains, rmw
        profiles, and variables holding any of these (with the statements changing them)."""
        text = tokens(expr)
        expr = strip(expr)
        if depth > 10:
            return Qos.unknown(text)
        type_name = expr.type.get_canonical().spelling
        if expr.kind == K.INTEGER_LITERAL or expr.type.get_canonical().kind in _INTEGERS:
            return self.depth_qos(expr, text)
        if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None:
            return self.qos_variable(expr, depth, text)
        if expr.kind == K.INIT_LIST_EXPR and "rmw_qos_profile" in type_name:
            return self.rmw_aggregate(expr, text)
        if expr.kind != K.CALL_EXPR or expr.referenced is None:
            return Qos.unknown(text)
        ref, args = expr.referenced, written_args(expr)
        owner = qualified(ref.semantic_parent)
        cls = owner.rsplit("::", 1)[-1]
        if ref.kind == K.CONSTRUCTOR and owner.startswith("rclcpp::") and PRESET_NAMES.get(cls) and cls != "QoS":
            qos = Qos.preset(PRESET_NAMES[cls])
            if args:
                qos.initialise(*self.qos_initialization(args[0], depth), text)
            return qos
        if ref.kind == K.CONSTRUCTOR and owner == "rclcpp::QoS":
            return self.qos_constructed(args, depth, text)
        if ref.kind == K.CONSTRUCTOR and derives_from_qos(ref.semantic_parent):
            return self.qos_subclass(ref, args, depth, text)
        if owner == "rclcpp::QoS" and ref.spelling in ("get_rmw_qos_profile",):
            obj = object_of(expr)
            return self.qos_value(obj, depth + 1) if obj is not None else Qos.unknown(text)
        if owner == "rclcpp::QoS" and ref.kind == K.CXX_METHOD:
            obj = object_of(expr)
            base = self.qos_value(obj, depth + 1).copy() if obj is not None else Qos.unknown(text)
            self.qos_apply(base, ref.spelling, args[0] if args else None, text)
            return base
        if ref.kind == K.CONSTRUCTOR and len(args) == 1:  # a copy
            return self.qos_value(args[0], depth + 1)
        if ref.kind in (K.FUNCTION_DECL, K.CXX_METHOD) and (body := self.single_return(ref)) is not None:
            return self.qos_value(body, depth + 1)
        return Qos.unknown(text)

    def qos_subclass(self, ctor: ci.Cursor, args: list[ci.Cursor], depth: int, text: str) -> Qos:
        """A class derived from rclcpp::QoS (nav2::qos::LatchedPublisherQoS): its constructor's
        base initializer, with the arguments (or defaults) bound to its parameters, then the
        builder calls its body makes on `this`."""
        definition = ctor.get_definition()
        if definition is None:
            return Qos.unknown(text)
        params = [c for c in definition.get_children() if c.kind == K.PARM_DECL]
        bound = {self.ctx.key(p): args[i] if i < len(args) else default_argument(definition, i)
                 for i, p in enumerate(params)}
        if any(value is None for value in bound.values()):
            return Qos.unknown(text)
        children = list(definition.get_children())
        body = next((c for c in children if c.kind == K.COMPOUND_STMT), None)
        base = next((c for c in children if c.kind in (K.CALL_EXPR, K.UNEXPOSED_EXPR)
                     and (body is None or c.extent.start.offset < body.extent.start.offset)), None)
        self.ctx.bindings.update(bound)
        try:
            qos = self.qos_value(base, depth + 1).copy() if base is not None else Qos.unknown(text)
            for stmt in body.get_children() if body is not None else []:
                call = strip(stmt)
                root = chain_root(call) if call.kind == K.CALL_EXPR and call.referenced is not None and \
                    qualified(call.referenced.semantic_parent) == "rclcpp::QoS" else None
                if root is not None and root.kind == K.CXX_THIS_EXPR:
                    qos = self.replay(qos, call, depth + 1)
                else:
                    qos.unread.append(text)
        finally:
            for key in bound:
                self.ctx.bindings.pop(key, None)
        return qos

    def depth_qos(self, expr: ci.Cursor, text: str) -> Qos:
        qos = Qos.preset("default")
        value = self.ctx.value(expr)
        qos.initialise("keep_last", value if isinstance(value, str) and number(value) is not None else None, text)
        return qos

    def qos_constructed(self, args: list[ci.Cursor], depth: int, text: str) -> Qos:
        """rclcpp::QoS(depth), QoS(KeepLast(n)), QoS(initialization, rmw_profile), a copy."""
        if not args:
            return Qos.unknown(text)
        first = strip(args[0])
        first_type = first.type.get_canonical().spelling
        if first.type.get_canonical().kind in _INTEGERS or first.kind == K.INTEGER_LITERAL:
            return self.depth_qos(first, text)
        if "QoSInitialization" in first_type or "KeepLast" in first_type or "KeepAll" in first_type:
            qos = self.qos_value(args[1], depth + 1).copy() if len(args) > 1 else Qos.preset("default")
            if len(args) == 1:
                qos.profile = ""
            qos.initialise(*self.qos_initialization(args[0], depth), text)
            return qos
        return self.qos_value(args[0], depth + 1)

    def qos_initialization(self, expr: ci.Cursor, depth: int) -> tuple[str | None, str | None]:
        """History and depth of a QoSInitialization: KeepLast(n), KeepAll(), from_rmw(profile)."""
        expr = strip(expr)
        if expr.kind == K.CALL_EXPR and expr.referenced is not None:
            owner, args = qualified(expr.referenced.semantic_parent), written_args(expr)
            if owner == "rclcpp::KeepAll" or expr.spelling == "KeepAll":
                return "keep_all", None
            if (owner == "rclcpp::KeepLast" or expr.spelling == "KeepLast") and args:
                value = self.ctx.value(args[0])
                return "keep_last", value if isinstance(value, str) and number(value) is not None else None
            if expr.spelling == "from_rmw" and args:
                profile = self.qos_value(args[0], depth + 1)
                return profile.policies.get("history"), profile.policies.get("depth")
            if expr.referenced.kind == K.CONSTRUCTOR and len(args) == 1:
                return self.qos_initialization(args[0], depth + 1)
        return None, None

    def qos_apply(self, qos: Qos, method: str, arg: ci.Cursor | None, text: str) -> None:
        """One builder method: .reliable(), .keep_last(5), .durability(...), .deadline(100ms)..."""
        if arg is None:
            qos.apply(method, None, text)
        elif method in ("deadline", "lifespan", "liveliness_lease_duration"):
            seconds = self.durations.seconds(arg)
            qos.apply(method, seconds_text(seconds) if seconds is not None else None, text)
        elif method in ("keep_last", "depth"):
            value = self.ctx.value(arg)
            qos.apply(method, value if isinstance(value, str) and number(value) is not None else None, text)
        elif method in ("history", "reliability", "durability", "liveliness"):
            qos.apply(method, self.enum_spelling(arg), text)

    def enum_spelling(self, expr: ci.Cursor, depth: int = 0) -> str | None:
        """The enumerator an expression names (`rclcpp::ReliabilityPolicy::BestEffort`,
        `RMW_QOS_POLICY_RELIABILITY_RELIABLE`), through constants."""
        expr = strip(expr)
        if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None and depth < 4:
            ref = expr.referenced
            if ref.kind == K.ENUM_CONSTANT_DECL:
                return qualified(ref)
            init = [c for c in ref.get_children() if c.kind not in SKIP]
            if ref.kind == K.VAR_DECL and init and ref.type.is_const_qualified():
                return self.enum_spelling(init[-1], depth + 1)
        return None

    def qos_variable(self, expr: ci.Cursor, depth: int, text: str) -> Qos:
        """A variable or member holding a QoS or an rmw profile: its initial value, then the
        statements before this use that change it (in a condition: the policy is unknown)."""
        decl = expr.referenced
        if decl.spelling in PRESET_NAMES and not self.ctx.in_main(decl):
            return Qos.preset(PRESET_NAMES[decl.spelling])
        if decl.kind == K.PARM_DECL:
            return self.qos_parameter(decl, expr, depth, text)
        if decl.kind not in (K.VAR_DECL, K.FIELD_DECL):
            return Qos.unknown(text)
        init = [c for c in decl.get_children() if c.kind not in SKIP]
        initial = init[-1] if init else self.definitions.member_initializer(decl)
        if initial is None:
            return Qos.unknown(text)
        qos = self.qos_value(initial, depth + 1).copy()
        for change in sorted(self.changes.mutations.get(self.ctx.key(decl), []), key=lambda m: m.offset):
            if change.offset < expr.extent.start.offset or not self.definitions.same_function(change.expr, expr):
                self.qos_mutation(qos, change, decl, depth)
        return qos

    def qos_mutation(self, qos: Qos, change: Mutation, decl: ci.Cursor, depth: int) -> None:
        expr, text = change.expr, tokens(change.expr)
        if expr.kind == K.BINARY_OPERATOR:
            lhs, rhs = [strip(c) for c in expr.get_children()][:2]
            field_name = lhs.spelling if lhs.kind == K.MEMBER_REF_EXPR and lhs.referenced != decl else None
            if field_name is None:
                replaced = self.qos_value(rhs, depth + 1)
                qos.policies, qos.profile, qos.unread = replaced.policies, replaced.profile, replaced.unread
            elif field_name in _RMW_FIELDS:
                self.qos_apply(qos, field_name, rhs, text)
        elif expr.kind == K.CALL_EXPR:
            replayed = self.replay(qos, expr, depth)
            qos.policies, qos.profile, qos.unread = replayed.policies, replayed.profile, replayed.unread
        if change.conditional:
            for method in self.changed_policies(expr):
                qos.set(method, None, text)

    def replay(self, qos: Qos, call: ci.Cursor, depth: int) -> Qos:
        """Apply a statement's chain of builder calls (`qos.keep_last(5).reliable();`) to `qos`."""
        chain: list[ci.Cursor] = []
        expr = strip(call)
        while expr.kind == K.CALL_EXPR and expr.referenced is not None and \
                qualified(expr.referenced.semantic_parent) == "rclcpp::QoS":
            chain.append(expr)
            obj = object_of(expr)
            if obj is None:
                break
            expr = strip(obj)
        result = qos.copy()
        if expr.kind == K.CALL_EXPR and expr.spelling == "operator=":
            return self.qos_value(written_args(expr)[-1], depth + 1)
        for link in reversed(chain):
            args = written_args(link)
            if link.spelling == "operator=" and args:
                result = self.qos_value(args[-1], depth + 1).copy()
            else:
                self.qos_apply(result, link.spelling, args[0] if args else None, tokens(link))
        return result

    @staticmethod
    def changed_policies(expr: ci.Cursor) -> list[str]:
        """The policies a statement may change (for statements that run only under a condition)."""
        words = {t.spelling for t in expr.get_tokens()}
        found = [FIXED_SETTERS[w][0] for w in words if w in FIXED_SETTERS]
        found += [w for w in words if w in _RMW_FIELDS]
        found += ["depth"] if "keep_last" in words else []
        return found

    def qos_parameter(self, decl: ci.Cursor, expr: ci.Cursor, depth: int, text: str) -> Qos:
        """A function parameter: the QoS all call sites in this file pass."""
        function = decl.semantic_parent
        params = parameter_names(function) if function is not None else []
        index = params.index(decl.spelling) if decl.spelling in params else -1
        sites = self.ctx.call_sites.get(self.ctx.key(function.canonical), []) if index >= 0 else []
        found = [self.qos_value(args[index], depth + 1) for site in sites if len(args := written_args(site)) > index]
        if found and all(q.facts() == found[0].facts() for q in found):
            return found[0]
        return Qos.unknown(text)

    def rmw_aggregate(self, expr: ci.Cursor, text: str) -> Qos:
        """rmw_qos_profile_t p = {history, depth, reliability, durability, deadline, ...}."""
        qos = Qos({}, "")
        for field_name, value in zip(_RMW_FIELDS, expr.get_children()):
            self.qos_apply(qos, field_name, value, text)
        return qos

    def single_return(self, function: ci.Cursor) -> ci.Cursor | None:
        """The expression of a function in this file whose body is one return statement."""
        definition = function.get_definition()
        if definition is None or not self.ctx.in_main(definition):
            return None
        body = next((c for c in definition.get_children() if c.kind == K.COMPOUND_STMT), None)
        statements = list(body.get_children()) if body is not None else []
        if len(statements) == 1 and statements[0].kind == K.RETURN_STMT:
            return next(statements[0].get_children(), None)
        return None
