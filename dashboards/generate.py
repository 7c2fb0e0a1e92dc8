#!/usr/bin/env python3
"""Writes the hexplore Grafana dashboards (dashboards/*.json) from the panel lists below.

The JSON files are what Grafana loads (deploy/grafana/provisioning/dashboards/hexplore.yaml);
this script is where they are edited: change a panel here, run `python3 dashboards/generate.py`,
commit both. tests/rig checks that the JSON files are what this script writes, that every
expression names a metric the services export, and (with a live team) that it returns data.
"""
import json
import pathlib
import sys

DATASOURCE = {"type": "prometheus", "uid": "hexplore-prometheus"}
SCHEMA_VERSION = 39
ROBOT = 'robot=~"$robot"'

# Team topics are the only ones that cross robots; the paper's communication categories.
CATEGORY_OF_TOPIC = {
    "team/pose": "pose",
    "team/map": "incremental map",
    "team/path": "executable path",
    "team/plan": "exploration route",
}
TEAM_TOPICS = 'topic=~"team/(pose|map|path|plan)"'
# hexplore_transport_dropped_total reasons: lost on the way vs refused by the receiver.
LOST_REASONS = 'reason=~"fault_injected|timeout|send_failed"'
REJECT_REASONS = 'reason=~"malformed|wrong_version|wrong_type|oversize"'


def by_category(expr):
    """Adds a `category` label (the paper's names) to series that carry a team topic label."""
    for topic, category in CATEGORY_OF_TOPIC.items():
        expr = f'label_replace({expr}, "category", "{category}", "topic", "{topic}")'
    return expr


def target(expr, legend, ref):
    return {"refId": ref, "datasource": DATASOURCE, "expr": expr, "legendFormat": legend, "range": True}


# Default state-timeline value mapping: hexplore_safety_yielding.
YIELDING_STATES = ["driving", "yielding"]
YIELDING_COLORS = ["green", "orange"]
# hexplore_sim_motion_state's states (common/sim robot_motion.cc to_string), coded 0..4 by motion_state_code().
MOTION_STATES = ["idle", "moving", "stopped", "blocked", "emergency stop"]
MOTION_COLORS = ["blue", "green", "yellow", "orange", "red"]


def value_mappings(texts, colors):
    """Grafana value mappings 0, 1, ... -> texts."""
    return [{"type": "value", "options": {str(i): {"text": t, "color": c, "index": i}
                                          for i, (t, c) in enumerate(zip(texts, colors))}}]


def panel(title, description, exprs, unit="short", kind="timeseries", stack=False, w=12, h=8,
          states=(YIELDING_STATES, YIELDING_COLORS), matrix=None):
    """exprs: list of (expr, legend). Placement is filled in by layout(). states: the value mapping
    of a state-timeline. matrix: (row label, column label) to pivot an instant table on, for
    tables whose values are the answer (otherwise a table shows only labels)."""
    refs = "ABCDEFGH"
    p = {
        "type": kind,
        "title": title,
        "description": description,
        "datasource": DATASOURCE,
        "gridPos": {"h": h, "w": w, "x": 0, "y": 0},
        "targets": [target(e, l, refs[i]) for i, (e, l) in enumerate(exprs)],
        "fieldConfig": {"defaults": {"unit": unit}, "overrides": []},
    }
    if kind == "timeseries":
        p["fieldConfig"]["defaults"]["custom"] = {
            "drawStyle": "line",
            "lineWidth": 1,
            "fillOpacity": 10 if stack else 0,
            "showPoints": "never",
            "stacking": {"mode": "normal" if stack else "none", "group": "A"},
        }
        p["options"] = {
            "legend": {"showLegend": True, "displayMode": "table", "placement": "right", "calcs": ["lastNotNull"]},
            "tooltip": {"mode": "multi", "sort": "desc"},
        }
    elif kind == "stat":
        p["options"] = {"reduceOptions": {"calcs": ["lastNotNull"], "fields": "", "values": False},
                        "colorMode": "value", "graphMode": "none", "textMode": "value_and_name"}
    elif kind == "state-timeline":
        p["options"] = {"showValue": "never", "mergeValues": True, "rowHeight": 0.8,
                        "legend": {"showLegend": True, "displayMode": "list", "placement": "bottom"}}
        p["fieldConfig"]["defaults"]["mappings"] = value_mappings(*states)
    elif kind == "table":
        p["options"] = {"showHeader": True}
        if matrix:
            # One row per `row` label, one column per `column` label, the values in the cells.
            p["transformations"] = [{"id": "groupingToMatrix", "options": {
                "rowField": matrix[0], "columnField": matrix[1], "valueField": "Value"}}]
        else:
            # Instant queries come back as Time | labels... | Value; the labels are the answer.
            p["transformations"] = [{"id": "organize", "options": {"excludeByName": {"Time": True, "Value": True}}}]
        for t in p["targets"]:
            t.update({"format": "table", "instant": True, "range": False})
    return p


def layout(panels):
    """Numbers the panels and packs them left to right, top to bottom, on Grafana's 24-column grid."""
    x = y = row_h = 0
    for i, p in enumerate(panels, start=1):
        g = p["gridPos"]
        if x + g["w"] > 24:
            x, y, row_h = 0, y + row_h, 0
        g["x"], g["y"] = x, y
        x += g["w"]
        row_h = max(row_h, g["h"])
        p["id"] = i
    return panels


def dashboard(uid, title, description, panels):
    return {
        "uid": uid,
        "title": title,
        "description": description,
        "tags": ["hexplore"],
        "schemaVersion": SCHEMA_VERSION,
        "version": 1,
        "editable": False,
        "graphTooltip": 1,
        "timezone": "utc",
        "time": {"from": "now-30m", "to": "now"},
        "refresh": "5s",
        "annotations": {"list": []},
        "links": [{"type": "dashboards", "tags": ["hexplore"], "asDropdown": False, "title": "hexplore",
                   "includeVars": True, "keepTime": True}],
        "templating": {"list": [{
            "name": "robot",
            "label": "robot",
            "type": "query",
            "datasource": DATASOURCE,
            "definition": "label_values(hexplore_process_uptime_seconds, robot)",
            "query": {"query": "label_values(hexplore_process_uptime_seconds, robot)", "refId": "robot"},
            "includeAll": True,
            "multi": True,
            "allValue": ".*",
            "current": {"selected": True, "text": ["All"], "value": ["$__all"]},
            "refresh": 2,
            "sort": 1,
        }]},
        "panels": layout(panels),
    }


def rate(metric, selector, window="$__rate_interval"):
    return f"rate({metric}{{{selector}}}[{window}])"


# ---------------------------------------------------------------- communication
def communication():
    sent = "hexplore_transport_sent_bytes_total"
    panels = [
        panel("Team bytes per second, per robot",
              "Bytes each robot sends on the team topics (pose, map, path, plan): what crosses the radio.",
              [(f"sum by (robot) ({rate(sent, ROBOT + ', ' + TEAM_TOPICS)})", "{{robot}}")], unit="Bps", stack=True),
        panel("Team bytes per second, per category",
              "The paper's categories: pose (team/pose), incremental map (team/map), "
              "executable path (team/path), exploration route (team/plan).",
              [(f"sum by (category) ({by_category(rate(sent, ROBOT + ', ' + TEAM_TOPICS))})", "{{category}}")],
              unit="Bps", stack=True),
        panel("Cumulative team KB, per robot",
              "Total kilobytes (1 KB = 1024 bytes) each robot has sent on the team topics since it started.",
              [(f"sum by (robot) ({sent}{{{ROBOT}, {TEAM_TOPICS}}}) / 1024", "{{robot}}")], unit="none"),
        panel("Cumulative team KB, per category",
              "Total kilobytes sent by the selected robots, per communication category (the paper's table).",
              [(f"sum by (category) ({by_category(f'{sent}{{{ROBOT}, {TEAM_TOPICS}}}')}) / 1024", "{{category}}")],
              unit="none"),
        panel("Team bytes received per second, per robot",
              "Bytes each robot accepts from its teammates on the team topics.",
              [(f"sum by (robot) ({rate('hexplore_transport_received_bytes_total', ROBOT + ', ' + TEAM_TOPICS)})",
                "{{robot}}")], unit="Bps", stack=True),
        panel("Messages per second, per topic",
              "Messages sent on each team topic by the selected robots.",
              [(f"sum by (topic) ({rate('hexplore_transport_sent_messages_total', ROBOT + ', ' + TEAM_TOPICS)})",
                "{{topic}}")], unit="short"),
        panel("Message latency p50 / p99, per topic",
              "Receive wall time minus the sender's header send time, from the receivers' histograms.",
              [(f"histogram_quantile(0.5, sum by (le, topic) "
                f"({rate('hexplore_transport_latency_seconds_bucket', ROBOT)}))", "{{topic}} p50"),
               (f"histogram_quantile(0.99, sum by (le, topic) "
                f"({rate('hexplore_transport_latency_seconds_bucket', ROBOT)}))", "{{topic}} p99")],
              unit="s", w=24),
    ]
    panels += communication_map_panels()
    return dashboard("hexplore-communication", "hexplore / communication",
                     "What the robots send each other: bytes per robot and per category, latency, map gaps.",
                     panels)


def communication_map_panels():
    detected, repaired = "hexplore_hlmap_gaps_detected_total", "hexplore_hlmap_gaps_repaired_total"
    return [
        panel("Map increment gaps detected and repaired",
              "Gaps in peers' team/map sequences seen by each robot's hlmap, and those closed by a repair "
              "snapshot (ZeroMQ Clone pattern); detected minus repaired is what is still missing.",
              [(f"sum by (robot) ({detected}{{{ROBOT}}})", "{{robot}} detected"),
               (f"sum by (robot) ({repaired}{{{ROBOT}}})", "{{robot}} repaired")], unit="short"),
        panel("Map repair requests and snapshots",
              "MapRepairRequests each robot sent to peers, and MapSnapshots it served them.",
              [(f"sum by (robot) (hexplore_hlmap_repair_requests_total{{{ROBOT}}})", "{{robot}} requested"),
               (f"sum by (robot) (hexplore_hlmap_snapshots_served_total{{{ROBOT}}})", "{{robot}} served")],
              unit="short"),
    ]


# ---------------------------------------------------------------- services
def services():
    dropped = "hexplore_transport_dropped_total"
    panels = [
        panel("CPU per service",
              "CPU time (user + system) per second of each service process; 1.0 = one core.",
              [(f"sum by (robot, service) ({rate('hexplore_process_cpu_seconds_total', ROBOT)})",
                "{{robot}} {{service}}")], unit="percentunit"),
        panel("CPU seconds per service, cumulative",
              "CPU seconds each service has used since it started.",
              [(f"sum by (robot, service) (hexplore_process_cpu_seconds_total{{{ROBOT}}})",
                "{{robot}} {{service}}")], unit="s"),
        panel("Messages dropped per second, by reason",
              "Messages lost in transport: injected faults, request time-outs, failed sends.",
              [(f"sum by (service, topic, reason) ({rate(dropped, ROBOT + ', ' + LOST_REASONS)})",
                "{{service}} {{topic}} {{reason}}")], unit="short"),
        panel("Messages rejected per second, by reason",
              "Frames a receiver refused: malformed, wrong schema version, wrong payload type, oversize.",
              [(f"sum by (service, topic, reason) ({rate(dropped, ROBOT + ', ' + REJECT_REASONS)})",
                "{{service}} {{topic}} {{reason}}")], unit="short"),
        panel("Drops and rejections, total",
              "All messages dropped or rejected since the services started, by reason.",
              [(f"sum by (reason) ({dropped}{{{ROBOT}}})", "{{reason}}")], unit="short", kind="stat"),
        panel("Service uptime",
              "Seconds since each service process started; a reset means a restart.",
              [(f"max by (robot, service) (hexplore_process_uptime_seconds{{{ROBOT}}})", "{{robot}} {{service}}")],
              unit="s"),
    ]
    panels += service_stage_panels()
    return dashboard("hexplore-services", "hexplore / services",
                     "Per-service cost: CPU, pipeline stage durations, dropped and rejected messages.", panels)


def quantiles(metric, by, legend, selector=ROBOT):
    """p50 and p99 of a histogram, grouped by `by`."""
    return [(f"histogram_quantile({q}, sum by (le, {by}) ({rate(metric + '_bucket', selector)}))",
             f"{legend} p{round(q * 100)}") for q in (0.5, 0.99)]


def service_stage_panels():
    return [
        panel("sim: LiDAR frame casting", "Time to ray-cast one LiDAR frame against the scene, per robot.",
              quantiles("hexplore_sim_scan_seconds", "robot", "{{robot}}"), unit="s"),
        panel("mapping: scan integration", "Time to integrate one scan into the perception map, per robot.",
              quantiles("hexplore_mapping_scan_integration_seconds", "robot", "{{robot}}"), unit="s"),
        panel("hlmap: segmentation, topology update, fusion",
              "Supervoxel segmentation per voxel delta, topology update per window, fusion per peer increment "
              "(all robots).",
              quantiles("hexplore_hlmap_segmentation_seconds", "service", "segmentation")
              + quantiles("hexplore_hlmap_topology_update_seconds", "service", "topology update")
              + quantiles("hexplore_hlmap_fusion_seconds", "service", "fusion"), unit="s"),
        panel("planning: stage durations",
              "Single-round planning time per stage (views, clustering, assignment, mnss, total), all robots.",
              quantiles("hexplore_planning_stage_seconds", "stage", "{{stage}}"), unit="s"),
        panel("mapping: scans rejected and points dropped, by reason",
              "Scans the mapping service refused and points it dropped from accepted scans.",
              [(f"sum by (robot, reason) ({rate('hexplore_mapping_scans_rejected_total', ROBOT)})",
                "{{robot}} scans {{reason}}"),
               (f"sum by (robot, reason) ({rate('hexplore_mapping_points_dropped_total', ROBOT)})",
                "{{robot}} points {{reason}}")], unit="short"),
        panel("Throughput: points integrated, rays cast",
              "Points the mapping service integrates and rays the simulator casts, per second.",
              [(f"sum by (robot) ({rate('hexplore_mapping_points_total', ROBOT)})", "{{robot}} points/s"),
               (f"sum by (robot) (hexplore_sim_rays_per_second{{{ROBOT}}})", "{{robot}} rays/s")], unit="short"),
    ]


# ---------------------------------------------------------------- team overview
def team_overview():
    panels = [
        panel("Services up, per robot",
              "Number of service processes of each robot whose metrics Prometheus reads.",
              [(f"count by (robot) (hexplore_process_uptime_seconds{{{ROBOT}}})", "{{robot}}")],
              unit="short", kind="stat", w=24, h=4),
    ]
    panels += mission_panels() + robot_panels() + team_panels()
    return dashboard("hexplore-team-overview", "hexplore / team overview",
                     "The exploration as it happens: completeness, robots, planning.", panels)


def mission_panels():
    """The station's view: completeness from its periodic map snapshots, mission clock."""
    team = "hexplore_station_completeness_ratio"
    return [
        panel("Completeness over time",
              "Share of the scene's ground-truth surface samples covered by occupied voxels, from the station's "
              "periodic snapshots of every robot's map: the team's union, the union restricted to what the "
              "team could observe, and each robot's own map.",
              [(f'max({team}{{scope="team"}})', "team"),
               (f'max({team}{{scope="observable"}})', "team, observable"),
               (f"max by (robot) (hexplore_station_robot_completeness_ratio{{{ROBOT}}})", "{{robot}}")],
              unit="percentunit", w=18, h=9),
        panel("Mission",
              "Sim time since the station started the mission, and the robots it hears.",
              [("max(hexplore_station_mission_time_seconds)", "mission time (s)"),
               ("max(hexplore_station_robots_heard)", "robots heard"),
               (f'max({team}{{scope="team"}}) * 100', "team completeness (%)")],
              unit="none", kind="stat", w=6, h=9),
    ]


def motion_state_code(selector):
    """One series per robot: the index of its current motion state in MOTION_STATES."""
    terms = [f'{i} * max by (robot) (hexplore_sim_motion_state{{{selector}, state="{state}"}})'
             for i, state in enumerate(MOTION_STATES) if i > 0]
    return " + ".join(terms)


def robot_panels():
    position = "hexplore_sim_position_meters"
    return [
        panel("Robot motion state",
              "What each robot's simulated body does: " + ", ".join(MOTION_STATES) + ".",
              [(motion_state_code(ROBOT), "{{robot}}")], unit="short", kind="state-timeline",
              states=(MOTION_STATES, MOTION_COLORS), w=24, h=6),
        panel("Robot positions over time",
              "Each robot's x and y in the scene frame (simulator ground truth).",
              [(f'max by (robot, axis) ({position}{{{ROBOT}, axis=~"x|y"}})', "{{robot}} {{axis}}")], unit="m"),
        panel("Robot positions now",
              "Each robot's position in the scene frame (x, y, z in metres).",
              [(f"max by (robot, axis) ({position}{{{ROBOT}}})", "{{robot}} {{axis}}")],
              unit="m", kind="table", matrix=("robot", "axis")),
    ]


def team_panels():
    stage = "hexplore_planning_stage_seconds"
    total = f'{ROBOT}, stage="total"'
    return [
        panel("Planning time per round",
              "Single-round planning time (all stages) per robot: mean over the window and p99.",
              [(f"sum by (robot) ({rate(stage + '_sum', total)}) / sum by (robot) ({rate(stage + '_count', total)})",
                "{{robot}} mean"),
               (f"histogram_quantile(0.99, sum by (le, robot) ({rate(stage + '_bucket', total)}))",
                "{{robot}} p99")], unit="s"),
        panel("Active planner",
              "The planner each robot runs now (switchable at run time from the station).",
              [(f"max by (robot, planner) (hexplore_planning_planner_active{{{ROBOT}}}) == 1", "{{robot}}: {{planner}}")],
              unit="short", kind="table"),
        panel("Task views left",
              "Task views (incomplete surfaces to observe) in each robot's last planning round; "
              "the exploration ends when none are left.",
              [(f"max by (robot) (hexplore_planning_views{{{ROBOT}}})", "{{robot}}")], unit="short"),
        panel("Assignment agreement",
              "Share of clusters each robot assigns as its reference solution does: how consistent the "
              "decentralized plans are.",
              [(f"max by (robot) (hexplore_planning_assignment_agreement_ratio{{{ROBOT}}})", "{{robot}}")],
              unit="percentunit"),
        panel("Map size per robot",
              "Perception voxels mapped and supervoxels in the fused high-level map.",
              [(f"max by (robot) (hexplore_mapping_voxels{{{ROBOT}}})", "{{robot}} voxels"),
               (f"max by (robot) (hexplore_hlmap_supervoxels{{{ROBOT}}})", "{{robot}} supervoxels")],
              unit="short"),
        panel("Trajectory length",
              "Distance each robot has travelled (simulator odometry).",
              [(f"max by (robot) (hexplore_sim_odometry_meters{{{ROBOT}}})", "{{robot}}")], unit="m"),
        panel("Robot state: yielding to a teammate",
              "1 while a robot's safety service holds it for a teammate (path conflict), 0 while it drives on.",
              [(f"max by (robot) (hexplore_safety_yielding{{{ROBOT}}})", "{{robot}}")], unit="short",
              kind="state-timeline"),
        panel("Robot events",
              "Path conflicts, yields and detours (safety); blocked terrain, manoeuvres and collisions (sim), cumulative.",
              [(f"sum by (robot) (hexplore_safety_conflicts_total{{{ROBOT}}})", "{{robot}} conflicts"),
               (f"sum by (robot) (hexplore_safety_yields_total{{{ROBOT}}})", "{{robot}} yields"),
               (f"sum by (robot) (hexplore_safety_detours_total{{{ROBOT}}})", "{{robot}} detours"),
               (f"sum by (robot) (hexplore_sim_blocked_total{{{ROBOT}}})", "{{robot}} blocked"),
               (f"sum by (robot) (hexplore_sim_maneuvers_total{{{ROBOT}}})", "{{robot}} manoeuvres"),
               (f"sum by (robot) (hexplore_sim_collisions_total{{{ROBOT}}})", "{{robot}} collisions")],
              unit="short"),
        panel("Simulation time",
              "Each robot's simulation clock.",
              [(f"max by (robot) (hexplore_sim_time_seconds{{{ROBOT}}})", "{{robot}}")], unit="s"),
    ]


DASHBOARDS = {
    "hexplore-team-overview.json": team_overview,
    "hexplore-communication.json": communication,
    "hexplore-services.json": services,
}


def render(make):
    return json.dumps(make(), indent=2, sort_keys=False) + "\n"


def main(argv):
    out_dir = pathlib.Path(argv[1]) if len(argv) > 1 else pathlib.Path(__file__).resolve().parent
    for name, make in DASHBOARDS.items():
        (out_dir / name).write_text(render(make))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
