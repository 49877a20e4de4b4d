#!/usr/bin/env python3
"""Integral controller that drives image brightness toward a setpoint."""
import rospy
from std_msgs.msg import Float32, Float64


def main():
    rospy.init_node('auto_exposure')
    target = rospy.get_param('~target_brightness', 0.45)
    gain = rospy.get_param('~gain', 0.2)
    state = {'exposure': rospy.get_param('~initial_exposure', 0.5)}
    pub = rospy.Publisher('exposure', Float64, queue_size=1)

    def on_brightness(msg):
        state['exposure'] += gain * (target - msg.data)
        state['exposure'] = max(0.0, min(1.0, state['exposure']))
        pub.publish(Float64(state['exposure']))

    rospy.Subscriber('brightness', Float32, on_brightness)
    rospy.spin()


if __name__ == '__main__':
    main()
