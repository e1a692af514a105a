#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Every source file of SplineViz starts with its licence identifier,
``SPDX-License-Identifier: BSD-3-Clause`` (see LICENSE), in the file's own
comment syntax: first line, or right after a ``#!`` line or an ``<?xml ?>``
declaration.

    scripts/spdx.py            # check: list the files without it, exit 1 if any
    scripts/spdx.py --fix      # add the line where it is missing
    scripts/spdx.py --check DIR

Source files: C and C++ (.h .hpp .c .cxx .cpp .txx), GLSL (.glsl), CMake
(CMakeLists.txt, .cmake, .cmake.in), Python (.py), shell (.sh, .sh.in, and
files without an extension that start with ``#!``) and XML (.xml) - outside
build trees, .git, test data and fuzzing corpora.
"""
import os
import sys

IDENTIFIER = "SPDX-License-Identifier: BSD-3-Clause"
SKIP_DIRS = {".git", "__pycache__"}
# Data, not source (relative to the repository root).
SKIP_PATHS = {os.path.join("Testing", "Data"), os.path.join("Testing", "Fuzz", "corpus")}


def comment_style(path):
    """'//', '#', 'xml' or None (not a source file)."""
    name = os.path.basename(path)
    for suffix, style in ((".cmake.in", "#"), (".sh.in", "#")):
        if name.endswith(suffix):
            return style
    ext = os.path.splitext(name)[1]
    if ext in (".h", ".hpp", ".c", ".cxx", ".cpp", ".txx", ".glsl"):
        return "//"
    if name == "CMakeLists.txt" or ext in (".cmake", ".py", ".sh"):
        return "#"
    if ext == ".xml":
        return "xml"
    if ext == "":
        try:
            with open(path, "rb") as f:
                if f.read(2) == b"#!":
                    return "#"
        except OSError:
            pass
    return None


def source_files(root):
    for directory, dirs, files in os.walk(root):
        rel = os.path.relpath(directory, root)
        keep = []
        for d in sorted(dirs):
            sub = os.path.normpath(os.path.join(rel, d))
            if d in SKIP_DIRS or sub in SKIP_PATHS:
                continue
            if os.path.exists(os.path.join(directory, d, "CMakeCache.txt")):
                continue  # a build tree
            keep.append(d)
        dirs[:] = keep
        for name in sorted(files):
            path = os.path.join(directory, name)
            style = comment_style(path)
            if style and not os.path.islink(path):
                yield path, style


def has_identifier(text):
    """The identifier as a comment line of its own among the first three."""
    for line in text.splitlines()[:3]:
        line = line.strip()
        for start, end in (("//", ""), ("#", ""), ("<!--", "-->")):
            if line.startswith(start) and line.endswith(end):
                if line[len(start):len(line) - len(end)].strip() == IDENTIFIER:
                    return True
    return False


def with_identifier(text, style):
    lines = text.splitlines(keepends=True)
    at = 0
    if lines and (lines[0].startswith("#!") or lines[0].startswith("<?xml")):
        at = 1
    line = {"//": "// %s\n", "#": "# %s\n", "xml": "<!-- %s -->\n"}[style] % IDENTIFIER
    return "".join(lines[:at] + [line] + lines[at:])


def main(argv):
    fix = "--fix" in argv
    args = [a for a in argv if not a.startswith("--")]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    missing = []
    count = 0
    for path, style in source_files(root):
        count += 1
        with open(path, encoding="utf-8") as f:
            text = f.read()
        if has_identifier(text):
            continue
        missing.append(os.path.relpath(path, root))
        if fix:
            with open(path, "w", encoding="utf-8") as f:
                f.write(with_identifier(text, style))
    if fix:
        print("added the SPDX line to %d of %d source files" % (len(missing), count))
        return 0
    if missing:
        for path in missing:
            print("ERROR: no '%s' at the top of %s" % (IDENTIFIER, path))
        print("%d of %d source files lack it; scripts/spdx.py --fix adds it" % (len(missing), count))
        return 1
    print("all %d source files carry '%s'" % (count, IDENTIFIER))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
