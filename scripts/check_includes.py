#!/usr/bin/env python3
"""Checks that the server's seams do not run back up.

    scripts/check_includes.py

The relay (server/relay/) reaches sessions only through SessionFanout
(server/relay/session_fanout.hpp) and the call (server/call/) reaches its members only through
CallPeer (server/call/call_peer.hpp), so both can be tested without sockets and neither is rebuilt
for every change to the server or its connections. This fails when a file of those folders
includes server/server.hpp or server/connection.hpp (under any spelling of the path that names
those two files of server/). Prints one line per include (FILE:LINE: what) and exits 1 when there
is any, 0 when there is none.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDERS = ("server/relay", "server/call")
FORBIDDEN = {"server/server.hpp", "server/connection.hpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]')


def resolved(including, name):
    """The repository paths an include could mean: from the root (the project's include path) or
    from the including file's own folder."""
    own = os.path.normpath(os.path.join(os.path.dirname(including), name)).replace(os.sep, "/")
    return {os.path.normpath(name).replace(os.sep, "/"), own}


def violations(root=ROOT):
    found = []
    for folder in FOLDERS:
        for directory, _, files in os.walk(os.path.join(root, folder)):
            for file in sorted(files):
                path = os.path.join(directory, file)
                relative = os.path.relpath(path, root).replace(os.sep, "/")
                with open(path, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        match = INCLUDE.match(line)
                        if match and resolved(relative, match.group(1)) & FORBIDDEN:
                            found.append(f"{relative}:{number}: includes {match.group(1)} (reach the server through "
                                         "server/relay/session_fanout.hpp or server/call/call_peer.hpp)")
    return found


def main():
    found = violations(sys.argv[1] if len(sys.argv) > 1 else ROOT)
    for line in found:
        print(line)
    if not found:
        print(f"no file under {' or '.join(FOLDERS)} includes {' or '.join(sorted(FORBIDDEN))}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
