"""C++ behavior across the files of a node (cpp/behavior.link_files): a publish call in one file
reached from a callback, a loop or a thread another file registers or runs; the code of a
workspace header the file uses; calls a file that does not compile lost from its AST; bad input.
The single-file patterns are fixtures in corpus/cpp_ros1 and corpus/cpp_ros2."""

from __future__ import annotations

from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.extract import CppEnvironment, extract_cpp
from archlog.extract.summary import NodeSummary, Site

HEADER = """#pragma once
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>

class Relay {
 public:
  explicit Relay(ros::NodeHandle& nh);
  void spin();

 private:
  void onCommand(const std_msgs::String::ConstPtr& msg);
  void onEnable(const std_msgs::Bool::ConstPtr& msg);
  void report();
  void forward(const std::string& text);
  ros::Publisher out_pub_;
  ros::Publisher status_pub_;
  ros::Subscriber command_sub_;
  ros::Subscriber enable_sub_;
  bool enabled_ = false;
};
"""

NODE = """#include "relay/relay.h"

Relay::Relay(ros::NodeHandle& nh) {
  out_pub_ = nh.advertise<std_msgs::String>("out", 1);
  status_pub_ = nh.advertise<std_msgs::String>("status", 1);
  command_sub_ = nh.subscribe("command", 1, &Relay::onCommand, this);
  enable_sub_ = nh.subscribe("enable", 1, &Relay::onEnable, this);
}

void Relay::onCommand(const std_msgs::String::ConstPtr& msg) {
  if (!enabled_) {
    return;
  }
  forward(msg->data);
}

void Relay::spin() {
  ros::Rate rate(4.0);
  while (ros::ok()) {
    ros::spinOnce();
    report();
    rate.sleep();
  }
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  ros::NodeHandle nh;
  Relay relay(nh);
  relay.spin();
  return 0;
}
"""

OUTPUT = """#include "relay/relay.h"

void Relay::onEnable(const std_msgs::Bool::ConstPtr& msg) { enabled_ = msg->data; }

void Relay::forward(const std::string& text) {
  std_msgs::String out;
  out.data = text;
  out_pub_.publish(out);
}

void Relay::report() {
  std_msgs::String status;
  status.data = enabled_ ? "enabled" : "disabled";
  status_pub_.publish(status);
}
"""


def _node(tmp_path: Path, files: dict[str, str]) -> tuple[NodeSummary, DiagnosticSink]:
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    sources = [tmp_path / name for name in files if name.endswith(".cpp")]
    sink = DiagnosticSink()
    env = CppEnvironment([tmp_path / "include"], None, [tmp_path])
    summary = extract_cpp(sources, "demo", "relay", env, {s: s.name for s in sources}, sink)
    return summary, sink


def _ways(summary: NodeSummary, file: str, line: int) -> set[tuple[str, int | None]]:
    return {(p.trigger, p.source.line if p.source else None) for p in summary.publishes
            if (p.file, p.line) == (file, line)}


def test_publish_calls_in_another_file_are_reached_from_this_files_callbacks_and_loops(tmp_path: Path) -> None:
    summary, _sink = _node(tmp_path, {"include/relay/relay.h": HEADER, "node.cpp": NODE, "output.cpp": OUTPUT})
    assert _ways(summary, "output.cpp", 8) == {("callback", 6)}
    assert _ways(summary, "output.cpp", 14) == {("loop", None)}
    forward = next(p for p in summary.publishes if p.line == 8)
    assert [(g.var, g.value, g.file, g.line) for g in forward.guards] == [("Relay::enabled_", "true", "node.cpp", 11)]
    loop = next(p for p in summary.publishes if p.line == 14)
    assert loop.period == "0.25"
    # the flag's writer is a callback of the other file's subscriber; its initial value is in the header
    assert {(w.value, w.source) for w in summary.writes} == {("?", Site("node.cpp", 7)), ("false", None)}


def test_alone_a_file_does_not_know_how_its_functions_are_reached(tmp_path: Path) -> None:
    summary, _sink = _node(tmp_path, {"include/relay/relay.h": HEADER, "output.cpp": OUTPUT})
    assert {p.trigger for p in summary.publishes} == {"unknown"}
    assert {p.publisher for p in summary.publishes} == {None}


BASE = """#pragma once
#include <ros/ros.h>
#include <std_msgs/Empty.h>

class Periodic {
 public:
  explicit Periodic(ros::NodeHandle& nh) {
    timer_ = nh.createTimer(ros::Duration(0.5), &Periodic::tick, this);
  }
  virtual ~Periodic() = default;

 protected:
  virtual void step() = 0;

 private:
  void tick(const ros::TimerEvent&) { step(); }
  ros::Timer timer_;
};
"""

DERIVED = """#include "relay/periodic.h"

class Beacon : public Periodic {
 public:
  explicit Beacon(ros::NodeHandle& nh) : Periodic(nh) { pub_ = nh.advertise<std_msgs::Empty>("beacon", 1); }

 protected:
  void step() override { pub_.publish(std_msgs::Empty()); }

 private:
  ros::Publisher pub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "beacon");
  ros::NodeHandle nh;
  Beacon beacon(nh);
  ros::spin();
  return 0;
}
"""


def test_a_timer_made_in_a_workspace_header_drives_the_override_of_a_file(tmp_path: Path) -> None:
    summary, _sink = _node(tmp_path, {"include/relay/periodic.h": BASE, "beacon.cpp": DERIVED})
    assert [(p.kind, p.file, p.line) for p in summary.ports if p.kind == "timer"] == \
        [("timer", "include/relay/periodic.h", 8)]
    assert _ways(summary, "beacon.cpp", 8) == {("timer", 8)}
    assert next(p for p in summary.publishes if p.line == 8).source == Site("include/relay/periodic.h", 8)


BROKEN = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <missing_pkg/Missing.h>

ros::Publisher g_pub;

void announce(const std::string& text) {
  std_msgs::String msg;
  msg.data = text;
  g_pub.publish(msg);
}

void onThing(const missing_pkg::Missing::ConstPtr& thing) {
  announce(thing->undeclared_field.name());
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "broken");
  ros::NodeHandle nh;
  g_pub = nh.advertise<std_msgs::String>("announcements", 1);
  ros::Subscriber sub = nh.subscribe("thing", 1, onThing);
  ros::spin();
  return 0;
}
"""


def test_calls_a_file_that_does_not_compile_lost_are_read_from_its_text(tmp_path: Path) -> None:
    summary, sink = _node(tmp_path, {"broken.cpp": BROKEN})
    assert any(d.code == "cpp-compile" for d in sink.items)
    assert _ways(summary, "broken.cpp", 10) == {("callback", 21)}


def test_bad_input_gives_no_behavior_and_raises_nothing(tmp_path: Path) -> None:
    summary, sink = _node(tmp_path, {"garbage.cpp": "int main( { while (ros::ok() { pub.publish(; } }}}\n#if\n"})
    assert summary.publishes == [] and summary.writes == []
    assert sink.items
