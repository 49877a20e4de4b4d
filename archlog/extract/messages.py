"""Index of .msg/.srv/.action definitions in the workspace and in installed share dirs."""

from __future__ import annotations

from pathlib import Path

from archlog.extract.workspace import Workspace, share_dirs

KINDS = ("msg", "srv", "action")


def message_files(workspace: Workspace) -> dict[str, tuple[str, Path]]:
    """Map 'pkg/Name' to (kind, file) for every definition found; workspace ones win."""
    found: dict[str, tuple[str, Path]] = {}
    folders = [(p.name, p.path) for p in workspace.packages.values()]
    for share in share_dirs():
        if share.is_dir():
            folders += [(d.name, d) for d in share.iterdir() if (d / "package.xml").is_file()]
    for pkg, folder in folders:
        for kind in KINDS:
            for path in sorted((folder / kind).glob(f"*.{kind}")):
                found.setdefault(f"{pkg}/{path.stem}", (kind, path))
    return found
