#!/usr/bin/env python3
"""The code's structure as doc/architecture.md states it, checked.

1. Folder order: every `#include <cdea/F/...>` of a file in folder G names a
   folder F that comes no later than G in the order of doc/architecture.md
   ("Folder order"). python/ stands above every folder.
2. No include cycle between files (a header and its source count as one file).
3. No function in source/, include/ or python/ longer than 80 lines, from the
   first line of its declaration to its closing brace.
4. No file there longer than 600 lines (a file that grows past it holds more
   than one concern).
5. No friend declaration in fe/: what is built on the model's state sees it
   through the read-only ModelAccess (include/cdea/fe/model_access.h), not
   its inside.
6. Unit factors only in the table of quantities (include/cdea/base/units.h):
   a power of ten of a unit (1e3, 1e-3, 1e6, 1e-6, 1e9, 1e-9, 1e12, 1e-12,
   1000., 0.001) that multiplies or divides a value from the right (x times 1e3,
   x over 1e3) is a unit factor, and none may stand anywhere else in source/,
   include/ and python/ (MAX_UNIT_FACTORS, the number allowed outside the
   table, is 0). A relative tolerance or bound is written before its scale
   (1e-9 * scale) and is not one.
7. The rows of the table (Quantity objects) are defined only in the table's
   files (model/quantity.h, model/quantities_*.h, model/output_fields.*):
   a study names a row, never makes one.

Usage: structure_check.py [SOURCE_DIR] [--list-functions N]
Prints every violation with its file and line; exits 1 if there is one.
"""
import os
import re
import sys

MAX_FUNCTION_LINES = 80
MAX_FILE_LINES = 600
MAX_UNIT_FACTORS = 0
UNIT_TABLE = "include/cdea/base/units.h"
QUANTITY_TABLE = re.compile(r"^(include/cdea|source)/model/(quantity\.h|quantities_\w+\.h|"
                            r"output_fields\.(h|cc))$")


def folder_order(root):
    """The folders in the order of the line after '## Folder order' that joins
    them with '->', read from doc/architecture.md."""
    text = open(os.path.join(root, "doc", "architecture.md"), encoding="utf-8").read()
    section = text.split("## Folder order", 1)
    if len(section) != 2:
        sys.exit("structure_check: doc/architecture.md has no '## Folder order' section")
    for line in section[1].splitlines():
        if "->" in line:
            return [name.strip() for name in line.split("->")]
    sys.exit("structure_check: no 'a -> b -> ...' line under '## Folder order'")


def code_files(root):
    """(path relative to root, folder) of every C++ file under include/cdea,
    source and python."""
    files = []
    for top in ("include/cdea", "source", "python"):
        base = os.path.join(root, top)
        for directory, _, names in os.walk(base):
            for name in sorted(names):
                if not name.endswith((".h", ".cc")):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root)
                inside = os.path.relpath(directory, base)
                if top == "python":
                    folder = "python"
                else:
                    folder = inside.split(os.sep)[0] if inside != "." else ""
                files.append((path, folder))
    return files


INCLUDE = re.compile(r'^\s*#\s*include\s*<cdea/([^>]+)>')


def includes(root, path):
    """(line number, included path under include/cdea) of a file."""
    found = []
    with open(os.path.join(root, path), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m:
                found.append((number, m.group(1)))
    return found


def unit_of(path):
    """A header and its source as one node: 'folder/name'."""
    stem = os.path.splitext(path)[0]
    for prefix in ("include/cdea/", "source/"):
        if stem.startswith(prefix):
            return stem[len(prefix):]
    return stem


def check_order_and_cycles(root, order):
    problems = []
    rank = {name: i for i, name in enumerate(order)}
    rank["python"] = len(order)
    edges = {}
    for path, folder in code_files(root):
        if folder not in rank:
            problems.append(f"{path}: folder '{folder or '(top)'}' is not in the folder order "
                            f"of doc/architecture.md ({' -> '.join(order)})")
            continue
        node = unit_of(path)
        for number, target in includes(root, path):
            target_folder = target.split("/")[0] if "/" in target else ""
            if target_folder not in rank:
                problems.append(f"{path}:{number}: includes <cdea/{target}>, whose folder is not "
                                f"in the folder order")
                continue
            if rank[target_folder] > rank[folder]:
                problems.append(f"{path}:{number}: includes <cdea/{target}> from folder "
                                f"'{target_folder}', above '{folder}' in the folder order")
            target_node = os.path.splitext(target)[0]
            if target_node != node:
                edges.setdefault(node, set()).add(target_node)
    for cycle in cycles(edges):
        problems.append("include cycle: " + " -> ".join(cycle + [cycle[0]]))
    return problems


def cycles(edges):
    """The strongly connected components with more than one node (Tarjan)."""
    index, low, stack, on_stack, result = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                result.append(sorted(component))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return result


def strip_code(text):
    """@p text with comments, string and character literals blanked (line
    breaks kept), so that braces and parentheses are the code's own."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if m:
                end = text.find(")" + m.group(1) + '"', i)
                end = n if end < 0 else end + len(m.group(1)) + 2
                out.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
                i = end
            else:
                out.append(c)
                i += 1
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


CONTROL = re.compile(r'\b(if|for|while|switch|catch|do|else|try|return)\s*$')
SCOPE = re.compile(r'\b(namespace|class|struct|union|enum)\b')
SIGNATURE_END = re.compile(
    r'\)\s*(const|override|final|noexcept(\s*\([^)]*\))?|mutable|volatile|&|&&|\s)*'
    r'(->\s*[\w:<>,\s\*&]+)?\s*$')


def functions(text):
    """(name, first line, last line) of every function body at namespace or
    class scope in C++ @p text."""
    code = strip_code(text)
    result = []
    scopes = []  # 'scope', 'function' or 'other' for every open brace
    last_end = 0  # just after the last ';', '{' or '}' outside a function
    paren = 0
    function_start = None
    for i, c in enumerate(code):
        if c == "(":
            paren += 1
        elif c == ")":
            paren -= 1
        if paren > 0:
            continue
        in_function = "function" in scopes
        if c == "{":
            if in_function:
                scopes.append("other")
                continue
            head = code[last_end:i]
            kind = classify(head)
            scopes.append(kind)
            if kind == "function":
                start = last_end + len(head) - len(head.lstrip())
                function_start = (start, name_of(head))
            last_end = i + 1
        elif c == "}":
            kind = scopes.pop() if scopes else "other"
            if kind == "function" and function_start:
                first = code.count("\n", 0, function_start[0]) + 1
                last = code.count("\n", 0, i) + 1
                result.append((function_start[1], first, last))
                function_start = None
            if "function" not in scopes:
                last_end = i + 1
        elif c == ";" and not in_function:
            last_end = i + 1
    return result


def classify(head):
    """What the brace after @p head (the text since the last statement) opens."""
    # Preprocessor lines (includes before the first function) are not part
    # of the declaration.
    lines = [line for line in head.split("\n") if not line.lstrip().startswith("#")]
    h = " ".join(" ".join(lines).split())
    if not h or h.endswith(("=", ",", "return")):
        return "other"
    # Access specifiers before a declaration.
    h = re.sub(r'^((public|private|protected)\s*:\s*)+', '', h)
    if re.search(r'\)\s*:', h) and "(" in h:
        # A constructor with its initializer list: name(...) : a(x), b{y}
        pass
    elif SCOPE.search(h) and "(" not in h.split(SCOPE.search(h).group(0))[0]:
        if not re.search(r'\)\s*$', h):
            return "scope"
    if h.startswith('extern "') or h.startswith("extern"):
        return "scope"
    if CONTROL.search(h.split("(")[0]):
        return "other"
    if SIGNATURE_END.search(h) or re.search(r'\)\s*:\s*[\w:]+\s*[({]', h):
        return "function"
    return "other"


def name_of(head):
    h = " ".join(head.split())
    m = re.search(r'([~\w:]+|operator\s*[^\s(]+)\s*\(', h)
    return m.group(1) if m else h[:40]


def check_function_lengths(root, listing=0):
    problems, all_functions = [], []
    for path, _ in code_files(root):
        text = open(os.path.join(root, path), encoding="utf-8").read()
        n_lines = text.count("\n")
        if n_lines > MAX_FILE_LINES:
            problems.append(f"{path}: {n_lines} lines (at most {MAX_FILE_LINES} in a file)")
        for name, first, last in functions(text):
            lines = last - first + 1
            all_functions.append((lines, f"{path}:{first}: {name}"))
            if lines > MAX_FUNCTION_LINES:
                problems.append(f"{path}:{first}: function {name} has {lines} lines "
                                f"(at most {MAX_FUNCTION_LINES})")
    if listing:
        for lines, where in sorted(all_functions, reverse=True)[:listing]:
            print(f"{lines:5d}  {where}")
    return problems


FRIEND = re.compile(r'\bfriend\b')


def check_friends(root):
    problems = []
    for path, folder in code_files(root):
        if folder != "fe":
            continue
        code = strip_code(open(os.path.join(root, path), encoding="utf-8").read())
        for number, line in enumerate(code.split("\n"), 1):
            if FRIEND.search(line):
                problems.append(f"{path}:{number}: a friend declaration in fe/ (use the "
                                f"read-only ModelAccess, include/cdea/fe/model_access.h)")
    return problems


UNIT_LITERAL = r"(?:1e-?(?:3|6|9|12)|1000\.0*|0\.001)"
UNIT_FACTOR = re.compile(r"[*/]\s*(" + UNIT_LITERAL + r")(?![\w.])")
QUANTITY_DEFINITION = re.compile(r"\bQuantity\s+\w+\s*[{=(]")


def check_unit_factors(root):
    """Unit factors and rows of the table outside the table (rules 6 and 7)."""
    problems, factors = [], []
    for path, _ in code_files(root):
        code = strip_code(open(os.path.join(root, path), encoding="utf-8").read())
        for number, line in enumerate(code.split("\n"), 1):
            if path != UNIT_TABLE:
                factors += [f"{path}:{number}: unit factor {m.group(1)}"
                            for m in UNIT_FACTOR.finditer(line)]
            if not QUANTITY_TABLE.match(path) and QUANTITY_DEFINITION.search(line):
                problems.append(f"{path}:{number}: a row of the table of quantities defined "
                                f"outside it (model/quantities_*.h)")
    if len(factors) > MAX_UNIT_FACTORS:
        problems += factors
        problems.append(f"{len(factors)} unit factors outside {UNIT_TABLE} (at most "
                        f"{MAX_UNIT_FACTORS}): convert through a unit of the table "
                        f"(units::mm.from_si(x), units::kPa.in_si(x))")
    return problems, len(factors)


def main():
    args = sys.argv[1:]
    listing = 0
    if "--list-functions" in args:
        k = args.index("--list-functions")
        listing = int(args[k + 1])
        del args[k:k + 2]
    root = args[0] if args else os.environ.get(
        "CDEA_SOURCE_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    order = folder_order(root)
    unit_problems, n_factors = check_unit_factors(root)
    problems = (check_order_and_cycles(root, order) + check_function_lengths(root, listing) +
                check_friends(root) + unit_problems)
    for p in problems:
        print(p)
    n_files = len(code_files(root))
    print(f"structure_check: {n_files} files, folder order {' -> '.join(order)} (python above), "
          f"{n_factors} unit factors outside the table: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
