"""Generate C++ message headers with Debian's gencpp. Runs under /usr/bin/python3 (genmsg and
gencpp import only there); driven by archlog.extract.cpp.msg_headers through stdin/stdout JSON.

Input: {"out": DIR, "templates": DIR, "search": ["pkg:dir", ...], "files": [[pkg, path], ...]}.
Output: {"errors": [[path, message], ...]}. An .action file is first expanded into its seven
messages (Goal, Result, Feedback and the Action* wrappers), as actionlib does.
"""

import json
import os
import sys
import tempfile

ACTION_WRAPPERS = {
    "Action": "{n}ActionGoal action_goal\n{n}ActionResult action_result\n{n}ActionFeedback action_feedback\n",
    "ActionGoal": "Header header\nactionlib_msgs/GoalID goal_id\n{n}Goal goal\n",
    "ActionResult": "Header header\nactionlib_msgs/GoalStatus status\n{n}Result result\n",
    "ActionFeedback": "Header header\nactionlib_msgs/GoalStatus status\n{n}Feedback feedback\n",
}


def expand_action(path, folder):
    """The messages an .action file stands for, written into folder; returns their paths."""
    with open(path) as handle:
        pieces = handle.read().split("\n---")
    if len(pieces) != 3:
        raise ValueError("an .action file needs goal, result and feedback separated by ---")
    name = os.path.basename(path)[: -len(".action")]
    texts = {"Goal": pieces[0], "Result": pieces[1].lstrip("-\n"), "Feedback": pieces[2].lstrip("-\n")}
    texts.update({suffix: body.format(n=name) for suffix, body in ACTION_WRAPPERS.items()})
    written = []
    for suffix, text in texts.items():
        target = os.path.join(folder, name + suffix + ".msg")
        with open(target, "w") as handle:
            handle.write(text)
        written.append(target)
    return written


def main():
    request = json.load(sys.stdin)
    from genmsg.template_tools import generate_from_file

    errors = []
    search = list(request["search"])
    jobs = []
    with tempfile.TemporaryDirectory() as scratch:
        for pkg, path in request["files"]:
            if path.endswith(".action"):
                folder = os.path.join(scratch, pkg)
                os.makedirs(folder, exist_ok=True)
                try:
                    jobs += [(pkg, p) for p in expand_action(path, folder)]
                except (OSError, ValueError) as exc:
                    errors.append([path, str(exc)])
                if pkg + ":" + folder not in search:
                    search.append(pkg + ":" + folder)
            else:
                jobs.append((pkg, path))
        for pkg, path in jobs:
            out = os.path.join(request["out"], pkg)
            try:
                generate_from_file(path, pkg, out, request["templates"], search,
                                   {"msg.h.template": "@NAME@.h"}, {"srv.h.template": "@NAME@.h"})
            except Exception as exc:  # genmsg raises many types for bad definitions
                errors.append([path, f"{type(exc).__name__}: {exc}"])
    print(json.dumps({"errors": errors}))


if __name__ == "__main__":
    main()
