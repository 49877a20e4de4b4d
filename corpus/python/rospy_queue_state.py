#!/usr/bin/env python3
"""Behavior: state hidden in emptiness checks: goals queue up in a callback (deque, Queue, list)
and a 2 Hz loop hands them out; `if not self.x`, len() and .empty() all test the same state."""
import collections
import queue

import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path
from std_msgs.msg import String


class GoalSequencer(object):

    def __init__(self):
        self.goals = collections.deque()
        self.path = []
        self.events = queue.Queue()
        self.goal_pub = rospy.Publisher("current_goal", PoseStamped, queue_size=1)
        self.event_pub = rospy.Publisher("events", String, queue_size=10)
        self.length_pub = rospy.Publisher("path_length", String, queue_size=1)
        rospy.Subscriber("goals", PoseStamped, self.on_goal)
        rospy.Subscriber("plan", Path, self.on_plan)

    def on_goal(self, msg):
        self.goals.append(msg)
        self.events.put("queued")

    def on_plan(self, msg):
        self.path = msg.poses

    def has_goal(self):
        return len(self.goals) > 0

    def step(self):
        if not self.events.empty():
            self.event_pub.publish(String(data=self.events.get()))
        if not self.path:
            return
        self.length_pub.publish(String(data=str(len(self.path))))
        if not self.has_goal():
            return
        self.goal_pub.publish(self.goals.popleft())

    def run(self):
        rate = rospy.Rate(2)
        while not rospy.is_shutdown():
            self.step()
            rate.sleep()


if __name__ == "__main__":
    rospy.init_node("goal_sequencer")
    GoalSequencer().run()
