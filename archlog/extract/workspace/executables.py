"""Find a package's node executables: CMake targets, Python entry points and scripts, nodelet
plugins and ROS 2 components."""

from __future__ import annotations

import ast
import configparser
import os
import re
from collections.abc import Callable
from pathlib import Path

from lxml import etree

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.files import files_under, parse_xml_elements, walk
from archlog.extract.workspace.cmake import commands
from archlog.extract.workspace.packages import Executable, Package, pruned

_REGISTER_NODE = re.compile(r"^[ \t]*RCLCPP_COMPONENTS_REGISTER_NODE\s*\(\s*([\w:]+)\s*\)", re.M)
_NODE_CONSTRUCTOR = re.compile(r"\b(\w+)::\1\s*\([^)]*\)\s*:\s*(?:[\w:]*::)?(?:Node|LifecycleNode)\s*\(")
_LINK_WORDS = {"PRIVATE", "PUBLIC", "INTERFACE", "debug", "optimized", "general"}
_LIBRARY_WORDS = {"SHARED", "STATIC", "MODULE", "OBJECT", "EXCLUDE_FROM_ALL", "WIN32", "MACOSX_BUNDLE",
                  "NO_TARGET_LINK_LIBRARIES", "PRIVATE", "PUBLIC", "INTERFACE"}
SOURCE_SUFFIXES = {".cpp", ".cc", ".cxx", ".c++", ".C"}
# what CMake appends, in order, to a source named without its extension (C, C++, CUDA, headers)
_CMAKE_EXTENSIONS = (".c", ".C", ".c++", ".cc", ".cpp", ".cxx", ".cu", ".m", ".M", ".mm", ".h", ".hh", ".h++", ".hm",
                     ".hpp", ".hxx", ".in", ".txx")
_KEYWORD = re.compile(r"^[A-Z][A-Z0-9_]*$")  # an argument keyword of a CMake command (OPTIONS, SHARED...)
_EXPORT = re.compile(r"\bPLUGINLIB_(?:EXPORT_CLASS\s*\(\s*([\w:]+)|DECLARE_CLASS\s*\(\s*\w+\s*,\s*\w+\s*,\s*([\w:]+))")
_SHEBANG = re.compile(rb"^#!.*python")


class ExecutableFinder:
    """Reads package files (reporting what the sandbox refuses) and fills each package's executables."""

    def __init__(self, diagnostics: DiagnosticSink, display: Callable[[Path | str], str]) -> None:
        self.diagnostics = diagnostics
        self.display = display

    def read(self, path: Path, kind: str, asker: tuple[Path, int] | None = None) -> str | None:
        """A package file's text, or None with a diagnostic when the sandbox refuses it (at the
        file:line that named it, else at the file)."""
        try:
            return sandbox.read_text(path, kind)
        except sandbox.Refused as exc:
            where, line = asker or (path, 1)
            self.diagnostics.add(self.display(where), line, exc.code, f"not read: {exc}", "warning")
            return None

    def find(self, package: Package) -> None:
        """Every executable of a package, in order of precedence (a later finding of a name wins)."""
        self._cmake_executables(package)
        self._entry_points(package)
        self._script_executables(package)
        self._plugins(package)
        self._components(package)

    def _cmake_executables(self, package: Package) -> None:
        self._cmake_dir(package, package.path, {"CMAKE_CURRENT_SOURCE_DIR": str(package.path)}, {}, depth=0)
        self._linked_sources(package)

    def _linked_sources(self, package: Package) -> None:
        """Packages often build the node's code into a library of their own that the executable
        links (target_link_libraries, followed transitively within the package): its sources belong
        to the executable, except, in ROS 2, those defining a node class the executable's own
        sources never name, and in ROS 1, those exporting a plugin (a nodelet) or defining the
        constructors of classes that no source read with the executable names (tf2_ros's library
        holds Buffer, TransformListener...: static_transform_publisher uses StaticTransformBroadcaster
        only; a nodelet loaded by its plugin name, as image_proc's node loads "image_proc/debayer"
        through nodelet::Loader, runs under its own name: system/nodelets.py). Of the files read, the
linked ones count only where the executable's own code reaches them (extract/cpp/reach.py)."""
        words = _Words([package.path / "include", *package.include_dirs])
        for exe in package.executables.values():
            exe.parameter_files = [package.parameter_libraries[library] for library in _libraries(package, exe.target)
                                   if library in package.parameter_libraries]
            if exe.lang != "cpp" or exe.cls is not None:
                continue
            own = "\n".join(_text(s) for s in exe.sources)
            linked = [s for s in _linked(package, exe.target) if s not in exe.sources]
            if package.ament:
                exe.linked = [s for s in linked if all(re.search(rf"\b{c}\b", own) for c in _node_classes(s))]
                exe.sources += exe.linked
                continue
            classes = {s: exported_plugins(s) or _constructed_classes(s) for s in linked}
            exe.linked = [s for s in linked if not classes[s]]
            named_words = words.with_headers(exe.sources + exe.linked)
            waiting = [s for s in linked if classes[s]]
            while named := [s for s in waiting if any(cls.rsplit("::", 1)[-1] in named_words for cls in classes[s])]:
                exe.linked += named
                waiting = [s for s in waiting if s not in named]
                named_words |= words.with_headers(named)
            exe.sources += exe.linked

    def _cmake_dir(self, package: Package, folder: Path, variables: dict[str, str], read: dict[Path, bool], depth: int,
                   asker: tuple[Path, int] | None = None) -> None:
        """Read one CMakeLists.txt (named at `asker`: an add_subdirectory() line); its
        add_subdirectory() folders inherit a copy of the variables. A folder is read once per
        package (`read`, folders whose reading is under way map to True): reading it again would
        multiply the work with every repetition; one that adds itself, directly or through its
        subfolders, is reported (CMake refuses it)."""
        cmake = folder / "CMakeLists.txt"
        if not cmake.is_file() or depth > 8:
            return
        real = folder.resolve()
        if real in read:
            if read[real] and asker is not None:
                self.diagnostics.add(self.display(asker[0]), asker[1], "cmake-subdirectory",
                                     f"add_subdirectory() of {self.display(folder)}, a folder being read; skipped",
                                     "warning")
            return
        read[real] = True
        self._cmake_file(package, folder, cmake, variables, read, depth, asker)
        read[real] = False

    def _cmake_file(self, package: Package, folder: Path, cmake: Path, variables: dict[str, str],
                    read: dict[Path, bool], depth: int, asker: tuple[Path, int] | None) -> None:
        """Read the CMakeLists.txt of `folder`: its targets, sources, links and subfolders."""
        if (text := self.read(cmake, "build", asker)) is None:
            return
        variables = {**variables, "CMAKE_CURRENT_SOURCE_DIR": str(folder)}
        cmds = commands(text, variables, lambda line, message: self.diagnostics.add(
            self.display(cmake), line, "budget-exceeded", f"{message}; the rest of this file is not read", "warning"))
        output_names = {
            c.args[0]: c.args[c.args.index("OUTPUT_NAME") + 1]
            for c in cmds
            if c.name == "set_target_properties" and "OUTPUT_NAME" in c.args[:-1]
        }
        for c in cmds:
            if c.name in ("add_executable", "cuda_add_executable", "ament_auto_add_executable") and c.args and \
                    "IMPORTED" not in c.args and "ALIAS" not in c.args:
                target = c.args[0]
                name = output_names.get(target, target)
                package.executables[name] = Executable(package.name, name, "cpp", _sources(folder, c.args), c.line,
                                                       target=target)
            elif c.name in ("add_library", "cuda_add_library", "ament_auto_add_library") and c.args:
                package.libraries[c.args[0]] = _sources(folder, c.args)
            elif c.name == "target_sources" and c.args:
                extra = _sources(folder, c.args)
                if c.args[0] in package.libraries:
                    package.libraries[c.args[0]] += extra
                exe = package.executables.get(output_names.get(c.args[0], c.args[0]))
                if exe is not None and exe.cls is None:
                    exe.sources += extra
            elif c.name == "generate_parameter_library" and len(c.args) >= 2:
                package.parameter_libraries[c.args[0]] = _under(folder, c.args[1])
                package.libraries.setdefault(c.args[0], [])
            elif c.name == "target_link_libraries" and c.args:
                package.links.setdefault(c.args[0], []).extend(a for a in c.args[1:] if a not in _LINK_WORDS)
            elif c.name in ("rclcpp_components_register_node", "rclcpp_components_register_nodes") and c.args:
                self._registered_components(package, c.name, c.args, c.line)
            elif c.name == "pluginlib_export_plugin_description_file" and len(c.args) >= 2:
                described = str(_under(folder, c.args[1]))
                if described not in package.plugin_xml:
                    package.plugin_xml.append(described)
            elif c.name == "include_directories":
                package.include_dirs += [_under(folder, a) for a in c.args if a not in ("SYSTEM", "BEFORE", "AFTER")
                                         and "$" not in a]
            elif c.name == "add_subdirectory" and c.args:
                self._cmake_dir(package, _under(folder, c.args[0]), variables, read, depth + 1, (cmake, c.line))
            elif c.name in ("catkin_install_python", "install") and "PROGRAMS" in c.args:
                for arg in c.args[c.args.index("PROGRAMS") + 1:]:
                    if arg == "DESTINATION":
                        break
                    path = _under(folder, arg)
                    if path.is_file():
                        lang = "python" if path.suffix == ".py" or _is_python_script(path) else "other"
                        package.executables[path.name] = Executable(package.name, path.name, lang, [path], c.line)

    def _plugins(self, package: Package) -> None:
        """The classes of the plugin descriptions the package exports (package.xml's `plugin=` attribute,
        CMake's pluginlib_export_plugin_description_file; every class of every `<library>`: one root, a
        `<class_libraries>` wrapper, or several top-level ones). A nodelet is an executable; any other
        class is kept by its lookup name and C++ type for the nodes whose parameters name it."""
        described: set[Path] = set()
        for raw in package.plugin_xml:
            path = Path(raw.replace("${prefix}", str(package.path)))
            if path.resolve() in described:
                continue
            described.add(path.resolve())
            try:
                root = parse_xml_elements(path, "build")
            except (sandbox.Refused, etree.XMLSyntaxError) as exc:
                self.diagnostics.add(self.display(package.path / "package.xml"), 1, "plugin-xml",
                                     f"plugin description {raw} cannot be read: {exc}", "warning")
                continue
            for library in root.iter("library"):
                target = Path(library.get("path", "")).name.removeprefix("lib")
                for cls in library.iter("class"):
                    name, type_ = cls.get("name") or cls.get("type", ""), cls.get("type", "")
                    sources = package.libraries.get(target) or _exporting(package.path, type_)
                    sources = sources + [s for s in _linked(package, target) if s not in sources]
                    if "nodelet" in cls.get("base_class_type", "nodelet"):
                        plugin = name.split("/", 1)[-1]
                        package.executables[plugin] = Executable(package.name, plugin, "cpp", sources,
                                                                 cls.sourceline or 0, type_, plugin=name)
                    elif type_:
                        found = Executable(package.name, type_, "cpp", sources, cls.sourceline or 0, type_)
                        package.plugin_classes.update({name: found, type_: found})

    def _registered_components(self, package: Package, command: str, args: tuple[str, ...], line: int) -> None:
        """rclcpp_components_register_node(lib PLUGIN ns::Class [EXECUTABLE exe]) and
        rclcpp_components_register_nodes(lib ns::A ns::B)."""
        sources = package.libraries.get(args[0], [])
        if command.endswith("_node"):
            plugin = args[args.index("PLUGIN") + 1] if "PLUGIN" in args[:-1] else None
            classes = [plugin] if plugin else []
            executable = args[args.index("EXECUTABLE") + 1] if "EXECUTABLE" in args[:-1] else None
        else:
            classes = [a for a in args[1:] if "::" in a]
            executable = None
        for cls in classes:
            package.executables[cls] = Executable(package.name, cls, "cpp", list(sources), line, cls)
        if executable and classes:
            package.executables[executable] = Executable(package.name, executable, "cpp", list(sources), line,
                                                         classes[0], standalone=True)

    def _components(self, package: Package) -> None:
        """Components registered in the sources (RCLCPP_COMPONENTS_REGISTER_NODE) but not in
        CMakeLists.txt: the library compiling the file, else the file alone."""
        for path in _source_files(package.path):
            text = _text(path)
            if "RCLCPP_COMPONENTS_REGISTER_NODE" not in text:
                continue
            for cls, line in registered_components(text):
                if cls in package.executables:
                    continue
                sources = next((s for s in package.libraries.values() if path in s), [path])
                package.executables[cls] = Executable(package.name, cls, "cpp", list(sources), line, cls)

    def _entry_points(self, package: Package) -> None:
        """console_scripts of setup.py / setup.cfg (catkin and ament_python packages)."""
        for spec in self._console_scripts(package.path):
            name, _, target = spec.partition("=")
            module = target.strip().split(":")[0].strip()
            relative = Path(*module.split("."))
            for base in (package.path, package.path / "src"):
                for candidate in (base / relative.with_suffix(".py"), base / relative / "__init__.py"):
                    if candidate.is_file():
                        package.executables[name.strip()] = Executable(package.name, name.strip(), "python",
                                                                       [candidate], entry=target.strip())
                        break

    def _console_scripts(self, folder: Path) -> list[str]:
        specs: list[str] = []
        setup_cfg = folder / "setup.cfg"
        if setup_cfg.is_file() and (text := self.read(setup_cfg, "build")) is not None:
            parser = configparser.ConfigParser()
            try:
                parser.read_string(text, str(setup_cfg))
                specs += [ln for ln in parser.get("options.entry_points", "console_scripts", fallback="").splitlines()
                          if "=" in ln]
            except configparser.Error as exc:
                self.diagnostics.add(self.display(setup_cfg), 1, "setup-cfg", f"setup.cfg does not parse: {exc}",
                                     "warning")
        setup_py = folder / "setup.py"
        if setup_py.is_file() and (text := self.read(setup_py, "build")) is not None:
            try:
                tree = ast.parse(text)
            except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
                line = exc.lineno if isinstance(exc, SyntaxError) and exc.lineno else 1
                self.diagnostics.add(self.display(setup_py), line, "setup-py", "setup.py does not parse", "warning")
                return specs
            for node in ast.walk(tree):
                if isinstance(node, ast.Dict):
                    for key, value in zip(node.keys, node.values):
                        if isinstance(key, ast.Constant) and key.value == "console_scripts" and \
                                isinstance(value, (ast.List, ast.Tuple)):
                            specs += [e.value for e in value.elts
                                      if isinstance(e, ast.Constant) and isinstance(e.value, str)]
        return specs

    def _script_executables(self, package: Package) -> None:
        """Executable Python scripts in the usual folders, and modules with a `__main__` block
        that use rospy or rclpy. A module an entry point already runs is that one executable: its
        `__main__` block is the same program (ros2 run finds only the entry point)."""
        entry_modules = {exe.sources[0] for exe in package.executables.values() if exe.lang == "python" and exe.sources}
        for folder in ("scripts", "nodes", "bin", "src", package.name):
            for path in files_under(package.path / folder):
                if path.name in package.executables or path in entry_modules or not path.is_file() or \
                        path.suffix in SOURCE_SUFFIXES:
                    continue
                if os.access(path, os.X_OK) and _is_python_script(path) or _is_main_module(path):
                    package.executables[path.name] = Executable(package.name, path.name, "python", [path])


def _linked(package: Package, target: str) -> list[Path]:
    """The sources of the package's libraries a target links, transitively."""
    linked: list[Path] = []
    for library in _libraries(package, target):
        linked += [s for s in package.libraries[library] if s not in linked]
    return linked


def _libraries(package: Package, target: str) -> list[str]:
    """The package's libraries a target links, transitively, in order."""
    pending, seen = list(package.links.get(target, [])), list[str]()
    while pending:
        library = pending.pop(0)
        if library in package.libraries and library not in seen and library != target:
            seen.append(library)
            pending += package.links.get(library, [])
    return seen


def _text(path: Path) -> str:
    """A source file's text for indexing; empty when the sandbox refuses it (the extractor that
    reads it for its node reports why)."""
    try:
        return sandbox.read_text(path, "source")
    except sandbox.Refused:
        return ""


_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


class _Words:
    """The words of sources and of the package headers they include, three levels deep (a class a
    source names only in a member its header declares is named by that source), each file read
    once; a word after a slash does not count (the Type of a plugin name pkg/Type)."""

    def __init__(self, folders: list[Path]) -> None:
        self.folders = folders
        self.files: dict[Path, tuple[set[str], list[str]]] = {}

    def with_headers(self, sources: list[Path]) -> set[str]:
        words: set[str] = set()
        for source in sources:
            words |= self._reached(source, 3)
        return words

    def _reached(self, source: Path, depth: int) -> set[str]:
        if source not in self.files:
            text = _text(source)
            self.files[source] = set(_WORD.findall(text)), _INCLUDE.findall(text)
        words, includes = self.files[source]
        words = set(words)
        for include in includes if depth else []:
            found = next((f / include for f in [source.parent, *self.folders] if (f / include).is_file()), None)
            if found is not None and found != source:
                words |= self._reached(found, depth - 1)
        return words


_WORD = re.compile(r"(?<![\w/])\w+")
_CONSTRUCTOR = re.compile(r"\b(\w+)::\1\s*\(")


def _constructed_classes(source: Path) -> list[str]:
    """Classes whose constructors a C++ file defines."""
    return sorted(set(_CONSTRUCTOR.findall(_text(source))))


def _node_classes(source: Path) -> list[str]:
    """Node classes a C++ file defines: constructors whose base initializer is a Node."""
    return sorted(set(_NODE_CONSTRUCTOR.findall(_text(source))))


def exported_plugins(source: Path) -> list[str]:
    """Classes a C++ file exports as plugins (PLUGINLIB_EXPORT_CLASS, PLUGINLIB_DECLARE_CLASS)."""
    return sorted({(m.group(1) or m.group(2)).lstrip(":") for m in _EXPORT.finditer(_text(source))})


def registered_components(text: str) -> list[tuple[str, int]]:
    """(class, line) of every RCLCPP_COMPONENTS_REGISTER_NODE(ns::Class) in a C++ source."""
    return [(m.group(1).lstrip(":"), text.count("\n", 0, m.start()) + 1) for m in _REGISTER_NODE.finditer(text)]


def _sources(folder: Path, args: tuple[str, ...]) -> list[Path]:
    """The C++ sources of add_executable / add_library / ament_auto_add_* / target_sources
    (ament_auto's DIRECTORY d: every source under d)."""
    found: list[Path] = []
    words = list(args[1:])
    for index, word in enumerate(words):
        if word == "DIRECTORY" and index + 1 < len(words):
            found += _source_files(_under(folder, words[index + 1]))
        elif word not in _LIBRARY_WORDS and Path(word).suffix in SOURCE_SUFFIXES | {".cu"}:
            found.append(_under(folder, word))
        elif word not in _LIBRARY_WORDS and not _KEYWORD.match(word) and "$" not in word and "<" not in word:
            path = _under(folder, word)
            if path.is_file():
                continue  # a header, or a file of another language
            # CMake's lookup: a name not found as written is tried with each source extension
            given = next((path.with_name(path.name + ext) for ext in _CMAKE_EXTENSIONS
                          if path.with_name(path.name + ext).is_file()), None)
            if given is not None and given.suffix in SOURCE_SUFFIXES | {".cu"}:
                found.append(given)
            elif given is None and not path.suffix:
                found.append(path)  # missing: reported (cpp-missing) when the executable is read
    return found


def _source_files(folder: Path) -> list[Path]:
    """C++ sources under a folder, outside build trees."""
    return [dirpath / f for dirpath, _dirs, filenames in walk(folder, pruned) for f in filenames
            if Path(f).suffix in SOURCE_SUFFIXES]


def _under(folder: Path, path: str) -> Path:
    """A CMake path argument: absolute as given, otherwise relative to the current folder."""
    return Path(path) if Path(path).is_absolute() else folder / path


def _exporting(folder: Path, cls: str) -> list[Path]:
    """Source files that PLUGINLIB_EXPORT_CLASS the class (when its library is not found)."""
    pattern = re.compile(r"PLUGINLIB_EXPORT_CLASS\s*\(\s*" + re.escape(cls) + r"\b")
    return [p for p in files_under(folder) if p.suffix in SOURCE_SUFFIXES and pattern.search(_text(p))]


def _is_main_module(path: Path) -> bool:
    if path.suffix != ".py" or path.name in ("setup.py", "__init__.py") or "test" in path.parts[-2:-1]:
        return False
    text = _text(path)
    return "__main__" in text and ("import rospy" in text or "import rclpy" in text or "from rclpy" in text)


def _is_python_script(path: Path) -> bool:
    try:
        return bool(_SHEBANG.match(sandbox.read_bytes(path, "source")[:200]))
    except sandbox.Refused:
        return False
