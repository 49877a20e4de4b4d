"""rclpy without a subclass: rclpy.create_node, clients, actions, declare_parameters."""
import rclpy
from rclpy.action import ActionClient, ActionServer
from example_interfaces.srv import AddTwoInts
from nav2_msgs.action import NavigateToPose
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = rclpy.create_node("commander")
    node.declare_parameters("", [("speed", 0.5), ("frame", "map")])
    client = node.create_client(AddTwoInts, "add_two_ints")
    nav = ActionClient(node, NavigateToPose, "navigate_to_pose")
    server = ActionServer(node, NavigateToPose, "relay_navigate", lambda goal: None)
    pub = node.create_publisher(Twist, "cmd_vel", 10)
    rclpy.spin(node)


if __name__ == "__main__":
    main()
