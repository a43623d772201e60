#!/usr/bin/env python3
"""Checks the project's include graph: no cycles (no back edges), and the
layers in order (core includes neither io nor ros; io does not include ros).

Reads every #include "..." of include/ and src/, resolves it against
include/, the including file's folder or src/core (the core's private
headers, by subsystem), and exits non-zero naming the
cycle or the include that breaks a layer. Run by ctest (include_graph).
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def layer(path):
    for name in ("core", "io", "ros", "tools"):
        if f"/{name}/" in f"/{path}":
            return name
    return "node" if path.startswith("src/") else None


ORDER = {"core": 0, "io": 1, "ros": 2, "node": 3, "tools": 3}


def main():
    files = []
    for top in ("include", "src"):
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            files += [os.path.relpath(os.path.join(folder, n), ROOT) for n in names if n.endswith((".h", ".cpp"))]
    graph, problems = {}, []
    for f in files:
        text = open(os.path.join(ROOT, f), encoding="utf-8").read()
        edges = []
        for inc in INCLUDE.findall(text):
            # include/, the including file's folder, or the core's private headers ("contacts/island.h")
            for candidate in (os.path.join("include", inc), os.path.join(os.path.dirname(f), inc),
                              os.path.join("src", "core", inc)):
                if os.path.exists(os.path.join(ROOT, candidate)):
                    edges.append(os.path.normpath(candidate))
                    break
            # else: a generated message header (rigid_body_sim/Step.h): outside the graph
        graph[f] = edges
        for e in edges:
            a, b = layer(f), layer(e)
            if a in ORDER and b in ORDER and ORDER[b] > ORDER[a]:
                problems.append(f"layer: {f} ({a}) includes {e} ({b})")
    # Depth-first search; a grey node met again closes a cycle.
    colour, stack = {}, []

    def visit(node):
        colour[node] = "grey"
        stack.append(node)
        for nxt in graph.get(node, []):
            if colour.get(nxt) == "grey":
                problems.append("cycle: " + " -> ".join(stack[stack.index(nxt):] + [nxt]))
            elif nxt not in colour:
                visit(nxt)
        stack.pop()
        colour[node] = "black"

    for f in sorted(graph):
        if f not in colour:
            visit(f)
    for p in problems:
        print(p)
    edges = sum(len(e) for e in graph.values())
    print(f"include graph: {len(graph)} files, {edges} project includes, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
