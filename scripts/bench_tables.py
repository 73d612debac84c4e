#!/usr/bin/env python3
"""Prints inkwire-bench JSON results as Markdown tables (one per suite).

    scripts/bench_tables.py bench.json [more.json ...]

Rows are renderer/variant, columns the LOD objects; cells are "median fps (rel_default)". A
cell measured in several files (runs of the same build) shows the median of each over the runs.
Counters named with --counter (default front_faces) get a table of their own.
"""
import argparse
import json
import statistics
import sys


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--counter", action="append", default=None)
    args = parser.parse_args()
    counters = args.counter or ["front_faces"]
    results, machines = [], []
    for name in args.files:
        with open(name) as f:
            data = json.load(f)
        machines.append(data["machine"])
        results += data["results"]
    for m in {json.dumps(m, sort_keys=True) for m in machines}:
        m = json.loads(m)
        print(f"Machine: {m.get('cpu')}, {m.get('threads')} threads, GL `{m.get('gl_renderer')}` via {m.get('gl_backend', '?')}.\n")
    for suite in dict.fromkeys(r["suite"] for r in results):
        rows = [r for r in results if r["suite"] == suite]
        objects = list(dict.fromkeys(r["object"] for r in rows))
        faces = {r["object"]: r["faces"] for r in rows}
        configs = list(dict.fromkeys((r["renderer"], r["variant"]) for r in rows))
        runs = {}
        for r in rows:
            runs.setdefault((r["renderer"], r["variant"], r["object"]), []).append(r)
        cell = {key: dict(rs[-1], fps_median=statistics.median(r["fps_median"] for r in rs),
                          rel_default=statistics.median(r["rel_default"] for r in rs))
                for key, rs in runs.items()}
        print(f"### {suite}: median fps (relative to default)\n")
        print("| renderer / variant | " + " | ".join(f"{o} ({faces[o]})" for o in objects) + " |")
        print("|---|" + "---|" * len(objects))
        for c in configs:
            cells = []
            for o in objects:
                r = cell.get((c[0], c[1], o))
                cells.append(f"{r['fps_median']:.0f} ({r['rel_default']:.2f})" if r else "")
            print(f"| {c[0]}{' / ' + c[1] if c[1] else ''} | " + " | ".join(cells) + " |")
        print()
        for counter in counters:
            with_counter = [c for c in configs if any(counter in cell.get((c[0], c[1], o), {}).get("counters", {}) for o in objects)]
            if not with_counter:
                continue
            print(f"### {suite}: {counter}\n")
            print("| renderer / variant | " + " | ".join(objects) + " |")
            print("|---|" + "---|" * len(objects))
            for c in with_counter:
                vals = [cell.get((c[0], c[1], o), {}).get("counters", {}).get(counter) for o in objects]
                print(f"| {c[0]}{' / ' + c[1] if c[1] else ''} | " + " | ".join("" if v is None else f"{v:g}" for v in vals) + " |")
            print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
