#!/usr/bin/python3
"""Checks that the folders of src/ and kernels/ include each other in one direction only.

A folder A "includes" a folder B when a file in A has `#include "B/..."` (paths are relative
to src/ or the repository root, as the build's include directories are). The folders and
these edges form a graph; a group of folders that reach each other through it (a strongly
connected component of more than one folder) is a cycle, and a cycle fails the check:
every file include that keeps the group together is printed, so the one to move is plain.

  scripts/check_layers.py            # exit 0: no cycle; exit 1: the cycles and their includes
  scripts/check_layers.py --graph    # also print every folder edge with its include count
"""
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def source_files():
    for top in ('src', 'kernels'):
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            for name in names:
                if name.endswith(('.hpp', '.cpp', '.h', '.in')):
                    yield os.path.relpath(os.path.join(folder, name), ROOT)


def resolve(include, files):
    """The repository path an include names: under src/, at the root, or beside the includer."""
    for candidate in (os.path.join('src', include), include):
        if candidate in files:
            return candidate
    return None


def folder_edges():
    files = set(source_files())
    edges = {}  # (from folder, to folder) -> ["file -> included file", ...]
    for path in sorted(files):
        here = os.path.dirname(path)
        with open(os.path.join(ROOT, path), errors='replace') as text:
            for line in text:
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = resolve(match.group(1), files) or resolve(os.path.join(here, match.group(1)), files)
                if target and os.path.dirname(target) != here:
                    edges.setdefault((here, os.path.dirname(target)), []).append(f'{path} -> {target}')
    return edges


def cycles(edges):
    """Strongly connected components with more than one folder (Tarjan, iterative)."""
    graph = {}
    for a, b in edges:
        graph.setdefault(a, []).append(b)
        graph.setdefault(b, [])
    index, low, stack, on_stack, groups, counter = {}, {}, [], set(), [], 0
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, 0)]
        while work:
            node, next_child = work.pop()
            if next_child == 0:
                index[node] = low[node] = counter
                counter += 1
                stack.append(node)
                on_stack.add(node)
            children = sorted(graph[node])
            if next_child < len(children):
                work.append((node, next_child + 1))
                child = children[next_child]
                if child not in index:
                    work.append((child, 0))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    groups.append(sorted(group))
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
    return groups


def main():
    edges = folder_edges()
    if '--graph' in sys.argv[1:]:
        for (a, b), includes in sorted(edges.items()):
            print(f'{a} -> {b}  ({len(includes)})')
    groups = cycles(edges)
    if not groups:
        folders = {f for edge in edges for f in edge}
        print(f'check_layers: no include cycle among the {len(folders)} folders of src/ and kernels/')
        return 0
    for group in groups:
        print('check_layers: these folders include each other: ' + ', '.join(group))
        for (a, b), includes in sorted(edges.items()):
            if a in group and b in group:
                for include in includes:
                    print('    ' + include)
    return 1


if __name__ == '__main__':
    sys.exit(main())
