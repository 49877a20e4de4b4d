"""Values a Python node takes from its command line: through argparse, `args.NAME` where `args =
parser.parse_args()` (or `parser.parse_known_args()`, whose first item it is) and `parser` is an
`argparse.ArgumentParser` the same function (or module) builds with `add_argument` calls; or a word
of the command line itself, `sys.argv[N]` / `rospy.myargv(argv=sys.argv)[N]` (guarded by
`if len(argv) > N`, with the default the guard gives).

The value is a CommandArg, bound per node instance to the instance's command-line words (launch
`args=`/`arguments=`, an ExecuteProcess's words) or to the argument's default when the words lack it.
Lists (`nargs='*'`), flags and positionals after a list are not followed: None, folded as unknown.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass

from archlog.extract.python.index import FileIndex, Function, arg
from archlog.values import CommandArg, Unknown, Value

_FLAGS = {"store_true", "store_false", "store_const", "count", "append_const", "help", "version"}
_PARSE = {"parse_args", "parse_known_args", "parse_intermixed_args", "parse_known_intermixed_args"}


@dataclass(frozen=True)
class _Argument:
    """One add_argument call: its option strings (none for a positional), dest, and how it is read."""

    call: ast.Call
    options: tuple[str, ...]
    dest: str
    flag: bool  # takes no value word
    single: bool  # gives one word (not a list)


def parsed_argument(index: FileIndex, file: str, expr: ast.Attribute, scope: Function | None,
                    fold: Callable[[ast.expr, Function | None], Value]) -> Value | None:
    """The CommandArg behind `args.NAME`, or None when `args` is not argparse's result in this file;
    `fold` folds the argument's default in the function that builds the parser."""
    if not isinstance(expr.value, ast.Name):
        return None
    parser = _parser_of(index, expr.value.id, scope)
    if parser is None:
        return None
    name, where = parser
    arguments = [_argument(call) for call in _calls(index, name, where)]
    wanted = next((a for a in arguments if a is not None and a.dest == expr.attr), None)
    if wanted is None or not wanted.single or None in arguments:
        return None
    valued = tuple(o for a in arguments if a is not None and a.options and not a.flag for o in a.options)
    if wanted.flag:
        return _flag(wanted, valued, file, expr.lineno)
    default = next((kw.value for kw in wanted.call.keywords if kw.arg == "default"), None)
    unset = Unknown(f"{ast.unparse(expr)} (command-line argument {wanted.dest} not given)", file,
                    expr.lineno)
    value = fold(default, where) if default is not None and not _is_none(default) else unset
    if wanted.options:
        return CommandArg(0, wanted.options, value, valued, file, expr.lineno)
    positionals = [a for a in arguments if a is not None and not a.options]
    before = positionals[:positionals.index(wanted)]
    if any(not a.single for a in before):
        return None
    return CommandArg(len(before) + 1, (), value, valued, file, expr.lineno)


def _flag(flag: _Argument, valued: tuple[str, ...], file: str, line: int) -> CommandArg | None:
    """A store_true/store_false flag: "true"/"false" as a parameter's boolean is written; other
    flag actions are not followed."""
    action = next(kw.value for kw in flag.call.keywords if kw.arg == "action")
    default = next((kw.value for kw in flag.call.keywords if kw.arg == "default"), None)
    if not isinstance(action, ast.Constant) or action.value not in ("store_true", "store_false") or \
            default is not None and not (isinstance(default, ast.Constant) and isinstance(default.value, bool)):
        return None
    present = action.value == "store_true"
    unset = (not present) if default is None else bool(default.value)
    return CommandArg(0, flag.options, str(unset).lower(), valued, file, line, str(present).lower())


def _parser_of(index: FileIndex, args: str, scope: Function | None) -> tuple[str, Function | None] | None:
    """The parser variable whose parse result `args` holds, and the function both are assigned in."""
    where = scope if scope is not None and (args in scope.assigns or _unpacked(scope.node, args)) else None
    values = [*(where.assigns if where is not None else index.module_assigns).get(args, []),
              *_unpacked(where.node if where is not None else index.tree, args)]
    if len(values) != 1 or not isinstance(values[0], ast.expr):
        return None
    call = values[0]
    if isinstance(call, ast.Subscript) and isinstance(call.slice, ast.Constant) and call.slice.value == 0:
        call = call.value  # parse_known_args()[0]
    if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) and call.func.attr in _PARSE
            and isinstance(call.func.value, ast.Name) and _reads_command_line(call, index, where)):
        return None
    parser = call.func.value.id
    made = (where.assigns if where is not None else index.module_assigns).get(parser, [])
    if len(made) != 1 or not isinstance(made[0], ast.Call) or index.qualified(made[0].func) != "argparse.ArgumentParser":
        return None
    return parser, where


def _unpacked(root: ast.AST, name: str) -> list[ast.expr]:
    """`name, rest = X.parse_known_args()`: X.parse_known_args()[0] for `name`."""
    return [ast.Subscript(node.value, ast.Constant(0)) for node in ast.walk(root) if isinstance(node, ast.Assign)
            and len(node.targets) == 1 and isinstance(target := node.targets[0], ast.Tuple) and target.elts
            and isinstance(target.elts[0], ast.Name) and target.elts[0].id == name]


def _reads_command_line(call: ast.Call, index: FileIndex, where: Function | None) -> bool:
    """parse_args() reads sys.argv; given words, only those that are the command line (rospy.myargv,
    rclpy's remove_ros_args, sys.argv[1:], or a variable holding one of them, from its second word)
    are followed."""
    given = arg(call, 0, "args")
    if isinstance(given, ast.Subscript) and isinstance(given.slice, ast.Slice) and given.slice.upper is None \
            and isinstance(given.slice.lower, ast.Constant) and given.slice.lower.value == 1:
        return _command_line(index, given.value, where)
    return given is None or "argv" in ast.unparse(given)


def _command_line(index: FileIndex, expr: ast.expr, where: Function | None) -> bool:
    """`sys.argv`, `rospy.myargv(...)`, rclpy's `remove_ros_args(...)`, or a name one function (or
    the module) assigns once to one of them: every word of the command line, the program first."""
    if isinstance(expr, ast.Name):
        values = (where.assigns if where is not None and expr.id in where.assigns else index.module_assigns).get(expr.id, [])
        return len(values) == 1 and isinstance(values[0], ast.expr) and _command_line(index, values[0], where)
    called = index.qualified(expr.func) if isinstance(expr, ast.Call) else None
    return index.qualified(expr) == "sys.argv" or called is not None and called.rsplit(".", 1)[-1] in (
        "myargv", "remove_ros_args")


def argv_word(index: FileIndex, file: str, expr: ast.expr, scope: Function | None,
              fold: Callable[[ast.expr, Function | None], Value]) -> Value | None:
    """`argv[N]` of the command line (N >= 1; a word not given is unknown), or `argv[N] if
    len(argv) > N else D` (D when not given); None for anything else."""
    guarded = None
    if isinstance(expr, ast.IfExp) and isinstance(test := expr.test, ast.Compare) and len(test.ops) == 1 and \
            isinstance(test.left, ast.Call) and isinstance(test.left.func, ast.Name) and test.left.func.id == "len" \
            and len(test.left.args) == 1 and isinstance(bound := test.comparators[0], ast.Constant) and \
            isinstance(bound.value, int) and not isinstance(bound.value, bool):
        guarded = ast.unparse(test.left.args[0]), bound.value + isinstance(test.ops[0], ast.Gt), expr.orelse
        expr = expr.body
    if not (isinstance(expr, ast.Subscript) and isinstance(expr.slice, ast.Constant) and
            isinstance(position := expr.slice.value, int) and not isinstance(position, bool) and position >= 1
            and _command_line(index, expr.value, scope)):
        return None
    if guarded is not None and (guarded[0] != ast.unparse(expr.value) or guarded[1] != position + 1):
        return None
    default = fold(guarded[2], scope) if guarded is not None else \
        Unknown(f"{ast.unparse(expr)} (command-line argument {position} not given)", file, expr.lineno)
    return CommandArg(position, (), default, (), file, expr.lineno)


def _calls(index: FileIndex, parser: str, where: Function | None) -> list[ast.Call]:
    """The parser's add_argument calls in source order, in the function (or module) that builds it."""
    root: ast.AST = where.node if where is not None else index.tree
    calls = [node for node in ast.walk(root) if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
             and node.func.attr == "add_argument" and isinstance(node.func.value, ast.Name)
             and node.func.value.id == parser and index.function_of(node) is where]
    return sorted(calls, key=lambda c: (c.lineno, c.col_offset))


def _argument(call: ast.Call) -> _Argument | None:
    """What an add_argument call declares; None when its names or kind are not literal."""
    names = [a.value for a in call.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
    if not names or len(names) != len(call.args):
        return None
    keywords = {kw.arg: kw.value for kw in call.keywords if kw.arg}
    action = keywords.get("action")
    action_name = action.value if isinstance(action, ast.Constant) else None if action is None else "?"
    nargs = keywords.get("nargs")
    single = nargs is None or isinstance(nargs, ast.Constant) and nargs.value == "?"
    dest_kw = keywords.get("dest")
    options = tuple(n for n in names if n.startswith("-"))
    if dest_kw is not None:
        if not (isinstance(dest_kw, ast.Constant) and isinstance(dest_kw.value, str)):
            return None
        dest = dest_kw.value
    elif options:
        long = next((o for o in options if o.startswith("--")), options[0])
        dest = long.lstrip("-").replace("-", "_")
    else:
        dest = names[0]
    return _Argument(call, options, dest, action_name in _FLAGS, single and action_name not in ("append", "extend", "?"))


def _is_none(expr: ast.expr) -> bool:
    return isinstance(expr, ast.Constant) and expr.value is None
