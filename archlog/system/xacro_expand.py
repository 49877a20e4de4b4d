"""Expanding a xacro file with the xacro library without running anything the file holds.

xacro evaluates `${...}` with Python's `eval` behind a check of the names the code uses, which a
nested code object (a lambda, a comprehension) walks past; its `$(eval)` is Python's `eval`, its
`$(env)` reads the real environment, and it opens whatever files a description names. For the duration of one expansion
(`routed`), archlog puts its own pieces at xacro's seams and restores xacro's afterwards:

- text and expressions (`eval_text`, `safe_eval`): `${...}` goes through archlog's restricted
  evaluator (`substitution.restricted_eval`) over xacro's names (properties, math, pure builtins,
  the `xacro.` helpers), `$(...)` through archlog's roslaunch substitutions (`$(env)` sees only the
  sandbox's environment, `$(find)` the workspace); the lexing is linear;
- files (`parse`, `xacro.load_yaml`): read through `archlog.sandbox` as descriptions; an include
  pattern (`glob`) is listed only inside the sandbox's roots, and a pattern reaching out of them is
  refused by its text (never naming what it would match);
- budgets: every element expanded spends one `elements`, every file read and text evaluated its
  `characters`, the sibling scans of xacro's node splicing `steps`; include and macro nesting is a
  `depth`;
- macro parameters are parsed with a pattern without nested repetition (xacro's backtracks
  exponentially on a hostile default).
"""

from __future__ import annotations

import errno
import glob
import os
import re
import xml.dom.minidom
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace

import yaml

from archlog import budget, sandbox
from archlog.budget import BudgetExceeded
from archlog.extract.launch.evaluate import MATH, PURE_BUILTINS, bounded, restricted_eval, spend
from archlog.extract.launch.model import SubstitutionError
from archlog.extract.launch.ros1_subst import SubstContext, substitute

_TOKEN = re.compile(r"(?P<dollars>\$\$+[{(])|(?P<expr>\$\{[^}]*\})|(?P<extension>\$\([^)]*\))"
                    r"|(?P<text>[^$]+|\$[^{($]+|\$$)")
"""xacro's lexer (`LEXER`) as one pattern, matched from a position instead of slicing the text."""

_MACRO_ARG = re.compile(r"^\s*([^\s:=]+?)\s*:?=\s*(\^\|?)?"
                        r"(\$\{.*?\}|\$\(.*?\)|(?:'.*?'|\".*?\"|[^\s'\"])+|)(?:\s+|$)(.*)")
"""xacro's `re_macro_arg` with `[^\\s'\"]` once per repetition (the same language)."""

ENTITY = "<!ENTITY"

SIBLINGS_PER_STEP = 25
"""xacro splices expanded nodes into their parent with minidom, which finds a node's place by a
scan of its siblings: so many siblings scanned count as one evaluation step (the scans make an
expansion into one parent quadratic)."""

_METHODS = {dict: {"get", "keys", "values", "items"}, list: {"index", "count"}, tuple: {"index", "count"}}
"""Read-only methods an expression may call on the containers it holds."""


Place = tuple[Path | None, int | None]
"""A file and line of a description (None: not found; report it where the description is set)."""


@dataclass
class Expanded:
    """A description's XML text, the files it came from, and the environment variables it read
    that the run was not given (each with the place that read it)."""

    text: str
    files: list[Path]
    unseen: list[tuple[sandbox.NotGiven, Place]]
    legacy: list[tuple[str, Place]] = field(default_factory=list)  # macros called without xacro:, with places


class XacroFailure(Exception):
    """An expansion that stopped: the diagnostic code, the place that stopped it, and the
    variables read but not given before it did."""

    def __init__(self, code: str, message: str, place: Place, unseen: list[tuple[sandbox.NotGiven, Place]]) -> None:
        super().__init__(message)
        self.code, self.place, self.unseen = code, place, unseen


def expand(source: Path, mappings: dict[str, str], find: Callable[[str], Path | None]) -> Expanded:
    """Expand a xacro file (raises `XacroFailure`)."""
    expansion = Expansion(find)
    xacro = expansion.xacro
    with budget.scope(), routed(expansion):
        try:
            text = xacro.process_file(str(source), mappings=dict(mappings)).toxml()
            return Expanded(text, [source, *map(Path, xacro.all_includes)], expansion.unseen, expansion.legacy)
        except Exception as exc:  # xacro reports every failure as some exception
            raise expansion.failure(exc, source) from None


class Expansion:
    """One expansion: package lookup, xacro's global names, and the piece of text that failed."""

    def __init__(self, find: Callable[[str], Path | None]) -> None:
        import xacro
        self.xacro = xacro
        self.find = find
        self.needle: str | None = None  # text of the innermost failing piece, to find its line by
        self.unseen: list[tuple[sandbox.NotGiven, Place]] = []
        self.legacy: list[tuple[str, Place]] = []
        self.names = self._names()

    def _names(self) -> dict[str, object]:
        """xacro's global names: pure builtins and math directly and in `python.`/`math.`, and the
        `xacro.` helpers (messages are dropped, files are read through the sandbox)."""
        xacro = self.xacro
        helpers = {"load_yaml": self.load_yaml, "abs_filename": xacro.abs_filename_spec,
                   "dotify": xacro.YamlDictWrapper, "tokenize": _tokenize, "fatal": _fatal,
                   "arg": lambda name: xacro.substitution_args_context["arg"][name],
                   **dict.fromkeys(("message", "warning", "error", "print_location"), _quiet)}
        return {**PURE_BUILTINS, **MATH, "load_yaml": self.load_yaml, "abs_filename": xacro.abs_filename_spec,
                "dotify": xacro.YamlDictWrapper, "python": _namespace(xacro, PURE_BUILTINS),
                "math": _namespace(xacro, MATH), "xacro": _namespace(xacro, helpers)}

    def failure(self, exc: Exception, source: Path) -> XacroFailure:
        """What stopped the expansion (a budget, a file refused, anything else xacro rejects) and
        the line of the innermost file or macro holding the piece that stopped it."""
        cause = _cause(exc)
        if isinstance(cause, (RecursionError, MemoryError)):
            limit = budget.current().limits["depth"]
            message, code = f"nested or grown past what archlog expands (depth limit {limit})", "budget-exceeded"
        else:
            code = cause.code if isinstance(cause, sandbox.Refused) else \
                "budget-exceeded" if isinstance(cause, BudgetExceeded) else "robot-description"
            message = str(cause) or type(cause).__name__
        return XacroFailure(code, f"xacro cannot expand {source}: {message}", self._located(self.needle or ""),
                            self.unseen)

    def _located(self, text: str) -> Place:
        """The first line holding `text` in the innermost macro's file, then the files being read."""
        xacro = self.xacro
        files = [m.history[-1][-1] for m in reversed(xacro.macrostack or []) if m.history and m.history[-1]]
        files += list(reversed(xacro.filestack or []))
        needle = next((part.strip() for part in text.splitlines() if part.strip()), "")
        for name in (f for f in files if f):
            try:
                lines = sandbox.read_text(name, "description").splitlines()
            except sandbox.Refused:
                continue
            found = next((number for number, line in enumerate(lines, 1) if needle and needle in line), None)
            if found is not None:
                return Path(name), found
        return None, None

    def eval_text(self, text: str, symbols: object) -> object:
        """xacro's `eval_text`: a lone `${}` or `$()` keeps its type, anything else is joined."""
        results: list[object] = []
        position = 0
        while position < len(text):
            token = _TOKEN.match(text, position)
            if token is None:
                self.needle = self.needle or text
                raise SubstitutionError(f"invalid expression: {text[position:position + 80]}")
            spend("steps")
            position = token.end()
            try:
                results.append(self._token(token, symbols))
            except Exception:
                self.needle = self.needle or token[0]  # the innermost piece that failed, as written
                raise
        value = results[0] if len(results) == 1 else "".join(map(str, results))
        if isinstance(value, str):
            try:
                spend("characters", len(value))
            except BudgetExceeded:
                self.needle = self.needle or text
                raise
        return value

    def _token(self, token: re.Match[str], symbols: object) -> object:
        if token["expr"]:
            return self.evaluate(str(self.eval_text(token["expr"][2:-1], symbols)), symbols)
        if token["extension"]:
            return self.extension(str(self.eval_text(token["extension"][2:-1], symbols)))
        return token[0][1:] if token["dollars"] else token[0]

    def evaluate(self, expr: str, symbols: object, _locals: object = None) -> object:
        """xacro's `safe_eval`, by archlog's evaluator: names from the property tables (whose root
        is `names`), attributes of namespaces and YAML dictionaries."""
        def lookup(name: str) -> object:
            try:
                return symbols[name]  # type: ignore[index]
            except KeyError:
                raise SubstitutionError(f"name '{name}' is not defined") from None

        return restricted_eval(expr, lookup, self.attribute)

    def attribute(self, target: object, name: str) -> object:
        xacro = self.xacro
        if isinstance(target, xacro.NameSpace) or (isinstance(target, xacro.YamlDictWrapper)
                                                    and name not in _METHODS[dict]):
            try:
                return target[name]
            except (KeyError, AttributeError):
                raise SubstitutionError(f"no '{name}' in this namespace") from None
        allowed = next((names for kind, names in _METHODS.items() if isinstance(target, kind)), set())
        if name not in allowed:
            raise SubstitutionError(f"cannot use .{name} of {type(target).__name__}")
        return getattr(target, name)

    def extension(self, inner: str) -> str:
        """`$(...)` as roslaunch resolves it, with the sandbox's environment (a variable not given
        is noted with its place); `$(cwd)` as xacro."""
        xacro = self.xacro
        if inner == "cwd":
            return os.path.abspath(xacro.root_dir)
        current = xacro.filestack[-1] if xacro.filestack and xacro.filestack[-1] else "."
        context = SubstContext(dict(xacro.substitution_args_context.get("arg", {})), self.find, Path(current))
        with sandbox.reads_not_given() as unseen:
            try:
                return substitute(f"$({inner})", context)
            finally:
                self.unseen += [(read, self._located(read.name)) for read in unseen]

    def load_yaml(self, filename: object) -> object:
        """`xacro.load_yaml`: a YAML file of the workspace (its units tags too), within budget."""
        xacro = self.xacro
        path = xacro.abs_filename_spec(str(filename))
        text = sandbox.read_text(path, "description")
        spend("characters", len(text))
        try:
            data = yaml.load(text, Loader=self._yaml_loader())  # a SafeLoader with xacro's unit tags
        except yaml.YAMLError as exc:
            raise SubstitutionError(f"{path} is not YAML: {exc}") from None
        xacro.all_includes.append(path)
        return xacro.YamlListWrapper.wrap(bounded(data))

    def _yaml_loader(self) -> type[yaml.SafeLoader]:
        class XacroYamlLoader(yaml.SafeLoader):
            """A SafeLoader with xacro's unit tags (degrees, radians...)."""

        for unit in self.xacro.ConstructUnits:
            XacroYamlLoader.add_constructor(unit.value.tag, unit.constructor)
        return XacroYamlLoader

    def parse(self, _inp: object, filename: str | None = None) -> xml.dom.minidom.Document:
        """xacro's `parse` of a file (the only way xacro calls it): include nesting checked against
        the depth, the file read through the sandbox; a missing file stays xacro's error, which an
        optional include skips."""
        xacro = self.xacro
        path = os.path.join(xacro.root_dir, str(filename))
        try:
            budget.current().check("depth", len(xacro.filestack))
            text = sandbox.read_text(path, "description")
            spend("characters", len(text))
        except BudgetExceeded:
            self.needle = self.needle or os.path.basename(path)
            raise
        except sandbox.Refused as exc:
            if exc.code == "not-a-file" and not os.path.lexists(path):
                xacro.filestack.pop()
                raise xacro.XacroException(exc=FileNotFoundError(errno.ENOENT, "No such file", path)) from None
            self.needle = self.needle or os.path.basename(path)
            raise
        try:
            return parse_xml(text)
        except ValueError:  # entities
            self.needle = self.needle or ENTITY
            raise

    def glob(self, pattern: str) -> list[str]:
        """The files an include pattern names, listed only when the pattern (its folder before the
        first wildcard, no `..` after it) and every match stay inside the sandbox's roots."""
        parts = Path(pattern).parts
        fixed = next((i for i, part in enumerate(parts) if glob.has_magic(part)), len(parts))
        policy = sandbox.current()
        confined = policy.inside(Path(*parts[:fixed]) if fixed else Path(".")) and ".." not in parts[fixed:]
        found = glob.glob(pattern) if confined else None
        if found is None or not all(policy.inside(match) for match in found):
            self.needle = self.needle or os.path.basename(pattern)
            raise sandbox.Refused("outside-workspace", pattern, "reaches outside the analysed paths; not listed")
        spend("steps", len(found))
        return found

    def eval_all(self, original: Callable[..., None]) -> Callable[..., None]:
        """xacro's `eval_all`, each element spending one of the budget and macro nesting checked
        against the depth."""
        xacro = self.xacro

        def counted(node: xml.dom.minidom.Element, macros: object, symbols: object) -> None:
            try:
                budget.spend("elements")
                budget.current().check("depth", len(xacro.macrostack))
                original(node, macros, symbols)
            except (BudgetExceeded, RecursionError):
                self.needle = self.needle or f"<{node.tagName}"
                raise

        return counted

    def handle_macro_call(self, original: Callable[..., bool]) -> Callable[..., bool]:
        """xacro's `handle_macro_call`, also for the legacy call without the prefix (`<kobuki/>` for a
        macro kobuki), which xacro before 1.13 expanded with a deprecation warning and xacro 2 leaves
        as an element; each such call is recorded with its place."""
        xacro = self.xacro

        def call(node: xml.dom.minidom.Element, macros: object, symbols: object) -> bool:
            name = node.tagName
            if ":" not in name:
                try:
                    xacro.resolve_macro(name, macros, symbols)
                except (KeyError, TypeError):
                    return original(node, macros, symbols)
                self.legacy.append((name, self._located(f"<{name}")))
                node.tagName = node.nodeName = "xacro:" + name
            return original(node, macros, symbols)

        return call

    def replace_node(self, original: Callable[..., None]) -> Callable[..., None]:
        """xacro's `replace_node`, the sibling scans of its insertions and removal spent as steps."""
        def counted(node: xml.dom.minidom.Node, by: xml.dom.minidom.Node | list[xml.dom.minidom.Node] | None,
                    content_only: bool = False) -> None:
            docs = [] if by is None else by if isinstance(by, list) else [by]
            moved = sum(len(doc.childNodes) if content_only else 1 for doc in docs)
            parent = node.parentNode
            assert parent is not None  # xacro replaces only nodes inside a document
            try:
                spend("steps", (moved + 1) * len(parent.childNodes) // SIBLINGS_PER_STEP)
            except BudgetExceeded:
                self.needle = self.needle or f"<{node.nodeName}"
                raise
            original(node, by, content_only)

        return counted


def parse_xml(text: str) -> xml.dom.minidom.Document:
    """A description's XML; one that declares entities is refused (expat stops an entity bomb only
    after seconds of expansion, and descriptions have no use for entities)."""
    if ENTITY in text:
        raise ValueError("the description declares XML entities, which archlog does not expand")
    return xml.dom.minidom.parseString(text)


def _cause(exc: BaseException) -> BaseException:
    """The budget, refusal or recursion behind an exception xacro may have wrapped, else itself."""
    seen: BaseException | None = exc
    while seen is not None:
        if isinstance(seen, (BudgetExceeded, sandbox.Refused, RecursionError, MemoryError)):
            return seen
        seen = getattr(seen, "exc", None) or seen.__cause__ or seen.__context__
    return exc


def _namespace(xacro: object, names: Mapping[str, object]) -> object:
    space = xacro.NameSpace()  # type: ignore[attr-defined]
    space.update(names)
    return space


def _tokenize(text: str, sep: str = ",; ", skip_empty: bool = True) -> list[str]:
    """`xacro.tokenize`, its separators taken literally (xacro puts them into a pattern)."""
    parts = re.split(f"[{re.escape(sep)}]", str(text))
    return [part for part in parts if part] if skip_empty else parts


def _fatal(*args: object) -> None:
    raise SubstitutionError(" ".join(map(str, args)))


def _quiet(*_args: object, **_kwargs: object) -> str:
    """xacro's message helpers print to the terminal; here they say nothing."""
    return ""


@contextmanager
def routed(expansion: Expansion) -> Iterator[None]:
    """xacro with archlog's evaluation, reading, budgets and macro parameter pattern, and its
    state (module globals) fresh; all restored afterwards (this is not thread-safe)."""
    xacro = expansion.xacro
    replaced = {"eval_text": expansion.eval_text, "safe_eval": expansion.evaluate, "parse": expansion.parse,
                "eval_all": expansion.eval_all(xacro.eval_all),
                "replace_node": expansion.replace_node(xacro.replace_node),
                "handle_macro_call": expansion.handle_macro_call(xacro.handle_macro_call),
                "_global_symbols": expansion.names, "re_macro_arg": _MACRO_ARG, "all_includes": [],
                "glob": SimpleNamespace(glob=expansion.glob),  # the module xacro lists include patterns with
                "substitution_args_context": {}, "filestack": None, "macrostack": None}
    saved = {name: getattr(xacro, name) for name in replaced}
    for name, value in replaced.items():
        setattr(xacro, name, value)
    try:
        yield
    finally:
        for name, value in saved.items():
            setattr(xacro, name, value)
