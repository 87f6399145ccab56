"""Runs every `probeproxy` command written in a fenced code block of README.md and docs/*.md,
as a user would paste it from the repository's root, and fails when one no longer runs (exit
code other than 0, or 1 for `validate`'s findings). A line with a placeholder (an upper-case
word such as SCENE), `...` or `[optional]` parts is a synopsis, not a command: it is counted
and skipped. `build/scenes` is the generated suite, `build/demo` what `scripts/setup.sh demo`
leaves (`probeproxy demo --out build/demo --no-bench`, made here first); outputs go to a scratch
folder.
    documented_commands.py PROBEPROXY REPO SUITE_DIR WORK_DIR"""
import glob
import os
import re
import shutil
import subprocess
import sys
import time

probeproxy, repo, suite, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, "build"))
os.symlink(suite, os.path.join(work, "build", "scenes"))
subprocess.run([probeproxy, "demo", "--out", os.path.join(work, "build", "demo"), "--no-bench"],
               check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

command = re.compile(r"^\s*(?:build/plugin/cli/)?probeproxy\s")
synopsis = re.compile(r"\.\.\.|\[|\b[A-Z][A-Z_]{2,}\b")
ran, skipped, failures = 0, 0, []
for page in ["README.md"] + sorted(glob.glob(os.path.join(repo, "docs", "*.md"))):
    text = open(os.path.join(repo, page) if page == "README.md" else page).read()
    for block in re.findall(r"```[a-z]*\n(.*?)```", text, re.S):
        for line in block.replace("\\\n", " ").splitlines():
            if not command.match(line):
                continue
            line = re.sub(r"\s+#.*$", "", line.strip())  # a trailing comment
            if synopsis.search(line):
                skipped += 1
                continue
            argv = re.sub(r"^(?:build/plugin/cli/)?probeproxy", probeproxy, line, count=1)
            start = time.time()
            result = subprocess.run(argv, shell=True, cwd=work, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, text=True, timeout=600)
            ok = result.returncode == 0 or (result.returncode == 1 and " validate " in line)
            print("%s %5.1f s rc %d  %s: %s" % ("ok  " if ok else "FAIL", time.time() - start,
                                                result.returncode, os.path.basename(page), line))
            ran += 1
            if not ok:
                failures.append("%s: %s\n    %s" % (page, line, result.stderr.strip()[-300:]))
print("%d documented commands run, %d synopsis lines skipped" % (ran, skipped))
if failures or ran == 0:
    print("\n".join(failures) or "no command found", file=sys.stderr)
    sys.exit(1)
