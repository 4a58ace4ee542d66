#!/usr/bin/env python3
"""Fails when a C++ source is over 700 lines or a function body over 120 (issue 22).

Scans *.cc and *.h under the folders below (not tests/). A function is a `{` at namespace
or class scope whose head (the code since the last `;`, `{` or `}` there) ends in `)`,
maybe with const/override/noexcept, a trailing return type or a constructor's initialiser
list; lambdas and blocks count in the function around them. Data (`= {...}`, `x{...}`,
enums) is no function body. A function that is itself a data table may say so with
`// size-check: data table` on its first line. Its size is the lines from `{` to `}`.
Usage: check_sizes.py [--exclude FOLDER]...  One line per violation, then exit 1.
"""
import argparse
import bisect
import pathlib
import re
import sys

MAX_FILE_LINES = 700
MAX_FUNCTION_LINES = 120
FOLDERS = ["model", "datasets", "estimation", "report", "operations", "apps", "validation",
           "benchmarks", "python"]
MARKER = "size-check: data table"
SCOPE = re.compile(r"^(inline\s+)?namespace\b|^extern$")  # `extern "C"`: its string is blanked
FUNCTION_END = re.compile(
    r"\)\s*(?:(?:const|volatile|override|final|noexcept|mutable|&&|&)\s*|->[^;{}=]*)*$")
CTOR_INIT = re.compile(r"\)\s*(?:noexcept\s*)?:\s*[\w:<>]+\s*[({]")  # `) : member(` or `{`
CLASS = re.compile(r"\b(class|struct|union)\b[^()=;]*$")
NAME = re.compile(r"(\w+)\s*=\s*\[|(operator\s*\(\s*\)|operator[^\w(]+|~?[A-Za-z_][\w:~]*)\s*\(")
LITERAL = re.compile(r"//[^\n]*|/\*.*?\*/"  # comments, raw strings, strings, chars
                     r"""|R"([^(\s]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*'""", re.S)
DIGIT_SEPARATOR = re.compile(r"(?<=[0-9a-fA-F])'(?=[0-9a-fA-F])")  # 1'000: no char literal
DIRECTIVE = re.compile(r"^[ \t]*#(?:[^\n]*\\\n)*[^\n]*", re.M)


def blank(text):
    """The code with comments, literals and preprocessor lines as spaces (newlines kept)."""
    spaces = lambda m: re.sub(r"[^\n]", " ", m.group(0))
    text = DIGIT_SEPARATOR.sub(" ", text)
    text = LITERAL.sub(spaces, text)  # one pass: a `//` inside a string is no comment
    return DIRECTIVE.sub(spaces, text)


def kind(head):
    """What a `{` at namespace or class scope opens, from the code before it."""
    if SCOPE.search(head):
        return "scope"
    if FUNCTION_END.search(head) or (CTOR_INIT.search(head) and head[-1:] in ")}"):
        return "function"
    if CLASS.search(head) and not re.search(r"\benum\b", head):
        return "scope"
    return "data"  # enum, `= {`, `x{`, a constructor's `member{`


def functions(text):
    """Yields (first line, name, body lines) of each function at namespace or class scope."""
    code, raw_lines = blank(text), text.split("\n")
    newlines = [i for i, c in enumerate(code) if c == "\n"]
    line = lambda pos: bisect.bisect_left(newlines, pos)  # 0-based line of a position
    stack, head_start, depth_in_body = [], 0, 0  # stack: (kind, position, head start)
    for i, c in enumerate(code):
        if c == ";" and not depth_in_body:
            head_start = i + 1
        elif c == "{":
            k = "block" if depth_in_body else kind(" ".join(code[head_start:i].split()))
            stack.append((k, i, head_start))
            depth_in_body += k != "scope"
            if k == "scope":
                head_start = i + 1
        elif c == "}" and stack:
            k, open_at, head = stack.pop()
            depth_in_body -= k != "scope"
            if k == "function":
                start = head + len(code[head:open_at]) - len(code[head:open_at].lstrip())
                first, last = line(start), line(open_at)
                if not any(MARKER in raw_lines[n] for n in range(first, last + 1)):
                    name = NAME.search(" ".join(code[start:open_at].split()))
                    name = (name.group(2) or name.group(1)) if name else "?"  # `x = [`: a lambda
                    yield first + 1, name, line(i) - last + 1
            if k != "block" and not depth_in_body and k != "data":
                head_start = i + 1  # a data brace leaves its head open until its `;`


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exclude", action="append", default=[], help="a folder not to scan")
    args = parser.parse_args()
    root = pathlib.Path(__file__).resolve().parent.parent
    excluded = {e.strip("/") for e in args.exclude}
    files = sorted(p for folder in FOLDERS if folder not in excluded
                   for p in (root / folder).rglob("*") if p.suffix in (".cc", ".h"))
    violations, largest_file, largest_function = [], (0, ""), (0, "")
    for path in files:
        rel, text = path.relative_to(root).as_posix(), path.read_text(errors="replace")
        lines = text.count("\n")
        largest_file = max(largest_file, (lines, rel))
        if lines > MAX_FILE_LINES:
            violations.append(f"{rel}:1: file has {lines} lines (limit {MAX_FILE_LINES})")
        for line, name, size in functions(text):
            largest_function = max(largest_function, (size, f"{rel}:{line} {name}"))
            if size > MAX_FUNCTION_LINES:
                violations.append(f"{rel}:{line}: function {name} has {size} lines "
                                  f"(limit {MAX_FUNCTION_LINES})")
    print("\n".join(violations) if violations else
          f"check_sizes: {len(files)} files, none over {MAX_FILE_LINES} lines, no function "
          f"over {MAX_FUNCTION_LINES}; largest file {largest_file[1]} ({largest_file[0]}), "
          f"largest function {largest_function[1]} ({largest_function[0]})")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
