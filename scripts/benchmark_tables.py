#!/usr/bin/env python3
"""Makes the benchmark tables of docs/benchmarks.md from inkwire-bench's JSON.

    scripts/benchmark_tables.py                  # docs/bench/*.json -> docs/benchmarks.md
    scripts/benchmark_tables.py --check          # exit 1 when docs/benchmarks.md is not up to date
    scripts/benchmark_tables.py --print A.json   # print the tables of any runs, change nothing

Each JSON file is what `inkwire-bench --suite S --json FILE` writes (the shape in docs/cli.md,
"inkwire-bench"). Its suites' tables replace what stands between the markers

    <!-- benchmark-tables: SUITE -->
    <!-- /benchmark-tables: SUITE -->

in the document; a suite whose markers are missing is an error that names them. Rows measured in
several files (runs of the same build) show the median of each figure over the runs. Frame suites
give a table of median fps (with the ratio to the default renderer of the same run) per object,
and one per counter; suites that count other things give their counters, a column or a row each.
The run's date is the machine's `date` when the JSON has one, else the file's last commit date
(its modification time when it is not committed as it is).
"""
import argparse
import datetime
import glob
import json
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIELDS = ("faces", "frames", "fps_median", "fps_min", "fps_max", "rel_default")


class Refused(Exception):
    pass


def load(path):
    """The runs of one file: (machine, results), checked for the shape docs/cli.md gives."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        raise Refused(f"{path}: not readable as JSON ({e})")
    if not isinstance(data, dict) or not isinstance(data.get("results"), list) or not isinstance(data.get("machine", {}), dict):
        raise Refused(f"{path}: not inkwire-bench JSON (wants an object with 'machine' and a list 'results')")
    for i, r in enumerate(data["results"]):
        if not isinstance(r, dict) or not all(isinstance(r.get(k), str) for k in ("suite", "renderer", "variant", "object")):
            raise Refused(f"{path}: result {i} lacks suite, renderer, variant or object")
        if not all(isinstance(r.get(k, 0), (int, float)) for k in FIELDS):
            raise Refused(f"{path}: result {i} has a figure that is not a number")
        counters = r.get("counters", {})
        if not isinstance(counters, dict) or not all(isinstance(v, (int, float)) for v in counters.values()):
            raise Refused(f"{path}: result {i}'s counters are not all numbers")
    return data.get("machine", {}), data["results"]


def run_date(path, machine):
    """When a file's runs were made: its machine's `date` if it says, else its last commit, else its mtime."""
    if isinstance(machine.get("date"), str):
        return machine["date"][:10]
    try:
        out = subprocess.run(["git", "log", "-1", "--format=%cs", "--", os.path.abspath(path)], cwd=ROOT,
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--", os.path.abspath(path)], cwd=ROOT,
                               capture_output=True, text=True, check=True).stdout.strip()
        if out and not dirty:
            return out
    except (OSError, subprocess.CalledProcessError):
        pass
    return datetime.date.fromtimestamp(os.path.getmtime(path)).isoformat()


def number(v):
    """A figure as a table shows it: whole numbers whole, others to about four digits."""
    if v is None:
        return ""
    if float(v).is_integer() and abs(v) < 1e15:
        return str(int(v))
    if abs(v) >= 1000:
        return str(round(v))
    if abs(v) >= 100:
        return f"{v:.1f}"
    if abs(v) >= 0.001:
        return f"{v:.4g}"
    return f"{v:.2e}"


def label(row):
    """renderer / variant, said once: no renderer named as its suite, no data set named as the object."""
    variant = row["variant"].replace(",data=" + row["object"], "")
    if row["renderer"] == row["suite"] and variant:
        return variant
    return row["renderer"] + (" / " + variant if variant else "")


def merged(rows):
    """One row per (renderer, variant, object): the median of each figure over the runs."""
    runs = {}
    for r in rows:
        runs.setdefault((r["renderer"], r["variant"], r["object"]), []).append(r)
    out = []
    for key, rs in runs.items():
        row = dict(rs[-1])
        for f in FIELDS:
            row[f] = statistics.median(r.get(f, 0) for r in rs)
        keys = dict.fromkeys(k for r in rs for k in r.get("counters", {}))
        row["counters"] = {k: statistics.median(r["counters"][k] for r in rs if k in r.get("counters", {})) for k in keys}
        row["runs"] = len(rs)
        out.append(row)
    return out


def table(header, lines):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(cells) + " |" for cells in lines]
    return out


def frame_tables(suite, rows):
    """Frame suites: fps per object (rel_default in brackets), then each counter per object."""
    objects = list(dict.fromkeys(r["object"] for r in rows))
    faces = {r["object"]: r.get("faces", 0) for r in rows}
    configs = list(dict.fromkeys(label(r) for r in rows))
    cell = {(label(r), r["object"]): r for r in rows}
    out = []
    if len(objects) > 1:
        out += [f"**{suite}: median fps (relative to default)**", ""]
        header = ["renderer / variant"] + [f"{o} ({faces[o]})" if faces[o] else o for o in objects]
        out += table(header, [[c] + [f"{cell[c, o]['fps_median']:.0f} ({cell[c, o]['rel_default']:.2f})" if (c, o) in cell else ""
                                     for o in objects] for c in configs])
        counters = list(dict.fromkeys(k for r in rows for k in r["counters"]))
        for k in counters:
            with_k = [c for c in configs if any(k in cell.get((c, o), {}).get("counters", {}) for o in objects)]
            out += ["", f"**{suite}: {k}**", ""]
            out += table(["renderer / variant"] + objects,
                         [[c] + [number(cell.get((c, o), {}).get("counters", {}).get(k)) for o in objects] for c in with_k])
        return out
    counters = list(dict.fromkeys(k for r in rows for k in r["counters"]))
    header = ["renderer / variant", "object", "fps median", "fps min", "fps max", "relative to default"] + counters
    lines = [[label(r), f"{r['object']} ({r['faces']})" if r.get("faces") else r["object"], f"{r['fps_median']:.0f}",
              f"{r['fps_min']:.0f}", f"{r['fps_max']:.0f}", f"{r['rel_default']:.2f}"] + [number(r["counters"].get(k)) for k in counters]
             for r in rows]
    return table(header, lines)


def counter_tables(suite, rows):
    """Suites of counters: a table per object, counters as columns, or as rows when they outnumber the rows."""
    out = []
    objects = list(dict.fromkeys(r["object"] for r in rows))
    for o in objects:
        these = [r for r in rows if r["object"] == o]
        counters = list(dict.fromkeys(k for r in these for k in r["counters"]))
        if out:
            out.append("")
        if len(objects) > 1 or o not in ("", "-"):
            out += [f"**{suite}: {o}**", ""]
        if len(counters) > len(these) and len(these) <= 8:
            out += table(["counter"] + [label(r) for r in these], [[k] + [number(r["counters"].get(k)) for r in these] for k in counters])
        else:
            out += table(["renderer / variant"] + counters, [[label(r)] + [number(r["counters"].get(k)) for k in counters] for r in these])
    return out


def suite_block(suite, sources):
    """The Markdown of one suite: where its figures come from, then its tables."""
    rows = merged([r for _, _, results in sources for r in results if r["suite"] == suite])
    files = [path for path, _, results in sources if any(r["suite"] == suite for r in results)]
    machines = {json.dumps(m, sort_keys=True) for path, m, results in sources if path in files}
    dates = sorted({run_date(path, m) for path, m, _ in sources if path in files})
    runs = max(r["runs"] for r in rows)
    named = ", ".join(f"`{os.path.relpath(p, ROOT)}`" for p in files)
    out = [f"Run of {' to '.join([dates[0], dates[-1]] if len(dates) > 1 else dates)}: `inkwire-bench --suite {suite}` "
           f"({named}{'; each cell the median of ' + str(runs) + ' runs' if runs > 1 else ''}), made into tables by "
           f"`scripts/benchmark_tables.py`."]
    for m in sorted(machines):
        m = json.loads(m)
        extra = "".join(f", {k} `{v}`" for k, v in sorted(m.items()) if k not in ("cpu", "threads", "gl_renderer", "gl_backend"))
        out.append(f"Machine: {m.get('cpu', '?')}, {m.get('threads', '?')} threads, GL `{m.get('gl_renderer', '?')}` "
                   f"via {m.get('gl_backend', '?')}{extra}.")
    out.append("")
    timed = [r for r in rows if r.get("fps_median", 0) > 0]
    counted = [r for r in rows if r.get("fps_median", 0) <= 0]
    if timed:
        out += frame_tables(suite, timed)
    if counted:
        if timed:
            out.append("")
        out += counter_tables(suite, counted)
    return "\n".join(out)


def undated(text):
    return re.sub(r"^Run of [0-9-]+(?: to [0-9-]+)?:", "Run of DATE:", text, flags=re.M)


def marker(suite, closing=False):
    return f"<!-- {'/' if closing else ''}benchmark-tables: {suite} -->"


def rewrite(text, blocks):
    missing = []
    for suite, block in blocks.items():
        pattern = re.compile(re.escape(marker(suite)) + r"\n.*?" + re.escape(marker(suite, True)), re.S)
        if not pattern.search(text):
            missing.append(suite)
            continue
        text = pattern.sub(lambda _: marker(suite) + "\n" + block + "\n" + marker(suite, True), text, count=1)
    if missing:
        raise Refused("no markers for " + ", ".join(missing) + ": add a section with the lines\n" +
                      "\n".join(f"  {marker(s)}\n  {marker(s, True)}" for s in missing))
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", help="inkwire-bench JSON files (default: docs/bench/*.json)")
    parser.add_argument("--doc", default=os.path.join(ROOT, "docs", "benchmarks.md"), help="the document to write the tables into")
    parser.add_argument("--check", action="store_true", help="change nothing; exit 1 when the document is not up to date")
    parser.add_argument("--print", action="store_true", help="print the tables instead of writing them into the document")
    args = parser.parse_args()
    files = args.files or sorted(glob.glob(os.path.join(ROOT, "docs", "bench", "*.json")))
    if not files:
        print("benchmark_tables.py: no JSON files (docs/bench/*.json is empty)", file=sys.stderr)
        return 1
    try:
        sources = [(path, *load(path)) for path in files]
        suites = list(dict.fromkeys(r["suite"] for _, _, results in sources for r in results))
        blocks = {s: suite_block(s, sources) for s in suites}
        if args.print:
            for s, block in blocks.items():
                print(f"## {s}\n\n{block}\n")
            return 0
        with open(args.doc, encoding="utf-8") as f:
            before = f.read()
        after = rewrite(before, blocks)
    except Refused as e:
        print(f"benchmark_tables.py: {e}", file=sys.stderr)
        return 1
    if args.check:
        # The dates follow git and the files' times, which a checkout may change: the tables are checked.
        if undated(after) != undated(before):
            print(f"benchmark_tables.py: {os.path.relpath(args.doc)} is not up to date with its JSON: run scripts/benchmark_tables.py",
                  file=sys.stderr)
            return 1
        return 0
    if after != before:
        with open(args.doc, "w", encoding="utf-8") as f:
            f.write(after)
    print(f"benchmark_tables.py: {', '.join(suites)} written into {os.path.relpath(args.doc)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
