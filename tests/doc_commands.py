#!/usr/bin/python3
"""The docs stay true: run the shell commands that README.md and docs/guides/*.md show.

For each page, in order, every ```sh block's command lines run with bash in a scratch
directory of that page (later lines use files earlier ones wrote), where `build` links to the
build tree and `datasets`, `examples`, `scripts`, `python`, `docs` to the source tree, so
`./build/ringid ...` and `datasets/...` resolve and what the commands write lands in the
scratch directory. Each command must exit 0.

Markers, HTML comments on the lines directly above a ```sh fence (several may stack):

  <!-- not run: REASON -->        the block is not run; the test prints it and REASON
  <!-- not run 2,4-5: REASON -->  only the block's commands 2, 4 and 5 (counted from 1; a
                                  command is a line with its continuations, comments and
                                  blank lines not counted)
  <!-- exits: N -->              the block's commands exit with status N, not 0

The flags of a `./build/ringid COMMAND` line that is not run are still checked: each must be
one that `ringid COMMAND --help` lists (with `|` alternatives among the ones it lists), so a
synopsis cannot drift either.

Quoted output: a plain ``` (or ```text) block that follows a ```sh block, directly or after a
lead-in that says so (a short paragraph ending in ':' that says what the command prints, says
or gives), holds lines the block's commands printed (stdout and stderr). Each quoted line but
`...` must match a printed line, whitespace collapsed: the text exactly, `...` inside a line
anything, and numbers within 2 % (or one unit of the quoted number's last decimal); a number
before `ms`, `s` or `model evaluations` (a timing, a count of evaluations) matches any number.
Every line not found is reported.

usage: doc_commands.py --source DIR --build DIR [--keep] [PAGE ...]
"""

import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

LINKED_FROM_SOURCE = ["datasets", "examples", "scripts", "python", "docs"]
COMMAND_TIMEOUT_S = 150

FENCE = re.compile(r"^(\s*)```\s*([\w+-]*)\s*$")
MARKER = re.compile(r"^\s*<!--\s*(.*?)\s*-->\s*$")
NOT_RUN = re.compile(r"^not run(?:\s+([\d,\s-]+?))?\s*:\s*(.+)$")
EXITS = re.compile(r"^exits:\s*(\d+)$")
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
NUMBER_RE = re.compile(NUMBER)
LOOSE_AFTER = re.compile(r"\s*(?:ms\b|s\b|model evaluations\b)")
ELLIPSIS = re.compile(r"\.\.\.|…")
LEAD_IN_WORDS = re.compile(r"\b(print|prints|printed|says?|gives?|output)\b", re.I)


class Block:
    def __init__(self, lang, lines, line_no, markers, lead_in):
        self.lang = lang          # the fence's info string, lower case ('' for plain)
        self.lines = lines        # the lines between the fences
        self.line_no = line_no    # the opening fence's line, from 1
        self.markers = markers    # the HTML comments directly above the fence
        self.lead_in = lead_in    # the prose since the previous block (no heading between)


def read_blocks(path):
    """The fenced blocks of a Markdown page, in order."""
    with open(path, encoding="utf-8") as f:
        text = f.read().splitlines()
    blocks, i, prose = [], 0, []
    while i < len(text):
        m = FENCE.match(text[i])
        if not m:
            if text[i].lstrip().startswith("#"):
                prose = [None]  # a heading: what follows is not a lead-in of the last block
            else:
                prose.append(text[i])
            i += 1
            continue
        markers, j = [], i - 1
        while j >= 0 and MARKER.match(text[j]):
            markers.insert(0, MARKER.match(text[j]).group(1))
            j -= 1
        start, body, i = i, [], i + 1
        while i < len(text) and not re.match(r"^\s*```\s*$", text[i]):
            body.append(text[i])
            i += 1
        blocks.append(Block(m.group(2).lower(), body, start + 1, markers, prose))
        prose = []
        i += 1
    return blocks


def commands_of(lines):
    """The block's commands: continuation lines joined, comments and blank lines left out."""
    commands, current = [], ""
    for line in lines:
        if not current and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if line.rstrip().endswith("\\"):
            current += line.rstrip()[:-1] + " "
            continue
        current += line
        commands.append(current.strip())
        current = ""
    if current:
        commands.append(current.strip())
    return commands


def selected(spec, count):
    """The commands (from 1) a `not run 2,4-5` selector names; all where it names none."""
    if not spec:
        return set(range(1, count + 1))
    chosen = set()
    for part in spec.replace(" ", "").split(","):
        lo, _, hi = part.partition("-")
        chosen.update(range(int(lo), int(hi or lo) + 1))
    return chosen


def plan(block):
    """(command, reason it is not run or None, expected status) for each command of a block."""
    commands = commands_of(block.lines)
    skip, status = {}, 0
    for marker in block.markers:
        m = NOT_RUN.match(marker)
        if m:
            numbers = selected(m.group(1), len(commands))
            if not numbers <= set(range(1, len(commands) + 1)):
                raise ValueError("line %d: '%s' names a command the block does not have"
                                 % (block.line_no, marker))
            for n in numbers:
                skip[n] = m.group(2)
        m = EXITS.match(marker)
        if m:
            status = int(m.group(1))
    return [(c, skip.get(n), status) for n, c in enumerate(commands, 1)]


def collapse(text):
    return " ".join(text.split())


def quoted_pattern(line):
    """A regex for a quoted line and, per number group, (quoted value, unit, loose)."""
    pattern, numbers, pos = "", [], 0
    pieces = ELLIPSIS.split(line)
    for k, piece in enumerate(pieces):
        if k:
            pattern += ".*?"
        pos = 0
        for m in NUMBER_RE.finditer(piece):
            pattern += re.escape(piece[pos:m.start()]) + "(" + NUMBER + ")"
            text = m.group(0)
            digits = text.lower().split("e")[0]
            exponent = int(text.lower().split("e")[1]) if "e" in text.lower() else 0
            decimals = len(digits.split(".")[1]) if "." in digits else 0
            # one unit of the last digit, for a number given with decimals or an exponent;
            # an integer (a count, a rank) must match within the 2 % alone
            unit = 10.0 ** (exponent - decimals) if decimals or exponent else 0.0
            loose = bool(LOOSE_AFTER.match(piece, m.end()))
            numbers.append((float(text), unit, loose))
            pos = m.end()
        pattern += re.escape(piece[pos:])
    return re.compile(pattern), numbers


def line_matches(quoted, printed_lines):
    pattern, numbers = quoted_pattern(quoted)
    for printed in printed_lines:
        m = pattern.fullmatch(printed)
        if not m:
            continue
        ok = True
        for (want, unit, loose), got_text in zip(numbers, m.groups()):
            got = float(got_text)
            if loose or want == got:
                continue
            if abs(want - got) > max(0.02 * max(abs(want), abs(got)), unit * (1 + 1e-9)):
                ok = False
                break
        if ok:
            return True
    return False


def check_output(quoted_lines, printed):
    """The quoted lines that no printed line matches."""
    printed_lines = [collapse(l) for l in printed.splitlines() if l.strip()]
    missing = []
    for line in quoted_lines:
        q = collapse(line)
        if not q or ELLIPSIS.fullmatch(q):
            continue
        if not line_matches(q, printed_lines):
            missing.append(line)
    return missing


def is_quoted_output(block, previous):
    """A plain block that quotes what the previous (sh) block's commands print."""
    if block.lang not in ("", "text") or previous is None or previous.lang != "sh":
        return False
    if None in block.lead_in:
        return False
    prose = " ".join(l.strip() for l in block.lead_in if l.strip())
    return not prose or (prose.endswith(":") and bool(LEAD_IN_WORDS.search(prose)))


class Flags:
    """The flags `ringid COMMAND --help` lists, read once per command."""

    def __init__(self, ringid, cwd):
        self.ringid, self.cwd, self.cache = ringid, cwd, {}

    def of(self, command):
        if command not in self.cache:
            r = subprocess.run([self.ringid, command, "--help"], cwd=self.cwd, text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=30)
            flags = {}
            for m in re.finditer(r"^\s+--(\w+)(\S*)", r.stdout, re.M):
                values = m.group(2)
                flags[m.group(1)] = (set(values[1:].split("|"))
                                     if values.startswith("=") and "|" in values else None)
            self.cache[command] = flags if r.returncode == 0 else None
        return self.cache[command]

    def problems(self, line):
        """What is wrong with the flags of a `./build/ringid COMMAND ...` line not run."""
        words = line.split()
        if len(words) < 2 or not words[0].endswith("build/ringid") or words[1].startswith("-"):
            return []
        known = self.of(words[1])
        if known is None:
            return ["ringid %s --help fails: no such command?" % words[1]]
        out = []
        for m in re.finditer(r"(?<![\w-])--(\w+)(?:=([^\s\]]*))?", line):
            name, value = m.group(1), m.group(2)
            if name == "help":
                continue
            if name not in known and not (name.startswith("no") and name[2:] in known):
                out.append("--%s is not a flag of ringid %s" % (name, words[1]))
            elif value and "|" in value and known.get(name):
                bad = [v for v in value.split("|") if v not in known[name]]
                if bad:
                    out.append("--%s: %s not among its values" % (name, ", ".join(bad)))
        return out


def scratch_dir(source, build, root):
    d = tempfile.mkdtemp(prefix="page-", dir=root)
    os.symlink(os.path.abspath(build), os.path.join(d, "build"))
    for name in LINKED_FROM_SOURCE:
        target = os.path.join(source, name)
        if os.path.exists(target):
            os.symlink(os.path.abspath(target), os.path.join(d, name))
    return d


def run_page(page, args, flags, root, totals):
    rel = os.path.relpath(page, args.source)
    blocks = read_blocks(page)
    if not any(b.lang == "sh" for b in blocks):
        return
    print("== %s" % rel, flush=True)
    cwd = scratch_dir(args.source, args.build, root)
    outputs = {}  # id of a sh block -> what its commands printed, None where any was skipped
    previous = None
    for block in blocks:
        if block.lang == "sh":
            printed, complete = "", True
            for command, reason, status in plan(block):
                shown = command if len(command) <= 110 else command[:107] + "..."
                if reason:
                    totals["skipped"].append((rel, block.line_no, command, reason))
                    print("  skip  %s\n        not run: %s" % (shown, reason), flush=True)
                    complete = False
                    for problem in flags.problems(command):
                        totals["failures"].append("%s:%d: %s: %s"
                                                  % (rel, block.line_no, shown, problem))
                        print("  FAIL  " + problem, flush=True)
                    continue
                start = time.monotonic()
                try:
                    r = subprocess.run(["bash", "-c", command], cwd=cwd, text=True,
                                       stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                       stderr=subprocess.STDOUT, timeout=COMMAND_TIMEOUT_S,
                                       errors="replace")
                    code, out = r.returncode, r.stdout
                except subprocess.TimeoutExpired as e:
                    code = "timeout after %d s" % COMMAND_TIMEOUT_S
                    out = e.stdout if isinstance(e.stdout, str) else ""
                seconds = time.monotonic() - start
                totals["ran"] += 1
                ok = code == status
                print("  %-4s  %s  (%.1f s%s)" % ("ok" if ok else "FAIL", shown, seconds,
                                                "" if ok else ", exit %s, expected %d"
                                                % (code, status)), flush=True)
                if not ok:
                    tail = "\n".join(out.splitlines()[-15:])
                    print("        " + tail.replace("\n", "\n        "), flush=True)
                    totals["failures"].append("%s:%d: %s: exit %s, expected %d"
                                              % (rel, block.line_no, shown, code, status))
                printed += out
            outputs[id(block)] = printed if complete else None
        elif is_quoted_output(block, previous):
            printed = outputs.get(id(previous))
            if printed is None:
                print("  (the output quoted at line %d is not checked: its commands are not "
                      "all run)" % block.line_no, flush=True)
            else:
                missing = check_output(block.lines, printed)
                totals["quotes"] += 1
                for line in missing:
                    totals["failures"].append("%s:%d: quoted output not printed: %s"
                                              % (rel, block.line_no, line.strip()))
                print("  %-4s  the output quoted at line %d (%d lines not found)"
                      % ("ok" if not missing else "FAIL", block.line_no, len(missing)),
                      flush=True)
                for line in missing:
                    print("        not printed: " + line.strip(), flush=True)
        previous = block


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the source tree")
    parser.add_argument("--build", required=True, help="the build tree (holds ringid)")
    parser.add_argument("--keep", action="store_true", help="keep the scratch directories")
    parser.add_argument("pages", nargs="*", help="pages to run (default: README.md and "
                        "docs/guides/*.md)")
    args = parser.parse_args()
    args.source, args.build = os.path.abspath(args.source), os.path.abspath(args.build)
    ringid = os.path.join(args.build, "ringid")
    if not os.access(ringid, os.X_OK):
        print("doc_commands: no %s: build the tool first" % ringid)
        return 1
    pages = ([os.path.abspath(p) for p in args.pages] if args.pages else
             [os.path.join(args.source, "README.md")] +
             sorted(os.path.join(args.source, "docs", "guides", p)
                    for p in os.listdir(os.path.join(args.source, "docs", "guides"))
                    if p.endswith(".md")))
    root = tempfile.mkdtemp(prefix="ringid-doc-commands-")
    totals = {"ran": 0, "skipped": [], "quotes": 0, "failures": []}
    start = time.monotonic()
    try:
        flags = Flags(ringid, root)
        for page in pages:
            run_page(page, args, flags, root, totals)
    finally:
        if args.keep:
            print("scratch directories kept in " + root)
        else:
            shutil.rmtree(root, ignore_errors=True)
    print("\n%d commands run, %d not run, %d quoted outputs checked, %.0f s"
          % (totals["ran"], len(totals["skipped"]), totals["quotes"],
             time.monotonic() - start))
    if totals["failures"]:
        print("%d failures:" % len(totals["failures"]))
        for f in totals["failures"]:
            print("  " + f)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
