#!/usr/bin/env python3
"""Refreshes the `--help` blocks of docs/cli.md from the built programs: each "## PROGRAM [SUB]"
section's ```text block is replaced by what `build/bin/PROGRAM [SUB] --help` prints now. The prose
around them is left as written.

Usage: scripts/cli_reference.py [BIN_DIR]   (default build/bin)"""
import os
import re
import subprocess
import sys

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
bin_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "build", "bin")
path = os.path.join(here, "docs", "cli.md")
text = open(path).read()


def refreshed(match):
    heading, body = match.group(1), match.group(2)
    program, *sub = heading.split()
    out = subprocess.run([os.path.join(bin_dir, program), *sub, "--help"], capture_output=True, text=True, check=True).stdout
    help_text = out.replace(bin_dir + "/", "").replace("build/bin/", "").rstrip()
    block = re.sub(r"```text\n.*?\n```", lambda _: "```text\n" + help_text + "\n```", body, count=1, flags=re.S)
    return f"## {heading}\n{block}"


text = re.sub(r"^## (inkwire-[\w-]+(?: [\w-]+)?)\n(.*?)(?=^## |\Z)", refreshed, text, flags=re.S | re.M)
open(path, "w").write(text)
print(f"refreshed {path}")
