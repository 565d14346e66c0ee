#!/usr/bin/env python3
"""House limits (issue 24, STYLE "rules that live only in prose"): no source
file over 800 lines, and no function over 150 lines without a one-line reason
at its top.

Usage: house_limits.py <source root> [--list]
       house_limits.py --self-test

Files: every .cpp and .h under core/, devices/, views/, app/ and tests/.
Functions: a brace-matching scan of the .cpp files (comments, strings and
character literals blanked first). A block opened at namespace or class level
whose head holds a parenthesis and no top-level '=' is a function (lambdas and
local classes count towards the function around them); its length runs from
the first line of its head to its closing brace. A long function is allowed
when the comment lines right above its head, or the first line of its body,
carry

    // long-function: <the reason, in a few words>

--list prints every file and function over the limits, allowed or not, with
the reason; without it only the violations are printed. Exit status 1 when a
limit is broken.
"""

import os
import re
import sys

MAX_FILE_LINES = 800
MAX_FUNCTION_LINES = 150
ROOTS = ("core", "devices", "views", "app", "tests")
MARKER = re.compile(r"//\s*long-function:\s*(\S.*)$")

# Files exempt from both limits while a split of them is under way (none now:
# the UFF reader, the structural problem and diagnose() were split in issue 24).
SPLIT_IN_PROGRESS: dict = {}

# Functions that were over the limit when the rule came (issue 24), in files
# outside the split of that session. Each is to be split along its seams or
# given a `// long-function:` reason; remove the line when done. Keys are
# "path:function name" so that edits above a function do not break the list.
KNOWN_LONG_FUNCTIONS = {
    "core/geometry/mode_shape.cpp:shapeField": "181 lines when the rule came",
    "core/io/uff/uff_parse_58.cpp:parse58": "286 lines when the rule came (moved unchanged by the reader's split)",
    "core/io/uff/uff_reader.cpp:next": "154 lines when the rule came (moved unchanged by the reader's split)",
    "core/modal/refine.cpp:refineModalModel": "180 lines when the rule came",
    "core/signal/hit_quality.cpp:assessHit": "198 lines when the rule came",
    "core/stability/mode_tracking.cpp:sweepOnGrid": "199 lines when the rule came",
    "devices/rigtests/stiffness_tests.cpp:runDynamicStiffnessTest": "207 lines when the rule came",
    "devices/rigtests/tyre_tests.cpp:runRelaxationTest": "165 lines when the rule came",
    "devices/rigtests/tyre_tests.cpp:runSteadyStateTest": "235 lines when the rule came",
    "devices/sim/tyre_tester.cpp:tyreTesterCapabilities": "177 lines when the rule came",
    "views/modal/identification_page.cpp:IdentificationPage::IdentificationPage": "159 lines when the rule came",
    "views/panels/parameter_texts.cpp:parameterTexts": "331 lines when the rule came",
    "views/scene/mode_animation_view.cpp:ModeAnimationView::ModeAnimationView": "153 lines when the rule came",
    "views/scene/scene_view.cpp:SceneView::SceneView": "182 lines when the rule came",
    "app/cli/commands/frf.cpp:frfCommand": "239 lines when the rule came",
    "app/cli/commands/identify.cpp:identifyCommand": "183 lines when the rule came",
    "app/cli/commands/rig.cpp:runTest": "159 lines when the rule came",
    "app/cli/commands/run.cpp:runCommand": "151 lines when the rule came",
    "app/gui/builtin_pages.cpp:registerBuiltinPages": "235 lines when the rule came",
    "tests/views/campaign/hammer_station_page_test.cpp:HammerStationPageTest::wholeCampaignFromTheKeyboard": "297 lines when the rule came",
}


def blank_comments_and_strings(text):
    """Replaces comments, string and character literals by spaces, keeping
    newlines, so braces inside them do not count."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        nxt = text[i + 1] if i + 1 < n else ""
        if c == "/" and nxt == "/":
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif c == "/" and nxt == "*":
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and nxt == '"':
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if m:
                end = text.find(")" + m.group(1) + '"', i)
                end = n if end < 0 else end + len(m.group(1)) + 2
                out.append(re.sub(r"[^\n]", " ", text[i:end]))
                i = end
            else:
                out.append(c)
                i += 1
        elif c in "\"'":
            # A digit separator (1'000) is not a character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and nxt.isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def top_level_equals(head):
    depth = 0
    for k, ch in enumerate(head):
        if ch in "([<":
            depth += 1
        elif ch in ")]>":
            depth = max(0, depth - 1)
        elif ch == "=" and depth == 0:
            prev = head[k - 1] if k > 0 else ""
            nxt = head[k + 1] if k + 1 < len(head) else ""
            if prev not in "=!<>+-*/%&|^" and nxt != "=":
                return True
    return False


def function_name(head):
    m = re.search(r"([~\w:]+(?:operator\s*\S+?)?)\s*\(", head)
    return m.group(1) if m else head.strip()[:40]


def scan_functions(text):
    """Yields (name, first line, last line, head line index) of every function
    body opened at namespace or class level."""
    clean = blank_comments_and_strings(text)
    # Preprocessor lines (with their continuations) hold no braces we want.
    clean = re.sub(r"(?m)^[ \t]*#.*(?:\\\n.*)*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), clean)
    stack = []  # entries: "decl" (namespace, class, extern block) or ("func", name, line)
    head_start = 0
    line = 1
    for pos, ch in enumerate(clean):
        if ch == "\n":
            line += 1
            continue
        in_function = any(isinstance(s, tuple) for s in stack)
        if ch == "{":
            if in_function:
                stack.append("inner")
                continue
            head = clean[head_start:pos]
            stripped = " ".join(head.split())
            is_decl = (
                re.search(r"\b(namespace|class|struct|union|enum)\b[^()]*$", stripped)
                or re.match(r'^extern\b', stripped)
                or "(" not in stripped
                or (top_level_equals(stripped) and "operator" not in stripped)
            )
            if is_decl:
                stack.append("decl")
            else:
                first = line - head.count("\n")
                # The head starts at its first non-blank line.
                for part in head.split("\n"):
                    if part.strip():
                        break
                    first += 1
                stack.append(("func", function_name(stripped), first))
            head_start = pos + 1
        elif ch == "}":
            top = stack.pop() if stack else "decl"
            if isinstance(top, tuple):
                yield top[1], top[2], line
            if not any(isinstance(s, tuple) for s in stack):
                head_start = pos + 1
        elif ch == ";" and not in_function:
            head_start = pos + 1
        elif ch == ":" and not in_function:
            # "public:" and friends end a head too.
            tail = clean[head_start:pos].strip()
            if tail in ("public", "private", "protected", "signals", "public slots", "private slots",
                        "protected slots", "Q_SIGNALS", "Q_SLOTS"):
                head_start = pos + 1


def allow_reason(lines, first, body_line):
    """The `long-function:` reason in the comment block right above line
    `first` (1-based) or on the body's first line."""
    k = first - 2
    while k >= 0 and lines[k].strip().startswith("//"):
        m = MARKER.search(lines[k])
        if m:
            return m.group(1).strip()
        k -= 1
    for probe in (body_line - 1, body_line):
        if 0 <= probe < len(lines):
            m = MARKER.search(lines[probe])
            if m:
                return m.group(1).strip()
    return None


def source_files(root):
    for top in ROOTS:
        base = os.path.join(root, top)
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames[:] = sorted(d for d in dirnames if d not in ("corpus", "data", "build"))
            for f in sorted(filenames):
                if f.endswith((".cpp", ".h")):
                    yield os.path.relpath(os.path.join(dirpath, f), root)


def check(root, split_in_progress, known_long):
    """(failures, allowed) over the source files under root."""
    failures = []
    notes = []
    for rel in source_files(root):
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            text = f.read()
        lines = text.split("\n")
        count = len(lines) - 1 if text.endswith("\n") else len(lines)
        exempt = split_in_progress.get(rel)
        if count > MAX_FILE_LINES:
            entry = f"{rel}: {count} lines (limit {MAX_FILE_LINES})"
            (notes if exempt else failures).append(entry + (f" [allowed: {exempt}]" if exempt else ""))
        if not rel.endswith(".cpp"):
            continue
        for name, first, last in scan_functions(text):
            length = last - first + 1
            if length <= MAX_FUNCTION_LINES:
                continue
            body_line = first
            while body_line <= len(lines) and "{" not in lines[body_line - 1]:
                body_line += 1
            reason = exempt or allow_reason(lines, first, body_line) or known_long.get(f"{rel}:{name}")
            entry = f"{rel}:{first}: {name}() is {length} lines (limit {MAX_FUNCTION_LINES})"
            if reason:
                notes.append(entry + f" [allowed: {reason}]")
            else:
                failures.append(entry + "; split it, or put `// long-function: <reason>` above it")
    return failures, notes


def self_test():
    """Runs the scan on made-up sources whose answers are known, so a scanner
    that stops seeing long functions (or sees them everywhere) fails."""
    import tempfile

    filler = "  x += 1;\n"
    cases = {
        # 160-line function: over the limit.
        "core/a/long.cpp": "namespace n {\nint f(int x) {\n" + filler * 158 + "}\n}  // namespace n\n",
        # The same with a reason above it (after its doc comment): allowed.
        "core/a/reasoned.cpp": "// Does f.\n// long-function: one table of cases\nint g(int x) {\n" + filler * 158
        + "}\n",
        # A 200-line table at namespace level is data, not a function; a
        # 100-line function holding a lambda and braces in strings, comments
        # and characters stays one function of 104 lines.
        "core/a/data.cpp": "const int kTable[] = {\n" + "  1,\n" * 200 + "};\n"
        + "int h(int x) {\n  auto l = [&] { return \"{{\"; };  // {\n  char c = '{';\n  /* { */\n" + filler * 98
        + "}\n",
        # An inline member of 155 lines in a class body is a function.
        "core/a/member.cpp": "class C {\n public:\n  int m(int x) {\n" + filler * 153 + "  }\n};\n",
        # A file of 801 lines.
        "core/a/big.h": "// line\n" * 801,
    }
    with tempfile.TemporaryDirectory() as root:
        for rel, text in cases.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        failures, notes = check(root, {}, {})
    expected_failures = [
        "core/a/big.h: 801 lines",
        "core/a/long.cpp:2: f() is 160 lines",
        "core/a/member.cpp:3: m() is 155 lines",
    ]
    expected_notes = ["core/a/reasoned.cpp:3: g() is 160 lines (limit 150) [allowed: one table of cases]"]
    ok = len(failures) == len(expected_failures) and all(
        any(f.startswith(e) for f in failures) for e in expected_failures)
    ok = ok and notes == expected_notes
    if not ok:
        print("house_limits self-test failed:")
        print("  failures:", failures)
        print("  allowed:", notes)
        return 1
    print("house_limits self-test: long functions, reasons, tables, lambdas and file length read as expected")
    return 0


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    if argv[1] == "--self-test":
        return self_test()
    root = argv[1]
    listing = "--list" in argv[2:]
    failures, notes = check(root, SPLIT_IN_PROGRESS, KNOWN_LONG_FUNCTIONS)
    if listing:
        for n in notes:
            print(n)
    for f in failures:
        print(f)
    if failures:
        print(f"house limits: {len(failures)} over the limits", file=sys.stderr)
        return 1
    print(f"house limits: no file over {MAX_FILE_LINES} lines, no function over {MAX_FUNCTION_LINES} lines "
          f"without a reason ({len(notes)} allowed)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
