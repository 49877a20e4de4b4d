#!/usr/bin/env python3
"""Stands in for the base's hardware node: it hosts the controller_manager services the spawner calls."""
import rospy
from controller_manager_msgs.srv import (LoadController, LoadControllerResponse, SwitchController,
                                         SwitchControllerResponse, UnloadController, UnloadControllerResponse)

if __name__ == '__main__':
    rospy.init_node('base_hw')
    rospy.Service('controller_manager/load_controller', LoadController, lambda _req: LoadControllerResponse(True))
    rospy.Service('controller_manager/switch_controller', SwitchController,
                  lambda _req: SwitchControllerResponse(True))
    rospy.Service('controller_manager/unload_controller', UnloadController,
                  lambda _req: UnloadControllerResponse(True))
    rospy.spin()
