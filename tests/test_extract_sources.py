"""rospy (ast) and roscpp (libclang) extraction on small sources written here."""

from __future__ import annotations

import json
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.extract import CppEnvironment, extract_cpp
from archlog.extract.python.node import extract_python
from archlog.values import ParamRef, Unknown

PY = '''#!/usr/bin/env python3
import rospy
from std_msgs.msg import String as S
import geometry_msgs.msg
from nav_msgs import msg as nm
from nav_msgs.srv import GetMap
TOPIC = "chatter"

def main():
    rospy.init_node("talker")
    rospy.Publisher(TOPIC, S, queue_size=10)
    rospy.Subscriber(rospy.get_param("~input", "cmd"), geometry_msgs.msg.Twist, print)
    rospy.Subscriber(f"/{TOPIC}_echo", nm.Odometry, print)
    rospy.ServiceProxy(name="static_map", service_class=GetMap)
    rospy.Service("~reset", GetMap, print)
    rospy.Publisher(make_topic(), S)
'''

CPP = r'''#include <ros/ros.h>
#include <std_msgs/String.h>
#include <sensor_msgs/LaserScan.h>
#include <nav_msgs/GetMap.h>
static const std::string PREFIX = "out";
class Relay {
 public:
  Relay() : pnh_("~") {
    pub_ = nh_.advertise<std_msgs::String>(PREFIX + "/text", 10);
    sub_ = pnh_.subscribe("scan", 10, &Relay::onScan, this);
    srv_ = nh_.advertiseService("get_map", &Relay::onMap, this);
  }
  void onScan(const sensor_msgs::LaserScan::ConstPtr& m) {}
  bool onMap(nav_msgs::GetMap::Request& req, nav_msgs::GetMap::Response& res) { return true; }
 private:
  ros::NodeHandle nh_, pnh_;
  ros::Publisher pub_; ros::Subscriber sub_; ros::ServiceServer srv_;
};
void onImage(const sensor_msgs::LaserScanConstPtr& msg) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  ros::NodeHandle nh;
  ros::NodeHandle cam(nh, "camera");
  std::string topic;
  nh.param<std::string>("input_topic", topic, "image");
  ros::Subscriber s = cam.subscribe(topic, 1, onImage);
  ros::ServiceClient c = nh.serviceClient<nav_msgs::GetMap>("static_map");
  Relay r;
  ros::spin();
}
'''


def ports(summary):
    return [(p.kind, p.name, p.type, p.handle_ns, p.line) for p in summary.ports]


def test_rospy_calls_types_and_values(tmp_path: Path) -> None:
    (tmp_path / "talker.py").write_text(PY)
    sink = DiagnosticSink()
    s = extract_python(tmp_path / "talker.py", "demo", "talker.py", "talker.py", sink)
    assert s.default_name == "talker" and sink.items == []
    got = ports(s)
    assert got[0] == ("publisher", "chatter", "std_msgs/String", "", 11)
    assert got[1][0:3] == ("subscriber", ParamRef("~input", "cmd", "", "talker.py", 12), "geometry_msgs/Twist")
    assert got[2][0:3] == ("param_read", "~input", "")
    assert got[3][0:3] == ("subscriber", "/chatter_echo", "nav_msgs/Odometry")
    assert got[4][0:3] == ("service_client", "static_map", "nav_msgs/GetMap")
    assert got[5][0:3] == ("service_server", "~reset", "nav_msgs/GetMap")
    assert got[6][0] == "publisher" and got[6][1] == Unknown("make_topic()", "talker.py", 16)


def test_python2_is_repaired_and_garbage_is_a_diagnostic(tmp_path: Path) -> None:
    (tmp_path / "old.py").write_text("import rospy\nfrom std_msgs.msg import String\nprint 'hello'\n"
                                     "rospy.Publisher('out', String)\n")
    sink = DiagnosticSink()
    s = extract_python(tmp_path / "old.py", "demo", "old.py", "old.py", sink)
    assert [(p.kind, p.name, p.line) for p in s.ports] == [("publisher", "out", 4)]
    assert [(d.line, d.code) for d in sink.items] == [(3, "python2")] and s.incomplete is None
    (tmp_path / "garbage.py").write_bytes(b"\x00\x01 def (((\n" * 300)
    sink = DiagnosticSink()
    s = extract_python(tmp_path / "garbage.py", "demo", "g", "garbage.py", sink)
    assert s.ports == [] and [d.code for d in sink.items] == ["python-syntax"] and s.incomplete


def test_roscpp_handles_templates_callbacks_and_params(tmp_path: Path) -> None:
    (tmp_path / "relay.cpp").write_text(CPP)
    sink = DiagnosticSink()
    s = extract_cpp([tmp_path / "relay.cpp"], "demo", "relay", CppEnvironment([]), {tmp_path / "relay.cpp": "relay.cpp"},
                    sink)
    assert s.default_name == "relay" and sink.items == []
    got = {(k, n if isinstance(n, str) else type(n).__name__, t, h, line) for k, n, t, h, line in ports(s)}
    assert ("publisher", "out/text", "std_msgs/String", "", 9) in got
    assert ("subscriber", "scan", "sensor_msgs/LaserScan", "~", 10) in got
    assert ("service_server", "get_map", "nav_msgs/GetMap", "", 11) in got
    assert ("service_client", "static_map", "nav_msgs/GetMap", "", 27) in got
    image = next(p for p in s.ports if p.kind == "subscriber" and p.line == 26)
    assert image.handle_ns == "camera" and image.type == "sensor_msgs/LaserScan"
    assert image.name == ParamRef("input_topic", "image", "", "relay.cpp", 25)


def test_cpp_that_does_not_compile_keeps_the_calls(tmp_path: Path) -> None:
    (tmp_path / "broken.cpp").write_text(
        '#include <ros/ros.h>\n#include <std_msgs/String.h>\n#include <no/such_header.h>\n'
        'int main(int c, char** v) { ros::init(c, v, "b"); ros::NodeHandle nh;\n'
        '  ros::Publisher p = nh.advertise<std_msgs::String>("chatter", 1);\n  undeclared_call(); }\n')
    sink = DiagnosticSink()
    s = extract_cpp([tmp_path / "broken.cpp"], "demo", "b", CppEnvironment([]), {tmp_path / "broken.cpp": "broken.cpp"},
                    sink)
    assert [(d.file, d.code) for d in sink.items] == [("broken.cpp", "cpp-compile")]
    assert sink.items[0].line == 3
    assert [(p.kind, p.name, p.type) for p in s.ports] == [("publisher", "chatter", "std_msgs/String")]


def _good_and_other(tmp_path: Path, other: str) -> None:
    """A package of two executables: `good` advertises /out, `other` is an empty main."""
    pkg = tmp_path / "src" / "demo"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='2'><name>demo</name><version>0.1.0</version><description>d"
                                     "</description><maintainer email='dev@example.com'>m</maintainer>"
                                     "<license>MIT</license></package>")
    (pkg / "CMakeLists.txt").write_text(f"project(demo)\nadd_executable(good src/good.cpp)\n"
                                        f"add_executable({other} src/{other}.cpp)\n")
    (pkg / "src" / "good.cpp").write_text('#include <ros/ros.h>\n#include <std_msgs/String.h>\nint main(int c, char** v)'
                                          ' { ros::init(c, v, "good"); ros::NodeHandle nh;\n'
                                          '  nh.advertise<std_msgs::String>("out", 1); }\n')
    (pkg / "src" / f"{other}.cpp").write_text("int main() {}\n")


def test_a_parser_crash_costs_one_executable_not_the_run(tmp_path: Path, monkeypatch) -> None:
    """Fault injection: the C++ extractor aborts the worker process on one file."""
    import os

    import archlog.analysis as analysis

    _good_and_other(tmp_path, "bad")
    real = analysis.extract_cpp

    def crashing(sources, *args):
        if sources[0].name == "bad.cpp":
            os.abort()
        return real(sources, *args)

    monkeypatch.setattr(analysis, "extract_cpp", crashing)
    result = analysis.analyse([tmp_path], [], {}, [])
    assert [(n, t) for _p, n, t, _ty in result.store.rows("publisher")] == [("/good", "/out")]
    assert [(d.file, d.code) for d in result.diagnostics.items] == [("src/demo/src/bad.cpp", "cpp-crash")]


def test_an_executable_past_its_cpu_time_costs_that_executable(tmp_path: Path, monkeypatch) -> None:
    """The job limit counts CPU seconds (a busy machine does not cut a job short): a job that
    spins past it ends its worker and is reported as a crash; the other executable is read."""
    import archlog.analysis as analysis

    _good_and_other(tmp_path, "slow")
    real = analysis.extract_cpp

    def spinning(sources, *args):
        while sources[0].name == "slow.cpp":  # spends CPU time until the job's CPU limit stops it
            sum(range(1000))
        return real(sources, *args)

    monkeypatch.setattr(analysis, "extract_cpp", spinning)
    monkeypatch.setattr(analysis, "CPP_JOB_CPU_SECONDS", 1)
    monkeypatch.setattr(analysis, "CPP_JOB_WALL_SECONDS", 60)  # bounds the test if the CPU limit failed
    result = analysis.analyse([tmp_path], [], {}, [])
    assert [(n, t) for _p, n, t, _ty in result.store.rows("publisher")] == [("/good", "/out")]
    assert [(d.file, d.code) for d in result.diagnostics.items] == [("src/demo/src/slow.cpp", "cpp-crash")]


def test_handles_and_strings_through_constructor_call_sites(tmp_path: Path) -> None:
    """A NodeHandle and a name passed into a constructor: absolute, private and relative names."""
    from archlog.analysis import analyse

    pkg = tmp_path / "src" / "rp"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='2'><name>rp</name><version>0.1.0</version><description>d"
                                     "</description><maintainer email='dev@example.com'>m</maintainer>"
                                     "<license>MIT</license></package>")
    (pkg / "CMakeLists.txt").write_text("project(rp)\nadd_executable(talker src/talker.cpp)\n")
    (pkg / "src" / "talker.cpp").write_text(
        '#include <ros/ros.h>\n#include <std_msgs/String.h>\n'
        'struct Part { Part(const std::string& name, ros::NodeHandle& nh) {\n'
        '    ros::NodeHandle pnh(nh, name);\n'
        '    a_ = pnh.advertise<std_msgs::String>("/chatter", 1);\n'
        '    b_ = pnh.advertise<std_msgs::String>("~status", 1);\n'
        '    c_ = pnh.advertise<std_msgs::String>("rel", 1); }\n'
        '  ros::Publisher a_, b_, c_; };\n'
        'int main(int argc, char** argv) { ros::init(argc, argv, "talker"); ros::NodeHandle nh;\n'
        '  Part p("arm", nh); ros::spin(); }\n')
    result = analyse([tmp_path], [], {}, [])
    assert sorted(t for _p, _n, t, _ty in result.store.rows("publisher")) == ["/arm/rel", "/chatter", "/talker/status"]


def test_newer_python_syntax_is_repaired(tmp_path: Path) -> None:
    (tmp_path / "new.py").write_text("import rclpy\nfrom std_msgs.msg import String\ntype Alias = list[int]\n"
                                     "def f[T](x: T) -> T:\n    return x\nclass C[T]:\n    pass\n"
                                     "node = rclpy.create_node('n')\nnode.create_publisher(String, 'out', 1)\n")
    sink = DiagnosticSink()
    s = extract_python(tmp_path / "new.py", "demo", "n", "new.py", sink)
    assert [(p.kind, p.name) for p in s.ports] == [("publisher", "out")] and s.default_name == "n"
    assert [(d.line, d.code) for d in sink.items] == [(3, "python2")]


def test_python_that_no_repair_can_save_is_a_diagnostic(tmp_path: Path) -> None:
    (tmp_path / "future.py").write_text("import rclpy\n" + "x = (\n" * 30)
    sink = DiagnosticSink()
    s = extract_python(tmp_path / "future.py", "demo", "f", "future.py", sink)
    assert s.ports == [] and s.incomplete and [d.code for d in sink.items] == ["python-syntax"]


def test_compile_commands_flags_are_used(tmp_path: Path) -> None:
    """A define that only the compile database sets decides which topic the node uses."""
    (tmp_path / "src").mkdir()
    source = tmp_path / "src" / "n.cpp"
    source.write_text('#include <ros/ros.h>\n#include <std_msgs/String.h>\nint main(int c, char** v) {\n'
                      '  ros::init(c, v, "n"); ros::NodeHandle nh;\n#ifdef USE_FRONT\n'
                      '  nh.advertise<std_msgs::String>("front", 1);\n#else\n'
                      '  nh.advertise<std_msgs::String>("rear", 1);\n#endif\n}\n')
    (tmp_path / "build").mkdir()
    (tmp_path / "build" / "compile_commands.json").write_text(json.dumps([
        {"directory": str(tmp_path / "build"), "file": str(source),
         "command": f"/usr/bin/c++ -DUSE_FRONT -I/nonexistent -o n.o -c {source}"}]))
    names_of = {source: "src/n.cpp"}
    with_db = extract_cpp([source], "demo", "n", CppEnvironment([], None, [tmp_path]), names_of, DiagnosticSink())
    without = extract_cpp([source], "demo", "n", CppEnvironment([]), names_of, DiagnosticSink())
    assert [p.name for p in with_db.ports] == ["front"] and [p.name for p in without.ports] == ["rear"]


def test_cpp_alternatives_and_loops(tmp_path: Path) -> None:
    source = tmp_path / "alt.cpp"
    source.write_text(
        '#include <ros/ros.h>\n#include <std_msgs/String.h>\n#include <string>\n#include <vector>\n'
        'int main(int argc, char** argv) {\n  ros::init(argc, argv, "alt");\n  ros::NodeHandle nh;\n'
        '  nh.advertise<std_msgs::String>(argc > 1 ? "front/scan" : "rear/scan", 1);\n'
        '  std::string mode;\n  if (argc > 2) { mode = "fast"; } else { mode = "slow"; }\n'
        '  nh.advertise<std_msgs::String>("mode_" + mode, 1);\n'
        '  for (const std::string side : {"left", "right"}) nh.advertise<std_msgs::String>(side + "/image", 1);\n'
        '  const char* cams[] = {"cam0", "cam1"};\n'
        '  for (const char* cam : cams) nh.advertise<std_msgs::String>(std::string(cam) + "/info", 1);\n}\n')
    s = extract_cpp([source], "demo", "alt", CppEnvironment([]), {source: "alt.cpp"}, DiagnosticSink())
    got = [(p.line, p.name.options if hasattr(p.name, "options") else p.name) for p in s.ports]
    assert got == [(8, ("front/scan", "rear/scan")), (11, ("mode_fast", "mode_slow")), (12, "left/image"),
                   (12, "right/image"), (14, "cam0/info"), (14, "cam1/info")]


def test_classes_nested_in_functions_and_classes_are_read(tmp_path: Path) -> None:
    """A node class defined inside a function (or another class) used to raise a KeyError."""
    (tmp_path / "nested.py").write_text(
        "import rospy\nfrom std_msgs.msg import String\n\n\ndef main():\n    class Relay:\n"
        "        def __init__(self):\n            self.pub = rospy.Publisher('out', String, queue_size=1)\n\n"
        "    class Outer:\n        class Inner:\n            def start(self):\n"
        "                rospy.Subscriber('in', String, print)\n\n"
        "    rospy.init_node('relay')\n    Relay()\n    Outer.Inner().start()\n")
    sink = DiagnosticSink()
    s = extract_python(tmp_path / "nested.py", "demo", "nested.py", "nested.py", sink)
    assert sorted((p.kind, p.name) for p in s.ports) == [("publisher", "out"), ("subscriber", "in")]


LIBRARY = r'''#include <ros/ros.h>
#include <std_msgs/String.h>
void cb(const std_msgs::String::ConstPtr& m) {}
struct Listener { Listener(); ros::Subscriber sub; };
Listener::Listener() { ros::NodeHandle nh; sub = nh.subscribe<std_msgs::String>("heard", 1, &cb); }
struct Helper { void run(); void stop(); ros::Publisher pub; };
void Helper::run() { ros::NodeHandle nh; pub = nh.advertise<std_msgs::String>("helped", 1); }
'''


def _linked_ports(tmp_path: Path, main: str, library: str = LIBRARY) -> list[str]:
    (tmp_path / "main.cpp").write_text(main)
    (tmp_path / "lib.cpp").write_text(library)
    files = [tmp_path / "main.cpp", tmp_path / "lib.cpp"]
    s = extract_cpp(files, "demo", "m", CppEnvironment([]), {f: f.name for f in files}, DiagnosticSink(),
                    linked=files[1:])
    return sorted(str(p.name) for p in s.ports)


def test_library_ports_count_where_the_executable_reaches_them(tmp_path: Path) -> None:
    """A linked library's port counts when own code calls its function, through a function
    pointer whose address it takes, or a call clang cannot resolve (a template's, by name)."""
    head = '#include <ros/ros.h>\nstruct Helper { void run(); };\n'
    assert _linked_ports(tmp_path, head + "int main() { Helper h; }\n") == []
    assert _linked_ports(tmp_path, head + "int main() { Helper h; h.run(); }\n") == ["helped"]
    assert _linked_ports(tmp_path, head + "int main() { auto f = &Helper::run; }\n") == ["helped"]
    assert _linked_ports(tmp_path, head + "template <class T> void go(T& t) { t.run(); }\n"
                         "int main() { Helper h; go(h); }\n") == ["helped"]


def test_library_ports_stay_when_reachability_cannot_be_decided(tmp_path: Path) -> None:
    """A reached library function in a file that does not compile may call anything: every
    library port is kept; one that is not reached does not matter."""
    broken = LIBRARY.replace("#include <ros/ros.h>", "#include <ros/ros.h>\n#include <no/such_header.h>") + \
        "void Helper::stop() { undeclared(); }\n"
    head = '#include <ros/ros.h>\nstruct Helper { void run(); void stop(); };\n'
    assert _linked_ports(tmp_path, head + "int main() { Helper h; h.stop(); }\n", broken) == ["heard", "helped"]
    assert _linked_ports(tmp_path, head + "int main() { }\n", broken) == []


def _catkin(root: Path, name: str, cmake: str, files: dict[Path, str]) -> None:
    pkg = root / "src" / name
    (pkg / "launch").mkdir(parents=True)
    (pkg / "package.xml").write_text(f"<package format='2'><name>{name}</name><version>0.1.0</version><description>d"
                                     "</description><maintainer email='dev@example.com'>m</maintainer>"
                                     "<license>MIT</license></package>")
    (pkg / "CMakeLists.txt").write_text(cmake)
    for rel, text in files.items():
        (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
        (pkg / rel).write_text(text)


def test_a_linked_librarys_unreached_ports_are_not_the_nodes(tmp_path: Path) -> None:
    """corpus/cpp_ros1_files/library_code_not_reached built as CMake builds it: the executable's
    own file, a library it links; the library's Listener, never built, subscribes nothing."""
    from archlog.analysis import analyse

    fixture = Path(__file__).parent.parent / "corpus" / "cpp_ros1_files" / "library_code_not_reached"
    _catkin(tmp_path, "kit", "project(kit)\nadd_library(kit lib/broadcaster.cpp lib/listener.cpp lib/stages.cpp)\n"
            "add_executable(sender main.cpp)\ntarget_link_libraries(sender kit ${catkin_LIBRARIES})\n",
            {p.relative_to(fixture): p.read_text() for p in fixture.rglob("*.*")})
    (tmp_path / "src" / "kit" / "launch" / "s.launch").write_text('<launch><node pkg="kit" type="sender" name="s"/></launch>')
    result = analyse([tmp_path], ["kit/launch/s.launch"], {}, [])
    assert sorted(t for _p, _n, t, _ty in result.store.rows("publisher")) == ["/audit", "/chatter", "/report"]
    assert list(result.store.rows("subscriber")) == []


def test_a_port_exists_when_every_branch_around_it_is_taken(tmp_path: Path) -> None:
    """corpus/cpp_ros1/roscpp_nested_conditions.cpp under three configurations of its parameters."""
    from archlog.analysis import analyse

    source = Path(__file__).parent.parent / "corpus" / "cpp_ros1" / "roscpp_nested_conditions.cpp"
    _catkin(tmp_path, "feat", "project(feat)\nadd_executable(feature src/feature.cpp)\n",
            {Path("src/feature.cpp"): source.read_text()})
    got = {}
    for indices, surface in (("false", "false"), ("false", "true"), ("true", "true")):
        (tmp_path / "src" / "feat" / "launch" / "f.launch").write_text(
            f'<launch><node pkg="feat" type="feature" name="f"><param name="use_indices" value="{indices}"/>'
            f'<param name="use_surface" value="{surface}"/></node></launch>')
        result = analyse([tmp_path], ["feat/launch/f.launch"], {}, [])
        got[indices, surface] = sorted(t for _p, _n, t, _ty in result.store.rows("subscriber"))
    assert got == {("false", "false"): ["/f/input"], ("false", "true"): ["/f/surface"],
                   ("true", "true"): ["/f/indices", "/f/surface"]}
