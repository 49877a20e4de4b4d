"""Count the messages on some topics of a running ROS 1 system (run under /usr/bin/python3, where
Debian's rospy is; never imported by the tests).

    topic_monitor.py TOPIC...

Subscribes to every TOPIC with rospy.AnyMsg (no message classes needed) and writes one line per
event to stdout, flushed at once:

    msg TOPIC        a message arrived on TOPIC (latched messages too)
    ready TOPIC...   every subscription has a publisher connection, or the connect timeout
                     (env ARCHLOG_MONITOR_CONNECT, seconds, default 10) passed; lists the topics
                     still without one

Stops on SIGINT/SIGTERM, or when stdin closes (the test is gone).
"""

import os
import sys
import threading
import time

import rospy

_LOCK = threading.Lock()


def emit(*words: str) -> None:
    with _LOCK:
        sys.stdout.write(" ".join(words) + "\n")
        sys.stdout.flush()


def main(topics: list[str]) -> None:
    rospy.init_node("archlog_topic_monitor", anonymous=True)
    subscribers = {topic: rospy.Subscriber(topic, rospy.AnyMsg, lambda _msg, t=topic: emit("msg", t))
                   for topic in topics}
    deadline = time.monotonic() + float(os.environ.get("ARCHLOG_MONITOR_CONNECT", "10"))
    while time.monotonic() < deadline and not rospy.is_shutdown():
        if all(s.get_num_connections() > 0 for s in subscribers.values()):
            break
        time.sleep(0.05)
    emit("ready", *sorted(t for t, s in subscribers.items() if s.get_num_connections() == 0))
    threading.Thread(target=lambda: (sys.stdin.read(), rospy.signal_shutdown("stdin closed")),
                     daemon=True).start()
    rospy.spin()


if __name__ == "__main__":
    main(sys.argv[1:])
