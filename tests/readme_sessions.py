#!/usr/bin/env python3
"""The README's shell sessions are tests: every `$ cueball ...` line of a
``` block of the README runs, from a scratch copy of docs/, with the built
binary first on PATH, and must print what the README shows below it.

A printed line matches exactly but for runs of spaces (a table's columns
widen with its widest value) and for wall-clock figures, which are masked
(`seconds ... wall-clock time`, `shots_per_second`, `seconds_per_shot`, the
seconds of a plan's `cost` line). `...` within a line stands for any text,
and a line of its own `...` for any lines. `head`, `cut` and `cat` of a file
the session wrote run too, and `echo $?` prints the status of the command
before it. A command that reads a file the session does not have (a user's
own: `match.json`, `overlapping.json`, `shots/*.csv`) is skipped, with the
`echo $?` after it; so are the Python sessions, which
python/tests/test_readme.py runs.

usage: readme_sessions.py README.md CUEBALL_BINARY
Exit status 0 when every session prints what the README shows, 1 naming
each line that does not, 2 for bad usage.
"""

import glob
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

BLOCK = re.compile(r"^```[a-z]*\n(.*?)^```", re.M | re.S)
RUNS = ("cueball", "head", "cut", "cat")
# Flags whose value is a file the command writes, not one it reads.
OUTPUT_FLAGS = {"-o", "--outcomes", "--record", "--scenario-out", "--html", "--out"}
WALL_CLOCK = re.compile(r"wall-clock|shots_per_second|seconds_per_shot")
COST_SECONDS = re.compile(r"(cost\b.*?)[0-9]+(?:\.[0-9]+)? s\b")
NUMBER = re.compile(r"[0-9][0-9.e+-]*")


def normalized(line: str) -> str:
    """The line as compared: runs of spaces as one, wall-clock figures masked."""
    line = " ".join(line.split())
    if WALL_CLOCK.search(line):
        return NUMBER.sub("#", line)
    return COST_SECONDS.sub(r"\1# s", line)


def matches(expected: list[str], got: list[str]) -> bool:
    """Whether `got` fits `expected`, whose `...` lines stand for any lines."""
    patterns = [None if e.strip() == "..." else re.compile(".*".join(map(re.escape, normalized(e).split("..."))))
                for e in expected]
    # reach[j]: the first j lines of `got` can be matched by the patterns so far
    reach = [True] + [False] * len(got)
    for p in patterns:
        nxt = [False] * (len(got) + 1)
        for j in range(len(got) + 1):
            if not reach[j]:
                continue
            if p is None:
                for k in range(j, len(got) + 1):
                    nxt[k] = True
                break
            if j < len(got) and p.fullmatch(normalized(got[j])):
                nxt[j + 1] = True
        reach = nxt
    return reach[len(got)]


def reads_a_missing_file(command: str, cwd: pathlib.Path) -> bool:
    words = shlex.split(command)
    for i, w in enumerate(words):
        if i > 0 and (words[i - 1] in OUTPUT_FLAGS or words[i - 1].startswith(">")):
            continue
        if w.startswith(">") or not re.search(r"\.(json|csv)$", w):
            continue
        if not glob.glob(str(cwd / w)):
            return True
    return False


def sessions(readme: pathlib.Path) -> list[tuple[int, str, list[str]]]:
    """(line number, command, the lines the README prints for it), in order."""
    text = readme.read_text(encoding="utf-8")
    out = []
    for block in BLOCK.finditer(text):
        first = text.count("\n", 0, block.start()) + 2
        lines = block.group(1).rstrip("\n").split("\n")
        starts = [i for i, line in enumerate(lines) if line.startswith("$ ")]
        for n, i in enumerate(starts):
            end = starts[n + 1] if n + 1 < len(starts) else len(lines)
            command = re.split(r"\s{2,}#", lines[i][2:])[0].strip()
            out.append((first + i, command, lines[i + 1:end]))
    return out


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__.strip().split("\n\n")[-2], file=sys.stderr)
        return 2
    readme = pathlib.Path(sys.argv[1]).resolve()
    binary = pathlib.Path(sys.argv[2]).resolve()
    failures = ran = skipped = 0
    with tempfile.TemporaryDirectory(prefix="cueball-readme-") as scratch:
        cwd = pathlib.Path(scratch) / "work"
        shutil.copytree(readme.parent / "docs", cwd / "docs")
        bin_dir = pathlib.Path(scratch) / "bin"  # the sessions call the binary by name
        bin_dir.mkdir()
        (bin_dir / "cueball").symlink_to(binary)
        env = dict(os.environ, PATH=f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}")
        status = None  # of the command before, None where it did not run
        for line_number, command, expected in sessions(readme):
            if command == "echo $?":
                if status is None:
                    continue
                got = [str(status)]
            elif command.split()[0] not in RUNS:
                status = None
                continue
            elif reads_a_missing_file(command, cwd):
                skipped += 1
                status = None
                continue
            else:
                run = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True, timeout=600)
                status = run.returncode
                got = run.stdout.rstrip("\n").split("\n") if run.stdout.strip() else []
            ran += 1
            if not matches(expected, got):
                failures += 1
                print(f"{readme.name}:{line_number}: `{command}` printed:\n  " + "\n  ".join(got) +
                      "\nwhere the README shows:\n  " + "\n  ".join(expected), file=sys.stderr)
    print(f"{ran} commands run, {skipped} skipped (a user's own files), {failures} not as the README shows")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
