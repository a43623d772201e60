#!/usr/bin/env python3
"""Loads every robot description under the folders given and runs each for a
while with rbsim: whether it loads (or why not), what the load repaired, how
long the load took, and whether the run stayed finite, within the joints'
limits and without gaining energy. Prints a Markdown table and a summary.

    robot_zoo.py RBSIM [--duration S] [--height M] [--set KEY=VALUE ...] DIR_OR_URDF...

A floating robot starts with its base at --height (default 1.5 m) and falls;
a robot whose root is `world` hangs where its URDF puts it. Meshes resolve
through ROS_PACKAGE_PATH (set it to the folder holding the descriptions'
packages). Not a test: the descriptions are public files nobody here wrote
(bench/README.md, "Robots users have").
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET


def urdf_files(paths):
    for p in paths:
        if os.path.isfile(p):
            yield p
            continue
        for root, _, files in os.walk(p):
            for f in sorted(files):
                if f.lower().endswith(".urdf"):
                    yield os.path.join(root, f)


def describe(path):
    """(root link, {joint: (lower, upper)} of limited joints, moving joint count) or None."""
    try:
        robot = ET.parse(path).getroot()
    except (ET.ParseError, OSError):
        return None
    children = {j.find("child").get("link") for j in robot.iter("joint") if j.find("child") is not None}
    roots = [l.get("name") for l in robot.findall("link") if l.get("name") not in children]
    limits, moving = {}, 0
    for j in robot.findall("joint"):
        kind = j.get("type")
        if kind in ("revolute", "prismatic", "continuous"):
            moving += 1
        lim = j.find("limit")
        if kind in ("revolute", "prismatic") and lim is not None:
            try:
                limits[j.get("name")] = (float(lim.get("lower", 0)), float(lim.get("upper", 0)))
            except ValueError:
                pass
    return (roots[0] if roots else None), limits, moving


def cause(stderr):
    """The refusal, shortened: its last clause after the file name."""
    line = next((l for l in stderr.splitlines() if "error" in l), stderr.strip().splitlines()[-1:] or [""])
    line = line if isinstance(line, str) else line[0]
    line = re.sub(r"^rbsim: error: ", "", line)
    line = re.sub(r"^/\S+?: ", "", line)
    return line[:160]


def run(rbsim, path, args):
    info = describe(path)
    root, limits, moving = info if info else (None, {}, 0)
    fixed = root == "world"
    with tempfile.TemporaryDirectory() as tmp:
        out_csv = os.path.join(tmp, "run.csv")
        cmd = [rbsim, "--urdf", path, "--duration", str(args.duration), "--csv", out_csv, "--every", "1"]
        if not fixed:
            cmd += ["--set", "initial.position=[0,0,%g]" % args.height]
        for s in args.set:
            cmd += ["--set", s]
        start = time.monotonic()
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            return {"file": path, "status": "timeout", "cause": "no answer in %g s" % args.timeout}
        wall = time.monotonic() - start
        row = {"file": path, "moving": moving, "fixed": fixed, "exit": p.returncode,
               "repairs": sum(1 for l in p.stderr.splitlines() if "loaded with repairs" in l),
               "warnings": [l for l in p.stderr.splitlines() if "warning" in l]}
        if p.returncode != 0 or not p.stdout.strip():
            row.update(status="refused" if p.returncode == 2 or "error" in p.stderr else "failed", cause=cause(p.stderr))
            return row
        out = json.loads(p.stdout.strip().splitlines()[-1])
        row["load_s"] = wall - out["wall_s"]
        row["energy"] = (out["energy"]["start"], out["energy"]["end"])
        row["penetration"] = out["max_penetration"]
        row["at_rest"] = bool(out.get("at_rest", False))
        row["started_inside"] = any("inside the scene" in w for w in row["warnings"])
        excess, finite = 0.0, True
        with open(out_csv) as f:
            for r in csv.DictReader(f):
                for k, v in r.items():
                    x = float(v) if v not in (None, "") and k != "body" else 0.0
                    finite = finite and math.isfinite(x)
                    if k.endswith(".position") and k[: -len(".position")] in limits:
                        lo, hi = limits[k[: -len(".position")]]
                        excess = max(excess, lo - x, x - hi)
        row.update(status="ran", excess=excess, finite=finite)
        return row


def gains(r):
    """Whether the run ended with more energy than it started with (beyond 1e-3 relative)."""
    e0, e1 = r["energy"]
    return e1 > e0 + 1e-3 * max(1.0, abs(e0))


def lifted(r):
    """A start inside the ground (warned) lifted out by the position stage, which adds no velocity: the
    gain is the lift's potential energy, and the robot ends at rest."""
    return r["started_inside"] and r["at_rest"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rbsim")
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--duration", type=float, default=1.0)
    ap.add_argument("--height", type=float, default=1.5)
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--json", help="also write the rows to this file")
    args = ap.parse_args()
    rows = []
    print("| description | joints | result | load s | energy J (start -> end) | past a limit | deepest mm |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for path in urdf_files(args.paths):
        r = run(args.rbsim, path, args)
        rows.append(r)
        name = os.path.relpath(path, os.path.commonpath([os.path.abspath(p) for p in args.paths]) or "/")
        if r["status"] != "ran":
            print("| %s | %s | %s: %s | | | | |" % (name, r.get("moving", ""), r["status"], r["cause"].replace("|", "/")))
        else:
            e0, e1 = r["energy"]
            flags = [] if r["finite"] else ["NOT FINITE"]
            if gains(r) and lifted(r):
                flags.append("lifted out of the ground, at rest")
            elif gains(r):
                flags.append("gains energy")
            if r["excess"] > 1e-3:
                flags.append("past a limit")
            if r["repairs"]:
                flags.append("repaired")
            print("| %s | %d | %s | %.2f | %.4g -> %.4g | %.3g | %.1f |" % (
                name, r["moving"], "runs" + (" (" + ", ".join(flags) + ")" if flags else ""), r["load_s"], e0, e1,
                r["excess"], 1e3 * r["penetration"]), flush=True)
    ran = [r for r in rows if r["status"] == "ran"]
    good = [r for r in ran if r["finite"] and r["excess"] <= 1e-3 and not gains(r)]
    lift = [r for r in ran if r["finite"] and r["excess"] <= 1e-3 and gains(r) and lifted(r)]
    print("\n%d descriptions: %d load and run, %d of them finite, within limits and gaining no energy, %d more gaining "
          "only the lift out of a start inside the ground (warned; at rest at the end); %d refused or failed"
          % (len(rows), len(ran), len(good), len(lift), len(rows) - len(ran)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
