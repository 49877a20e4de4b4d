#!/usr/bin/env python3
"""Starts the checker the package's library defines; its ports are there, not here."""
import rospy
from rig_check.checker import CheckerNode, UnusedNode  # noqa: F401  (UnusedNode is imported, never started)


def main():
    rospy.init_node("rig_check")
    CheckerNode(0.1)
    rospy.spin()


if __name__ == "__main__":
    main()
