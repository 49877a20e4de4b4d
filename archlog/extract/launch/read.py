"""Reading launch files: the XML root of a launch file (what cannot be read is a diagnostic), and
the booleans launch attributes and conditions are written with."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.files import parse_xml


def open_xml(path: Path, shown: str, diagnostics: DiagnosticSink, remove_pis: bool = False) -> etree._Element | None:
    """The <launch> root of an XML launch file; None (with a diagnostic at `shown`) when it is
    malformed, refused or has another root."""
    try:
        root = parse_xml(path, "launch", remove_comments=True, remove_pis=remove_pis)
    except etree.XMLSyntaxError as exc:
        diagnostics.add(shown, exc.lineno or 1, "launch-xml", f"malformed launch XML: {exc.msg}", "error")
        return None
    except sandbox.Refused as exc:
        diagnostics.add(shown, 1, exc.code, f"cannot read launch file: {exc}", "error")
        return None
    if root.tag != "launch":
        diagnostics.add(shown, root.sourceline or 1, "launch-xml", f"root element is <{root.tag}>, not <launch>",
                        "error")
        return None
    return root


def boolean(text: str, numeric: bool = True) -> bool | None:
    """`text` as a launch boolean: true or false in any case (and 1 or 0 when `numeric`), else None."""
    value = text.lower()
    if value == "true" or (numeric and value == "1"):
        return True
    if value == "false" or (numeric and value == "0"):
        return False
    return None
