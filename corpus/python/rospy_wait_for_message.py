#!/usr/bin/env python3
"""Behavior: a coverage planner blocks on rospy.wait_for_message for the map, then plans at
0.5 Hz; its heartbeat starts before the wait and does not need the map."""
import rospy
from nav_msgs.msg import OccupancyGrid, Path
from std_msgs.msg import Empty


def beat(pub):
    pub.publish(Empty())


def main():
    rospy.init_node("coverage_planner")
    heartbeat = rospy.Publisher("~heartbeat", Empty, queue_size=1)
    plan_pub = rospy.Publisher("coverage_plan", Path, queue_size=1, latch=True)
    rospy.Timer(rospy.Duration(1.0), lambda _event: beat(heartbeat))
    grid = rospy.wait_for_message("map", OccupancyGrid, timeout=rospy.get_param("~map_timeout", 30.0))
    rate = rospy.Rate(0.5)
    while not rospy.is_shutdown():
        plan = Path()
        plan.header.frame_id = grid.header.frame_id
        plan_pub.publish(plan)
        rate.sleep()


if __name__ == "__main__":
    main()
