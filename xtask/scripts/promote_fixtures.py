#!/usr/bin/env python3
"""Promote fixture statuses from the last `cargo xtask validate` run.

Reads target/validation/report.json and, in fixtures/reported/*.json (not hps_lab.json, whose
format belongs to hps-emulsion's test), sets for every fixture with rows in the report:

- "status": "reproduced" when every row of the fixture is reproduced and the rows cover
  every value of a multi-valued fixture;
- "status": "partially reproduced" plus "reproduced_keys": [...] when some keys are (a key counts
  only if all its rows, e.g. both load cases, are reproduced);
- leaves "pending" otherwise.

A row agrees when its status is "reproduced", "input" or "by-construction" (an echo within
tolerance); the fixture status "reproduced" means that its rows must keep agreeing (the
regression guard), whichever of the three they are.

Only the status line (and the inserted reproduced_keys line) changes; the rest of each file is
kept byte for byte. Statuses are only promoted, never demoted: a regression must be looked at.
Usage: python3 xtask/scripts/promote_fixtures.py [ROOT]
"""
import glob
import json
import os
import re

AGREES = ("reproduced", "input", "by-construction")
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
report = json.load(open(os.path.join(root, "target", "validation", "report.json")))
rows = {}
for r in report["results"]:
    rows.setdefault(r["id"], []).append(r)

def leaves(v, prefix=""):
    """Keys of a multi-valued fixture as the report spells them (`a`, `0`, `2.1`)."""
    if isinstance(v, dict):
        items = v.items()
    elif isinstance(v, list):
        items = ((str(i), x) for i, x in enumerate(v))
    else:
        return [prefix] if prefix else []
    out = []
    for k, x in items:
        p = f"{prefix}.{k}" if prefix else k
        out += leaves(x, p) if isinstance(x, (dict, list)) else [p]
    return out


def decide(rs, q):
    value = q.get("values", q.get("value"))
    covered = {r["key"] for r in rs}
    complete = None in covered or not isinstance(value, (dict, list)) or set(leaves(value)) <= covered
    if complete and all(r["status"] in AGREES for r in rs):
        return "reproduced", []
    keys = {}
    for r in rs:
        if r["key"] is not None:
            keys.setdefault(r["key"], []).append(r["status"] in AGREES)
    good = sorted(k for k, v in keys.items() if all(v))
    if good:
        return "partially reproduced", good
    return None, []

changed = 0
for path in sorted(glob.glob(os.path.join(root, "fixtures", "reported", "*.json"))):
    if os.path.basename(path) == "hps_lab.json":
        continue
    before = json.load(open(path))
    by_id = {q["id"]: q for q in before["quantities"]}
    lines = open(path).read().split("\n")
    out, cur = [], None
    for line in lines:
        m = re.match(r'^(\s*)"id": "([^"]+)",$', line)
        if m:
            cur = m.group(2)
        m = re.match(r'^(\s*)"status": "([^"]*)",$', line)
        if m and cur in rows:
            indent, old = m.group(1), m.group(2)
            new, keys = decide(rows[cur], by_id[cur])
            if new and old in ("pending", "partially reproduced"):
                out.append(f'{indent}"status": "{new}",')
                if keys:
                    out.append(f'{indent}"reproduced_keys": {json.dumps(keys)},')
                changed += old != new
                continue
        if re.match(r'^\s*"reproduced_keys": ', line):
            continue  # rewritten next to its status line
        out.append(line)
    text = "\n".join(out)
    after = json.loads(text)
    # Everything but status / reproduced_keys must be unchanged.
    for a, b in zip(before["quantities"], after["quantities"]):
        a2 = {k: v for k, v in a.items() if k not in ("status", "reproduced_keys")}
        b2 = {k: v for k, v in b.items() if k not in ("status", "reproduced_keys")}
        assert a2 == b2, a["id"]
    open(path, "w").write(text)
print(f"promoted {changed} fixtures")
