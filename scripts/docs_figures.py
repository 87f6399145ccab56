#!/usr/bin/env python3
"""Figures in the docs come from the scripts that measure them. A generated block is
written in a page as

    <!-- figures: scripts/proxy_table.py {probeproxy} {suite} -->
    ...the script's standard output, verbatim...
    <!-- /figures -->

and this script reruns the command and puts its output between the markers:

    scripts/docs_figures.py --update [--build build] [--suite DIR] [PAGE...]   rewrite the blocks
    scripts/docs_figures.py --check  [--build build] [--suite DIR] [PAGE...]   exit 1 on drift

`{probeproxy}` is the build's CLI, `{build}` the build folder, `{suite}` the suite levels
(default `<build>/scenes`); the command runs from the
repository with /usr/bin/python3 when it is a .py. A block whose marker says `figures(slow):`
is rewritten by --update only (it runs for many minutes: the corpus and layout tables);
--check skips it and says so. Table columns headed "ms" or "s" (or ending so) are wall times:
--check compares every other cell exactly and those not at all, so a busy machine does not
count as drift."""
import argparse
import difflib
import glob
import os
import re
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BLOCK = re.compile(r"(<!-- figures(\(slow\))?: (.*?) -->\n)(.*?)(<!-- /figures -->)", re.S)


def run(command, build, suite):
    words = command.replace("{probeproxy}", os.path.join(build, "plugin", "cli", "probeproxy"))
    words = words.replace("{build}", build).replace("{suite}", suite).split()
    if words[0].endswith(".py"):
        words = ["/usr/bin/python3"] + words
    done = subprocess.run(words, cwd=REPO, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"docs_figures: `{command}` failed ({done.returncode}): {done.stderr.strip()[-500:]}")
    return done.stdout


def without_timings(text):
    """The text with the cells of wall-time columns (header ending in ' ms' or ' s') blanked."""
    out, timing, in_table = [], set(), False
    for line in text.splitlines():
        if not line.startswith("|"):
            in_table = False
            out.append(line)
            continue
        cells = line.strip().strip("|").split("|")
        if not in_table:  # a table's first row is its header
            in_table = True
            timing = {i for i, c in enumerate(cells)
                      if c.strip() in ("ms", "s") or c.strip().endswith((" ms", " s"))}
        out.append("|".join("" if i in timing else c for i, c in enumerate(cells)))
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--update", action="store_true")
    mode.add_argument("--check", action="store_true")
    parser.add_argument("--build", default="build")
    parser.add_argument("--suite", default=None)
    parser.add_argument("pages", nargs="*")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    suite = os.path.abspath(args.suite or os.path.join(build, "scenes"))
    pages = args.pages or [os.path.join(REPO, "README.md")] + sorted(glob.glob(os.path.join(REPO, "docs", "*.md")))

    drifted = 0
    for page in pages:
        text = open(page).read()
        changed = text
        for m in reversed(list(BLOCK.finditer(text))):
            slow, command, old = m.group(2), m.group(3), m.group(4)
            name = f"{os.path.relpath(page, REPO)}: {command}"
            if args.check and slow:
                print(f"skipped (slow) {name}")
                continue
            new = run(command, build, suite)
            if args.update:
                changed = changed[:m.start(4)] + new + changed[m.end(4):]
                print(f"updated {name}")
            elif without_timings(new) != without_timings(old):
                drifted += 1
                print(f"DRIFTED {name}")
                sys.stdout.writelines(difflib.unified_diff(
                    old.splitlines(True), new.splitlines(True), "in the page", "measured now", n=0))
            else:
                print(f"current {name}")
        if args.update and changed != text:
            open(page, "w").write(changed)
    return 1 if drifted else 0


if __name__ == "__main__":
    sys.exit(main())
