#!/usr/bin/env python3
"""Checks that no function of core/ or filter_geodesic_remesh/ is longer than 80 lines.

    python3 scripts/check_function_length.py [ROOT] [--max N] [--list]
                                               # exit 1 and one line per function over the limit
    python3 scripts/check_function_length.py --self-test
                                               # exit 0 if the checker measures planted functions right

A function's length is counted from the line of its opening brace to the line of its closing
brace, both included; lambdas and local classes count towards the function that holds them.
A body is a brace block opened directly inside a namespace, a class or at file scope whose
preceding text (since the last ';', '{' or '}') holds a ')' - so class, enum, namespace bodies
and brace initialisers are not functions. Comments, strings and character literals are skipped.
This is a lexical check, not a C++ parser: it is exact for the code style of this project
(clang-format, one declaration per statement).
"""
import pathlib
import re
import sys
import tempfile

LIMIT = 80
LAYERS = ("core", "filter_geodesic_remesh")
SUFFIXES = (".h", ".cpp", ".hpp", ".inl")
NAME = re.compile(r"([A-Za-z_~][A-Za-z_0-9:<>~]*|operator\s*\S+)\s*\(")


def strip(text):
    """The text with comments, strings and char literals blanked (newlines kept)."""
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
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(n, j + 1)
            out.append(c + " " * (j - i - 2) + c if j - i >= 2 else c)
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(text):
    """(name, first line, length in lines) of every function body in the text."""
    code = strip(text)
    found = []
    stack = []  # per open brace: 'scope' (namespace/class/file), 'function' or 'other'
    since = 0  # start of the text preceding the next brace
    body_start = {}
    line = 1
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            head = code[since:i]
            inside_scope = all(kind == "scope" for kind, *_ in stack)
            words = head.split()
            if re.search(r"\b(namespace|class|struct|union|enum)\b", head) and ")" not in head.split("=")[0][-1:]:
                kind = "scope" if re.search(r"\b(namespace|class|struct|union)\b", head) and "(" not in head else "other"
            else:
                kind = "function" if inside_scope and ")" in head and not head.rstrip().endswith("=") else "other"
            if kind == "scope" and "=" in head:
                kind = "other"
            if not words and inside_scope:
                kind = "other"
            name = None
            if kind == "function":
                names = NAME.findall(head)
                name = names[0] if names else "?"
                name = re.sub(r"\s+", "", name)
            stack.append((kind, line, name))
            since = i + 1
        elif c == "}":
            if stack:
                kind, first, name = stack.pop()
                if kind == "function":
                    found.append((name, first, line - first + 1))
            since = i + 1
        elif c == ";":
            since = i + 1
    return found


def long_functions(root, limit):
    root = pathlib.Path(root)
    out = []
    for layer in LAYERS:
        for src in sorted((root / layer).rglob("*")):
            if src.suffix not in SUFFIXES:
                continue
            rel = src.relative_to(root).as_posix()
            for name, first, length in functions(src.read_text(errors="replace")):
                out.append((length, rel, first, name))
    return [f for f in out if f[0] > limit], out


def self_test():
    short_body = "\n".join(["  x += 1;"] * 10)
    long_body = "\n".join(["  x += 1;  // a } in a comment"] * 85)
    text = f"""#include <vector>
namespace gr {{
namespace {{
struct Record {{
  int a = 0;
  int twice() const {{
    return 2 * a;
  }}
}};
enum class Kind {{ A, B }};
}}  // namespace
const std::vector<int> kTable = {{1, 2, 3}};
int shortOne(int x) {{
{short_body}
  auto lambda = [&](int y) {{ return y + 1; }};
  const char* s = "{{ not a brace";
  return lambda(x);
}}
int Foo::longOne(int x) const {{
{long_body}
  if (x) {{
    x = 0;
  }}
  return x;
}}
}}  // namespace gr
"""
    got = {name: length for name, _, length in functions(text)}
    want = {"twice": 3, "shortOne": 15, "Foo::longOne": 91}
    if got != want:
        print(f"self-test FAILED: measured {got}, expected {want}")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        (pathlib.Path(tmp) / "core" / "base").mkdir(parents=True)
        (pathlib.Path(tmp) / "core" / "base" / "x.cpp").write_text(text)
        over, _ = long_functions(tmp, LIMIT)
        if [f[3] for f in over] != ["Foo::longOne"]:
            print(f"self-test FAILED: over the limit {over}")
            return 1
    print("self-test passed: the planted 91-line function is caught, the others are not")
    return 0


def main(argv):
    if "--self-test" in argv:
        return self_test()
    limit = LIMIT
    if "--max" in argv:
        limit = int(argv[argv.index("--max") + 1])
    rest = [a for i, a in enumerate(argv) if not a.startswith("--") and (i == 0 or argv[i - 1] != "--max")]
    root = rest[0] if rest else pathlib.Path(__file__).resolve().parent.parent
    over, every = long_functions(root, limit)
    if "--list" in argv:
        for length, rel, first, name in sorted(every, reverse=True)[:40]:
            print(f"{length:5d}  {rel}:{first}  {name}")
        return 0
    for length, rel, first, name in sorted(over, reverse=True):
        print(f"{rel}:{first}: {name} is {length} lines (limit {limit})")
    if over:
        return 1
    print(f"{len(every)} functions, none over {limit} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
