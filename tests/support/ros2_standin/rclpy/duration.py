"""rclpy.duration as a generated test uses it: a duration from seconds."""


class Duration:
    def __init__(self, *, seconds=0.0, nanoseconds=0):
        self.nanoseconds = int(seconds * 1e9) + nanoseconds
