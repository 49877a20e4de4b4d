"""roscpp nodes: recover ros::init, NodeHandles and their API calls with libclang."""

from __future__ import annotations

import glob
import re
import shutil
import subprocess
from functools import lru_cache
from pathlib import Path

import clang.cindex as ci

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.summary import NodeSummary, Port
from archlog.values import ParamRef, Unknown, Value, concat

K = ci.CursorKind
# NodeHandle method -> port kind
_METHODS = {
    "advertise": "publisher", "subscribe": "subscriber",
    "advertiseService": "service_server", "serviceClient": "service_client",
}
_PARAM_METHODS = {"param", "getParam", "getParamCached"}
_KEEP_GOING = 0x200
_MSG_TYPE = re.compile(r"\b(\w+)::(\w+?)(?:Request|Response)?_<")
_PLAIN_TYPE = re.compile(r"\b(?!std\b|boost\b|ros\b)(\w+)::(\w+?)(?:Request|Response)?(?:::(?:Const)?Ptr|ConstPtr)?\b")


@lru_cache(maxsize=1)
def resource_dir() -> str | None:
    """clang's builtin headers, which the PyPI libclang wheel does not ship."""
    clang = shutil.which("clang") or shutil.which("clang-14")
    if clang:
        out = subprocess.run([clang, "-print-resource-dir"], capture_output=True, text=True, check=False)
        if out.returncode == 0 and Path(out.stdout.strip(), "include").is_dir():
            return out.stdout.strip()
    found = sorted(glob.glob("/usr/lib/llvm-*/lib/clang/*/include/stddef.h"), reverse=True)
    return str(Path(found[0]).parent.parent) if found else None


def include_dirs(extra: list[Path]) -> list[str]:
    dirs = [str(p) for p in extra if p.is_dir()]
    dirs += sorted(glob.glob("/opt/ros/*/include"))
    return dirs + ["/usr/include"]


def extract_cpp(sources: list[Path], package: str, executable: str, includes: list[Path],
                display: "callable[[Path], str]", diagnostics: DiagnosticSink) -> NodeSummary:
    """Parse each source of one executable; a file that fails becomes a diagnostic."""
    summary = NodeSummary(package, executable, "cpp")
    args = ["-x", "c++", "-std=c++17", *(f"-I{d}" for d in include_dirs(includes))]
    rdir = resource_dir()
    if rdir:
        args += ["-resource-dir", rdir]
    index = ci.Index.create()
    for source in sources:
        shown = display(source)
        if not source.is_file():
            diagnostics.add(shown, 1, "cpp-missing", "source file listed in CMakeLists.txt does not exist", "error")
            summary.incomplete = summary.incomplete or f"{shown}: missing"
            continue
        try:
            tu = index.parse(str(source), args=args, options=_KEEP_GOING)
        except ci.TranslationUnitLoadError as exc:
            diagnostics.add(shown, 1, "cpp-parse", f"libclang could not parse this file: {exc}", "error")
            summary.incomplete = summary.incomplete or f"{shown}: could not be parsed"
            continue
        for diag in tu.diagnostics:
            if diag.severity >= ci.Diagnostic.Error and diag.location.file and \
                    Path(diag.location.file.name) == source:
                diagnostics.add(shown, diag.location.line, "cpp-compile",
                                f"C++ does not compile here ({diag.spelling}); recovery may be partial", "warning")
                summary.incomplete = summary.incomplete or f"{shown}:{diag.location.line}: does not compile"
                break
        _Walker(summary, source, shown).walk(tu.cursor)
    return summary


class _Walker:
    def __init__(self, summary: NodeSummary, source: Path, shown: str) -> None:
        self.summary, self.source, self.file = summary, str(source), shown
        self.handles: dict[tuple, Value] = {}
        self.param_vars: dict[tuple, Value] = {}
        self.call_sites: dict[tuple, list[ci.Cursor]] = {}

    @staticmethod
    def key(decl: ci.Cursor | None) -> tuple | None:
        if decl is None or decl.location.file is None:
            return None
        return (decl.location.file.name, decl.location.line, decl.location.column)

    def in_main(self, cursor: ci.Cursor) -> bool:
        loc = cursor.location
        return loc.file is not None and loc.file.name == self.source

    def unknown(self, cursor: ci.Cursor, why: str = "") -> Unknown:
        text = " ".join(t.spelling for t in cursor.get_tokens())[:120] or cursor.spelling
        return Unknown(text + (f" ({why})" if why else ""), self.file, cursor.location.line)

    # -- traversal ------------------------------------------------------------------------
    def walk(self, root: ci.Cursor) -> None:
        cursors = [c for c in root.walk_preorder() if self.in_main(c)]
        for cursor in cursors:
            if cursor.kind == K.CALL_EXPR and cursor.referenced is not None:
                self.call_sites.setdefault(self.key(cursor.referenced), []).append(cursor)
        for cursor in cursors:
            if cursor.kind == K.CONSTRUCTOR:
                self.member_inits(cursor)
        for cursor in cursors:
            if cursor.kind == K.CALL_EXPR:
                self.call(cursor)

    def handle_ns(self, decl: ci.Cursor) -> Value:
        ctor = next((c for c in decl.get_children() if c.kind in (K.CALL_EXPR, K.UNEXPOSED_EXPR)), None)
        return self.ctor_ns(ctor) if ctor is not None else ""

    def ctor_ns(self, ctor: ci.Cursor) -> Value:
        while ctor.kind == K.UNEXPOSED_EXPR and len(list(ctor.get_children())) == 1:
            ctor = next(ctor.get_children())
        args = _written_args(ctor) if ctor.kind == K.CALL_EXPR else []
        if not args:
            return ""
        first_is_handle = "NodeHandle" in args[0].type.spelling
        parent = self.handle_of(args[0]) if first_is_handle else ""
        if first_is_handle and len(args) == 1:
            return parent
        ns = self.value(args[1] if first_is_handle else args[0])
        if not isinstance(ns, str) or not isinstance(parent, str):
            return concat(parent, "/", ns) if parent else ns
        if ns.startswith("/") or not parent:
            return ns
        return f"~{ns}" if parent == "~" else names.canonical(f"{parent}/{ns}") if not parent.startswith("/") \
            else names.join(parent, ns)

    def member_inits(self, ctor: ci.Cursor) -> None:
        children = list(ctor.get_children())
        for member, init in zip(children, children[1:]):
            if member.kind == K.MEMBER_REF and "NodeHandle" in member.type.spelling:
                self.handles[self.key(member.referenced)] = self.ctor_ns(init)

    def handle_of(self, expr: ci.Cursor, depth: int = 0) -> Value:
        """The namespace of the NodeHandle an expression refers to."""
        for cursor in expr.walk_preorder():
            if cursor.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and "NodeHandle" in cursor.type.spelling:
                decl = cursor.referenced
                key = self.key(decl)
                if key not in self.handles and decl is not None and decl.kind == K.VAR_DECL:
                    self.handles[key] = self.handle_ns(decl)
                if key in self.handles:
                    return self.handles[key]
                if decl is not None and decl.kind == K.FIELD_DECL:
                    return ""
                if decl is not None and decl.kind == K.PARM_DECL and depth < 4:
                    return self.parameter_handle(decl, expr, depth)
                break
        return self.unknown(expr, "NodeHandle of unknown origin")

    def parameter_handle(self, param: ci.Cursor, expr: ci.Cursor, depth: int) -> Value:
        """A handle parameter takes the namespace every call site in this file passes for it."""
        return self.from_call_sites(param, expr, lambda arg: self.handle_of(arg, depth + 1), "NodeHandle")

    def from_call_sites(self, param: ci.Cursor, expr: ci.Cursor, evaluate, what: str) -> Value:
        """The value all call sites in this file agree on for a parameter (a function summary)."""
        function = param.semantic_parent
        params = [p.spelling for p in function.get_arguments()] if function is not None else []
        index = params.index(param.spelling) if param.spelling in params else -1
        sites = self.call_sites.get(self.key(function), []) if index >= 0 else []
        found = {evaluate(args[index]) for site in sites if len(args := _written_args(site)) > index}
        if len(found) == 1:
            return next(iter(found))
        why = f"no call site passes this {what}" if not found else f"call sites pass different values for {what}"
        return self.unknown(expr, why)

    # -- values ---------------------------------------------------------------------------
    def value(self, expr: ci.Cursor, depth: int = 0) -> Value:
        kind = expr.kind
        if depth > 12:
            return self.unknown(expr)
        if kind == K.STRING_LITERAL:
            return _unquote(expr.spelling)
        if kind in (K.INTEGER_LITERAL, K.FLOATING_LITERAL, K.CXX_BOOL_LITERAL_EXPR):
            return "".join(t.spelling for t in expr.get_tokens())
        if kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR):
            decl = expr.referenced
            key = self.key(decl)
            if key in self.param_vars:
                return self.param_vars[key]
            if decl is not None and decl.kind == K.PARM_DECL:
                return self.from_call_sites(decl, expr, lambda arg: self.value(arg, depth + 1), decl.spelling)
            if decl is not None and decl.kind == K.VAR_DECL:
                init = [c for c in decl.get_children() if c.kind not in (K.TYPE_REF, K.NAMESPACE_REF, K.TEMPLATE_REF)]
                if init and decl.type.is_const_qualified() or init and _single_assignment(decl):
                    return self.value(init[-1], depth + 1)
            return self.unknown(expr)
        if kind == K.CALL_EXPR and expr.spelling == "operator+":
            args = list(expr.get_arguments()) or [c for c in expr.get_children() if c.kind != K.UNEXPOSED_EXPR
                                                  or c.spelling != "operator+"]
            if len(args) == 2:
                return concat(self.value(args[0], depth + 1), self.value(args[1], depth + 1))
        children = [c for c in expr.get_children() if c.kind not in (K.TYPE_REF, K.NAMESPACE_REF, K.TEMPLATE_REF)]
        if kind in (K.UNEXPOSED_EXPR, K.CALL_EXPR, K.PAREN_EXPR, K.CXX_FUNCTIONAL_CAST_EXPR) and len(children) == 1:
            return self.value(children[0], depth + 1)
        if kind == K.CALL_EXPR and expr.spelling in ("basic_string", "string") and children:
            return self.value(children[0], depth + 1)
        return self.unknown(expr)

    # -- API calls ------------------------------------------------------------------------
    def call(self, call: ci.Cursor) -> None:
        ref = call.referenced
        name = call.spelling
        parent = ref.semantic_parent.spelling if ref is not None and ref.semantic_parent is not None else ""
        args = _written_args(call)
        if name == "init" and parent == "ros" and len(args) >= 3:
            self.summary.default_name = self.value(args[2])
            self.summary.name_file, self.summary.name_line = self.file, call.location.line
            self.summary.anonymous = len(args) > 3 and "AnonymousName" in " ".join(
                t.spelling for t in args[3].get_tokens())
        elif parent == "NodeHandle" and args:
            handle = self.handle_of(next(call.get_children()))
            if name in _METHODS:
                type_ = self.port_type(call, ref, args, name)
                self.add(_METHODS[name], call, self.value(args[0]), type_, handle)
            elif name in _PARAM_METHODS:
                self.param(call, args, handle)

    def param(self, call: ci.Cursor, args: list[ci.Cursor], handle: Value) -> None:
        pname = self.value(args[0])
        has_default = len(args) > 2 or (call.spelling == "param" and len(args) == 2 and _is_rvalue(args[1]))
        default = self.value(args[-1]) if has_default else None
        self.add("param_read", call, pname, "", handle, default)
        if len(args) > 1 and isinstance(pname, str) and not (has_default and len(args) == 2):
            target = next((c for c in args[1].walk_preorder() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)), None)
            key = self.key(target.referenced) if target is not None else None
            if key is not None:
                fallback = default if default is not None else self.unknown(call, "parameter without default")
                self.param_vars[key] = ParamRef(pname, fallback, handle, self.file, call.location.line)

    def port_type(self, call: ci.Cursor, ref: ci.Cursor, args: list[ci.Cursor], name: str) -> Value:
        callee = next(call.get_children())
        template_arg = next((_ros_type(c.type) for c in callee.get_children() if c.kind == K.TYPE_REF), None)
        if template_arg and name != "subscribe":
            return template_arg
        if name in ("subscribe", "advertiseService"):
            for arg in args[1:]:
                for cursor in arg.walk_preorder():
                    target = cursor.referenced if cursor.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) else None
                    if target is not None and target.kind in (K.FUNCTION_DECL, K.CXX_METHOD):
                        params = list(target.get_arguments())
                        if params and (found := _ros_type(params[0].type)):
                            return found
        return template_arg or self.unknown(call, "message type not resolved")

    def add(self, kind: str, call: ci.Cursor, name: Value, type_: Value, handle: Value,
            default: Value | None = None) -> None:
        loc = call.location
        self.summary.ports.append(Port(kind, name, type_, self.file, loc.line, loc.column, handle, default))


def _is_rvalue(expr: ci.Cursor) -> bool:
    """A literal or temporary, not a variable the parameter could be stored into."""
    return not any(c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) for c in expr.walk_preorder())


def _written_args(call: ci.Cursor) -> list[ci.Cursor]:
    """The call's arguments as written (default arguments have no location)."""
    return [a for a in call.get_arguments() if a.location.file is not None]


def _ros_type(type_: ci.Type) -> str | None:
    """'sensor_msgs/LaserScan' from a C++ type such as const sensor_msgs::LaserScan::ConstPtr&."""
    canonical = type_.get_canonical().spelling
    match = _MSG_TYPE.search(canonical)
    if match:
        return f"{match.group(1)}/{match.group(2)}"
    for spelling in (canonical, type_.spelling):
        match = _PLAIN_TYPE.search(spelling.replace("const ", ""))
        if match:
            return f"{match.group(1)}/{match.group(2)}"
    return None


def _unquote(literal: str) -> str:
    body = literal[literal.index('"') + 1: literal.rindex('"')] if '"' in literal else literal
    return body.encode("utf-8").decode("unicode_escape", errors="replace") if "\\" in body else body


def _single_assignment(decl: ci.Cursor) -> bool:
    """A local string variable that is initialised and never assigned again in its function."""
    scope = decl.semantic_parent
    if scope is None:
        return False
    for cursor in scope.walk_preorder():
        if cursor.kind in (K.BINARY_OPERATOR, K.CALL_EXPR, K.COMPOUND_ASSIGNMENT_OPERATOR) and \
                cursor.spelling in ("operator=", "operator+=", "=", "+="):
            refs = [c for c in cursor.get_children() if c.kind == K.DECL_REF_EXPR]
            if refs and refs[0].referenced == decl:
                return False
    return True
