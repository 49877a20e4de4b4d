"""Properties of the velocity limiter (written by hand for the generated test)."""

import math

from archlog.testgen.runtime import Event, Properties as Generated


class Properties(Generated):
    def on_cmd_vel(self, event: Event) -> None:
        """/cmd_vel (geometry_msgs/Twist): every command is a finite number within the limits."""
        for part in ("linear", "angular"):
            for axis in "xyz":
                value = event.msg[part][axis]
                assert math.isfinite(value) and abs(value) <= 0.8 + 1e-9, f"cmd_vel.{part}.{axis} = {value}"
