"""Nodelets: plugin XML and PLUGINLIB_EXPORT_CLASS map pkg/Type to a class; launch `nodelet load`
instances get that class's ports, with the manager's handles and their own remaps."""

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
    ports = sorted((n, t, ty) for rel in ("publisher", "subscriber") for _p, n, t, ty in result.store.rows(rel))
    assert ports == [("/cam/blur", "/cam/blur/blurred", "sensor_msgs/Image"),
                     ("/cam/blur", "/cam/image_raw", "sensor_msgs/Image"),
                     ("/cam/edges", "/cam/edges", "sensor_msgs/Image")]
    assert sorted(result.store.rows("nodelet")) == [("/cam/blur", "vision/Blur", "/manager"),
                                                   ("/cam/edges", "vision/Edges", "")]
    assert [d.code for d in result.diagnostics.items] == []  # the manager too has a model (nodelet.yaml)


def test_plugin_descriptions_with_several_libraries() -> None:
    """corpus/workspace/nodelet_libraries: one description with two top-level <library>
    elements after an XML declaration (not one XML document, as robot_localization's
    nodelet_plugins.xml), one with a <class_libraries> wrapper; every class of every library is read."""
    fixture = Path(__file__).resolve().parent.parent / "corpus" / "workspace" / "nodelet_libraries"
    result = analyse([fixture], [str(fixture / "main.launch")], {}, [])
    ports = sorted((n, t) for rel in ("publisher", "subscriber") for _p, n, t, _ty in result.store.rows(rel))
    assert ports == [("/a", "/a/out_a"), ("/b", "/b/out_b"), ("/c", "/in_c"), ("/d", "/in_d")]
    assert sorted(result.store.rows("nodelet")) == [("/a", "filters/FilterA", "/manager"),
                                                   ("/b", "filters/FilterB", "/manager"),
                                                   ("/c", "wrapped/C", ""), ("/d", "wrapped/D", "")]
    assert [d.code for d in result.diagnostics.items] == []  # the manager too has a model (nodelet.yaml)


def test_a_nodelet_that_hands_its_handle_to_an_object_of_its_file() -> None:
    """corpus/workspace/nodelet_helper_object: the nodelet class calls `smoother_->init(ph)` on a
    class of its own file whose header does not compile here (its generated Config is missing); the
    method's calls are read from the tokens, in the namespace of the handle the nodelet passes."""
    fixture = Path(__file__).resolve().parent.parent / "corpus" / "workspace" / "nodelet_helper_object"
    result = analyse([fixture], [str(fixture / "main.launch")], {}, [])
    ports = sorted((rel, t) for rel in ("publisher", "subscriber", "service_server")
                   for _p, n, t, _ty in result.store.rows(rel) if n == "/smoother")
    assert ports == [("publisher", "/smoother/parameter_descriptions"), ("publisher", "/smoother/parameter_updates"),
                     ("publisher", "/smoother/smooth_cmd_vel"), ("service_server", "/smoother/set_parameters"),
                     ("subscriber", "/smoother/raw_cmd_vel")]
    assert [d.code for d in result.diagnostics.items] == ["cpp-compile"]
