#!/usr/bin/env python3
"""Fails when a C++ source file is over 700 lines or a function body over 120 (issue 22).

Scans *.cc and *.h under the library, tool, validation and benchmark folders (not tests/).
A function is a `{` at namespace or class scope whose head (the text since the last `;`,
`{` or `}` there) ends in `)`, maybe followed by const, override, noexcept, a trailing
return type or a constructor's initialiser list; lambdas and blocks count in the function
around them. Braces of data (`= {...}`, `x{...}`, enums) are not function bodies. A function
that is a data table may say so with `// size-check: data table` on its first line.
Usage: check_sizes.py [--exclude DIR]...   (prints one line per violation, exits 1)
"""
import argparse
import pathlib
import re
import sys

MAX_FILE_LINES = 700
MAX_FUNCTION_LINES = 120
FOLDERS = ["model", "datasets", "estimation", "report", "apps", "validation", "benchmarks"]
MARKER = "size-check: data table"
# The end of a function's head: `)` then qualifiers or a trailing return type.
FUNCTION_END = re.compile(
    r"\)\s*(?:(?:const|volatile|override|final|noexcept|mutable|&&|&)\s*|->[^;{}=]*)*$")
# A constructor's initialiser list: `) : member(...), member{...}`.
CTOR_INIT = re.compile(r"\)\s*(?:noexcept\s*)?:\s*[\w:<>]+\s*[({]")
NAME = re.compile(r"(operator\s*\(\s*\)|operator[^\w(]+|~?[A-Za-z_][\w:~]*)\s*\(")


def blank(text):
    """Replaces comments, string and char literals and preprocessor lines by spaces,
    keeping newlines, so that only code braces remain."""
    out, i, n = list(text), 0, len(text)
    def wipe(a, b):
        for k in range(a, min(b, n)):
            if out[k] != "\n":
                out[k] = " "
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":  # a directive, with its continuation lines
            j = i
            while j < n and (text[j] != "\n" or text[j - 1] == "\\"):
                j += 1
            wipe(i, j); i = j; continue
        if c == "\n":
            line_start = True; i += 1; continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i); j = n if j < 0 else j
            wipe(i, j); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2); j = n if j < 0 else j + 2
            wipe(i, j); i = j
        elif c == "R" and text.startswith('"', i + 1):  # raw string R"d(...)d"
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            j = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if j < 0 else j + len(m.group(1)) + 2
            wipe(i, j); i = j
        elif c == "'" and re.search(r"(?:^|[^\w.])\d[\w.']*$", text[max(0, i - 40):i]):
            i += 1  # a digit separator (1'000), not a char literal
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            wipe(i, j + 1); i = j + 1
        else:
            i += 1
    return "".join(out)


def functions(path):
    """Yields (line, name, body lines) for each function at namespace or class scope."""
    raw = path.read_text(encoding="utf-8", errors="replace")
    raw_lines, code = raw.split("\n"), blank(raw)
    stack, head_start = [], 0  # stack: 'scope' (namespace/class), 'function' or 'data'
    for i, c in enumerate(code):
        in_body = any(entry[0] != "scope" for entry in stack)
        if c == ";" and not in_body:
            head_start = i + 1
        elif c == "{":
            if in_body:
                stack.append(("block", i)); continue
            head = " ".join(code[head_start:i].split())
            words = re.sub(r"template\s*<.*?>", "", head).split()
            if words and words[0] in ("namespace", "extern", "inline") and "(" not in head:
                kind = "scope"
            elif FUNCTION_END.search(head) or (CTOR_INIT.search(head) and head[-1:] in ")}"):
                kind = "function"
            elif words and words[0] in ("class", "struct", "union") and "=" not in head:
                kind = "scope"
            else:
                kind = "data"  # enum, `= {`, `x{`, and a constructor's `member{` alike
            stack.append((kind, i, head_start))
            if kind == "scope":
                head_start = i + 1
        elif c == "}" and stack:
            top = stack.pop()
            if top[0] == "function":
                start = top[2] + len(code[top[2]:top[1]]) - len(code[top[2]:top[1]].lstrip())
                first = code.count("\n", 0, start)
                open_line, close_line = code.count("\n", 0, top[1]), code.count("\n", 0, i)
                match = NAME.search(" ".join(code[start:top[1]].split()))
                marked = any(MARKER in raw_lines[k] for k in range(first, open_line + 1))
                if not marked:
                    yield first + 1, match.group(1) if match else "?", close_line - open_line + 1
            if top[0] in ("scope", "function") and not any(entry[0] != "scope" for entry in stack):
                head_start = i + 1  # a data brace keeps its head open until its `;`


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exclude", action="append", default=[], help="a folder to skip")
    args = parser.parse_args()
    root = pathlib.Path(__file__).resolve().parent.parent
    excluded = {e.strip("/") for e in args.exclude}
    files = sorted(p for folder in FOLDERS if folder not in excluded
                   for p in (root / folder).rglob("*") if p.suffix in (".cc", ".h"))
    violations, largest_file, largest_function = [], (0, ""), (0, "")
    for path in files:
        rel = path.relative_to(root).as_posix()
        lines = path.read_text(encoding="utf-8", errors="replace").count("\n")
        largest_file = max(largest_file, (lines, rel))
        if lines > MAX_FILE_LINES:
            violations.append(f"{rel}:1: file has {lines} lines (limit {MAX_FILE_LINES})")
        for line, name, size in functions(path):
            largest_function = max(largest_function, (size, f"{rel}:{line} {name}"))
            if size > MAX_FUNCTION_LINES:
                violations.append(f"{rel}:{line}: function {name} has {size} lines "
                                  f"(limit {MAX_FUNCTION_LINES})")
    for v in violations:
        print(v)
    if violations:
        return 1
    print(f"check_sizes: {len(files)} files within {MAX_FILE_LINES} lines and functions within "
          f"{MAX_FUNCTION_LINES}; largest file {largest_file[1]} ({largest_file[0]}), "
          f"largest function {largest_function[1]} ({largest_function[0]})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
