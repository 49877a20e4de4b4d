"""Docks the robot, then arms the charger."""

import rclpy
from dock_interfaces.action import Dock
from rclpy.action import ActionClient
from rclpy.node import Node
from std_srvs.srv import Trigger


class MissionRunner(Node):
    def __init__(self):
        super().__init__("mission_runner")
        self.dock_client = ActionClient(self, Dock, "dock")
        self.arm_client = self.create_client(Trigger, "docking_server/arm_charger")

    def run(self):
        self.dock_client.wait_for_server()
        rclpy.spin_until_future_complete(self, self.dock_client.send_goal_async(Dock.Goal()))
        self.arm_client.wait_for_service()
        rclpy.spin_until_future_complete(self, self.arm_client.call_async(Trigger.Request()))


def main():
    rclpy.init()
    MissionRunner().run()
    rclpy.shutdown()
