"""The workspace index: the packages under the analysed paths, and lookup of installed ones."""

from __future__ import annotations

import os
import re
from pathlib import Path

from catkin_pkg.package import InvalidPackage, parse_package_string

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.executables import ExecutableFinder
from archlog.extract.workspace.packages import Executable, Package, manifests, share_dirs


class Workspace:
    """The packages under the indexed paths, plus lookup of installed packages for `$(find)`."""

    def __init__(self, roots: list[Path], diagnostics: DiagnosticSink) -> None:
        self.roots = [Path(os.path.realpath(r)) for r in roots]
        self.diagnostics = diagnostics
        self.packages: dict[str, Package] = {}
        self._finder = ExecutableFinder(diagnostics, self.display)
        for root in self.roots:
            for manifest in manifests(root):
                self._index(manifest)

    def display(self, path: Path | str) -> str:
        """A path as shown in reports: relative to the first indexed root that contains it."""
        for shown in (os.path.realpath(path), os.path.abspath(path)):  # a symlink out: where it is
            for root in self.roots:
                base = root if root.is_dir() else root.parent
                if Path(shown).is_relative_to(base):
                    return Path(shown).relative_to(base).as_posix()
        return str(path)

    def find(self, pkg: str) -> Path | None:
        """Where `$(find pkg)` points: the indexed paths first, then installed share dirs."""
        if pkg in self.packages:
            return self.packages[pkg].path
        for share in share_dirs():
            candidate = share / pkg
            if (candidate / "package.xml").is_file():
                return candidate
        return None

    def version(self, pkg: str) -> str | None:
        """The version (package.xml's <version>) of the package `$(find pkg)` would find, or None."""
        if pkg in self.packages:
            return self.packages[pkg].version or None
        folder = self.find(pkg)
        if folder is None:
            return None
        try:
            return _version(sandbox.read_text(folder / "package.xml", "build"))
        except sandbox.Refused:
            return None

    def executable(self, pkg: str, exe: str) -> Executable | None:
        package = self.packages.get(pkg)
        return package.executables.get(exe) if package else None

    def plugin_class(self, name: str) -> Executable | None:
        """The pluginlib class a package of the workspace declares under this lookup name or C++ type."""
        return next((found for package in self.packages.values() if (found := package.plugin_classes.get(name))), None)

    def _index(self, manifest: Path) -> None:
        folder = manifest.parent
        text = self._finder.read(manifest, "build")
        if text is None:
            return
        try:
            parsed = parse_package_string(text, str(manifest))
            name = parsed.name
            plugin_xml = [e.attributes["plugin"] for e in parsed.exports if "plugin" in e.attributes]
            ament = any(d.name.startswith("ament_") for d in parsed.buildtool_depends) or any(
                e.tagname == "build_type" and (e.content or "").startswith("ament_") for e in parsed.exports)
            depends = frozenset(d.name for d in [*parsed.build_depends, *parsed.exec_depends, *parsed.run_depends])
        except (InvalidPackage, Exception) as exc:  # catkin_pkg raises several error types
            match = re.search(r"<name>\s*([^<\s]+)\s*</name>", text)
            self.diagnostics.add(self.display(manifest), 1, "package-xml", f"invalid package.xml: {_first_line(exc)}")
            if not match:
                return
            name, plugin_xml, ament, depends = match.group(1), [], False, frozenset()
        if name in self.packages:
            other = self.display(self.packages[name].path)
            self.diagnostics.add(self.display(manifest), 1, "duplicate-package",
                                 f"package {name} also found at {other}; using the first")
            return
        package = Package(name, folder, plugin_xml=plugin_xml, ament=ament, version=_version(text) or "",
                          depends=depends)
        self.packages[name] = package
        self._finder.find(package)


def _version(manifest: str) -> str | None:
    """The <version> a package.xml's text declares."""
    match = re.search(r"<version(?:\s[^>]*)?>\s*([^<\s]+)\s*</version>", manifest)
    return match.group(1) if match else None


def _first_line(exc: BaseException) -> str:
    """The message of a catkin_pkg error, whose first line is often only a heading."""
    lines = [ln.strip(" -") for ln in str(exc).strip().splitlines() if ln.strip(" -")]
    return "; ".join(ln for ln in lines if not ln.startswith("Error(s) in package")) or type(exc).__name__
