"""A timer in a callback group of the program's own has no known period (the group may hold its
callback back); rclpy's own groups keep it."""

from __future__ import annotations

import ast

import pytest

from archlog.extract.python.callback_groups import standard_group

SOURCE = '''
from rclpy.callback_groups import CallbackGroup, ReentrantCallbackGroup

class Throttled(CallbackGroup):
    def can_execute(self, entity):
        return False

class Talker:
    def __init__(self):
        self.fast = ReentrantCallbackGroup()
        self.slow = Throttled()
        self.create_timer(0.1, self.tick)
        self.create_timer(0.1, self.tick, None)
        self.create_timer(0.1, self.tick, callback_group=self.fast)
        self.create_timer(0.1, self.tick, callback_group=MutuallyExclusiveCallbackGroup())
        self.create_timer(0.1, self.tick, callback_group=self.slow)
        self.create_timer(0.1, self.tick, callback_group=Throttled())
        self.create_timer(0.1, self.tick, callback_group=given)
'''


@pytest.mark.parametrize(("index", "standard"), list(enumerate([True, True, True, True, False, False, False])))
def test_only_rclpys_groups_keep_a_timers_period(index: int, standard: bool) -> None:
    tree = ast.parse(SOURCE)
    timers = [n for n in ast.walk(tree) if isinstance(n, ast.Call) and getattr(n.func, "attr", "") == "create_timer"]
    call = timers[index]
    group = next((kw.value for kw in call.keywords if kw.arg == "callback_group"), call.args[2] if len(call.args) > 2 else None)
    assert standard_group(group, tree) is standard
