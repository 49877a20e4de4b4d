"""Nodelets: plugin XML and PLUGINLIB_EXPORT_CLASS map pkg/Type to a class; launch `nodelet load`
instances get that class's ports, with the manager's handles and their own remaps; the nodelet
mechanism's own ports (manager services, bonds) are the manager's and the loaders'."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse

MANIFEST = """<package format="2"><name>vision</name><version>0.1.0</version><description>d</description>
<maintainer email="dev@example.com">m</maintainer><license>MIT</license>
<depend>nodelet</depend><export><nodelet plugin="${prefix}/nodelets.xml"/></export></package>"""
PLUGINS = """<library path="lib/libvision_nodelets">
  <class name="vision/Blur" type="vision::Blur" base_class_type="nodelet::Nodelet"><description>b</description></class>
  <class name="vision/Edges" type="vision::Edges" base_class_type="nodelet::Nodelet"><description>e</description></class>
</library>"""
SOURCE = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
namespace vision {
class Blur : public nodelet::Nodelet {
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    pub_ = pnh.advertise<sensor_msgs::Image>("blurred", 1);
    sub_ = nh.subscribe("image", 1, &Blur::cb, this);
  }
  void cb(const sensor_msgs::Image::ConstPtr& msg) {}
  ros::Publisher pub_; ros::Subscriber sub_;
};
class Edges : public nodelet::Nodelet {
  void onInit() override {
    pub_ = getNodeHandle().advertise<sensor_msgs::Image>("edges", 1);
  }
  ros::Publisher pub_;
};
}
PLUGINLIB_EXPORT_CLASS(vision::Blur, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(vision::Edges, nodelet::Nodelet)
"""
LAUNCH = """<launch>
  <node pkg="nodelet" type="nodelet" name="manager" args="manager"/>
  <group ns="cam">
    <node pkg="nodelet" type="nodelet" name="blur" args="load vision/Blur /manager">
      <remap from="image" to="image_raw"/>
    </node>
    <node pkg="nodelet" type="nodelet" name="edges" args="standalone vision/Edges"/>
  </group>
</launch>"""


def test_nodelet_instances_get_their_class_ports(tmp_path: Path) -> None:
    pkg = tmp_path / "src" / "vision"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text(MANIFEST)
    (pkg / "nodelets.xml").write_text(PLUGINS)
    (pkg / "CMakeLists.txt").write_text("project(vision)\nadd_library(vision_nodelets src/nodelets.cpp)\n")
    (pkg / "src" / "nodelets.cpp").write_text(SOURCE)
    (pkg / "cams.launch").write_text(LAUNCH)
    result = analyse([tmp_path], [str(pkg / "cams.launch")], {}, [])
    ports = sorted((rel, n, t, ty) for rel in ("publisher", "subscriber") for _p, n, t, ty in result.store.rows(rel))
    bond = [(rel, node, "/manager/bond", "bond/Status") for rel in ("publisher", "subscriber")
            for node in ("/cam/blur", "/manager")]
    assert ports == sorted([("publisher", "/cam/blur", "/cam/blur/blurred", "sensor_msgs/Image"),
                            ("subscriber", "/cam/blur", "/cam/image_raw", "sensor_msgs/Image"),
                            ("publisher", "/cam/edges", "/cam/edges", "sensor_msgs/Image"), *bond])
    assert sorted(result.store.rows("nodelet")) == [("/cam/blur", "vision/Blur", "/manager"),
                                                   ("/cam/edges", "vision/Edges", "")]
    services = {(rel, n, s, ty) for rel in ("service_server", "service_client") for _p, n, s, ty in result.store.rows(rel)}
    assert services == {("service_server", "/manager", "/manager/load_nodelet", "nodelet/NodeletLoad"),
                        ("service_server", "/manager", "/manager/unload_nodelet", "nodelet/NodeletUnload"),
                        ("service_server", "/manager", "/manager/list", "nodelet/NodeletList"),
                        ("service_client", "/cam/blur", "/manager/load_nodelet", "nodelet/NodeletLoad"),
                        ("service_client", "/cam/blur", "/manager/unload_nodelet", "nodelet/NodeletUnload")}
    assert result.diagnostics.items == []  # the manager runs the nodelet mechanism: not opaque


def test_manager_without_bonded_loaders_has_no_bond(tmp_path: Path) -> None:
    """`--no-bond` loaders and `standalone` processes do not bond: the manager has only its services."""
    (tmp_path / "a.launch").write_text("""<launch>
  <node pkg="nodelet" type="nodelet" name="manager" args="manager"/>
  <node pkg="nodelet" type="nodelet" name="x" args="load some/Thing manager --no-bond"/>
</launch>""")
    result = analyse([tmp_path], [str(tmp_path / "a.launch")], {}, [])
    topics = sorted((n, t) for rel in ("publisher", "subscriber") for _p, n, t, _ty in result.store.rows(rel))
    assert topics == []
    clients = sorted((n, s) for _p, n, s, _ty in result.store.rows("service_client"))
    assert clients == [("/x", "/manager/load_nodelet"), ("/x", "/manager/unload_nodelet")]


def test_plugin_descriptions_with_several_libraries() -> None:
    """corpus/workspace/nodelet_libraries: one description with two top-level <library>
    elements after an XML declaration (not one XML document, as robot_localization's
    nodelet_plugins.xml), one with a <class_libraries> wrapper; every class of every library is read."""
    fixture = Path(__file__).resolve().parent.parent / "corpus" / "workspace" / "nodelet_libraries"
    result = analyse([fixture], [str(fixture / "main.launch")], {}, [])
    ports = sorted((n, t) for rel in ("publisher", "subscriber") for _p, n, t, _ty in result.store.rows(rel)
                   if not t.endswith("/bond"))
    assert ports == [("/a", "/a/out_a"), ("/b", "/b/out_b"), ("/c", "/in_c"), ("/d", "/in_d")]
    assert sorted(result.store.rows("nodelet")) == [("/a", "filters/FilterA", "/manager"),
                                                   ("/b", "filters/FilterB", "/manager"),
                                                   ("/c", "wrapped/C", ""), ("/d", "wrapped/D", "")]
    assert result.diagnostics.items == []


def test_plugin_named_under_another_prefix_than_its_package(tmp_path: Path) -> None:
    """pcl_ros declares its nodelets as pcl/VoxelGrid: `nodelet load pcl/VoxelGrid` runs the class
    of package pcl_ros (here vision_ros declares vision/Blur)."""
    pkg = tmp_path / "src" / "vision_ros"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text(MANIFEST.replace("<name>vision</name>", "<name>vision_ros</name>"))
    (pkg / "nodelets.xml").write_text(PLUGINS)
    (pkg / "CMakeLists.txt").write_text("project(vision_ros)\nadd_library(vision_nodelets src/nodelets.cpp)\n")
    (pkg / "src" / "nodelets.cpp").write_text(SOURCE)
    (pkg / "cams.launch").write_text(LAUNCH)
    result = analyse([tmp_path], [str(pkg / "cams.launch")], {}, [])
    ports = sorted((n, t) for _p, n, t, _ty in result.store.rows("publisher") if not t.endswith("/bond"))
    assert ports == [("/cam/blur", "/cam/blur/blurred"), ("/cam/edges", "/cam/edges")]
    assert result.diagnostics.items == []


LOADER_MAIN = """#include <nodelet/loader.h>
#include <ros/ros.h>
void loadSide(nodelet::Loader& manager, const std::string& side) {
  nodelet::M_string remappings;
  nodelet::V_string my_argv;
  remappings["image"] = ros::names::resolve(side + "/image_raw");
  manager.load(ros::this_node::getName() + "_blur_" + side, "vision/Blur", remappings, my_argv);
  remappings.clear();
  manager.load(ros::this_node::getName() + "_edges_" + side, "vision/Edges", remappings, my_argv);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "pipeline");
  nodelet::Loader manager(false);
  loadSide(manager, "left");
  loadSide(manager, "right");
  ros::spin();
}
"""


def test_executable_loading_nodelets_in_process_has_their_ports(tmp_path: Path) -> None:
    """A node executable that loads nodelets through nodelet::Loader (image_proc's, stereo_image_proc's
    way) has their ports under the names it gives them, with the remappings of each load; a helper
    called once per side loads once per call site. The library exporting them is not its own code."""
    pkg = tmp_path / "src" / "vision"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text(MANIFEST)
    (pkg / "nodelets.xml").write_text(PLUGINS)
    (pkg / "CMakeLists.txt").write_text("project(vision)\nadd_library(vision_nodelets src/nodelets.cpp)\n"
                                        "add_executable(pipeline src/pipeline.cpp)\n"
                                        "target_link_libraries(pipeline vision_nodelets)\n")
    (pkg / "src" / "nodelets.cpp").write_text(SOURCE)
    (pkg / "src" / "pipeline.cpp").write_text(LOADER_MAIN)
    (pkg / "run.launch").write_text('<launch><node pkg="vision" type="pipeline" name="pipe" ns="stereo"/></launch>')
    result = analyse([tmp_path], [str(pkg / "run.launch")], {}, [])
    ports = sorted((rel, n, t) for rel in ("publisher", "subscriber") for _p, n, t, _ty in result.store.rows(rel))
    # two Edges nodelets (one per side, no remapping) publish the same topic
    assert ports == [("publisher", "/stereo/pipe", "/stereo/edges"), ("publisher", "/stereo/pipe", "/stereo/edges"),
                     ("publisher", "/stereo/pipe", "/stereo/pipe_blur_left/blurred"),
                     ("publisher", "/stereo/pipe", "/stereo/pipe_blur_right/blurred"),
                     ("subscriber", "/stereo/pipe", "/stereo/left/image_raw"),
                     ("subscriber", "/stereo/pipe", "/stereo/right/image_raw")]
    assert result.diagnostics.items == []


def test_a_nodelet_that_hands_its_handle_to_an_object_of_its_file() -> None:
    """corpus/workspace/nodelet_helper_object: the nodelet class calls `smoother_->init(ph)` on a
    class of its own file whose header does not compile here (its generated Config is missing); the
    method's calls are read from the tokens, in the namespace of the handle the nodelet passes."""
    fixture = Path(__file__).resolve().parent.parent / "corpus" / "workspace" / "nodelet_helper_object"
    result = analyse([fixture], [str(fixture / "main.launch")], {}, [])
    ports = sorted((rel, t) for rel in ("publisher", "subscriber", "service_server")
                   for _p, n, t, _ty in result.store.rows(rel) if n == "/smoother" and not t.endswith("/bond"))
    assert ports == [("publisher", "/smoother/parameter_descriptions"), ("publisher", "/smoother/parameter_updates"),
                     ("publisher", "/smoother/smooth_cmd_vel"), ("service_server", "/smoother/set_parameters"),
                     ("subscriber", "/smoother/raw_cmd_vel")]
    # a note where pluginlib/class_list_macros.h (deprecated) is not installed: a stand-in is read
    assert [d.code for d in result.diagnostics.items if d.code != "cpp-ros1-stand-in"] == ["cpp-compile"]


ROTATE = """#include <dynamic_reconfigure/server.h>
#include <dynamic_reconfigure/TestConfig.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
namespace vision {
class Rotate : public nodelet::Nodelet {
  dynamic_reconfigure::Server<dynamic_reconfigure_test::TestConfig> srv_;
  ros::Publisher pub_;
  void onInit() override {
    pub_ = getNodeHandle().advertise<sensor_msgs::Image>("rotated", 1);
  }
};
}
PLUGINLIB_EXPORT_CLASS(vision::Rotate, nodelet::Nodelet)
"""


def test_reconfigure_server_without_handle_is_the_process(tmp_path: Path) -> None:
    """image_rotate's nodelet: a dynamic_reconfigure server member built without a handle serves in
    NodeHandle("~") of the process (ros::this_node::getName()), which for a nodelet loaded into a
    manager is the manager's name, not the nodelet's; standalone, the nodelet's own."""
    pkg = tmp_path / "src" / "vision"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text(MANIFEST)
    (pkg / "nodelets.xml").write_text(PLUGINS.replace("vision/Edges", "vision/Rotate").replace("vision::Edges",
                                                                                               "vision::Rotate"))
    (pkg / "CMakeLists.txt").write_text("project(vision)\nadd_library(vision_nodelets src/rotate.cpp)\n")
    (pkg / "src" / "rotate.cpp").write_text(ROTATE)
    (pkg / "run.launch").write_text("""<launch>
  <node pkg="nodelet" type="nodelet" name="manager" args="manager" ns="cam"/>
  <node pkg="nodelet" type="nodelet" name="rotate" args="load vision/Rotate manager" ns="cam"/>
  <node pkg="nodelet" type="nodelet" name="alone" args="standalone vision/Rotate"/>
</launch>""")
    result = analyse([tmp_path], [str(pkg / "run.launch")], {}, [])
    ports = sorted((n, t) for rel in ("publisher", "service_server") for _p, n, t, _ty in result.store.rows(rel)
                   if "manager/" not in t or "set_parameters" in t or "parameter_" in t)
    assert ports == [("/alone", "/alone/parameter_descriptions"), ("/alone", "/alone/parameter_updates"),
                     ("/alone", "/alone/set_parameters"), ("/alone", "/rotated"),
                     ("/cam/rotate", "/cam/manager/parameter_descriptions"),
                     ("/cam/rotate", "/cam/manager/parameter_updates"), ("/cam/rotate", "/cam/manager/set_parameters"),
                     ("/cam/rotate", "/cam/rotated")]
