#!/usr/bin/env python3
"""Checks that the docs keep up with the code.

Usage:
  python3 scripts/check_docs.py MESHQUILT_BINARY REPO_ROOT
  python3 scripts/check_docs.py --self-test

Fails (exit 1, one line per problem) when README.md has more than 200 lines; when a long
option printed by `MESHQUILT --help` or by `MESHQUILT <sub> [<sub> ...] --help` for any
subcommand (found in the "Subcommands:" section of CLI11's help) is missing from docs/cli.md;
when a command is missing from docs/cli.md's list of commands (its first paragraph) or a swatch
kind its section; when a key
of the stats JSON that `synth --stats` writes over a plane and over data/sphere.off (top-level
keys, stage names, repair counts) is missing from docs/cli.md; when a string literal in
host/ names a command-line flag (library messages say {name}; the front ends spell it); when
docs/performance.md or the README's figures differ from what docs/figures.json gives
(`perf/figures.py write --check`); or when another page quotes a timing (a decimal number of
seconds or milliseconds) outside the README's generated blocks: timings live in
docs/performance.md alone.
An option or key counts as documented when it appears inside backticks (a code span or a fenced
block) in docs/cli.md. On success prints "docs check: N options documented, K stats keys,
README L lines". Python 3 standard library only.
"""

import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

README_MAX_LINES = 200

# A long option name: --name, letters, digits, '-' and '_' (CLI11 prints a negated flag's default
# after it in braces, --no-cleanup{false}, and a value's type after a space).
LONG_OPTION = re.compile(r"--[A-Za-z0-9][A-Za-z0-9_-]*")
# Section headers of CLI11's help: "Options:", "Subcommands:", "Positionals:", "[Option Group: x]".
SECTION = re.compile(r"^(\S[^:]*):\s*$|^\[Option Group: .*\]\s*$")
# Entries of a section start with a short indent (CLI11 writes two spaces); wrapped descriptions
# are indented to the description column (30 by default), so deep lines are never entries.
ENTRY_MAX_INDENT = 6


def parse_help(text):
    """Returns (long options, subcommand names) from one CLI11 help text."""
    options, subcommands = [], []
    section = None
    for line in text.splitlines():
        if not line.strip():
            continue
        header = SECTION.match(line)
        if header:
            section = (header.group(1) or "option group").strip().lower()
            continue
        indent = len(line) - len(line.lstrip(" "))
        if indent == 0 or indent > ENTRY_MAX_INDENT:
            continue
        first = line.split()[0]
        if section == "subcommands":
            if not first.startswith("-") and first not in subcommands:
                subcommands.append(first)
        elif first.startswith("-"):
            # The name column alone: "-o,--output", "--plane", "--no-cleanup{false}". Options named
            # later on the line (Needs:, Excludes:, descriptions) are entries of their own.
            for name in first.split(","):
                match = LONG_OPTION.match(name)
                if match and match.group(0) not in options:
                    options.append(match.group(0))
    return options, subcommands


def collect_options(help_of):
    """Walks every command from the top. help_of(path) returns the help text of `path` (a list of
    subcommand names) or raises RuntimeError. Returns ({option: [command paths]}, problems)."""
    found, problems = {}, []
    queue, seen = [[]], set()
    while queue:
        path = queue.pop(0)
        key = tuple(path)
        if key in seen:
            continue
        seen.add(key)
        try:
            text = help_of(path)
        except RuntimeError as error:
            problems.append(str(error))
            continue
        options, subcommands = parse_help(text)
        if not options:
            problems.append("%s --help: no options found in its help" % " ".join(["meshquilt"] + path))
        for option in options:
            found.setdefault(option, []).append(" ".join(path) or "(top level)")
        for sub in subcommands:
            queue.append(path + [sub])
    return found, problems


def documented_options(markdown):
    """Long options that appear inside backticks: inline code spans and fenced blocks."""
    names = set()
    fenced = re.compile(r"^(```|~~~).*?^\1", re.S | re.M)
    for block in fenced.finditer(markdown):
        names.update(LONG_OPTION.findall(block.group(0)))
    rest = fenced.sub("", markdown)
    for span in re.findall(r"(`+)(.+?)\1", rest, re.S):
        names.update(LONG_OPTION.findall(span[1]))
    return names


def check(help_of, root):
    problems = []
    readme = root / "README.md"
    readme_lines = 0
    if readme.is_file():
        readme_lines = len(readme.read_text(encoding="utf-8").splitlines())
        if readme_lines > README_MAX_LINES:
            problems.append("README.md: %d lines, more than %d" % (readme_lines, README_MAX_LINES))
    else:
        problems.append("README.md: missing")
    cli_md = root / "docs" / "cli.md"
    documented = set()
    if cli_md.is_file():
        documented = documented_options(cli_md.read_text(encoding="utf-8"))
    else:
        problems.append("docs/cli.md: missing")
    found, help_problems = collect_options(help_of)
    problems.extend(help_problems)
    for option in sorted(found):
        if option not in documented:
            commands = ", ".join(found[option])
            problems.append("docs/cli.md: `%s` (%s) is not documented in backticks" % (option, commands))
    return problems, len(found), readme_lines


# A string literal holding a long option, outside comments.
FLAG_LITERAL = re.compile(r'"[^"\n]*--[a-z][^"\n]*"')


def flag_literals(path, text):
    """'PATH:LINE: ...' for each string literal in `text` that names a flag."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        code = line.split("//", 1)[0]
        if FLAG_LITERAL.search(code):
            found.append("%s:%d: a string names a flag (write {name}; the front end spells it): %s"
                         % (path, number, line.strip()))
    return found


def code_words(markdown):
    """Identifiers appearing inside backticks (code spans and fenced blocks)."""
    words = set()
    spans = re.findall(r"```.*?```|`[^`\n]+`", markdown, flags=re.S)
    for span in spans:
        words.update(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", span))
    return words


def stats_keys(binary, root):
    """Keys `synth --stats` writes over a plane and over data/sphere.off: top level, stages and
    repair counts."""
    keys = set()
    with tempfile.TemporaryDirectory() as folder:
        for where in (["--plane", "1x1"], ["--base", str(root / "data" / "sphere.off"), "--scale", "0.5"]):
            stats = Path(folder) / "stats.json"
            command = [binary, "synth", *where, "--progress", "none", "--backend", "cpu", "--stats", str(stats),
                       "-o", str(Path(folder) / "out.ply")]
            run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
            if run.returncode != 0:
                raise RuntimeError("%s: exit code %d" % (" ".join(command), run.returncode))
            data = json.loads(stats.read_text())
            keys.update(data)
            keys.update(data.get("stages", {}))
            for counts in data.get("repairs", {}).values():
                keys.update(counts)
    return keys


def check_sources_and_stats(binary, root, top_commands, swatch_kinds=()):
    problems = []
    for path in sorted((root / "host").rglob("*")):
        if path.suffix in (".cpp", ".h"):
            problems += flag_literals(path.relative_to(root), path.read_text(encoding="utf-8"))
    cli_md = (root / "docs" / "cli.md").read_text(encoding="utf-8")
    listed = code_words(cli_md.split("\n\n")[1] if "\n\n" in cli_md else cli_md)
    for command in top_commands:
        if command not in listed:
            problems.append("docs/cli.md: command `%s` is missing from the list of commands" % command)
    for kind in swatch_kinds:
        if kind != "check" and "### `swatch %s`" % kind not in cli_md:
            problems.append("docs/cli.md: swatch kind `%s` has no section (### `swatch %s`)" % (kind, kind))
    documented = code_words(cli_md)
    keys = stats_keys(binary, root)
    for key in sorted(keys - documented):
        problems.append("docs/cli.md: stats key `%s` (written by synth --stats) is not documented" % key)
    return problems, len(keys)


# A measured timing: "1.5 s", "0.19 s", "39 ms", "2.5 seconds". Whole seconds ("10 s") are
# limits and settings, not measurements.
TIMING = re.compile(r"\b\d+\.\d+ ?(?:s|seconds|minutes)\b|\b\d+(?:\.\d+)? ?ms\b")
GENERATED = re.compile(r"<!-- figures:([a-z-]+) -->.*?<!-- /figures:\1 -->", re.S)


def quoted_timings(name, text):
    """Timings quoted outside generated blocks, one problem per line."""
    text = GENERATED.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    return ["%s:%d: quotes a timing (%s); timings live in docs/performance.md" % (name, n, m.group(0))
            for n, line in enumerate(text.splitlines(), 1) for m in [TIMING.search(line)] if m]


def check_figures(root):
    problems = []
    pages = [root / "README.md", root / "CONTRIBUTING.md"] + sorted((root / "docs").glob("*.md"))
    for page in pages:
        if page.name != "performance.md" and page.exists():
            problems += quoted_timings(str(page.relative_to(root)), page.read_text(encoding="utf-8"))
    done = subprocess.run([sys.executable, str(root / "perf" / "figures.py"), "write", "--check"],
                          capture_output=True, text=True)
    if done.returncode != 0:
        problems.append((done.stderr or done.stdout).strip())
    return problems


def binary_help(binary):
    def help_of(path):
        command = [binary] + path + ["--help"]
        try:
            run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
        except (OSError, subprocess.TimeoutExpired) as error:
            raise RuntimeError("%s: %s" % (" ".join(command), error))
        text = run.stdout.decode("utf-8", "replace")
        if run.returncode != 0:
            first = text.strip().splitlines()[:1]
            raise RuntimeError("%s: exit code %d%s" % (" ".join(command), run.returncode,
                                                        (": " + first[0]) if first else ""))
        return text
    return help_of


# CLI11 help as 2.1 (defaults after '=', negated flags with their value in braces) and 2.3
# (defaults in brackets) print it, for --self-test.
SAMPLE_TOP = """\
meshquilt: grows 3D geometric textures over planes and meshes by mesh quilting
Usage: meshquilt [OPTIONS] SUBCOMMAND

Options:
  -h,--help                   Print this help message and exit

Subcommands:
  swatch                      writes a built-in swatch: chainmail, weave, wire, fruit, nuts or heightfield
  synth                       Grow a geometric texture over a plane or a base mesh by mesh quilting
  a-very-long-subcommand-name-past-the-column
                              a description on its own line
"""
SAMPLE_SYNTH_21 = """\
Grow a geometric texture over a plane or a base mesh by mesh quilting
Usage: meshquilt synth [OPTIONS]

Options:
  -h,--help                   Print this help message and exit
  --swatch TEXT               swatch mesh (OBJ, PLY, OFF, STL); default: a built-in chain mail
  --plane TEXT=4x4            output size WxH in swatch extents
  --no-cleanup{false}         keep elements that could not be made whole
  --write-texture TEXT        with --base: write the result in texture space, for `meshquilt embed` over an edited base
  -o,--output TEXT=quilt.ply  output mesh (.ply with element ids, .obj with groups, .off, .stl)
"""
SAMPLE_SWATCH_23 = """\
writes a built-in swatch: chainmail, weave, wire, fruit, nuts or heightfield
Usage: meshquilt swatch [OPTIONS] SUBCOMMAND

Options:
  -h,--help                   Print this help message and exit

Subcommands:
  chainmail                   European 4-in-1 chain mail: tilted rings, each linked through four neighbours
"""
SAMPLE_CHAINMAIL_23 = """\
European 4-in-1 chain mail
Usage: meshquilt swatch chainmail [OPTIONS]

Options:
  -h,--help                   Print this help message and exit
  -o,--output TEXT REQUIRED   output mesh (.ply .obj .off .stl)
  --rows INT [8]              ring rows along y (even)
  --preset TEXT:{default,small} [default]
                              starting sizes: default (paper-sized) or small
  --region FLOAT x 4 Needs: --plane
                              with --plane: cover this x-y rectangle
  --no-distortion-min{false}  with --embed shell: keep the original shell map
"""
SAMPLE_LONG = """\
x
Usage: meshquilt a-very-long-subcommand-name-past-the-column [OPTIONS]

Positionals:
  MESH TEXT REQUIRED          mesh to inspect (.obj .ply .off .stl)

Options:
  -h,--help                   Print this help message and exit
"""
SAMPLE_CLI_MD = """\
# sample
| option | |
| --- | --- |
| `--swatch FILE` | the swatch |
| `--plane WxH` | a plane |
| `-o`, `--output` | output |
Mentioned without backticks: --rows, so it does not count.
```
meshquilt synth --no-cleanup --write-texture t.mqt
```
`--preset`, `--region X0,Y0,X1,Y1`, `--help`.
"""

SAMPLE_SOURCE = """\
throw InputError("{age}: expected a share");
throw InputError("--age: expected a share");
// mentions --age in a comment only
x = "a -- b";  // a dash pair
y = f("use --base here");
"""


def self_test():
    failures = []

    def expect(what, got, want):
        if got != want:
            failures.append("%s: got %r, want %r" % (what, got, want))

    expect("top", parse_help(SAMPLE_TOP),
           (["--help"], ["swatch", "synth", "a-very-long-subcommand-name-past-the-column"]))
    expect("synth (CLI11 2.1)", parse_help(SAMPLE_SYNTH_21),
           (["--help", "--swatch", "--plane", "--no-cleanup", "--write-texture", "--output"], []))
    expect("swatch (CLI11 2.3)", parse_help(SAMPLE_SWATCH_23), (["--help"], ["chainmail"]))
    expect("chainmail (CLI11 2.3)", parse_help(SAMPLE_CHAINMAIL_23),
           (["--help", "--output", "--rows", "--preset", "--region", "--no-distortion-min"], []))
    expect("positionals", parse_help(SAMPLE_LONG), (["--help"], []))

    helps = {
        (): SAMPLE_TOP,
        ("synth",): SAMPLE_SYNTH_21,
        ("swatch",): SAMPLE_SWATCH_23,
        ("swatch", "chainmail"): SAMPLE_CHAINMAIL_23,
        ("a-very-long-subcommand-name-past-the-column",): SAMPLE_LONG,
    }

    def help_of(path):
        if tuple(path) not in helps:
            raise RuntimeError("meshquilt %s --help: exit code 2" % " ".join(path))
        return helps[tuple(path)]

    found, problems = collect_options(help_of)
    expect("walk problems", problems, [])
    expect("walk options", sorted(found),
           sorted(["--help", "--swatch", "--plane", "--no-cleanup", "--write-texture", "--output", "--rows",
                   "--preset", "--region", "--no-distortion-min"]))
    expect("walk commands of --rows", found.get("--rows"), ["swatch chainmail"])

    documented = documented_options(SAMPLE_CLI_MD)
    expect("documented", sorted(documented),
           sorted(["--swatch", "--plane", "--output", "--no-cleanup", "--write-texture", "--preset", "--region",
                   "--help"]))
    missing = sorted(set(found) - documented)
    expect("missing", missing, ["--no-distortion-min", "--rows"])

    expect("flag literals", [line.split(":")[1] for line in flag_literals("x.cpp", SAMPLE_SOURCE)], ["2", "5"])
    expect("code words", sorted(code_words("`a_b` and ```\nc {d}\n``` but not e")), ["a_b", "c", "d"])
    expect("timings", [p.split(":")[1] for p in quoted_timings(
        "x.md", "in 1.5 s\nfuzz 10 s\n<!-- figures:a -->\n2.5 s\n<!-- /figures:a -->\n39 ms and 0.2 seconds")],
        ["1", "6"])

    if failures:
        for failure in failures:
            print("self-test: " + failure)
        return 1
    print("self-test: ok")
    return 0


def main(argv):
    if len(argv) == 2 and argv[1] == "--self-test":
        return self_test()
    if len(argv) != 3:
        print("usage: python3 scripts/check_docs.py MESHQUILT_BINARY REPO_ROOT | --self-test", file=sys.stderr)
        return 2
    help_of = binary_help(argv[1])
    problems, options, readme_lines = check(help_of, Path(argv[2]))
    more, keys = check_sources_and_stats(argv[1], Path(argv[2]), parse_help(help_of([]))[1],
                                         parse_help(help_of(["swatch"]))[1])
    problems += more
    problems += check_figures(Path(argv[2]))
    if problems:
        for problem in problems:
            print(problem)
        return 1
    print("docs check: %d options documented, %d stats keys, README %d lines" % (options, keys, readme_lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
