#!/usr/bin/env python3
"""rospy forms: aliases, module and class constants, params with defaults, f-strings, format, %."""
import rospy
import std_msgs.msg
from geometry_msgs import msg as gm
from sensor_msgs.msg import LaserScan as Scan
from nav_msgs.srv import GetMap, GetPlan

PREFIX = "robot"
RATE_HZ = 10


class Planner(object):
    OUT = "plan"

    def __init__(self, scan_topic, ns="nav"):
        self.scan_topic = scan_topic
        self.ns = ns
        self.pub = rospy.Publisher("%s/%s" % (self.ns, self.OUT), std_msgs.msg.String, queue_size=1)
        rospy.Subscriber(self.scan_topic, Scan, self.on_scan)
        self.goal = rospy.Subscriber("{}/goal".format(PREFIX), gm.PoseStamped, self.on_goal)
        self.srv = rospy.Service("~make_plan", GetPlan, self.plan)

    def on_scan(self, msg):
        rospy.logdebug("scan with %d ranges", len(msg.ranges))

    def on_goal(self, msg):
        rospy.logdebug("goal in frame %s", msg.header.frame_id)

    def plan(self, req):
        return None


def main():
    rospy.init_node("planner", anonymous=False)
    topic = rospy.get_param("~scan_topic", "base_scan")
    Planner(topic)
    rospy.wait_for_service("static_map")
    get_map = rospy.ServiceProxy("static_map", GetMap)
    cmd = rospy.Publisher(f"/{PREFIX}/cmd_vel", gm.Twist, queue_size=1)
    rospy.set_param("~ready", True)
    rate = rospy.Rate(RATE_HZ)
    while not rospy.is_shutdown():
        rate.sleep()


if __name__ == "__main__":
    main()
