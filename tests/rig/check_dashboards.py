#!/usr/bin/env python3
"""Checks the Grafana dashboards in dashboards/ as Grafana would load them, and that they ask
only for metrics that exist.

usage: check_dashboards.py SOURCE_DIR

- every dashboards/*.json parses, has uid, title, schemaVersion and a panel list;
- panel ids are unique within a dashboard, every panel has a gridPos inside the 24 columns;
- every panel, target and query variable uses the data source uid that
  deploy/grafana/provisioning/datasources/*.yaml provisions;
- every target has a non-empty expr, refIds are unique within a panel;
- every hexplore_* metric named in an expression is registered somewhere in the C++ sources
  (common/, services/, tools/): a histogram's _bucket/_sum/_count series count as the histogram;
- the JSON files are exactly what dashboards/generate.py writes (no hand edits that the
  generator would undo);
- the provisioning dashboard provider points at the folder compose.yaml mounts dashboards/ on.
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

METRIC = re.compile(r"\bhexplore_[a-z0-9_]+")
HISTOGRAM_SERIES = ("_bucket", "_sum", "_count")
SOURCE_SUFFIXES = {".cc", ".h", ".cpp", ".hpp"}


def provisioned_uids(root):
    uids = set()
    for f in sorted((root / "deploy/grafana/provisioning/datasources").glob("*.yaml")):
        uids.update(re.findall(r"^\s*uid:\s*['\"]?([A-Za-z0-9_-]+)", f.read_text(), re.M))
    return uids


def source_text(root):
    chunks = []
    for folder in ("common", "services", "tools"):
        base = root / folder
        if base.is_dir():
            chunks += [p.read_text(errors="replace") for p in base.rglob("*") if p.suffix in SOURCE_SUFFIXES]
    return "\n".join(chunks)


def metric_exists(name, sources):
    candidates = [name] + [name[: -len(s)] for s in HISTOGRAM_SERIES if name.endswith(s)]
    return any(re.search(r'"' + re.escape(c) + r'"', sources) for c in candidates)


def expressions(dashboard):
    """(where, expr) for every PromQL expression: panel targets and query variables."""
    for p in dashboard.get("panels", []):
        for t in p.get("targets", []):
            yield f"panel {p.get('id')} '{p.get('title')}' target {t.get('refId')}", t.get("expr", "")
    for v in dashboard.get("templating", {}).get("list", []):
        if v.get("type") == "query":
            q = v.get("query")
            yield f"variable '{v.get('name')}'", q.get("query", "") if isinstance(q, dict) else (q or "")


def check_dashboard(path, uids, sources, problems):
    where = path.name
    try:
        d = json.loads(path.read_text())
    except json.JSONDecodeError as e:
        problems.append(f"{where}: not JSON: {e}")
        return 0
    for key in ("uid", "title", "schemaVersion", "panels"):
        if key not in d:
            problems.append(f"{where}: no '{key}'")
    if not isinstance(d.get("schemaVersion"), int) or d.get("schemaVersion", 0) < 30:
        problems.append(f"{where}: schemaVersion must be an integer >= 30 (Grafana 8+), is {d.get('schemaVersion')!r}")
    ids = [p.get("id") for p in d.get("panels", [])]
    for dup in sorted({i for i in ids if ids.count(i) > 1}, key=str):
        problems.append(f"{where}: panel id {dup} is used more than once")
    if any(not isinstance(i, int) for i in ids):
        problems.append(f"{where}: every panel needs an integer id")
    for p in d.get("panels", []):
        pw = f"{where}: panel {p.get('id')} '{p.get('title')}'"
        if p.get("type") == "row":
            continue
        g = p.get("gridPos") or {}
        if not all(isinstance(g.get(k), int) for k in ("x", "y", "w", "h")):
            problems.append(f"{pw}: gridPos needs integer x, y, w, h")
        elif g["x"] < 0 or g["w"] <= 0 or g["x"] + g["w"] > 24:
            problems.append(f"{pw}: gridPos {g} leaves Grafana's 24 columns")
        if (p.get("datasource") or {}).get("uid") not in uids:
            problems.append(f"{pw}: data source uid {(p.get('datasource') or {}).get('uid')!r} is not provisioned {sorted(uids)}")
        targets = p.get("targets") or []
        if not targets:
            problems.append(f"{pw}: no targets")
        refs = [t.get("refId") for t in targets]
        if len(set(refs)) != len(refs):
            problems.append(f"{pw}: duplicate refId in {refs}")
        for t in targets:
            if not str(t.get("expr", "")).strip():
                problems.append(f"{pw} target {t.get('refId')}: empty or missing expr")
            if (t.get("datasource") or {}).get("uid") not in uids:
                problems.append(f"{pw} target {t.get('refId')}: data source uid is not provisioned")
    for v in d.get("templating", {}).get("list", []):
        if v.get("type") == "query" and (v.get("datasource") or {}).get("uid") not in uids:
            problems.append(f"{where}: variable '{v.get('name')}' data source uid is not provisioned")
    count = 0
    for w, expr in expressions(d):
        count += 1
        names = set(METRIC.findall(expr))
        if not names:
            problems.append(f"{where}: {w}: expression names no hexplore_ metric: {expr}")
        for name in sorted(names):
            if not metric_exists(name, sources):
                problems.append(f"{where}: {w}: metric {name} is not registered in common/, services/ or tools/")
    return count


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    root = pathlib.Path(argv[1])
    problems = []
    uids = provisioned_uids(root)
    if len(uids) != 1:
        problems.append(f"deploy/grafana/provisioning/datasources: expected one data source uid, found {sorted(uids)}")
    provider = root / "deploy/grafana/provisioning/dashboards/hexplore.yaml"
    compose = (root / "compose.yaml").read_text()
    m = re.search(r"^\s*path:\s*(\S+)", provider.read_text(), re.M)
    if not m or f"./dashboards:{m.group(1)}" not in compose:
        problems.append(f"{provider}: the provider path is not where compose.yaml mounts ./dashboards")
    sources = source_text(root)
    files = sorted((root / "dashboards").glob("*.json"))
    if len(files) < 3:
        problems.append(f"dashboards/: expected the three dashboards, found {[f.name for f in files]}")
    uids_seen = {}
    total = 0
    for f in files:
        total += check_dashboard(f, uids, sources, problems)
        uid = json.loads(f.read_text()).get("uid") if f.read_text().strip().startswith("{") else None
        if uid in uids_seen:
            problems.append(f"{f.name}: dashboard uid '{uid}' also used by {uids_seen[uid]}")
        uids_seen[uid] = f.name
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, str(root / "dashboards/generate.py"), tmp], check=True)
        for g in sorted(pathlib.Path(tmp).glob("*.json")):
            committed = root / "dashboards" / g.name
            if not committed.exists() or committed.read_text() != g.read_text():
                problems.append(f"dashboards/{g.name} differs from what dashboards/generate.py writes; run it")
    print(f"checked {len(files)} dashboards, {total} expressions")
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
