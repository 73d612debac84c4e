#!/usr/bin/env python3
"""Checks that the docs point inside the repository.

    scripts/check_docs.py            # relative links in every Markdown file
    scripts/check_docs.py --paths    # also file paths named in comments, and requirement ids

Links: every relative link in a tracked Markdown file must name a tracked file or folder, and a
`#fragment` must name a heading (GitHub's anchor of it) or an `id=` in the target. Paths: every
token in a comment that looks like a repository path (a folder of the tree then a file name, such
as `client/web/net/session.js`) must name a tracked file, from the repository's root, from the
file's own folder, or as the tail of a tracked path; every requirement id cited as `SPEC D7` must
be defined in docs/requirements.md. Prints one line per broken reference
(FILE:LINE: what) and exits 1 when there is any, 0 when there is none.
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)|!\[[^\]]*\]\(([^)\s]+)\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
ANCHOR_ID = re.compile(r"""id=["']([^"']+)["']""")
SOURCE_EXTENSIONS = (".cpp", ".hpp", ".h", ".c", ".js", ".mjs", ".py", ".sh", ".cmake", ".glsl", ".vert", ".frag", ".html", ".css")
# A path token: folders separated by '/', ending in a file name with an extension.
PATH_TOKEN = re.compile(r"(?<![\w./:-])((?:\.\./|\./)?(?:[\w.-]+/)+[\w-]+\.(?:cpp|hpp|h|js|mjs|py|sh|md|json|cmake|glsl|vert|frag|html|css|txt))(?![\w/])")


def tracked_files():
    """The repository's files, or None outside a git checkout (an unpacked archive)."""
    try:
        out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    return [line for line in out.splitlines() if line]


def github_anchor(title):
    """The fragment GitHub gives a heading: lower case, punctuation dropped, spaces to '-'."""
    title = re.sub(r"`([^`]*)`", r"\1", title)
    title = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", title)
    title = title.strip().lower()
    title = re.sub(r"[^\w\- ]", "", title)
    return title.replace(" ", "-")


def anchors_of(path):
    anchors, seen, fenced = set(), {}, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.lstrip().startswith("```"):
                fenced = not fenced
                continue
            if fenced:
                continue
            anchors.update(ANCHOR_ID.findall(line))
            m = HEADING.match(line)
            if m:
                base = github_anchor(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                anchors.add(base if n == 0 else f"{base}-{n}")
    return anchors


def check_links(files, folders):
    problems, anchor_cache = [], {}
    for name in files:
        if not name.endswith(".md"):
            continue
        here = os.path.dirname(name)
        fenced = False
        with open(os.path.join(ROOT, name), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                if line.lstrip().startswith("```"):
                    fenced = not fenced
                    continue
                if fenced:
                    continue
                for m in LINK.finditer(re.sub(r"`[^`]*`", "", line)):
                    target = m.group(1) or m.group(2)
                    if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("//"):
                        continue  # an address outside (https:, mailto:)
                    path, _, fragment = target.partition("#")
                    resolved = os.path.normpath(os.path.join(here, path)) if path else name
                    if resolved.startswith(".."):
                        problems.append(f"{name}:{number}: link {target} leaves the repository")
                        continue
                    if resolved not in files and resolved not in folders:
                        problems.append(f"{name}:{number}: link {target}: no such file in the repository")
                        continue
                    if fragment and resolved.endswith(".md"):
                        if resolved not in anchor_cache:
                            anchor_cache[resolved] = anchors_of(os.path.join(ROOT, resolved))
                        if fragment not in anchor_cache[resolved]:
                            problems.append(f"{name}:{number}: link {target}: {resolved} has no heading #{fragment}")
    return problems


def comment_lines(name, text):
    """(line number, comment text) of a source file: //, /* */ and # comments."""
    hash_comments = name.endswith((".py", ".sh", ".cmake")) or os.path.basename(name) == "CMakeLists.txt"
    in_block = False
    for number, line in enumerate(text.splitlines(), 1):
        if in_block:
            yield number, line
            if "*/" in line:
                in_block = False
            continue
        if hash_comments:
            i = line.find("#")
            if i >= 0:
                yield number, line[i:]
            continue
        i = line.find("//")
        j = line.find("/*")
        if i >= 0 and (j < 0 or i < j):
            # Skip '//' inside a string such as "http://..." (the token check below needs a folder).
            yield number, line[i:]
        elif j >= 0:
            yield number, line[j:]
            if "*/" not in line[j:]:
                in_block = True


def check_paths(files):
    tracked = set(files)
    problems = []
    for name in files:
        if not (name.endswith(SOURCE_EXTENSIONS) or os.path.basename(name) == "CMakeLists.txt"):
            continue
        if name.startswith("third_party/"):
            continue
        try:
            with open(os.path.join(ROOT, name), encoding="utf-8") as f:
                text = f.read()
        except (UnicodeDecodeError, FileNotFoundError):
            continue
        here = os.path.dirname(name)
        for number, comment in comment_lines(name, text):
            for token in PATH_TOKEN.findall(comment):
                stem = os.path.splitext(os.path.basename(token))[0]
                if token.startswith(("../shared/", "build/", "demo-output/")) or len(stem) == 1 or stem.isupper():
                    continue  # data beside the checkout, build output, a placeholder (common/x.glsl, NAME.json)
                candidates = {os.path.normpath(token), os.path.normpath(os.path.join(here, token))}
                if candidates & tracked:
                    continue
                if any(path.endswith("/" + token.lstrip("./")) for path in tracked):
                    continue
                problems.append(f"{name}:{number}: comment names {token}, which is not in the repository")
    return problems


def check_requirement_ids(files):
    """Every id cited as `SPEC D7` (or a range, `SPEC F7-F11`) in a source file or a doc is defined in docs/requirements.md."""
    with open(os.path.join(ROOT, "docs", "requirements.md"), encoding="utf-8") as f:
        defined = set(re.findall(r"^- \*\*([A-Z][0-9]+)\*\*", f.read(), re.M))
    problems = []
    for name in files:
        if not (name.endswith(SOURCE_EXTENSIONS + (".md",)) or os.path.basename(name) == "CMakeLists.txt"):
            continue
        if name.startswith("third_party/") or name == "docs/requirements.md":
            continue
        try:
            with open(os.path.join(ROOT, name), encoding="utf-8") as f:
                lines = f.read().splitlines()
        except (UnicodeDecodeError, FileNotFoundError):
            continue
        for number, line in enumerate(lines, 1):
            for m in re.finditer(r"\bSPEC ([A-Z])([0-9]+)(?:-([A-Z]?)([0-9]+))?", line):
                ids = [m.group(1) + m.group(2)] + ([(m.group(3) or m.group(1)) + m.group(4)] if m.group(4) else [])
                for rid in ids:
                    if rid not in defined:
                        problems.append(f"{name}:{number}: SPEC {rid} is not defined in docs/requirements.md")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--paths", action="store_true", help="also check file paths named in source comments and the requirement ids cited")
    args = parser.parse_args()
    files = tracked_files()
    if files is None:
        print("check_docs.py: SKIPPED: not a git checkout, so no list of the repository's files")
        return 0
    folders = {os.path.dirname(f) for f in files}
    for folder in list(folders):
        while folder:
            folder = os.path.dirname(folder)
            folders.add(folder)
    problems = check_links(set(files), folders)
    if args.paths:
        problems += check_paths(files) + check_requirement_ids(files)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
