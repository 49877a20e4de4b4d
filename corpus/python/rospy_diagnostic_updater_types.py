#!/usr/bin/env python3
# A monitor that publishes diagnostics with the message class diagnostic_updater re-exports
# (diagnostic_common_diagnostics' ntp_monitor): its type is diagnostic_msgs/DiagnosticArray.
import diagnostic_updater as DIAG
import rospy


def main():
    rospy.init_node("clock_monitor")
    pub = rospy.Publisher("/diagnostics", DIAG.DiagnosticArray, queue_size=10)
    rate = rospy.Rate(1)
    while not rospy.is_shutdown():
        pub.publish(DIAG.DiagnosticArray())
        rate.sleep()


if __name__ == "__main__":
    main()
