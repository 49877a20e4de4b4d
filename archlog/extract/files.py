"""Reading workspace files through the sandbox: XML without external entities, and folder walks
that stay inside the analysed paths (no symlinked folder is entered, loops end)."""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator
from pathlib import Path

from lxml import etree

from archlog import sandbox


def unreadable(path: Path | str, kind: str) -> sandbox.Refused | None:
    """Why the sandbox will not read `path` as `kind` (None: it will). A path inside the
    sandbox that does not exist gives code `missing`, for callers that report it their own way."""
    try:
        sandbox.current().check(path, kind)
    except sandbox.Refused as exc:
        if exc.code == "not-a-file" and not os.path.lexists(path):
            return sandbox.Refused("missing", path, "not found")
        return exc
    return None


def parse_xml(path: Path | str, kind: str, **options: bool) -> etree._Element:
    """The root element of an XML file read under the sandbox (raises `sandbox.Refused` or
    `etree.XMLSyntaxError`). Only internal entities are expanded; no DTD, file or URL is loaded."""
    parser = etree.XMLParser(resolve_entities="internal", load_dtd=False, no_network=True, **options)
    return etree.fromstring(sandbox.read_bytes(path, kind), parser, base_url=str(path))


_DECLARATION = re.compile(rb"^\s*<\?xml[^>]*\?>")


def parse_xml_elements(path: Path | str, kind: str) -> etree._Element:
    """Like `parse_xml`, for files that may hold several top-level elements (pluginlib
    descriptions with one `<library>` after another): if the file is not one document, its text
    after the XML declaration is read again inside a synthetic root element, which is returned
    (line numbers are kept). A file with a DOCTYPE is not wrapped: its first error is raised."""
    data = sandbox.read_bytes(path, kind)
    parser = etree.XMLParser(resolve_entities="internal", load_dtd=False, no_network=True)
    try:
        return etree.fromstring(data, parser, base_url=str(path))
    except etree.XMLSyntaxError as exc:
        if b"<!DOCTYPE" in data or "Extra content" not in str(exc):
            raise
        declaration = _DECLARATION.match(data)
        if declaration:
            data = bytes(c if c in b"\r\n" else 32 for c in declaration.group()) + data[declaration.end():]
        try:
            return etree.fromstring(b"<plugin_descriptions>" + data + b"</plugin_descriptions>", parser,
                                    base_url=str(path))
        except etree.XMLSyntaxError:
            raise exc from None


def walk(folder: Path, prune: Callable[[str], bool] = lambda _name: False
         ) -> Iterator[tuple[Path, list[str], list[str]]]:
    """os.walk of a folder inside the sandbox, sorted, never entering a symlinked folder nor
    those `prune` names (the caller may prune `dirnames` further, in place). A folder outside the
    sandbox, a symlink loop or anything but a folder yields nothing."""
    if not sandbox.current().inside(folder) or not folder.is_dir():
        return
    for dirpath, dirnames, filenames in os.walk(folder):
        dirnames[:] = sorted(d for d in dirnames if not prune(d))
        yield Path(dirpath), dirnames, sorted(filenames)


def files_under(folder: Path, prune: Callable[[str], bool] = lambda _name: False) -> list[Path]:
    """Every file name under a folder (see `walk`), sorted by path."""
    return sorted(dirpath / name for dirpath, _dirs, names in walk(folder, prune) for name in names)
