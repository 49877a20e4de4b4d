"""Oracle 1 (issue 17): every ROS 1 node Debian ships, launched and observed.

For each node executable and nodelet of the Debian 12 ROS 1 packages listed in CASES: write a small
launch file (bench/debian_nodes/CASE.launch), start it on a private loopback master with the inputs
it needs (bench/debian_nodes/feeder.py publishes them, and subscribes to every output so that lazy
publishers wire up their inputs; a relay's input comes from a `rostopic pub` node of the launch file
instead, observed and scored with the case, since a relay's output has its input's type), read the
live graph with `archlog observe`, and compare it with what archlog recovers from the Debian source
package (`archlog diff SRC --launch CASE.launch --observed OBSERVED --format json`).

Scoring (the study metric): ports are publishers (node, topic, type), subscribers (node, topic) and
services (node, service), as `archlog diff` compares them; per case, missed = observed ports not
recovered, extra = recovered ports not observed, both divided by the number of observed ports.

Nodelets: the master sees a nodelet's ports under its manager's node name. A recovered port of a
nodelet instance N loaded into manager M (archlog names it after N) that the master does not show
under N is credited to M. The nodelet mechanism's own ports (topic M/bond, services
M/{load_nodelet,unload_nodelet,list}, and everything of the `nodelet load` loader processes) are
scored separately, credited to ros-nodelet-core ("nodelet infrastructure").

    python bench/debian_nodes.py [--debsrc /work/debsrc] [--only CASE,...] [--package SRC,...]
                                 [--output bench/results/debian_nodes.json] [--observed-dir DIR]
    python bench/debian_nodes.py --compare BEFORE.json    # the tables of --output, beside an earlier run

Needs Debian 12's ROS 1 binary packages (see INSTALL) and the source packages extracted in --debsrc
(`apt-get source` with a deb-src entry; see the results JSON for the folders used).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT / "tests"))

from support.live_graph import SYSTEM_PYTHON, live_system  # noqa: E402

from archlog import observe  # noqa: E402

FIXTURES = HERE / "debian_nodes"
FEEDER = FIXTURES / "feeder.py"
ARCHLOG = [sys.executable, "-m", "archlog"]
INSTALL = ("libtopic-tools-dev libself-test-dev libpolled-camera-dev libpcl-ros-dev ros-image-proc ros-image-publisher "
           "ros-image-rotate ros-image-view ros-stereo-image-proc "
           "libimage-proc-dev libdepth-image-proc-dev libstereo-image-proc-dev libimage-rotate-dev "
           "libimage-publisher-dev libimage-view-dev image-transport-tools polled-camera-tool tf-tools "
           "tf2-tools libdiagnostic-aggregator-tools python3-diagnostic-common-diagnostics libself-test-tools "
           "libnodeletlib-tools ros-robot-state-publisher joint-state-publisher topic-tools python3-topic-tools "
           "python3-rosbag pcl-ros-tools python3-psutil python3-diagnostic-updater python3-opencv ntpdate "
           "python3-cv-bridge python3-image-geometry python3-stereo-msgs")
# Debian source package -> folder prefix in --debsrc (apt-get source's `NAME-VERSION`).
SOURCES = {
    "ros-ros-comm": "ros-ros-comm-1.15.15+ds",
    "ros-geometry": "ros-geometry-1.13.2",
    "ros-geometry2": "ros-geometry2-0.7.6",
    "ros-diagnostics": "ros-diagnostics-1.11.0",
    "ros-image-common": "ros-image-common-1.12.0",
    "ros-image-pipeline": "ros-image-pipeline-1.17.0",
    "ros-nodelet-core": "ros-nodelet-core-1.10.2",
    "ros-robot-state-publisher": "ros-robot-state-publisher-1.15.2",
    "ros-joint-state-publisher": "ros-joint-state-publisher-1.15.1",
    "ros-perception-pcl": "ros-perception-pcl-1.7.5",
}
NODELET_INFRA = "ros-nodelet-core"

URDF = '  <param name="robot_description" textfile="$(dirname)/robot.urdf"/>\n'  # bench/debian_nodes/robot.urdf


def cam(ns: str, image: str = "image_raw", encoding: str = "mono8", info: str = "camera_info", **kw) -> list[dict]:
    """An image and its camera_info under namespace `ns`."""
    pre = ns.rstrip("/") + "/"
    return [dict(topic=pre + image, kind="image", encoding=encoding, **kw),
            dict(topic=pre + info, kind="camera_info", **kw)]


@dataclass
class Case:
    name: str
    package: str  # Debian source package
    body: str  # launch file content inside <launch>
    publish: list[dict] = field(default_factory=list)
    listen: list[str] = field(default_factory=list)
    extra_sources: list[str] = field(default_factory=list)  # more source packages for the recovery
    settle: float = 3.0

    @property
    def launch_text(self) -> str:
        return "<launch>\n" + self.body.strip("\n") + "\n</launch>\n"


def node(pkg: str, exe: str, name: str, args: str = "", inner: str = "", respawn: bool = False) -> str:
    """respawn: for nodes that exit when their input topic is not published yet at start-up."""
    a = (f' args="{args}"' if args else "") + (' respawn="true" respawn_delay="2"' if respawn else "")
    return f'  <node pkg="{pkg}" type="{exe}" name="{name}"{a}>{inner}</node>' if inner else \
        f'  <node pkg="{pkg}" type="{exe}" name="{name}"{a}/>'


def pub(topic: str) -> str:
    """A `rostopic pub` node feeding `topic` std_msgs/String twice a second (named: rostopic's own
    names are anonymous)."""
    return node("rostopic", "rostopic", topic.strip("/") + "_pub", f"pub -r 2 {topic} std_msgs/String 'data: hi'")


def p(name: str, value: str) -> str:
    return f'<param name="{name}" value="{value}"/>'


def nodelet(plugin: str, name: str, inner: str = "", manager: str = "manager") -> str:
    return (node("nodelet", "nodelet", manager, "manager") + "\n"
            + node("nodelet", "nodelet", name, f"load {plugin} {manager}", inner))


def _cases() -> list[Case]:
    C = Case
    tf_pairs = dict(topic="/tf_static", kind="tf_static", pairs=[["base", "camera"], ["base", "laser"],
                                                                   ["camera", "depth"]])
    cloud = [dict(topic="/input", kind="cloud", frame="camera")]
    pcl = "ros-perception-pcl"
    ip = "ros-image-pipeline"
    cases = [
        # ros-ros-comm: topic_tools and rosbag; relays' inputs fed by `rostopic pub` (scored too)
        C("relay", "ros-ros-comm", pub("/chatter") + "\n" + node("topic_tools", "relay", "relay", "chatter chatter_out")),
        C("throttle", "ros-ros-comm",
          pub("/chatter") + "\n" + node("topic_tools", "throttle", "throttle", "messages chatter 1.0")),
        C("drop", "ros-ros-comm",
          pub("/chatter") + "\n" + node("topic_tools", "drop", "drop", "chatter 1 2 chatter_drop")),
        C("mux", "ros-ros-comm", pub("/a") + "\n" + pub("/b") + "\n" + node("topic_tools", "mux", "mux", "sel_out a b")),
        C("demux", "ros-ros-comm", pub("/chatter") + "\n" + node("topic_tools", "demux", "demux", "chatter x y")),
        C("transform", "ros-ros-comm",
          node("topic_tools", "transform", "transform", "/chatter /chatter_len std_msgs/UInt32 'len(m.data)'", respawn=True),
          [dict(topic="/chatter", kind="string")]),
        C("relay_field", "ros-ros-comm",
          node("topic_tools", "relay_field", "relay_field",
               "/chatter /chatter_copy std_msgs/String '{data: m.data}'", respawn=True),
          [dict(topic="/chatter", kind="string")]),
        C("rosbag_record", "ros-ros-comm",
          node("rosbag", "record", "record", "-O /tmp/archlog_debian_nodes_record.bag /chatter"),
          [dict(topic="/chatter", kind="string")]),
        C("rosbag_record_publish", "ros-ros-comm",
          node("rosbag", "record", "record", "-p -O /tmp/archlog_debian_nodes_record_p.bag /chatter"),
          [dict(topic="/chatter", kind="string")]),
        C("rostopic_echo", "ros-ros-comm", node("rostopic", "rostopic", "echo", "echo -n 1000 /chatter"),
          [dict(topic="/chatter", kind="string")]),
        # ros-geometry: tf
        C("tf_static_transform_publisher", "ros-geometry",
          node("tf", "static_transform_publisher", "static_tf", "0 0 1 0 0 0 base camera 100")),
        C("tf_echo", "ros-geometry", node("tf", "tf_echo", "tf_echo", "base camera"), [tf_pairs]),
        C("tf_monitor", "ros-geometry", node("tf", "tf_monitor", "tf_monitor"), [tf_pairs]),
        C("tf_change_notifier", "ros-geometry", node("tf", "tf_change_notifier", "tf_change_notifier"), [tf_pairs]),
        C("tf_remap", "ros-geometry",
          node("tf", "tf_remap", "tf_remap", inner='<rosparam param="mappings">[{old: camera, new: cam}]</rosparam>'),
          [dict(topic="/tf_old", kind="generic", type="tf2_msgs/TFMessage")]),
        C("tf_empty_listener", "ros-geometry", node("tf", "tf_empty_listener", "tf_empty_listener"), [tf_pairs]),
        # ros-geometry2: tf2
        C("tf2_static_transform_publisher", "ros-geometry2",
          node("tf2_ros", "static_transform_publisher", "static_tf2", "0 0 1 0 0 0 base camera")),
        C("tf2_buffer_server", "ros-geometry2", node("tf2_ros", "buffer_server", "tf2_buffer_server"), [tf_pairs]),
        C("tf2_echo_py", "ros-geometry2", node("tf2_tools", "echo.py", "tf2_echo", "base camera"), [tf_pairs]),
        # ros-diagnostics
        C("diagnostic_aggregator", "ros-diagnostics",
          node("diagnostic_aggregator", "aggregator_node", "diagnostic_aggregator",
               inner='<rosparam param="analyzers">{sensors: {type: "diagnostic_aggregator/GenericAnalyzer", '
                     'path: Sensors, startswith: ["cam"]}}</rosparam>'),
          [dict(topic="/diagnostics", kind="diagnostics", names=["cam: driver", "other"])]),
        C("cpu_monitor", "ros-diagnostics", node("diagnostic_common_diagnostics", "cpu_monitor.py", "cpu_monitor")),
        C("ram_monitor", "ros-diagnostics", node("diagnostic_common_diagnostics", "ram_monitor.py", "ram_monitor")),
        C("hd_monitor", "ros-diagnostics", node("diagnostic_common_diagnostics", "hd_monitor.py", "hd_monitor",
                                                "/tmp")),
        C("ntp_monitor", "ros-diagnostics", node("diagnostic_common_diagnostics", "ntp_monitor.py", "ntp_monitor",
                                                 "--offset-tolerance 500 127.0.0.1")),
        C("diag_tf_monitor", "ros-diagnostics",
          node("diagnostic_common_diagnostics", "tf_monitor.py", "diag_tf_monitor"), [tf_pairs]),
        # ros-image-common
        C("republish", "ros-image-common",
          node("image_transport", "republish", "republish", "raw in:=/camera/image_raw raw out:=/camera/image_copy"),
          cam("/camera")),
        # ros-image-pipeline: node executables
        C("image_proc", ip, node("image_proc", "image_proc", "image_proc", inner="") .replace(
            'name="image_proc"/>', 'name="image_proc" ns="camera"/>'), cam("/camera", encoding="bayer_rggb8")),
        C("stereo_image_proc", ip, node("stereo_image_proc", "stereo_image_proc", "stereo_image_proc").replace(
            '/>', ' ns="stereo"/>'), cam("/stereo/left", encoding="mono8", frame="camera")
          + cam("/stereo/right", encoding="mono8", frame="camera", right=True)),
        C("image_rotate", ip, node("image_rotate", "image_rotate", "image_rotate",
                                   inner='<remap from="image" to="/camera/image_raw"/>'),
          cam("/camera") + [tf_pairs]),
        C("image_publisher", ip, node("image_publisher", "image_publisher", "image_publisher",
                                      "/usr/share/pixmaps/debian-logo.png")),
        C("extract_images", ip, node("image_view", "extract_images", "extract_images",
                                     inner=p("filename_format", "/tmp/archlog_frame%04i.jpg")
                                     + '<remap from="image" to="/camera/image_raw"/>'), cam("/camera")),
        C("image_saver", ip, node("image_view", "image_saver", "image_saver",
                                  inner=p("filename_format", "/tmp/archlog_saved%04i.jpg") + p("save_all_image", "false")
                                  + '<remap from="image" to="/camera/image_raw"/>'), cam("/camera")),
        C("video_recorder", ip, node("image_view", "video_recorder", "video_recorder",
                                     inner=p("filename", "/tmp/archlog_video.avi")
                                     + '<remap from="image" to="/camera/image_raw"/>'), cam("/camera")),
        C("extract_images_sync", ip, node("image_view", "extract_images_sync", "extract_images_sync",
                                          inner='<rosparam param="inputs">[/left/image_raw, /right/image_raw]</rosparam>'
                                          + p("filename_format", "/tmp/archlog_sync%s_%04i.jpg")),
          [dict(topic="/left/image_raw", kind="image"), dict(topic="/right/image_raw", kind="image")]),
        C("cameracheck", ip, node("camera_calibration", "cameracheck.py", "cameracheck", "--size 8x6 --square 0.1"),
          cam("/monocular", image="image")),
        # ros-image-pipeline: nodelets
        C("nodelet_debayer", ip, nodelet("image_proc/debayer", "debayer"), cam("", encoding="bayer_rggb8")[:1]),
        C("nodelet_rectify", ip, nodelet("image_proc/rectify", "rectify"), cam("", image="image_mono")),
        C("nodelet_resize", ip, nodelet("image_proc/resize", "resize"), cam("", image="image")),
        C("nodelet_crop_decimate", ip, nodelet("image_proc/crop_decimate", "crop_decimate"),
          cam("/camera", image="image_raw")),
        C("nodelet_crop_non_zero", ip, nodelet("image_proc/crop_non_zero", "crop_non_zero"),
          [dict(topic="/image_raw", kind="image", encoding="32FC1")]),
        C("nodelet_convert_metric", ip, nodelet("depth_image_proc/convert_metric", "convert_metric"),
          [dict(topic="/image_raw", kind="image", encoding="16UC1")]),
        C("nodelet_disparity_depth", ip, nodelet("depth_image_proc/disparity", "depth_disparity"),
          [dict(topic="/left/image_rect", kind="image", encoding="32FC1"), dict(topic="/right/camera_info",
                                                                               kind="camera_info", right=True)]),
        C("nodelet_point_cloud_xyz", ip, nodelet("depth_image_proc/point_cloud_xyz", "point_cloud_xyz"),
          cam("", image="image_rect", encoding="32FC1")),
        C("nodelet_point_cloud_xyzrgb", ip, nodelet("depth_image_proc/point_cloud_xyzrgb", "point_cloud_xyzrgb"),
          cam("/rgb", image="image_rect_color", encoding="rgb8") + cam("/depth_registered", image="image_rect",
                                                                        encoding="32FC1")),
        C("nodelet_point_cloud_xyzi", ip, nodelet("depth_image_proc/point_cloud_xyzi", "point_cloud_xyzi"),
          cam("/intensity", image="image_rect") + cam("/depth", image="image_rect", encoding="32FC1")),
        C("nodelet_point_cloud_xyz_radial", ip,
          nodelet("depth_image_proc/point_cloud_xyz_radial", "point_cloud_xyz_radial"),
          cam("", image="image_raw", encoding="32FC1")),
        C("nodelet_register", ip, nodelet("depth_image_proc/register", "register"),
          cam("/depth", image="image_rect", encoding="32FC1", frame="depth") + cam("/rgb", frame="camera")[1:]
          + [tf_pairs]),
        C("nodelet_crop_foremost", ip, nodelet("depth_image_proc/crop_foremost", "crop_foremost"),
          [dict(topic="/image_rect", kind="image", encoding="32FC1")]),
        C("nodelet_stereo_disparity", ip, nodelet("stereo_image_proc/disparity", "disparity"),
          cam("/left", image="image_rect") + cam("/right", image="image_rect", right=True)),
        C("nodelet_stereo_point_cloud2", ip, nodelet("stereo_image_proc/point_cloud2", "point_cloud2"),
          cam("/left", image="image_rect_color", encoding="rgb8") + cam("/right", image="image_rect", right=True)[1:]
          + [dict(topic="/disparity", kind="disparity")]),
        C("nodelet_image_rotate", ip, nodelet("image_rotate/image_rotate", "image_rotate_nodelet"),
          cam("", image="image") + [tf_pairs]),
        C("nodelet_image_publisher", ip, nodelet("image_publisher/image_publisher", "image_publisher_nodelet",
                                                 inner=p("filename", "/usr/share/pixmaps/debian-logo.png"))),
        # robot_state_publisher, joint_state_publisher
        C("robot_state_publisher", "ros-robot-state-publisher",
          URDF + node("robot_state_publisher", "robot_state_publisher", "robot_state_publisher"),
          [dict(topic="/joint_states", kind="joint_states", names=["j1"])]),
        C("joint_state_publisher", "ros-joint-state-publisher",
          URDF + node("joint_state_publisher", "joint_state_publisher", "joint_state_publisher")),
        # ros-nodelet-core: a manager alone
        C("nodelet_manager", "ros-nodelet-core", node("nodelet", "nodelet", "manager", "manager")),
        # ros-perception-pcl: tools and nodelets
        C("pointcloud_to_pcd", pcl, node("pcl_ros", "pointcloud_to_pcd", "pointcloud_to_pcd",
                                         inner=p("prefix", "/tmp/archlog_pcd_")), cloud),
        C("convert_pointcloud_to_image", pcl,
          node("pcl_ros", "convert_pointcloud_to_image", "convert_pointcloud_to_image",
               inner='<remap from="input" to="/organized"/>'),
          [dict(topic="/organized", kind="cloud", frame="camera")]),
        C("pcl_passthrough", pcl, nodelet("pcl/PassThrough", "passthrough",
                                          inner=p("filter_field_name", "z") + p("filter_limit_min", "0.0")
                                          + p("filter_limit_max", "5.0")), cloud),
        C("pcl_voxel_grid", pcl, nodelet("pcl/VoxelGrid", "voxel_grid", inner=p("leaf_size", "0.1")), cloud),
        C("pcl_statistical_outlier_removal", pcl,
          nodelet("pcl/StatisticalOutlierRemoval", "statistical_outlier_removal", inner=p("mean_k", "5")), cloud),
        C("pcl_radius_outlier_removal", pcl,
          nodelet("pcl/RadiusOutlierRemoval", "radius_outlier_removal", inner=p("radius_search", "0.1")), cloud),
        C("pcl_crop_box", pcl, nodelet("pcl/CropBox", "crop_box"), cloud),
        # features, clustering and surface nodelets stop in onInit without ~spatial_locator (0: FLANN)
        C("pcl_normal_estimation", pcl, nodelet("pcl/NormalEstimation", "normal_estimation",
                                                inner=p("k_search", "5") + p("spatial_locator", "0")), cloud),
        C("pcl_sac_segmentation", pcl, nodelet("pcl/SACSegmentation", "sac_segmentation",
                                               inner=p("model_type", "0") + p("distance_threshold", "0.05")), cloud),
        C("pcl_euclidean_cluster_extraction", pcl,
          nodelet("pcl/EuclideanClusterExtraction", "euclidean_cluster_extraction",
                  inner=p("cluster_tolerance", "0.1") + p("spatial_locator", "0")), cloud),
        C("pcl_pcd_writer", pcl, nodelet("pcl/PCDWriter", "pcd_writer", inner=p("filename", "/tmp/archlog_w.pcd")),
          cloud),
        C("pcl_moving_least_squares", pcl, nodelet("pcl/MovingLeastSquares", "moving_least_squares",
                                                   inner=p("search_radius", "0.1") + p("spatial_locator", "0")), cloud),
    ]
    for c in cases:  # pcl_ros nodelets read ~input
        if c.name.startswith("pcl_"):
            c.publish = [dict(topic=f"/{c.name[4:]}/input", kind="cloud", frame="camera")]
    return cases


CASES = _cases()


# -- running -----------------------------------------------------------------


def launch_nodes(text: str) -> tuple[list[str], dict[str, str]]:
    """Node names of our own (flat) launch files, and nodelet loader instance -> manager."""
    names, loaded = [], {}
    for el in ET.fromstring(text).iter("node"):
        ns = el.get("ns", "").strip("/")
        name = "/" + "/".join(x for x in (ns, el.get("name")) if x)
        names.append(name)
        args = el.get("args", "").split()
        if el.get("pkg") == "nodelet" and args[:1] == ["load"] and len(args) >= 3:
            loaded[name] = args[2] if args[2].startswith("/") else "/" + args[2]
    return names, loaded


def run_archlog(cmd: list[str], timeout: float) -> subprocess.CompletedProcess:
    return subprocess.run(ARCHLOG + cmd, capture_output=True, text=True, timeout=timeout, cwd=ROOT)


def pcl_overlay(folder: Path) -> None:
    """Debian's pcl_ros (1.7.5-1) installs nodelet plugin XML with `lib/libpcl_ros_*` library paths, which
    its pluginlib does not resolve (image_pipeline's Debian patch 0010 fixes the same for its XML), so
    `nodelet load pcl/...` dies with exit code 255. An overlay package on ROS_PACKAGE_PATH with the
    paths fixed makes them loadable; nothing else changes."""
    share = Path("/usr/share/pcl_ros")
    if not (share / "package.xml").is_file() or (folder / "pcl_ros").is_dir():
        return
    (folder / "pcl_ros" / "plugins" / "nodelet").mkdir(parents=True)
    (folder / "pcl_ros" / "package.xml").write_text((share / "package.xml").read_text())
    for xml in (share / "plugins" / "nodelet").glob("*.xml"):
        (folder / "pcl_ros" / "plugins" / "nodelet" / xml.name).write_text(
            xml.read_text().replace('path="lib/lib', 'path="lib'))


def observe_case(case: Case, launch: Path, work: Path, window: float = 12.0) -> dict:
    """Run the case on a private master; the observed architecture of its nodes (feeder left out)."""
    empty = work / "empty_ws"
    empty.mkdir(exist_ok=True)
    pcl_overlay(empty)
    names, _ = launch_nodes(case.launch_text)
    spec = {"targets": names, "publish": case.publish, "listen": case.listen}
    with live_system(empty, [launch], settle=1.5, timeout=30.0) as system:
        system.spawn([str(SYSTEM_PYTHON), str(FEEDER), json.dumps(spec)], "feeder")
        start, last, seen = time.monotonic(), None, time.monotonic()
        while time.monotonic() - start < window:
            time.sleep(1.0)
            graph = observe.read_master(observe.master(system.uri))
            if graph != last:
                last, seen = graph, time.monotonic()
            elif time.monotonic() - seen >= case.settle and time.monotonic() - start >= 4.0:
                break
        out = run_archlog(["observe", "--master", system.uri], 30)
        if out.returncode != 0:
            raise RuntimeError(f"archlog observe failed: {out.stderr[-2000:]}")
        feeder_log = system.log("feeder")
        launch_log = (system.logs / "roslaunch.log").read_text(errors="replace")[-3000:]
    data = json.loads(out.stdout)
    drop = {"/archlog_feeder"}
    data["nodes"] = [n for n in data["nodes"] if n not in drop]
    for kind in ("publishers", "subscribers", "services"):
        data[kind] = [r for r in data[kind] if r[0] not in drop]
    data["_logs"] = {"feeder": feeder_log[-1500:], "roslaunch": launch_log}
    return data


def port_sets(arch: dict) -> dict[str, set[tuple]]:
    return {"publishers": {tuple(r) for r in arch["publishers"]},
            "subscribers": {tuple(r[:2]) for r in arch["subscribers"]},
            "services": {tuple(r) for r in arch["services"]}}


def is_infra(kind: str, row: tuple, managers: set[str], loaders: set[str]) -> bool:
    """The nodelet mechanism's own ports: bonds, the manager's services, the loader processes."""
    if row[0] in loaders:
        return True
    if row[0] not in managers:
        return False
    if kind == "services":
        return row[1] in {f"{row[0]}/{s}" for s in ("load_nodelet", "unload_nodelet", "list")}
    return row[1] == f"{row[0]}/bond"


def score(case: Case, observed: dict, diff: dict) -> dict:
    names, loaded = launch_nodes(case.launch_text)
    managers, loaders = set(loaded.values()), set(loaded)
    obs = port_sets(observed)
    result: dict = {"own": {"observed": 0, "missed": [], "extra": []},
                    "infra": {"observed": 0, "missed": [], "extra": []}}
    for kind in ("publishers", "subscribers", "services"):
        o = obs[kind]
        only_obs = {tuple(x) for x in diff[kind]["only_observed"]}
        only_rec = {tuple(x) for x in diff[kind]["only_recovered"]}
        rec = (o - only_obs) | {(loaded.get(r[0], r[0]), *r[1:]) if r[0] in loaded else r for r in only_rec}
        if managers and case.package != NODELET_INFRA:
            split = lambda rows, kind=kind: ([r for r in rows if is_infra(kind, r, managers, loaders)],  # noqa: E731
                                             [r for r in rows if not is_infra(kind, r, managers, loaders)])
        else:
            split = lambda rows: ([], list(rows))  # noqa: E731
        o_infra, o_own = split(o)
        r_infra, r_own = split(rec)
        for part, o_rows, r_rows in (("infra", set(o_infra), set(r_infra)), ("own", set(o_own), set(r_own))):
            result[part]["observed"] += len(o_rows)
            result[part]["missed"] += [[kind, *r] for r in sorted(o_rows - r_rows)]
            result[part]["extra"] += [[kind, *r] for r in sorted(r_rows - o_rows)]
    for part in result.values():
        n = part["observed"]
        part["under"] = round(100 * len(part["missed"]) / n, 1) if n else (0.0 if not part["missed"] else None)
        part["over"] = round(100 * len(part["extra"]) / n, 1) if n else (0.0 if not part["extra"] else None)
    result["nodes_observed"] = sorted(observed["nodes"])
    result["nodes_expected"] = names
    return result


def run_case(case: Case, debsrc: Path, work: Path, observed_dir: Path | None = None) -> dict:
    """Observe the case (or, with `observed_dir`, reuse the observation saved there by an earlier
    run for the same launch file) and score archlog's recovery against it."""
    launch = FIXTURES / f"{case.name}.launch"
    if not launch.is_file() or launch.read_text() != case.launch_text:
        launch.write_text(case.launch_text)
    started = time.monotonic()
    saved = observed_dir / f"{case.name}.observed.json" if observed_dir else None
    if saved is not None and saved.is_file() and json.loads(saved.read_text()).get("_launch") == case.launch_text:
        observed = json.loads(saved.read_text())
    else:
        observed = observe_case(case, launch, work)
        if saved is not None:
            saved.parent.mkdir(parents=True, exist_ok=True)
            saved.write_text(json.dumps({**observed, "_launch": case.launch_text}, indent=1))
    obs_file = work / f"{case.name}.observed.json"
    obs_file.write_text(json.dumps({k: v for k, v in observed.items() if not k.startswith("_")}, indent=1))
    sources = [case.package] + case.extra_sources
    if "nodelet" in case.launch_text and NODELET_INFRA not in sources:
        sources.append(NODELET_INFRA)
    paths = [str(debsrc / SOURCES[s]) for s in sources]
    out = run_archlog(["diff", *paths, "--launch", str(launch), "--observed", str(obs_file), "--format", "json"], 600)
    if out.returncode not in (0, 1):
        raise RuntimeError(f"archlog diff failed ({out.returncode}): {out.stderr[-2000:]}")
    diff = json.loads(out.stdout)
    result = score(case, observed, diff)
    result.update(case=case.name, package=case.package, sources=[SOURCES[s] for s in sources],
                  seconds=round(time.monotonic() - started, 1), alive=bool(set(observed["nodes"])))
    if not observed["nodes"] or set(result["nodes_expected"]) - set(observed["nodes"]):
        result["logs"] = observed.get("_logs")
    return result


# -- report ------------------------------------------------------------------


def pct(a: int, b: int) -> str:
    return f"{100 * a / b:.1f}" if b else "-"


def tables(results: list[dict]) -> str:
    """A markdown table per source package (one row per case; the nodelet infrastructure of all
    nodelet cases is one row under ros-nodelet-core), then a summary per package and the totals with
    and without that infrastructure."""
    rows: dict[str, list[tuple[str, int, int, int, bool]]] = {}
    infra = [0, 0, 0, 0]
    for r in results:
        own = r["own"]
        rows.setdefault(r["package"], []).append((r["case"], own["observed"], len(own["missed"]), len(own["extra"]), True))
        if r["infra"]["observed"] or r["infra"]["extra"]:
            infra = [infra[0] + 1, infra[1] + r["infra"]["observed"], infra[2] + len(r["infra"]["missed"]),
                     infra[3] + len(r["infra"]["extra"])]
    if infra[0]:
        rows.setdefault(NODELET_INFRA, []).append(
            (f"nodelet infrastructure of {infra[0]} nodelet cases (bond, manager services, loaders)", *infra[1:], False))
    lines = []
    summary = ["| source package | nodes | observed ports | missed | missed % | extra | extra % |",
               "|---|---:|---:|---:|---:|---:|---:|"]
    total, total_infra = [0, 0, 0, 0], [0, 0, 0]
    for pkg in sorted(rows):
        lines += [f"### {pkg}", "", "| node | observed ports | missed | missed % | extra | extra % |",
                  "|---|---:|---:|---:|---:|---:|"]
        n = o = m = e = 0
        for label, so, sm, se, is_node in rows[pkg]:
            lines.append(f"| {label} | {so} | {sm} | {pct(sm, so)} | {se} | {pct(se, so)} |")
            n, o, m, e = n + is_node, o + so, m + sm, e + se
            if not is_node:
                total_infra = [total_infra[0] + so, total_infra[1] + sm, total_infra[2] + se]
        lines.append("")
        summary.append(f"| {pkg} | {n} | {o} | {m} | {pct(m, o)} | {e} | {pct(e, o)} |")
        total = [total[0] + n, total[1] + o, total[2] + m, total[3] + e]
    n, o, m, e = total
    summary.append(f"| **total** | {n} | {o} | {m} | {pct(m, o)} | {e} | {pct(e, o)} |")
    o, m, e = o - total_infra[0], m - total_infra[1], e - total_infra[2]
    summary.append(f"| **total without nodelet infrastructure** | {n} | {o} | {m} | {pct(m, o)} | {e} | {pct(e, o)} |")
    return "\n".join(lines + ["### Summary", ""] + summary) + "\n"


def package_totals(results: list[dict], own_only: bool = True) -> dict[str, tuple[int, int, int]]:
    """(observed, missed, extra) ports per source package, the nodelet infrastructure left out."""
    totals: dict[str, tuple[int, int, int]] = {}
    for r in results:
        if "error" in r:
            continue
        o, m, e = totals.get(r["package"], (0, 0, 0))
        own = r["own"]
        totals[r["package"]] = (o + own["observed"], m + len(own["missed"]), e + len(own["extra"]))
    return totals


def comparison(before: list[dict], after: list[dict]) -> str:
    """A markdown table of missed and extra ports per source package, before and after."""
    old, new = package_totals(before), package_totals(after)
    lines = ["| source package | observed before | missed before | extra before | observed after | missed after "
             "| extra after |", "|---|---:|---:|---:|---:|---:|---:|"]
    sums = [0] * 6
    for pkg in sorted(old.keys() | new.keys()):
        row = [*old.get(pkg, (0, 0, 0)), *new.get(pkg, (0, 0, 0))]
        sums = [a + b for a, b in zip(sums, row)]
        o, m, e, o2, m2, e2 = row
        lines.append(f"| {pkg} | {o} | {m} ({pct(m, o)}%) | {e} ({pct(e, o)}%) | {o2} | {m2} ({pct(m2, o2)}%) "
                     f"| {e2} ({pct(e2, o2)}%) |")
    o, m, e, o2, m2, e2 = sums
    lines.append(f"| **total without nodelet infrastructure** | {o} | {m} ({pct(m, o)}%) | {e} ({pct(e, o)}%) | {o2} "
                 f"| {m2} ({pct(m2, o2)}%) | {e2} ({pct(e2, o2)}%) |")
    return "\n".join(lines) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--debsrc", type=Path, default=Path(os.environ.get("ARCHLOG_DEBSRC", "/work/debsrc")))
    ap.add_argument("--only", default="")
    ap.add_argument("--package", default="")
    ap.add_argument("--output", type=Path, default=HERE / "results" / "debian_nodes.json")
    ap.add_argument("--write-launch", action="store_true", help="only write the launch files")
    ap.add_argument("--observed-dir", type=Path, help="keep each observation there, and reuse a kept one "
                    "(same launch file) instead of launching again: recovery changes are scored in seconds")
    ap.add_argument("--compare", type=Path, metavar="BEFORE_JSON", help="print the tables of --output (no run) "
                    "and, per source package, its missed and extra ports beside those of an earlier results file")
    opts = ap.parse_args()
    if opts.compare:
        after = json.loads(opts.output.read_text())["cases"]
        print(tables([r for r in after if "error" not in r]) + "\n### Before and after\n\n"
              + comparison(json.loads(opts.compare.read_text())["cases"], after))
        return 0
    chosen = [c for c in CASES if (not opts.only or c.name in opts.only.split(","))
              and (not opts.package or c.package in opts.package.split(","))]
    FIXTURES.mkdir(exist_ok=True)
    for c in CASES:
        (FIXTURES / f"{c.name}.launch").write_text(c.launch_text)
    if opts.write_launch:
        return 0
    results = []
    with tempfile.TemporaryDirectory(prefix="archlog-debian-nodes-") as tmp:
        for c in chosen:
            try:
                r = run_case(c, opts.debsrc, Path(tmp), opts.observed_dir)
            except Exception as exc:
                r = {"case": c.name, "package": c.package, "error": str(exc)[-3000:]}
                print(f"{c.name}: ERROR {str(exc)[-500:]}", file=sys.stderr)
            else:
                print(f"{c.name}: observed {r['own']['observed']} missed {len(r['own']['missed'])} "
                      f"extra {len(r['own']['extra'])} ({r['seconds']} s)", file=sys.stderr)
            results.append(r)
    ok = [r for r in results if "error" not in r]
    print(tables(ok))
    opts.output.parent.mkdir(parents=True, exist_ok=True)
    old = json.loads(opts.output.read_text()) if opts.output.is_file() and (opts.only or opts.package) else {}
    merged = {r["case"]: r for r in old.get("cases", [])}
    merged.update({r["case"]: r for r in results})
    opts.output.write_text(json.dumps({"cases": [merged[k] for k in sorted(merged)]}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
