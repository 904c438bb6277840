#!/usr/bin/env python3
"""c_core and dclaw are layered: each source file uses (links to) only
files below it, never one that uses it back. From the objects' symbol
tables (nm: the functions each defines and each calls), the graph of
"file A calls a function of file B" must have no cycle; prints each file
with the files it calls.
Usage: check_layers.py LIBRARY.a OBJECT.o ..."""
import os
import subprocess
import sys


def symbols(args):
    """{member or object: (defined, undefined)} of nm's listing."""
    out = subprocess.run(["nm", "-A"] + args, stdout=subprocess.PIPE, text=True, check=True).stdout
    table = {}
    for line in out.splitlines():
        where, _, rest = line.rpartition(":")
        if not where:
            continue
        w = rest.split()
        name = os.path.basename(where.split(":")[-1])
        d, u = table.setdefault(name, (set(), set()))
        if len(w) == 3 and w[1] in "TDRB":
            d.add(w[2])
        elif len(w) == 2 and w[0] == "U":
            u.add(w[1])
    return table


table = symbols(sys.argv[1:])
owner = {s: f for f, (d, _) in table.items() for s in d}
graph = {f: sorted({owner[s] for s in u if s in owner and owner[s] != f}) for f, (_, u) in table.items()}
# cycles: Tarjan's strongly connected components
index, low, stack, on, comps, n = {}, {}, [], set(), [], [0]


def visit(v):
    index[v] = low[v] = n[0]
    n[0] += 1
    stack.append(v)
    on.add(v)
    for w in graph[v]:
        if w not in index:
            visit(w)
            low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop()
            on.discard(w)
            comp.append(w)
            if w == v:
                break
        comps.append(comp)


sys.setrecursionlimit(10000)
for v in sorted(graph):
    if v not in index:
        visit(v)
cycles = [sorted(c) for c in comps if len(c) > 1]
for f in sorted(graph):
    if graph[f]:
        print("     %-36s calls %s" % (f, ", ".join(graph[f])))
for c in cycles:
    print("FAIL files that call each other: %s" % " <-> ".join(c))
print("layers: %d files, %d passed, %d failed" % (len(graph), 1 if not cycles else 0, len(cycles)))
sys.exit(1 if cycles else 0)
