"""Index of .msg/.srv/.action definitions in the workspace and in installed share dirs."""

from __future__ import annotations

from pathlib import Path

from archlog import sandbox
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.packages import share_dirs

KINDS = ("msg", "srv", "action")


def message_files(workspace: Workspace) -> dict[str, tuple[str, Path]]:
    """Map each type name to (kind, file) for every definition found; workspace ones win. ROS 1
    names are 'pkg/Name'; a ROS 2 (ament) package's are 'pkg/msg/Name', 'pkg/srv/Name' and so on."""
    found: dict[str, tuple[str, Path]] = {}
    folders = [(p.name, p.path) for p in workspace.packages.values()]
    for share in share_dirs():
        if share.is_dir():
            folders += [(d.name, d) for d in share.iterdir() if (d / "package.xml").is_file()]
    for pkg, folder in folders:
        ros2 = _is_ament(folder / "package.xml")
        for kind in KINDS:
            for path in sorted((folder / kind).glob(f"*.{kind}")):
                found.setdefault(f"{pkg}/{kind}/{path.stem}" if ros2 else f"{pkg}/{path.stem}", (kind, path))
    return found


def _is_ament(manifest: Path) -> bool:
    """A ROS 2 package: its manifest names an ament build tool or build type."""
    try:
        return "ament_" in sandbox.read_text(manifest, "build")
    except sandbox.Refused:
        return False
