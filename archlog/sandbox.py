"""What archlog may take from the machine it runs on: the workspace is untrusted (it comes from a
pull request), so reading is confined and the environment is an explicit input.

- Files: only regular files under the analysed paths and the package roots archlog resolves
  packages from (ROS share and include folders), each under a size cap for its kind; a symlink
  is followed only when its target stays inside those roots. Anything else raises `Refused`,
  whose message names the path and never its content.
- Environment: only variables given with `--env NAME=VALUE`, set in `archlog.toml` (`[env]`), or
  on `ENV_ALLOWED` are visible; any other reads as unset. With `shell` (the command line's
  `--env-from-shell`, for a user checking locally; never a configuration file's setting), a
  variable the input asks for and was not given is read from this process's environment unless its
  name looks like a secret's (`SECRET_LIKE`); the names so read are kept in `from_shell`. A reader that meets one calls
  `not_given(name)`; the reader of the file collects those names (`reads_not_given()`) and reports
  an `env-not-given` diagnostic at its place with `not_given_message` (the name, never a value).

The policy in force is a context variable: `analyse()` installs one for the run with `active()`.
Outside it (library use, unit tests) every path is inside, and the environment is the allow-list.
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

ENV_ALLOWED = ("ROS_DISTRO", "ROS_VERSION", "ROS_PYTHON_VERSION")
"""Environment variables read from the machine without being given: they name the ROS release,
which launch files branch on, and hold no secret."""

SECRET_LIKE = re.compile(r"TOKEN|SECRET|PASSW|KEY|CREDENTIAL|AUTH|COOKIE|SESSION|PRIVATE|CERT", re.IGNORECASE)
"""Names of variables `--env-from-shell` never reads: they may hold a secret."""

MiB = 1 << 20
SIZE_CAPS = {"source": 8 * MiB, "launch": 4 * MiB, "params": 4 * MiB, "build": 4 * MiB,
             "description": 8 * MiB, "config": 4 * MiB, "message": 1 * MiB}
"""Largest file archlog reads, per kind of input (bytes)."""


class Refused(Exception):
    """A file archlog will not read. `code` is the diagnostic code: `outside-workspace`,
    `not-a-file` (directory, device, FIFO, socket, missing) or `too-large`."""

    def __init__(self, code: str, path: Path | str, why: str) -> None:
        super().__init__(f"{path}: {why}")
        self.code, self.path = code, str(path)


@dataclass(frozen=True)
class Sandbox:
    """The roots reading is confined to (None: anywhere), the environment archlog may see, and
    the size caps per kind."""

    roots: tuple[Path, ...] | None = None
    env: Mapping[str, str] = field(default_factory=dict)
    caps: Mapping[str, int] = field(default_factory=lambda: dict(SIZE_CAPS))
    shell: bool = False
    from_shell: list[str] = field(default_factory=list)
    _inside: dict[str, bool] = field(default_factory=dict, compare=False, repr=False)

    def inside(self, path: Path | str) -> bool:
        """Whether `path`, with every symlink resolved, lies under a root (a path with a NUL byte
        names no file). Each path is resolved once a run: a launch file included thousands of
        times is not resolved again each time."""
        text = str(path)
        if "\0" in text:
            return False
        if self.roots is None:
            return True
        known = self._inside.get(text)
        if known is None:
            real = Path(os.path.realpath(text))
            known = self._inside[text] = any(real == root or real.is_relative_to(root) for root in self.roots)
        return known

    def check(self, path: Path | str, kind: str = "source") -> Path:
        """`path` if archlog may read it as `kind`; raises `Refused` otherwise."""
        if "\0" in str(path):
            raise Refused("not-a-file", repr(str(path)), "a path with a NUL byte; not read")
        if not self.inside(path):
            raise Refused("outside-workspace", path, "outside the analysed paths; not read")
        try:
            info = os.stat(path)
        except OSError as exc:
            raise Refused("not-a-file", path, exc.strerror or "cannot be read") from None
        if not stat.S_ISREG(info.st_mode):
            raise Refused("not-a-file", path, "not a regular file; not read")
        cap = self.caps.get(kind, SIZE_CAPS["source"])
        if info.st_size > cap:
            raise Refused("too-large", path, f"{info.st_size} bytes, over the {cap}-byte cap for {kind} files")
        return path if isinstance(path, Path) else Path(path)

    def read_bytes(self, path: Path | str, kind: str = "source") -> bytes:
        checked = self.check(path, kind)
        cap = self.caps.get(kind, SIZE_CAPS["source"])
        try:
            with open(checked, "rb") as handle:
                data = handle.read(cap + 1)
        except OSError as exc:
            raise Refused("not-a-file", path, exc.strerror or "cannot be read") from None
        if len(data) > cap:  # grew since it was checked
            raise Refused("too-large", path, f"over the {cap}-byte cap for {kind} files")
        return data

    def read_text(self, path: Path | str, kind: str = "source") -> str:
        """The file's text; bytes that are not UTF-8 become U+FFFD (never an exception)."""
        return self.read_bytes(path, kind).decode("utf-8", errors="replace")

    def getenv(self, name: str) -> str | None:
        """An environment variable archlog may see, or None (unset, or not given)."""
        return self.env[name] if name in self.env else self.shell_value(name)

    def shell_value(self, name: str) -> str | None:
        """A variable of this shell under `--env-from-shell` (not a secret's name), else None."""
        if not self.shell or SECRET_LIKE.search(name) or name not in os.environ:
            return None
        if name not in self.from_shell:
            self.from_shell.append(name)
        return os.environ[name]


def machine_env(given: Mapping[str, str] | None = None) -> dict[str, str]:
    """The environment a run sees: the allow-listed variables of this process, then `given`."""
    env = {name: os.environ[name] for name in ENV_ALLOWED if name in os.environ}
    env.update(given or {})
    return env


def not_given_message(name: str) -> str:
    return (f"environment variable {name} is not given, so its value is unknown (archlog reads only the "
            f"variables passed with --env {name}=... or set in [env] of archlog.toml, and with --env-from-shell "
            f"those of this shell)")


class NotGiven(NamedTuple):
    """A variable the input read that the run was not given; `defaulted`: the input's own default
    was used instead ($(optenv X default), EnvironmentVariable's default_value, os.environ.get's)."""

    name: str
    defaulted: bool = False


def env_note(read: NotGiven) -> tuple[str, str]:
    """The diagnostic code and message of a variable not given: `env-default` (listed only with
    --verbose) when the input's default was used, else `env-not-given`."""
    if read.defaulted:
        return "env-default", (f"environment variable {read.name} is not given, so the default written next to "
                               f"it is used (pass --env {read.name}=... for another value)")
    return "env-not-given", not_given_message(read.name)


_current: ContextVar[Sandbox | None] = ContextVar("archlog_sandbox", default=None)
_not_given: ContextVar[list[NotGiven] | None] = ContextVar("archlog_env_not_given", default=None)


def current() -> Sandbox:
    """The policy in force (outside `active()`: no root confinement, allow-listed environment)."""
    return _current.get() or Sandbox(None, machine_env())


@contextmanager
def active(sandbox: Sandbox) -> Iterator[Sandbox]:
    token = _current.set(sandbox)
    try:
        yield sandbox
    finally:
        _current.reset(token)


def read_text(path: Path | str, kind: str = "source") -> str:
    """Read a file under the policy in force (raises `Refused`)."""
    return current().read_text(path, kind)


def read_bytes(path: Path | str, kind: str = "source") -> bytes:
    return current().read_bytes(path, kind)


def getenv(name: str) -> str | None:
    return current().getenv(name)


def shell_value(name: str) -> str | None:
    """A variable a launch file's own environment lacks, read from the shell (--env-from-shell)."""
    return current().shell_value(name)


def not_given(name: str, defaulted: bool = False) -> None:
    """Note that the input read `name`, a variable the run was not given (`defaulted`: and used
    its own default); a read without default outweighs one with."""
    names = _not_given.get()
    if names is None:
        return
    if NotGiven(name, True) in names and not defaulted:
        names.remove(NotGiven(name, True))
    if NotGiven(name, False) not in names and NotGiven(name, True) not in names:
        names.append(NotGiven(name, defaulted))


@contextmanager
def reads_not_given() -> Iterator[list[NotGiven]]:
    """The variables read but not given while inside (an inner collection keeps its own)."""
    names: list[NotGiven] = []
    token = _not_given.set(names)
    try:
        yield names
    finally:
        _not_given.reset(token)
