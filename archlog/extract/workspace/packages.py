"""The workspace's packages and executables as values, and where packages are found (indexed
folders, installed share folders)."""

from __future__ import annotations

import glob
import os
from dataclasses import dataclass, field
from pathlib import Path

from archlog.extract.files import walk

SKIP_DIRS = {"build", "devel", "install", "log", "node_modules", "__pycache__"}


@dataclass
class Executable:
    """A node executable, a nodelet plugin or a ROS 2 component (then `cls` names its C++ class,
    and only that class is the node; a component's name is the class, as launch files name it)."""

    package: str
    name: str
    lang: str
    sources: list[Path]
    line: int = 0
    cls: str | None = None
    target: str = ""  # the CMake target it is built from
    plugin: str = ""  # a nodelet's name as its plugin description declares it (pkg/Type)
    linked: list[Path] = field(default_factory=list)  # those of `sources` from libraries it links
    # the generate_parameter_library definitions (YAML) of the libraries it links
    parameter_files: list[Path] = field(default_factory=list)
    entry: str = ""  # a console_scripts entry point's `module:function`, what runs it
    # a program of its own that runs the component `cls` (rclcpp_components_register_node's EXECUTABLE)
    standalone: bool = False

    @property
    def kinds(self) -> list[tuple[str, str]]:
        """What launch files run it as: (package, name), and for a nodelet declared under another
        prefix than its package's (pcl_ros's `pcl/VoxelGrid`) that (prefix, Type) too."""
        declared = tuple(self.plugin.split("/", 1)) if "/" in self.plugin else None
        own = (self.package, self.name)
        return [own] if declared is None or declared == own else [own, (declared[0], declared[1])]


@dataclass
class Package:
    name: str
    path: Path
    executables: dict[str, Executable] = field(default_factory=dict)
    plugin_xml: list[str] = field(default_factory=list)
    include_dirs: list[Path] = field(default_factory=list)
    libraries: dict[str, list[Path]] = field(default_factory=dict)
    ament: bool = False  # a ROS 2 package (built with ament_cmake or ament_python)
    links: dict[str, list[str]] = field(default_factory=dict)  # CMake target -> libraries it links
    parameter_libraries: dict[str, Path] = field(default_factory=dict)  # generate_parameter_library target -> YAML
    version: str = ""  # package.xml's <version>
    depends: frozenset[str] = frozenset()  # the packages its package.xml depends on (build, exec, run)
    # the pluginlib classes (other than nodelets) its plugin descriptions declare, by lookup name and
    # by C++ type: what a node whose parameters name one loads (system/named_plugins.py)
    plugin_classes: dict[str, Executable] = field(default_factory=dict)


def share_dirs() -> list[Path]:
    """Installed package locations, in ROS's search order after the indexed paths: ROS 1's
    ROS_PACKAGE_PATH, the share folders of ROS 2's AMENT_PREFIX_PATH (as a ROS 2 setup file sets it,
    or a user for ROS 2 installed from PyPI: its prefix), /opt/ros and /usr/share."""
    dirs = [Path(p) for p in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
    dirs += [Path(p) / "share" for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    dirs += sorted(Path(p) for p in glob.glob("/opt/ros/*/share"))
    dirs.append(Path("/usr/share"))
    return dirs


def manifests(root: Path) -> list[Path]:
    """Every package.xml under a root (not below a package, nor in build folders or ignored trees)."""
    if (root / "package.xml").is_file():
        return [root / "package.xml"]
    found: list[Path] = []
    for dirpath, dirnames, filenames in walk(root, pruned):
        if "CATKIN_IGNORE" in filenames or "COLCON_IGNORE" in filenames:
            dirnames[:] = []
            continue
        if "package.xml" in filenames:
            found.append(dirpath / "package.xml")
            dirnames[:] = []
    return found


def pruned(folder: str) -> bool:
    """Folders a workspace walk does not enter: hidden ones and build trees."""
    return folder.startswith(".") or folder in SKIP_DIRS
