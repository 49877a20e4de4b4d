"""The path walk: a function's statements in order, with the guards of tests and early
returns, unbounded loops and their periods, state writes, and the publish calls reached."""

from __future__ import annotations

import ast
from dataclasses import replace

from archlog.extract.python.behavior.guards import Guards
from archlog.extract.python.behavior.paths import Context, Frame, join
from archlog.extract.python.behavior.syntax import ADDS, NO_INDEX, breaks, pairs, periodic, running
from archlog.extract.python.fold import ValueFolder
from archlog.extract.python.index import arg, in_scope
from archlog.extract.summary import Port, Publish, Site, StateWrite
from archlog.values import ParamRef, Unknown, Value

PUBLISH_METHODS = ("publish", "sendTransform")
_EXITS = {"sys.exit", "exit", "quit", "os._exit"}
_MAX_DEPTH = 16  # calls on one path
BUDGET = 4000  # function bodies walked per file


class Walk(Guards):
    """Walks functions on paths, collecting the publish calls reached and the state written."""

    def __init__(self, folder: ValueFolder, ports: list[Port]) -> None:
        super().__init__(folder, ports)
        self.publishes: dict[Publish, None] = {}
        self.writes: dict[StateWrite, None] = {}
        self.walked: set[tuple[object, ...]] = set()
        self.reached: set[int] = set()
        self.calls: dict[int, list[ast.Call]] = {}  # expression -> the calls it makes
        self.budget = BUDGET

    def enter(self, frame: Frame, ctx: Context) -> None:
        """Walk a function's body on a path (once per frame and path state)."""
        func = frame.func
        assert func is not None
        key = (frame, ctx.trigger, ctx.source, ctx.guards, ctx.loop)
        if key in self.walked or id(func) in ctx.stack or len(ctx.stack) >= _MAX_DEPTH or self.budget <= 0:
            return
        self.walked.add(key)
        self.budget -= 1
        self.reached.add(id(func))
        ctx = replace(ctx, stack=ctx.stack + (id(func),))
        if isinstance(func, ast.Lambda):
            self.expression(func.body, frame, ctx)
        else:
            self.walk(func.body, frame, ctx)

    # -- walking --------------------------------------------------------------------------
    def walk(self, body: list[ast.stmt], frame: Frame, ctx: Context) -> Context | None:
        """A block in order; returns the path state after it, None when it always leaves
        (return, raise, continue, break): the guards of early returns hold for what follows."""
        for stmt in body:
            after = self.statement(stmt, frame, ctx)
            if after is None:
                return None
            ctx = after
        return ctx

    def statement(self, stmt: ast.stmt, frame: Frame, ctx: Context) -> Context | None:
        """One statement; returns the path state after it (None when it always leaves)."""
        if isinstance(stmt, ast.If):
            self.expression(stmt.test, frame, ctx)
            yes, no = (self.walk(body, frame, self.branch(stmt, truth, frame, ctx))
                       for body, truth in ((stmt.body, True), (stmt.orelse, False)))
            return join(ctx, [c for c in (yes, no) if c is not None], stmt, 2)
        if isinstance(stmt, ast.While):
            self.expression(stmt.test, frame, ctx)
            inner = self.branch(stmt, True, frame, ctx)
            if periodic(stmt.test) or (self.state_only(stmt.test, frame) and any(
                    self.sleep(c, frame) is not None for c in in_scope(stmt.body) if isinstance(c, ast.Call))):
                inner = replace(inner, loop=(self.period(stmt, frame),))
            self.walk(stmt.body, frame, inner)
            self.walk(stmt.orelse, frame, ctx)
            return ctx if breaks(stmt.body) else self.branch(stmt, False, frame, ctx)
        if isinstance(stmt, (ast.For, ast.AsyncFor)):
            self.expression(stmt.iter, frame, ctx)
            self.walk(stmt.body, frame, ctx.depending(stmt))  # runs only for a non-empty iterable
            self.walk(stmt.orelse, frame, ctx)
            return ctx
        if isinstance(stmt, (ast.With, ast.AsyncWith)):
            for item in stmt.items:
                self.expression(item.context_expr, frame, ctx)
            return self.walk(stmt.body, frame, ctx)
        if isinstance(stmt, (ast.Try, ast.TryStar)):
            raised = ctx.depending(stmt, exact=not stmt.handlers)  # whether the body raised
            body = self.walk(stmt.body, frame, raised)
            ends = [self.walk(stmt.orelse, frame, body) if body is not None else None]
            ends += [self.walk(h.body, frame, raised) for h in stmt.handlers]
            self.walk(stmt.finalbody, frame, ctx)
            return join(ctx, [c for c in ends if c is not None], stmt, len(ends))
        if isinstance(stmt, ast.Match):
            self.expression(stmt.subject, frame, ctx)
            ends = [self.walk(case.body, frame, ctx.depending(stmt)) for case in stmt.cases]
            return join(ctx, [c for c in ends if c is not None] + [ctx.depending(stmt)], stmt, len(ends) + 1)
        if isinstance(stmt, (ast.Return, ast.Raise)):
            for part in (stmt.value,) if isinstance(stmt, ast.Return) else (stmt.exc, stmt.cause):
                if part is not None:
                    self.expression(part, frame, ctx)
            return None
        if isinstance(stmt, (ast.Continue, ast.Break)):
            return None
        if isinstance(stmt, ast.ClassDef):
            if frame.func is None:
                self.class_body(stmt, ctx)
            return ctx
        if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)):
            return ctx
        if isinstance(stmt, (ast.Assign, ast.AnnAssign, ast.AugAssign)) and stmt.value is not None:
            self.expression(stmt.value, frame, ctx)
            targets = stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]
            for target, value in pairs(targets, stmt.value if not isinstance(stmt, ast.AugAssign) else None):
                self.assignment(target, value, frame, ctx, stmt.lineno)
            return self.received(stmt.value, ctx)
        for child in ast.iter_child_nodes(stmt):
            if isinstance(child, ast.expr):
                self.expression(child, frame, ctx)
        if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Call) and \
                self.folder.qualified(stmt.value.func) in _EXITS:
            return None
        return self.received(stmt.value, ctx) if isinstance(stmt, ast.Expr) else ctx

    def branch(self, stmt: ast.If | ast.While, truth: bool, frame: Frame, ctx: Context) -> Context:
        """The path where `stmt`'s test is `truth`: its guards, and whether they are all it takes."""
        return ctx.guarded(self.condition(stmt.test, truth, frame)).depending(stmt, self.exact(stmt.test, truth, frame))

    def received(self, expr: ast.expr, ctx: Context) -> Context:
        """After rospy.wait_for_message(topic) a message has arrived: a state of its own
        (`wait_for_message@LINE`) that only that subscriber sets guards what follows."""
        waits = [c for c in self.calls.get(id(expr), []) if self.folder.qualified(c.func) == "rospy.wait_for_message"
                 and Site(self.file, c.lineno) in self.sites["subscriber"]]
        for wait in waits:
            var = f"wait_for_message@{wait.lineno}"
            self.writes[StateWrite(var, "set", Site(self.file, wait.lineno), self.file, wait.lineno)] = None
        return ctx.guarded([self.guard(f"wait_for_message@{w.lineno}", "set", w) for w in waits])

    def class_body(self, cls: ast.ClassDef, ctx: Context) -> None:
        """Class attributes are initial values of instance state."""
        frame = Frame(None, cls.name)
        for stmt in cls.body:
            if isinstance(stmt, (ast.Assign, ast.AnnAssign)) and stmt.value is not None:
                for target in stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]:
                    if isinstance(target, ast.Name):
                        var = f"{self.lineage(cls.name)[-1]}.{target.id}"
                        self.write(var, self.write_value(var, stmt.value, frame), ctx, stmt.lineno)

    def assignment(self, target: ast.expr, value: ast.expr | None, frame: Frame, ctx: Context, line: int) -> None:
        """A write to state; `a if c else b` writes either."""
        if isinstance(value, ast.IfExp):
            for branch in (value.body, value.orelse):
                self.assignment(target, branch, frame, ctx, line)
        elif isinstance(target, ast.Subscript):
            var = self.state_var(target.value, frame)
            if var:
                self.write(var, "nonempty" if value is not None else "?", ctx, line)
        elif var := self.state_var(target, frame):
            self.write(var, self.write_value(var, value, frame), ctx, line)

    def write(self, var: str, value: str, ctx: Context, line: int) -> None:
        """Record a state write (its source when a callback or timer runs it)."""
        source = ctx.source if ctx.trigger in ("timer", "callback") else None
        decided = not ctx.opaque and not ctx.guards and (source is not None or ctx.loop is None)  # not a loop's reset
        self.writes[StateWrite(var, value, source, self.file, line, decided)] = None

    def expression(self, expr: ast.expr, frame: Frame, ctx: Context) -> None:
        """The calls an expression makes (not those inside its lambdas)."""
        if id(expr) not in self.calls:
            self.calls[id(expr)] = [n for n in in_scope([expr]) if isinstance(n, ast.Call)]
        for call in self.calls[id(expr)]:
            self.call(call, frame, ctx)

    def call(self, call: ast.Call, frame: Frame, ctx: Context) -> None:
        """A call: container writes, publish calls, and the functions of the file it runs."""
        func = call.func
        name = self.folder.qualified(func) or ""
        # taking from a container never fills it
        if isinstance(func, ast.Attribute) and (var := self.state_var(func.value, frame)) and \
                (func.attr in ADDS or func.attr == "clear"):
            self.write(var, "nonempty" if func.attr in ADDS else "empty", ctx, call.lineno)
        targets = self.callables(func, frame)
        if not targets and (sites := self.publish_sites(call, frame)):
            self.publish(call, ctx, sites)
        if name in ("threading.Thread", "rospy.on_shutdown"):  # runs a function (with a thread's args)
            callee = arg(call, 0, "h") if name == "rospy.on_shutdown" else arg(call, NO_INDEX, "target")
            passed = arg(call, NO_INDEX, "args") if name == "threading.Thread" else None
            for target in self.callables(callee, frame) if callee is not None else []:
                self.enter(self.bind_arguments(target, passed.elts if isinstance(passed, (ast.Tuple, ast.List))
                                               else [], [], frame), ctx)
        for target in targets:
            self.enter(self.bind(target, call, frame), ctx)

    def publish_sites(self, call: ast.Call, frame: Frame) -> list[Site | None]:
        """For a publish call (`.publish()`, or `.sendTransform()` of a broadcaster) that is not a
        method of the file, the sites of the publishers it may use (None: not known); else []."""
        func = call.func
        if not isinstance(func, ast.Attribute) or func.attr not in PUBLISH_METHODS:
            return []
        sites: list[Site | None] = list(self.publisher_sites(func.value, frame))
        return sites or ([None] if func.attr == "publish" else [])

    def publish(self, call: ast.Call, ctx: Context, sites: list[Site | None]) -> None:
        """Record a publish call for each publisher it may use, with the path's trigger."""
        trigger, source, period = ctx.trigger, ctx.source, None
        if trigger not in ("timer", "callback") and ctx.loop is not None:
            trigger, source, period = "loop", None, ctx.loop[0]
        for site in sites:
            self.publishes[Publish(site, self.file, call.lineno, trigger, source, ctx.guards, period,
                                   not ctx.opaque)] = None


    # -- loops ----------------------------------------------------------------------------
    def period(self, loop: ast.While, frame: Frame) -> Value:
        """The loop's period in seconds: from its sleep (rate.sleep(), rospy.sleep(x),
        time.sleep(x), spin_once's timeout), preferring those at the top of its body."""
        top = [s.value for s in loop.body if isinstance(s, ast.Expr) and isinstance(s.value, ast.Call)]
        anywhere = [n for n in in_scope(loop.body) if isinstance(n, ast.Call)]
        for calls in (top, anywhere):
            found = list(dict.fromkeys(p for c in calls if (p := self.sleep(c, frame)) is not None))
            if len(found) == 1:
                return found[0]
            if found:
                return Unknown("several sleeps in the loop", self.file, loop.lineno)
        return Unknown("no sleep in the loop", self.file, loop.lineno)

    def state_only(self, test: ast.expr, frame: Frame) -> bool:
        """A test of state only (`while not self.done`): with a sleep, the loop runs until
        shutdown or until a callback changes the state."""
        if self.state_var(test, frame) or isinstance(test, ast.Constant):
            return True
        if isinstance(test, ast.Call):
            return running(test) is not None
        return isinstance(test, (ast.UnaryOp, ast.BoolOp, ast.Compare)) and all(
            self.state_only(c, frame) for c in ast.iter_child_nodes(test) if isinstance(c, ast.expr))

    def sleep(self, call: ast.Call, frame: Frame) -> Value | None:
        """The seconds a call sleeps (Unknown when not known); None when it does not sleep."""
        name = self.folder.qualified(call.func) or ""
        scope = self.function(frame)
        if isinstance(call.func, ast.Attribute) and call.func.attr == "wait" and (call.args or call.keywords):
            return Unknown(ast.unparse(call), self.file, call.lineno)  # a condition or event with a timeout
        if name in ("rospy.sleep", "time.sleep") and call.args:
            duration = call.args[0]
            if isinstance(duration, ast.Call) and duration.args and \
                    (self.folder.qualified(duration.func) or "").startswith("rospy.Duration"):
                duration = duration.args[0]
            return self.folder.value(duration, scope=scope)
        if name == "rclpy.spin_once":
            timeout = arg(call, NO_INDEX, "timeout_sec")
            return self.folder.value(timeout, scope=scope) if timeout is not None else \
                Unknown("spin_once waits for a callback", self.file, call.lineno)
        if isinstance(call.func, ast.Attribute) and call.func.attr == "sleep" and not call.args:
            rates = [self.rate(c, f) for c, f in self.origins(call.func.value, frame)]
            found = list(dict.fromkeys(r for r in rates if r is not None))
            return found[0] if len(found) == 1 else Unknown(ast.unparse(call), self.file, call.lineno)
        return None

    def rate(self, call: ast.Call, frame: Frame) -> Value | None:
        """Seconds of rospy.Rate(hz) / node.create_rate(hz); a parameter's default folds."""
        rospy = self.folder.qualified(call.func) == "rospy.Rate"
        if not rospy and not (isinstance(call.func, ast.Attribute) and call.func.attr == "create_rate"):
            return None
        hz = arg(call, 0, "hz" if rospy else "frequency")
        if hz is None:
            return Unknown(ast.unparse(call), self.file, call.lineno)
        value = self.folder.value(hz, scope=self.function(frame))
        if isinstance(value, ParamRef):
            value = value.default
        try:
            return repr(1 / float(value)) if isinstance(value, str) else Unknown(f"1/{ast.unparse(hz)}", self.file,
                                                                                 call.lineno)
        except (ValueError, ZeroDivisionError):
            return Unknown(f"1/{ast.unparse(hz)}", self.file, call.lineno)

