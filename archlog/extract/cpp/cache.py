"""An on-disk store of per-file extraction results (SQLite), keyed by content and flags."""

from __future__ import annotations

import hashlib
import json
import os
import pickle
import sqlite3
from functools import cache, lru_cache
from pathlib import Path
from stat import S_ISREG

from archlog import __version__, budget, sandbox


def cache_dir() -> Path:
    """$ARCHLOG_CACHE_DIR, else $XDG_CACHE_HOME/archlog, else ~/.cache/archlog (created)."""
    path = _cache_path()
    path.mkdir(parents=True, exist_ok=True)
    return path


def _cache_path() -> Path:
    return Path(os.environ.get("ARCHLOG_CACHE_DIR") or
                Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "archlog")


@lru_cache(maxsize=1)
def code_digest() -> str:
    """Changes whenever archlog's extraction code changes, so cached results never outlive it."""
    digest = hashlib.sha256(__version__.encode())
    package = Path(__file__).resolve().parents[2]
    for path in sorted([*package.glob("extract/**/*.py"), package / "values.py", package / "names.py"]):
        digest.update(path.read_bytes())
    return digest.hexdigest()


def file_stamp(path: Path | str) -> str:
    """What a cached result holds of a file it depends on: its content's digest, so that a fresh
    checkout of the same files (new mtimes, as on a CI runner with the cache restored) still hits;
    installed files (/usr, /opt, kept by their package manager) and files archlog may not read are
    stamped by size and mtime."""
    name = str(path)
    try:
        stat = os.stat(name)
    except OSError:
        return "missing"
    if name.startswith(("/usr/", "/opt/")):
        return f"{stat.st_size}:{stat.st_mtime_ns}"
    return _stamp(name, stat.st_size, stat.st_mtime_ns, sandbox.current().roots, str(_cache_path()))


@cache
def _stamp(name: str, size: int, mtime: int, _roots: tuple[Path, ...] | None, cache_folder: str) -> str:
    """file_stamp of a file outside /usr and /opt, once per version of the file and reading policy:
    the digest of a regular file within the size cap that archlog may read (opened without
    blocking: a FIFO the workspace names is never waited on)."""
    by_time = f"{size}:{mtime}"
    if size > sandbox.SIZE_CAPS["source"] or not (name.startswith((_ARCHLOG_PACKAGE, cache_folder))
                                                  or sandbox.current().inside(name)):
        return by_time
    try:
        with os.fdopen(os.open(name, os.O_RDONLY | os.O_NONBLOCK), "rb") as handle:
            if not S_ISREG(os.fstat(handle.fileno()).st_mode):
                return by_time
            return hashlib.sha256(handle.read(sandbox.SIZE_CAPS["source"] + 1)).hexdigest()[:32]
    except OSError:
        return "unreadable"


_ARCHLOG_PACKAGE = str(Path(__file__).resolve().parents[2])
"""archlog's own files (stand-in headers); its generated ones are in the cache folder."""


def key(*parts: bytes | str) -> str:
    """A cache key over the extraction code and every input that changes a result."""
    digest = hashlib.sha256(code_digest().encode())
    for part in parts:
        digest.update(b"\0" + (part.encode() if isinstance(part, str) else part))
    return digest.hexdigest()


class ResultCache:
    """get/put of picklable results, each under its key and the budget in force (values fold
    within its limits); a damaged or missing store just misses."""

    def __init__(self, name: str) -> None:
        self.path = cache_dir() / f"{name}.sqlite"
        self._db: sqlite3.Connection | None = None

    def _connect(self) -> sqlite3.Connection:
        if self._db is None:
            self._db = sqlite3.connect(self.path, timeout=30)
            self._db.execute("CREATE TABLE IF NOT EXISTS results (key TEXT PRIMARY KEY, value BLOB)")
        return self._db

    def get(self, cache_key: str) -> object | None:
        try:
            row = self._connect().execute("SELECT value FROM results WHERE key = ?", (_scoped(cache_key),)).fetchone()
            return pickle.loads(row[0]) if row else None
        except (sqlite3.Error, pickle.PickleError, EOFError, AttributeError):
            return None

    def put(self, cache_key: str, value: object) -> None:
        try:
            with self._connect() as db:
                db.execute("INSERT OR REPLACE INTO results VALUES (?, ?)", (_scoped(cache_key), pickle.dumps(value)))
        except sqlite3.Error:
            return


def _scoped(cache_key: str) -> str:
    return key(cache_key, json.dumps(dict(budget.current().limits), sort_keys=True))
