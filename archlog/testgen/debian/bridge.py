"""Feed and watch topics of a running ROS 1 system for a generated test (run under
/usr/bin/python3, where Debian's rospy is; never imported by archlog).

    bridge.py SPEC.json

SPEC: {"inputs": {topic: type}, "outputs": {topic: type}, "services": {service: type}, "nodes": [nodes
under test]}. Reads JSON lines on stdin:

    {"op": "publish", "topic": T, "msg": {...}}   publish a message given as a dict; a
                                                   {"now": offset} time is now + offset seconds
    {"op": "call", "service": S, "request": {...},  call a service (in a thread of its own); answer
     "id": N, "timeout": S}                        {"ev": "response", "service": S, "id": N, "t": ...,
                                                   "response": {...}} or, when the call failed, the same
                                                   with "error" instead of "response" (none after the
                                                   timeout)
    {"op": "wait", "timeout": S}                   answer {"ev": "ready", "missing": [...]} once every
                                                   input has a subscriber and every output a publisher
                                                   connected, every service is registered, and every node
                                                   under test's /rosout (or after S seconds, naming the
                                                   topics, services and nodes without)

and writes JSON lines on stdout: {"ev": "msg", "topic": T, "t": wall time, "msg": {...}} for every
message received on an output ({"ev": "error", ...} for a message that could not be published), and
{"ev": "log", "node": N, "t": when it was logged, "text": ...} for every ERROR or FATAL a node under
test logs to /rosout.
Stops when stdin closes.
"""

import json
import sys
import threading
import time

import genpy
import rosgraph
import roslib.message
import rospy
from rosgraph_msgs.msg import Log

_LOCK = threading.Lock()
_BYTES = ("uint8[", "char[")


def emit(event):
    with _LOCK:
        sys.stdout.write(json.dumps(event) + "\n")
        sys.stdout.flush()


def to_ros(value, slot_type, cls=None):
    """A genpy value of `slot_type` from its JSON form."""
    if slot_type.startswith(_BYTES):
        return bytes(v & 0xFF for v in value)
    if slot_type.endswith("]"):
        base = slot_type[:slot_type.index("[")]
        return [to_ros(v, base) for v in value]
    if slot_type in ("time", "duration"):
        if "now" in value:
            now = rospy.Time.now().to_sec() + value["now"]
            return rospy.Time.from_sec(max(now, 0.0))
        kind = rospy.Time if slot_type == "time" else rospy.Duration
        return kind(value["secs"], value["nsecs"])
    if isinstance(value, dict):
        cls = cls or roslib.message.get_message_class(slot_type)
        msg = cls()
        for name, sub_type in zip(cls.__slots__, cls._slot_types):
            if name in value:
                setattr(msg, name, to_ros(value[name], sub_type))
        return msg
    return value


def to_json(value):
    if isinstance(value, genpy.Message):
        return {name: to_json(getattr(value, name)) for name in value.__slots__}
    if isinstance(value, (genpy.Time, genpy.Duration)):
        return {"secs": value.secs, "nsecs": value.nsecs}
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    if isinstance(value, (list, tuple)):
        return [to_json(v) for v in value]
    return value


def call(proxy, service, request, number, timeout):
    """Call `service` through `proxy` and emit its response or why it failed."""
    try:
        proxy.wait_for_service(timeout)
        emit({"ev": "response", "service": service, "id": number, "t": time.time(), "response": to_json(proxy(request))})
    except Exception as exc:  # the node died, refused the request or is gone: the test's properties say which
        emit({"ev": "response", "service": service, "id": number, "t": time.time(),
              "error": f"{type(exc).__name__}: {exc}"})


def unregistered(master, services):
    """The services not registered on the master yet."""
    missing = []
    for service in sorted(services):
        try:
            master.lookupService(service)
        except (rosgraph.MasterError, OSError):
            missing.append(service)
    return missing


def unheard(master, rosout, nodes):
    """The nodes under test whose /rosout is not connected to the bridge yet."""
    connected = {c.endpoint_id for c in rosout.impl.connections}
    missing = []
    for node in sorted(nodes):
        try:
            uri = master.lookupNode(node)
        except (rosgraph.MasterError, OSError):
            uri = None
        if uri not in connected:
            missing.append(node)
    return missing


def main(spec_path):
    with open(spec_path) as f:
        spec = json.load(f)
    rospy.init_node("archlog_testgen_bridge", disable_signals=True)
    classes = {t: roslib.message.get_message_class(ty) for t, ty in {**spec["inputs"], **spec["outputs"]}.items()}
    publishers = {t: rospy.Publisher(t, classes[t], queue_size=100) for t in spec["inputs"]}
    subscribers = [rospy.Subscriber(t, classes[t], lambda m, t=t: emit(
        {"ev": "msg", "topic": t, "t": time.time(), "msg": to_json(m)}), queue_size=100) for t in spec["outputs"]]
    nodes = set(spec["nodes"])
    rosout = rospy.Subscriber("/rosout", Log, lambda m: m.level >= Log.ERROR and m.name in nodes and emit(
        {"ev": "log", "node": m.name, "t": m.header.stamp.to_sec() or time.time(), "text": m.msg}), queue_size=100)
    services = spec.get("services", {})
    proxies = {s: rospy.ServiceProxy(s, roslib.message.get_service_class(ty)) for s, ty in services.items()}
    master = rosgraph.Master(rospy.get_name())
    for line in sys.stdin:
        command = json.loads(line)
        if command["op"] == "publish":
            topic = command["topic"]
            try:
                publishers[topic].publish(to_ros(command["msg"], spec["inputs"][topic], classes[topic]))
            except Exception as exc:  # a value the message class refuses: the test reports it
                emit({"ev": "error", "topic": topic, "error": f"{type(exc).__name__}: {exc}"})
        elif command["op"] == "call":
            service = command["service"]
            try:
                request = to_ros(command["request"], services[service], proxies[service].request_class)
            except Exception as exc:  # a value the request class refuses: the test reports it
                emit({"ev": "response", "service": service, "id": command["id"], "t": time.time(),
                      "error": f"{type(exc).__name__}: {exc}"})
                continue
            threading.Thread(target=call, args=(proxies[service], service, request, command["id"], command["timeout"]),
                             daemon=True).start()
        elif command["op"] == "wait":
            end = time.monotonic() + command["timeout"]
            while True:
                missing = sorted([t for t, p in publishers.items() if p.get_num_connections() == 0]
                                 + [s.name for s in subscribers if s.get_num_connections() == 0]
                                 + unregistered(master, services) + unheard(master, rosout, nodes))
                if not missing or time.monotonic() > end:
                    break
                time.sleep(0.02)
            emit({"ev": "ready", "missing": missing})
    rospy.signal_shutdown("stdin closed")


if __name__ == "__main__":
    main(sys.argv[1])
