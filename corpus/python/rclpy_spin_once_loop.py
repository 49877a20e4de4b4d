"""Behavior (rclpy, functional style): a loop around spin_once forwards the latest command once
one has arrived (module state set through `global`), and a rate-driven watchdog in a thread."""
import threading

import rclpy
from geometry_msgs.msg import Twist
from std_msgs.msg import Bool

latest = None
estop = False


def on_command(msg):
    global latest
    latest = msg


def on_estop(msg):
    global estop
    estop = msg.data


def watchdog(node, pub):
    rate = node.create_rate(2.0)
    while rclpy.ok():
        pub.publish(Bool(data=estop))
        rate.sleep()


def main():
    rclpy.init()
    node = rclpy.create_node('command_gate')
    out = node.create_publisher(Twist, 'cmd_vel_out', 10)
    heartbeat = node.create_publisher(Bool, 'estop_state', 1)
    node.create_subscription(Twist, 'cmd_vel_in', on_command, 10)
    node.create_subscription(Bool, 'estop', on_estop, 1)
    threading.Thread(target=watchdog, args=(node, heartbeat), daemon=True).start()
    while rclpy.ok():
        rclpy.spin_once(node, timeout_sec=0.05)
        if latest is None or estop:
            continue
        out.publish(latest)
    rclpy.shutdown()


if __name__ == '__main__':
    main()
