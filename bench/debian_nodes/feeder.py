"""Inputs and listeners for one node under test (run under /usr/bin/python3, where Debian's rospy is).

    feeder.py SPEC_JSON

SPEC_JSON: {"targets": [NODE...], "publish": [{"topic", "kind", ...}...], "listen": [TOPIC...]}

- publishes every `publish` entry at 5 Hz (latched ones once); kinds: image, camera_info, cloud,
  disparity, tf_static, joint_states, diagnostics, string, generic (type + YAML-like dict);
- subscribes (rospy.AnyMsg) to every topic a target node publishes, as the master lists them, polled
  every 0.5 s, so that lazy publishers (image_transport, nodelet lazy mode) subscribe their inputs;
  and to the `listen` topics.

Its node name is /archlog_feeder; the bench leaves it out of the observed graph.
"""

import json
import struct
import sys

import genpy
import rosgraph
import roslib.message
import rospy

INFO = dict(height=48, width=64, distortion_model="plumb_bob", D=[0.0] * 5,
            K=[50.0, 0, 32, 0, 50.0, 24, 0, 0, 1], R=[1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0],
            P=[50.0, 0, 32, 0, 0, 50.0, 24, 0, 0, 0, 1, 0])
CHANNELS = {"mono8": (1, 1), "bayer_rggb8": (1, 1), "rgb8": (3, 1), "bgr8": (3, 1), "mono16": (1, 2),
            "16UC1": (1, 2), "32FC1": (1, 4)}


def message(spec):
    kind = spec["kind"]
    spec.get("frame", "camera")
    if kind == "image":
        cls = roslib.message.get_message_class("sensor_msgs/Image")
        enc = spec.get("encoding", "mono8")
        ch, size = CHANNELS[enc]
        w, h = spec.get("width", 64), spec.get("height", 48)
        if enc == "32FC1":
            data = struct.pack(f"<{w * h}f", *([1.5] * (w * h)))
        elif enc == "16UC1":
            data = struct.pack(f"<{w * h}H", *([1500] * (w * h)))
        else:
            data = bytes((x * 7) % 250 for x in range(w * h * ch * size))
        return cls(encoding=enc, width=w, height=h, step=w * ch * size, data=data)
    if kind == "camera_info":
        cls = roslib.message.get_message_class("sensor_msgs/CameraInfo")
        info = dict(INFO)
        if spec.get("right"):
            info["P"] = [50.0, 0, 32, -5.0, 0, 50.0, 24, 0, 0, 0, 1, 0]
        return cls(**info)
    if kind == "cloud":
        cls = roslib.message.get_message_class("sensor_msgs/PointCloud2")
        field = roslib.message.get_message_class("sensor_msgs/PointField")
        n = spec.get("points", 200)
        pts = b"".join(struct.pack("<ffff", (i % 20) * 0.05, (i // 20) * 0.05, 1.0 + (i % 3) * 0.01, float(i))
                       for i in range(n))
        fields = [field(name=c, offset=4 * k, datatype=7, count=1) for k, c in enumerate(("x", "y", "z", "intensity"))]
        return cls(height=1, width=n, fields=fields, is_bigendian=False, point_step=16, row_step=16 * n,
                   data=pts, is_dense=True)
    if kind == "disparity":
        cls = roslib.message.get_message_class("stereo_msgs/DisparityImage")
        img = message(dict(kind="image", encoding="32FC1"))
        return cls(image=img, f=50.0, T=0.1, min_disparity=0.0, max_disparity=64.0, delta_d=0.125)
    if kind == "tf_static":
        tfm = roslib.message.get_message_class("tf2_msgs/TFMessage")
        ts = roslib.message.get_message_class("geometry_msgs/TransformStamped")
        out = []
        for parent, child in spec["pairs"]:
            t = ts()
            t.header.frame_id, t.child_frame_id = parent, child
            t.transform.rotation.w = 1.0
            out.append(t)
        return tfm(transforms=out)
    if kind == "joint_states":
        cls = roslib.message.get_message_class("sensor_msgs/JointState")
        return cls(name=spec["names"], position=[0.1] * len(spec["names"]))
    if kind == "diagnostics":
        arr = roslib.message.get_message_class("diagnostic_msgs/DiagnosticArray")
        st = roslib.message.get_message_class("diagnostic_msgs/DiagnosticStatus")
        return arr(status=[st(level=0, name=n, message="ok", hardware_id="hw") for n in spec["names"]])
    if kind == "string":
        return roslib.message.get_message_class("std_msgs/String")(data=spec.get("data", "hello"))
    cls = roslib.message.get_message_class(spec["type"])
    msg = cls()
    genpy.message.fill_message_args(msg, [spec.get("fields", {})])
    return msg


def stamp(msg, spec, now):
    header = getattr(msg, "header", None)
    if header is not None:
        header.stamp, header.frame_id = now, spec.get("frame", "camera")
    if spec["kind"] == "disparity":
        msg.image.header = msg.header
    if spec["kind"] == "tf_static":
        for t in msg.transforms:
            t.header.stamp = now


def main(spec):
    rospy.init_node("archlog_feeder")
    master = rosgraph.Master("/archlog_feeder")
    targets = set(spec.get("targets", []))
    outputs = []
    for p in spec.get("publish", []):
        msg = message(p)
        latch = p["kind"] == "tf_static" or p.get("latch", False)
        outputs.append((p, msg, rospy.Publisher(p["topic"], type(msg), queue_size=5, latch=latch)))
    listened = {t: rospy.Subscriber(t, rospy.AnyMsg, lambda _m: None) for t in spec.get("listen", [])}
    rate = rospy.Rate(spec.get("rate", 5))
    tick = 0
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        for p, msg, pub in outputs:
            if pub.impl.is_latch and tick % 10:
                continue
            stamp(msg, p, now)
            pub.publish(msg)
        if tick % 3 == 0 and targets:
            try:
                pubs, _subs, _srvs = master.getSystemState()
            except Exception:
                pubs = []
            for topic, nodes in pubs:
                if topic not in listened and targets & set(nodes) and topic not in ("/rosout", "/rosout_agg"):
                    listened[topic] = rospy.Subscriber(topic, rospy.AnyMsg, lambda _m: None)
        tick += 1
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == "__main__":
    main(json.loads(sys.argv[1]))
