"""Lists the functions longer than 80 lines in core/, io/, cli/ and plugin/; exits 1 if any.

A function is a definition whose opening brace ends a line at namespace level (clang-formatted
code), up to its matching closing brace; lambdas and classes inside it count towards it. Bodies of
classes and initialisers of tables at namespace level are not functions.
Usage: python3 scripts/check_function_length.py [REPO_DIR]
"""
import os
import re
import sys

LIMIT = 80
repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
NOT_FUNCTIONS = re.compile(r"^\s*(namespace|class|struct|enum|union|extern)\b|=\s*\{?$|^\s*(const|constexpr|static|inline)?\s*[\w:<>, ]+\s+k\w+\[?\]?\s*=")


def strip(line):
    """The line without string and character literals and comments (for counting braces)."""
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])*'", "''", line)
    return line.split("//")[0]


def long_functions(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    found, depth, start, head, in_raw = [], 0, None, "", False
    for number, raw in enumerate(lines, 1):
        if in_raw:
            in_raw = ')"' not in raw
            continue
        if 'R"(' in raw and ')"' not in raw.split('R"(', 1)[1]:
            in_raw = True
        line = strip(raw)
        opens, closes = line.count("{"), line.count("}")
        if start is None and opens > closes and line.rstrip().endswith("{"):
            statement = (head + " " + line).strip()
            if "(" in statement and not NOT_FUNCTIONS.search(statement):
                start, base = number, depth
        depth += opens - closes
        head = line if not line.rstrip().endswith((";", "{", "}")) else ""
        if start is not None and depth <= base:
            if number - start + 1 > LIMIT:
                found.append((start, number - start + 1, lines[start - 1].strip()))
            start = None
    return found


bad = 0
for folder in ("core", "io", "cli", "plugin"):
    for root, _, files in os.walk(os.path.join(repo, folder)):
        for name in sorted(files):
            if not name.endswith((".cpp", ".h")):
                continue
            path = os.path.join(root, name)
            for line, length, text in long_functions(path):
                bad += 1
                print(f"{os.path.relpath(path, repo)}:{line}: {length} lines: {text[:70]}")
print(f"functions over {LIMIT} lines: {bad}")
sys.exit(1 if bad else 0)
