"""Oracle 2 (issue 17): archlog's recovery against architectures recorded while real ROS systems ran.

The public repository cmu-rss-lab/rosdiscover-evaluation (the ROSDiscover study) launched each
subject in simulation, read the ROS master (`observed.architecture.yml`) and recovered the same
system with its own static tool (`recovered.architecture.yml`). This script recovers the subjects
with archlog and scores archlog and the study's tool against the observation with the study's
metric: per kind, ports missing from the recovery (under-approximation) and ports only in the
recovery (over-approximation), BOTH divided by the observed count.

    python bench/eval_recovery.py materialize --meta DIR --mirrors /work/.mirror --out /work/evalsrc
    python bench/eval_recovery.py score --meta DIR --evalsrc /work/evalsrc [--json bench/results/...]

`--meta DIR` holds one folder per subject with the study's `experiment.yml`, `pkgs.rosinstall`,
`observed.architecture.yml` and `recovered.architecture.yml` (copied out of the study's repository
with `git show HEAD:experiments/recovery/subjects/SUBJECT/FILE`). `materialize` checks out every
rosinstall entry whose repository has a local bare mirror (`MIRRORS/owner+name/repo`) at the
listed version into `EVALSRC/SUBJECT/src/LOCAL-NAME` (the sources are never committed); entries
without a mirror are listed. `score` runs `archlog.analysis.analyse` on `EVALSRC/SUBJECT/src`
with the launch files and the environment of `experiment.yml` (the CLI has no `--env`; the Python
API takes `env=`), turns the facts into an `archlog.observe.Architecture` and scores.

Two archlog columns are printed: `archlog` (the workspace as checked out: a package whose source is
there is read from source, even where archlog ships a model of it) and `archlog+models` (the same,
with every model of archlog/models/ passed as `--model`, which takes precedence over sources), next
to `study` (the study's recovered.architecture.yml). Every port archlog misses is labelled with its
cause from CAUSE_PATTERNS (checked by hand; "unclassified" when no pattern matches).

Sources: only the rosinstall entries whose repositories were fetched are checked out (the packages
of the launched nodes, their launch files, robot descriptions, gazebo plugins and the libraries the
nodes link; message packages, ros_comm, ecl... were not), so some C++ does not compile for missing
headers (rosbag/bag.h, yaml-cpp, ecl); archlog then reads calls from the tokens.

What is compared (the same for all three sides):

* ports are (node, name) pairs: publishers and subscribers by topic, services by service name;
  types are left out (the master keeps one type per topic, and the study's files spell types in
  several ways, e.g. `sensor_msgs::JointState`);
* infrastructure is left out, as `archlog observe` does: /rosout, /rosout_agg, /clock, the
  logger services; also nodelet bond topics (`MANAGER/bond`: the nodelet loader's own traffic);
  and the `rostopic pub` node the study's run script started (not part of the launch files);
* a nodelet's ports are credited to its manager (`nodelet(N, Plugin, Manager)` facts), because the
  master sees them on the manager process; the loader node itself stays a node;
* archlog gives a robot description's gazebo plugin ports to the `spawn_model` instance that
  inserts the model; they are credited to gzserver, where they run (spawn_model's own ports too:
  the master sees spawn_model only while it runs, and the observation was taken later);
* a ros_control controller's ports (archlog makes one instance per controller a spawner starts)
  are credited to the node that hosts the controller manager: /gazebo (gzserver with
  gazebo_ros_control) when the configuration runs gazebo_ros/gzserver;
* an action server or client is expanded into its five topics (goal, cancel subscribed; status,
  feedback, result published by the server, reversed for a client), as the master sees them,
  unless the recovery already lists them.

Ports conditional on a transform: a node may create some ports only once tf can give it a
transform (move_base builds its costmaps, planners, services and action server only after each
costmap has looked up global_frame <- robot_base_frame). When no chain of broadcasts in the
configuration can ever provide that transform (AL701; `tf_blocked_port` facts), such a port is what
the code would create but not what the running system can show. The first table counts every port
(`archlog`, `archlog+models`); a second table (`archlog/tf`, `archlog+models/tf`) counts those
conditional ports as not expected, and every port so left out is listed with the wait it needs.
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tarfile
import time
from collections import defaultdict
from pathlib import Path

import yaml

SUBJECTS = ("husky", "turtlebot")
KINDS = ("nodes", "publishers", "subscribers", "services")
INFRA_TOPICS = frozenset({"/rosout", "/rosout_agg", "/clock"})
LOGGER_SERVICES = ("get_loggers", "set_logger_level")

# Repositories missing from the mirrors, with a stand-in: (owner/name, ref) -> (owner/name, ref).
STAND_INS = {
    # The release repository is not available; its upstream tag 0.1.3 is the released source.
    "ros-teleop/teleop_twist_joy-release": ("ros-teleop/teleop_twist_joy", lambda ref: ref.rsplit("/", 1)[-1].split("-")[0]),
    # The release repository is not available (the listed commit 2b7361c is a release-repo commit);
    # the husky subject was built for melodic, where LMS1xx was released as 0.2.0.
    "clearpath-gbp/lms1xx-release": ("clearpathrobotics/LMS1xx", lambda _ref: "0.2.0"),
}


# ----------------------------------------------------------------------------------------------
# materialize


def rosinstall_entries(path: Path) -> list[dict]:
    """(local name, owner/name, ref) for every entry of a rosinstall file."""
    out = []
    for item in yaml.safe_load(path.read_text()):
        kind, spec = next(iter(item.items()))
        uri = spec["uri"]
        repo_path = uri.split("github.com/", 1)[1]
        if kind == "tar":
            repo, _, ref = repo_path.partition("/archive/")
            ref = ref.removesuffix(".tar.gz")
        else:
            repo, ref = repo_path.removesuffix(".git"), str(spec["version"])
        out.append({"local": spec["local-name"], "repo": repo, "ref": ref})
    return out


def mirror_dir(mirrors: Path, repo: str) -> Path | None:
    base = mirrors / repo.replace("/", "+") / "repo"
    for candidate in (base / ".git", base):
        if (candidate / "HEAD").exists():
            return candidate
    return None


def _checkout_files(git: Path, ref: str, target: Path) -> list[str]:
    """Check out `ref` file by file, skipping blobs the snapshot lacks; returns the skipped paths."""
    listing = subprocess.run(["git", "--git-dir", str(git), "ls-tree", "-r", "-z", ref], capture_output=True,
                             check=True).stdout.decode().split("\0")
    skipped = []
    for line in filter(None, listing):
        meta, path = line.split("\t", 1)
        mode, kind, sha = meta.split()
        if kind != "blob":
            continue
        blob = subprocess.run(["git", "--git-dir", str(git), "cat-file", "blob", sha], capture_output=True)
        if blob.returncode:
            skipped.append(path)
            continue
        out = target / path
        out.parent.mkdir(parents=True, exist_ok=True)
        if mode == "120000":
            out.symlink_to(blob.stdout.decode())
        else:
            out.write_bytes(blob.stdout)
    return skipped


def materialize(meta: Path, mirrors: Path, out: Path) -> dict:
    report = {}
    for subject in SUBJECTS:
        entries = rosinstall_entries(meta / subject / "pkgs.rosinstall")
        done, absent, notes = [], [], []
        for entry in entries:
            repo, ref = entry["repo"], entry["ref"]
            git = mirror_dir(mirrors, repo)
            if git is None and repo in STAND_INS:
                stand_in, ref_of = STAND_INS[repo]
                git, ref = mirror_dir(mirrors, stand_in), ref_of(ref)
                if git is not None:
                    notes.append(f"{entry['local']}: {repo} not available, used {stand_in} at {ref}")
            if git is None:
                absent.append(entry["local"])
                continue
            target = out / subject / "src" / entry["local"]
            if target.exists():
                done.append(entry["local"])
                continue
            archive = subprocess.run(["git", "--git-dir", str(git), "archive", "--format=tar", ref],
                                     capture_output=True)
            if archive.returncode and "invalid object" in archive.stderr.decode():
                skipped = _checkout_files(git, ref, target)  # large blobs absent from the snapshot
                notes.append(f"{entry['local']}: {len(skipped)} large files absent from the snapshot: "
                             f"{', '.join(skipped[:3])}{' ...' if len(skipped) > 3 else ''}")
                done.append(entry["local"])
                continue
            if archive.returncode:
                notes.append(f"{entry['local']}: {ref} missing in {repo}: {archive.stderr.decode().strip()}")
                absent.append(entry["local"])
                continue
            target.mkdir(parents=True)
            with tarfile.open(fileobj=io.BytesIO(archive.stdout)) as tar:
                tar.extractall(target, filter="data")
            done.append(entry["local"])
        report[subject] = {"materialized": done, "absent": absent, "notes": notes}
        print(f"{subject}: {len(done)} of {len(entries)} rosinstall entries checked out, {len(absent)} without a mirror")
        for note in notes:
            print(f"  note: {note}")
    return report


# ----------------------------------------------------------------------------------------------
# the three sides in one shape: {kind: set of (node, name)} plus nodes


def _empty() -> dict[str, set]:
    return {k: set() for k in KINDS}


def _keep_topic(topic: str) -> bool:
    return topic not in INFRA_TOPICS and not topic.endswith("/bond")


def _keep_service(node: str, service: str) -> bool:
    return service not in {f"{node}/{x}" for x in LOGGER_SERVICES}


def _action_topics(node: str, action: str, server: bool, arch: dict[str, set]) -> None:
    base = action.rstrip("/")
    ins, outs = ("goal", "cancel"), ("status", "feedback", "result")
    for suffix in ins:
        arch["subscribers" if server else "publishers"].add((node, f"{base}/{suffix}"))
    for suffix in outs:
        arch["publishers" if server else "subscribers"].add((node, f"{base}/{suffix}"))


def from_study_yaml(path: Path) -> dict[str, set]:
    """An architecture file of the study (observed or recovered) in the compared shape."""
    arch = _empty()
    for node in yaml.safe_load(path.read_text()):
        name = node["fullname"]
        if name.startswith("/rostopic_"):  # the run script's `rostopic pub`
            continue
        arch["nodes"].add(name)
        for kind, key in (("publishers", "pubs"), ("subscribers", "subs")):
            for port in node.get(key) or []:
                if _keep_topic(port["name"]):
                    arch[kind].add((name, port["name"]))
        for port in node.get("provides") or []:
            if _keep_service(name, port["name"]):
                arch["services"].add((name, port["name"]))
        for port in node.get("action-servers") or []:
            _action_topics(name, port["name"], True, arch)
        for port in node.get("action-clients") or []:
            _action_topics(name, port["name"], False, arch)
    return arch


def recover(subject_src: Path, launches: list[str], env: dict[str, str],
            models: list[Path]) -> tuple[dict, dict, dict]:
    """archlog's recovery of one subject in the compared shape: every port the code creates, and the
    same without the ports created only after a transform the configuration can never provide
    (`tf_blocked_port`, AL701); and what went with it."""
    from archlog import names
    from archlog.analysis import analyse
    from archlog.rules.engine import Engine
    from archlog.rules.ruleset import load_rules
    from archlog.values import Unknown

    start = time.perf_counter()
    # `analyse(env=...)` sets the sandbox's environment, but in this version the ROS 1 launch
    # interpreter's $(env)/$(optenv) read os.environ (SubstContext's default), so set both.
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        analysis = analyse([subject_src], launches, {}, models, env=env)
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    seconds = time.perf_counter() - start
    store = analysis.store
    ctl = Engine(load_rules([])).ground(store)
    blocked = {str(store.from_term(a.symbol.arguments[0])): str(store.from_term(a.symbol.arguments[1]))
               for a in ctl.symbolic_atoms.by_signature("tf_blocked_port", 2)}
    waits = {str(w): (str(n), str(target), str(source)) for w, n, target, source in store.rows("tf_wait")}
    nodes = {str(r[0]): (r[1], r[2]) for r in store.rows("node")}
    host: dict[str, str] = {}
    for node, _plugin, manager in store.rows("nodelet"):
        if manager:
            host[str(node)] = names.resolve(str(manager), names.namespace_of(str(node)), str(node)) \
                if not str(manager).startswith("/") else str(manager)
    controller_host = next((n for n, kind in nodes.items() if kind == ("gazebo_ros", "gzserver")), None)
    controller_pkgs = set(_controller_instances(analysis))
    if controller_host:
        for node in controller_pkgs:
            host[node] = controller_host
        # archlog gives a robot description's gazebo plugin ports to the spawn_model instance
        # that inserts it; they run inside gzserver.
        for node, kind in nodes.items():
            if kind == ("gazebo_ros", "spawn_model"):
                host[node] = controller_host
    arch, expected = _empty(), _empty()
    arch["nodes"] = expected["nodes"] = {n for n in nodes if n not in controller_pkgs}
    unknown_ports = defaultdict(list)
    conditional: dict[str, list[str]] = defaultdict(list)  # wait -> ports counted as not expected

    def owner(node) -> str:
        return host.get(str(node), str(node))

    def add(port, node, kind: str, name: str) -> None:
        arch[kind].add((owner(node), name))
        if str(port) in blocked:
            conditional[blocked[str(port)]].append(f"{kind[:3]} {name}")
        else:
            expected[kind].add((owner(node), name))

    for kind, relation in (("publishers", "publisher"), ("subscribers", "subscriber")):
        for port, node, topic, _ty in store.rows(relation):
            if isinstance(topic, Unknown):
                unknown_ports[str(node)].append(f"{relation} {topic}")
            elif _keep_topic(topic):
                add(port, node, kind, topic)
    for port, node, service, _ty in store.rows("service_server"):
        if isinstance(service, Unknown):
            unknown_ports[str(node)].append(f"service_server {service}")
        elif _keep_service(str(node), service):
            add(port, node, "services", service)
    for relation, server in (("action_server", True), ("action_client", False)):
        for port, node, action, _ty in store.rows(relation):
            if not isinstance(action, Unknown):
                _action_topics(owner(node), action, server, arch)
                if str(port) not in blocked:
                    _action_topics(owner(node), action, server, expected)
    incomplete = defaultdict(list)
    for node, reason in store.rows("node_incomplete"):
        incomplete[str(node)].append(str(reason))
    diagnostics = [{"file": str(d.file), "line": d.line, "code": d.code, "severity": d.severity,
                    "message": d.message} for d in analysis.diagnostics.items]
    extra = {"seconds": round(seconds, 1), "node_kinds": {n: list(k) for n, k in nodes.items()},
             "credited": host, "unknown_ports": dict(unknown_ports), "incomplete": dict(incomplete),
             "diagnostics": diagnostics,
             "tf_conditional": {f"{waits[w][0]} waits for {waits[w][1]} <- {waits[w][2]}": sorted(set(ports))
                                for w, ports in conditional.items()}}
    return arch, expected, extra


def _controller_instances(analysis) -> set[str]:
    from archlog.diagnostics import DiagnosticSink
    from archlog.system.controllers import controller_nodes
    return {n.name for n in controller_nodes(analysis.config, DiagnosticSink())}


# ----------------------------------------------------------------------------------------------
# why archlog misses what it misses (checked by hand against the sources, 2026-11; a port that
# matches no pattern is printed as "unclassified", so new misses and fixed causes both show)

CAUSES = {
    "linked-library": "the node's code is in a catkin library the executable links (add_library + "
                      "target_link_libraries); archlog read only the executable's own sources, with no diagnostic. The "
                      "linked sources are now read, and since 2026-11-24 their ports count when the executable's "
                      "own code reaches them (extract/cpp/reach.py).",
    "model-condition": "archlog/models/diff_drive_controller.yaml published /tf only if ~enable_odom_tf; the "
                       "controller advertises /tf unconditionally (diff_drive_controller.cpp:727), so the master "
                       "sees it even with enable_odom_tf: false (husky control.yaml). Since 2026-11-24 the model "
                       "advertises it always and only the broadcast depends on the parameter.",
    "param-list": "topic names read at run time from a YAML file: cmd_vel_mux parses its yaml_cfg_file with "
                  "yaml-cpp (publisher, subscribers[].topic); since 2026-11-24 the shipped model "
                  "yocs_cmd_vel_mux.yaml lists them ({file: ~yaml_cfg_file, ...}, system/param_files.py).",
    "nh-across": "a NodeHandle handed to another object and used there: kobuki SafetyController(nh, name) "
                 "stores it in a member and subscribes/advertises in init(), defined in safety_controller.hpp "
                 "(which is parsed; the missing ecl include only makes the nodelet class invalid, and the calls "
                 "stay in the AST); a nodelet was read as its exported class's methods only, so the helper's "
                 "init() was dropped. Since 2026-11-24 the functions those methods call are read too (scope.py).",
    "loader-call-sites": "nodelet's Loader(bool) and Loader(const NodeHandle&) both call constructorImpl in "
                         "loader.cpp with different handles; which one the manager uses is decided in nodelet.cpp "
                         "(another file), so the load_nodelet/unload_nodelet/list services' names stay unknown "
                         "(port-name-unknown notes).",
    "no-compile": "the C++ does not compile here (rosbag/bag.h, yaml-cpp, generated dynamic_reconfigure "
                  "headers missing) and the token fallback misses calls on members of unresolved types "
                  "(amcl's diagnostic_updater, kinetic amcl's tf::TransformListener). Since 2026-11-24 amcl.yaml "
                  "lists bag mode's base_scan (`if: {option: [--run-from-bag]}`), so the source, which lacks "
                  "/diagnostics and has base_scan unconditionally, resolves fewer ports and the model is used.",
    "footprint-sub": "each costmap subscribes ~<costmap>/footprint as geometry_msgs/Polygon while publishing it "
                     "as PolygonStamped; archlog/models/move_base.yaml leaves the subscriber out so that every "
                     "move_base is not a type mismatch with itself.",
}

# (subject or "", tool or "", node regex, port regex, cause); first match wins.
CAUSE_PATTERNS = [
    ("husky", "", "/gazebo", r"/tf$", "model-condition"),
    ("", "archlog", "/(ekf_localization|joy_teleop/teleop_twist_joy|robot_state_publisher)", r".", "linked-library"),
    ("", "", "/amcl", r".", "no-compile"),
    ("", "", "/move_base", r"_costmap/footprint$", "footprint-sub"),
    ("", "", r"/\w+_nodelet_manager", r"_nodelet_manager/(list|load_nodelet|unload_nodelet)$", "loader-call-sites"),
    ("", "", "/mobile_base_nodelet_manager", r"^/cmd_vel_mux/input/(navi|safety_controller)$", "nh-across",
     "publisher"),
    ("", "", "/mobile_base_nodelet_manager", r"^/mobile_base/commands/velocity$", "nh-across", "subscriber"),
    ("", "", "/mobile_base_nodelet_manager", r"^/cmd_vel_mux/|^/mobile_base/commands/velocity$", "param-list"),
    ("", "", "/mobile_base_nodelet_manager", r"kobuki_safety_controller/|/mobile_base/events/|"
     r"navigation_velocity_smoother/|^/odom$", "nh-across"),
]


def cause_of(subject: str, tool: str, node: str, port: str, kind: str = "") -> str:
    """The cause of a missing port (a pattern may also name the port's kind: publisher, subscriber...)."""
    import re
    for subj, tl, node_re, port_re, cause, *kinds in CAUSE_PATTERNS:
        if subj in ("", subject) and tl in ("", tool) and re.fullmatch(node_re, node) and re.search(port_re, port) \
                and (not kinds or kind.rstrip("s") in kinds):
            return cause
    return "unclassified"


# ----------------------------------------------------------------------------------------------
# scoring


def score(recovered: dict[str, set], observed: dict[str, set]) -> dict:
    out = {}
    for kind in KINDS:
        ours, theirs = recovered[kind], observed[kind]
        missing, extra = sorted(theirs - ours), sorted(ours - theirs)
        out[kind] = {"observed": len(theirs), "recovered": len(ours), "missing": len(missing), "extra": len(extra),
                     "under": round(100 * len(missing) / len(theirs), 1) if theirs else 0.0,
                     "over": round(100 * len(extra) / len(theirs), 1) if theirs else 0.0,
                     "missing_ports": missing, "extra_ports": extra}
    ports = [k for k in KINDS if k != "nodes"]
    obs = sum(out[k]["observed"] for k in ports)
    miss, ext = sum(out[k]["missing"] for k in ports), sum(out[k]["extra"] for k in ports)
    out["ports"] = {"observed": obs, "recovered": sum(out[k]["recovered"] for k in ports), "missing": miss,
                    "extra": ext, "under": round(100 * miss / obs, 1), "over": round(100 * ext / obs, 1)}
    return out


def by_node(pairs, kind: str) -> dict[str, list[str]]:
    grouped = defaultdict(list)
    for node, name in pairs:
        grouped[node].append(f"{kind[:3]} {name}")
    return grouped


TOOLS = ("archlog", "archlog+models", "study")
# the same recoveries, a port created only after a transform the configuration can never provide
# (tf_blocked_port: AL701's wait) counted as not expected
TF_TOOLS = ("archlog/tf", "archlog+models/tf")


def print_table(results: dict, tools: tuple[str, ...] = TOOLS) -> None:
    head = " | ".join(f"{t:>17} {'miss':>4} {'extra':>5} {'under%':>6} {'over%':>6}" for t in tools)
    print(f"\n{'subject':10} {'kind':12} {'obs':>4} | {head}")
    for subject, res in results.items():
        for kind in (*KINDS, "ports"):
            cells = " | ".join(f"{r['recovered']:>17} {r['missing']:>4} {r['extra']:>5} {r['under']:>6} {r['over']:>6}"
                               for r in (res[t][kind] for t in tools))
            print(f"{subject:10} {kind:12} {res['archlog'][kind]['observed']:>4} | {cells}")
    print("(recovered = ports recovered; under% = missing / observed; over% = extra / observed)")


def print_differences(subject: str, tool: str, res: dict) -> dict[str, int]:
    """The missing and extra ports grouped by node; for archlog's misses, the cause of each."""
    counts: dict[str, int] = defaultdict(int)
    for label, key in (("missing", "missing_ports"), ("extra", "extra_ports")):
        grouped = defaultdict(list)
        for kind in KINDS:
            if kind == "nodes":
                for node in res[kind][key]:
                    grouped[node].insert(0, "NODE")
                continue
            for node, name in res[kind][key]:
                item = f"{kind[:3]} {name}"
                if label == "missing" and tool != "study":
                    cause = cause_of(subject, tool.removesuffix("/tf"), node, name, kind)
                    counts[cause] += 1
                    item += f" [{cause}]"
                grouped[node].append(item)
        print(f"\n{subject} / {tool}: {label} ({sum(len(v) for v in grouped.values())})")
        for node in sorted(grouped):
            print(f"  {node}: {', '.join(grouped[node])}")
    if counts:
        print(f"{subject} / {tool}: missing ports by cause: {dict(sorted(counts.items(), key=lambda kv: -kv[1]))}")
    return dict(counts)


def run_score(meta: Path, evalsrc: Path, json_out: Path | None, subjects: list[str]) -> None:
    from archlog.system.node_models import BUILTIN_DIR
    shipped = sorted(Path(BUILTIN_DIR).glob("*.yaml"))
    results, extras = {}, {}
    for subject in subjects:
        experiment = yaml.safe_load((meta / subject / "experiment.yml").read_text())
        src = evalsrc / subject / "src"
        launches = [str(src / Path(p).relative_to("/ros_ws/src")) for p in experiment["launches"]]
        env = {k: str(v).replace("/ros_ws/src", str(src)) for k, v in (experiment.get("environment") or {}).items()}
        observed = from_study_yaml(meta / subject / "observed.architecture.yml")
        study = from_study_yaml(meta / subject / "recovered.architecture.yml")
        ours, ours_tf, extra = recover(src, launches, env, [])
        # The same, with archlog's shipped models passed as --model: user models take precedence
        # over what is extracted from sources, so a modelled node keeps its model even when its
        # package's source (whose ports may live in a linked library) is in the workspace.
        modelled, modelled_tf, extra_m = recover(src, launches, env, shipped)
        results[subject] = {"archlog": score(ours, observed), "archlog+models": score(modelled, observed),
                            "study": score(study, observed), "archlog/tf": score(ours_tf, observed),
                            "archlog+models/tf": score(modelled_tf, observed)}
        extras[subject] = extra | {"with_models": {k: v for k, v in extra_m.items() if k != "node_kinds"}}
        print(f"{subject}: archlog took {extra['seconds']} s ({extra_m['seconds']} s with models), "
              f"{len(extra['diagnostics'])} diagnostics")
        reported = meta / subject / "observed.recoverd.compare.csv"
        if reported.exists():
            rows = [r.split(",") for r in reported.read_text().splitlines() if r.startswith(f"{subject},all,")]
            print("  the study's own reported numbers (its own filtering, kind: observed recovered missing extra):")
            for r in rows:
                print(f"    {r[2]}: {' '.join(r[3:7])}")
    print_table(results)
    print("\nThe same recoveries, with every port the node creates only after a transform that no chain of "
          "broadcasts in the configuration provides (AL701) counted as not expected (the table above counts them):")
    print_table(results, TF_TOOLS)
    for subject in results:
        for wait, ports in extras[subject]["tf_conditional"].items():
            print(f"  {subject}: {wait}, a wait that never ends here (AL701; its own transform is missing, or an "
                  f"earlier wait's): {len(ports)} ports not expected: {', '.join(ports)}")
    print("\ncauses of archlog's misses:")
    for key, text in CAUSES.items():
        print(f"  {key}: {text}")
    for subject, res in results.items():
        for tool in TOOLS + TF_TOOLS:
            res[tool]["missing_by_cause"] = print_differences(subject, tool, res[tool])
        extra = extras[subject]
        print(f"\n{subject}: archlog nodes with unknown port names: {json.dumps(extra['unknown_ports'], indent=1)}")
        print(f"{subject}: archlog incomplete nodes: {json.dumps(extra['incomplete'], indent=1)}")
        print(f"{subject}: ports credited to another node: {json.dumps(extra['credited'], indent=1)}")
        print(f"{subject}: archlog's diagnostics:")
        for d in extra["diagnostics"]:
            print(f"  {d['file']}:{d['line']}: {d['severity']} {d['code']}: {d['message'][:300]}")
    if json_out:
        json_out.parent.mkdir(parents=True, exist_ok=True)
        small = {s: {tool: {k: r[tool][k] for k in (*KINDS, "ports", "missing_by_cause") if k in r[tool]}
                     for tool in TOOLS + TF_TOOLS}
                 | {"seconds": extras[s]["seconds"], "tf_conditional": extras[s]["tf_conditional"],
                    "diagnostics": sorted({f"{d['severity']} {d['code']}" for d in extras[s]["diagnostics"]})}
                 for s, r in results.items()}
        json_out.write_text(json.dumps(small, indent=1, default=list) + "\n")
        print(f"\nwrote {json_out}")
    (evalsrc / "archlog-extras.json").write_text(json.dumps(extras, indent=1, default=str))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    m = sub.add_parser("materialize")
    m.add_argument("--meta", type=Path, required=True)
    m.add_argument("--mirrors", type=Path, default=Path("/work/.mirror"))
    m.add_argument("--out", type=Path, default=Path("/work/evalsrc"))
    s = sub.add_parser("score")
    s.add_argument("--meta", type=Path, required=True)
    s.add_argument("--evalsrc", type=Path, default=Path("/work/evalsrc"))
    s.add_argument("--json", type=Path)
    s.add_argument("--subject", action="append", choices=SUBJECTS)
    options = parser.parse_args(argv)
    if options.command == "materialize":
        report = materialize(options.meta, options.mirrors, options.out)
        (options.out / "materialized.json").write_text(json.dumps(report, indent=1) + "\n")
    else:
        run_score(options.meta, options.evalsrc, options.json, options.subject or list(SUBJECTS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
