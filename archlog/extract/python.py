"""rospy nodes: recover init_node, publishers, subscribers, services and params with Python's ast."""

from __future__ import annotations

import ast
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.summary import NodeSummary, Port
from archlog.values import ParamRef, Unknown, Value, concat

# rospy callable -> (port kind, index of the name argument, index and keyword of the type argument)
_PORTS: dict[str, tuple[str, str]] = {
    "rospy.Publisher": ("publisher", "data_class"),
    "rospy.Subscriber": ("subscriber", "data_class"),
    "rospy.Service": ("service_server", "service_class"),
    "rospy.ServiceProxy": ("service_client", "service_class"),
    "actionlib.SimpleActionServer": ("action_server", "ActionSpec"),
    "actionlib.SimpleActionClient": ("action_client", "action_spec"),
}
_PARAM_READS = {"rospy.get_param", "rospy.search_param", "rospy.has_param"}
_IDENTITY = {"rospy.resolve_name", "str"}


def extract_python(path: Path, package: str, executable: str, shown: str, diagnostics: DiagnosticSink) -> NodeSummary:
    """Read one rospy script; never imports or runs it."""
    summary = NodeSummary(package, executable, "python")
    try:
        source = path.read_bytes().decode("utf-8", errors="replace")
        tree = ast.parse(source, filename=str(path))
    except SyntaxError as exc:
        diagnostics.add(shown, exc.lineno or 1, "python-syntax",
                        f"does not parse as Python 3 ({exc.msg}); its ROS calls are not recovered", "error")
        summary.incomplete = f"{shown}:{exc.lineno or 1}: does not parse as Python 3"
        return summary
    except OSError as exc:
        diagnostics.add(shown, 1, "python-read", f"cannot read: {exc.strerror}", "error")
        summary.incomplete = f"{shown}: cannot be read"
        return summary
    _Visitor(summary, shown).visit(tree)
    return summary


class _Visitor(ast.NodeVisitor):
    def __init__(self, summary: NodeSummary, shown: str) -> None:
        self.summary, self.file = summary, shown
        self.aliases: dict[str, str] = {}
        self.constants: dict[str, ast.expr] = {}

    # -- module context -----------------------------------------------------------------
    def visit_Module(self, node: ast.Module) -> None:
        for stmt in ast.walk(node):
            if isinstance(stmt, ast.Import):
                for a in stmt.names:
                    self.aliases[a.asname or a.name.split(".")[0]] = a.name if a.asname else a.name.split(".")[0]
            elif isinstance(stmt, ast.ImportFrom) and stmt.module and not stmt.level:
                for a in stmt.names:
                    self.aliases[a.asname or a.name] = f"{stmt.module}.{a.name}"
        for stmt in node.body:
            if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 and isinstance(stmt.targets[0], ast.Name):
                name = stmt.targets[0].id
                self.constants[name] = stmt.value if name not in self.constants else ast.Constant(None)
        self.generic_visit(node)

    def qualified(self, expr: ast.expr) -> str | None:
        if isinstance(expr, ast.Name):
            return self.aliases.get(expr.id, expr.id)
        if isinstance(expr, ast.Attribute):
            base = self.qualified(expr.value)
            return f"{base}.{expr.attr}" if base else None
        return None

    # -- values -------------------------------------------------------------------------
    def unknown(self, expr: ast.expr) -> Unknown:
        return Unknown(ast.unparse(expr), self.file, expr.lineno)

    def value(self, expr: ast.expr | None, depth: int = 0) -> Value:
        if expr is None or depth > 8:
            return Unknown("<missing>", self.file, 0) if expr is None else self.unknown(expr)
        if isinstance(expr, ast.Constant) and isinstance(expr.value, str):
            return expr.value
        if isinstance(expr, ast.Constant) and isinstance(expr.value, (int, float, bool)):
            return str(expr.value).lower() if isinstance(expr.value, bool) else str(expr.value)
        if isinstance(expr, ast.Name) and isinstance(self.constants.get(expr.id), ast.expr):
            const = self.constants[expr.id]
            if not (isinstance(const, ast.Constant) and const.value is None):
                return self.value(const, depth + 1)
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Add):
            return concat(self.value(expr.left, depth + 1), self.value(expr.right, depth + 1))
        if isinstance(expr, ast.JoinedStr):
            parts = [self.value(v.value if isinstance(v, ast.FormattedValue) and v.conversion == -1
                                and v.format_spec is None else v, depth + 1) for v in expr.values]
            return concat(*parts)
        if isinstance(expr, ast.Call):
            func = self.qualified(expr.func)
            if func in _PARAM_READS and func == "rospy.get_param" and expr.args:
                name = self.value(expr.args[0], depth + 1)
                default = self.arg(expr, 1, "default")
                if isinstance(name, str):
                    return ParamRef(name, self.value(default, depth + 1) if default is not None
                                    else self.unknown(expr), "", self.file, expr.lineno)
            if func in _IDENTITY and len(expr.args) == 1:
                return self.value(expr.args[0], depth + 1)
        return self.unknown(expr)

    def message_type(self, expr: ast.expr | None) -> Value:
        name = self.qualified(expr) if expr is not None else None
        parts = name.split(".") if name else []
        if len(parts) == 3 and parts[1] in ("msg", "srv"):
            base = parts[2]
            if parts[1] == "msg" and base.endswith("Action"):
                base = base[: -len("Action")]
            return f"{parts[0]}/{base}"
        return self.unknown(expr) if expr is not None else Unknown("<missing type>", self.file, 0)

    @staticmethod
    def arg(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
        for kw in call.keywords:
            if kw.arg == keyword:
                return kw.value
        return call.args[index] if len(call.args) > index else None

    # -- calls --------------------------------------------------------------------------
    def visit_Call(self, node: ast.Call) -> None:
        func = self.qualified(node.func)
        if func == "rospy.init_node":
            self.summary.default_name = self.value(self.arg(node, 0, "name"))
            self.summary.name_file, self.summary.name_line = self.file, node.lineno
            anon = self.arg(node, 2, "anonymous")
            self.summary.anonymous = isinstance(anon, ast.Constant) and anon.value is True
        elif func in _PORTS:
            kind, type_kw = _PORTS[func]
            self.add(kind, node, self.value(self.arg(node, 0, "name")), self.message_type(self.arg(node, 1, type_kw)))
        elif func == "rospy.get_param" and node.args:
            default = self.arg(node, 1, "default")
            self.add("param_read", node, self.value(node.args[0]), "",
                     self.value(default) if default is not None else None)
        self.generic_visit(node)

    def add(self, kind: str, node: ast.Call, name: Value, type_: Value, default: Value | None = None) -> None:
        self.summary.ports.append(Port(kind, name, type_, self.file, node.lineno, node.col_offset + 1, "", default))
