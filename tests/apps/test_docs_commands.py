#!/usr/bin/env python3
"""The docs say what the program does: every `swell ...` command line in
README.md, docs/*.md and docs/design/*.md (in sh code blocks and inline code) names a real
subcommand and only options that subcommand has, as `swell SUB --help` lists
them, so a documented flag the program lost fails here; GETTING_STARTED.md
names every preset the program lists and every subcommand; the README's
commands write their files into out/, which git ignores.

usage: test_docs_commands.py SWELL_EXECUTABLE SOURCE_DIR
Runs swell only for --help and one refused preset name: a second or two.
"""
import glob
import os
import re
import subprocess
import sys

swell, source = sys.argv[1], sys.argv[2]
failures = []

# Commands the docs show on purpose as refused, each checked to be refused.
DOCUMENTED_REFUSALS = {"swell evening.toml", "swell rendr"}
# Fenced blocks of these languages hold no shell commands.
NOT_SHELL = {"toml", "python", "py", "cpp", "c++", "c", "cmake", "json", "glsl", "ini", "yaml"}
# Where a command ends on its line.
ENDS = {"|", "||", "&&", ";", ">", ">>", "2>", "2>&1", "&", "\\"}


def run(*args):
    return subprocess.run([swell, *args], capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, DISPLAY="", WAYLAND_DISPLAY=""))


def options_in_help(text):
    """The option names of a CLI11 help text: the first word of each option line."""
    names = set()
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("-"):
            names.update(n for n in stripped.split()[0].split(",") if n.startswith("-"))
    return names


def subcommands_in_help(text):
    lines = text.splitlines()
    start = next((i for i, l in enumerate(lines) if l.strip().upper().startswith("SUBCOMMANDS")), None)
    if start is None:
        return set()
    return {l.split()[0] for l in lines[start + 1:] if l.startswith("  ") and l.split()}


top_help = run("--help").stdout
SUBCOMMANDS = subcommands_in_help(top_help)
OPTIONS = {None: options_in_help(top_help)}
for sub in SUBCOMMANDS:
    OPTIONS[sub] = options_in_help(run(sub, "--help").stdout)
if not {"view", "render", "bench", "dataset"} <= SUBCOMMANDS or not OPTIONS.get("render"):
    sys.exit(f"could not read the subcommands and options from `swell --help`: {SUBCOMMANDS}, {OPTIONS}")


def spans(paragraph):
    """(line number, text) of each inline code span of a paragraph [(number, line)], one
    that runs over a line break included."""
    if not paragraph:
        return []
    text = "\n".join(line for _, line in paragraph)
    first = paragraph[0][0]
    return [(first + text.count("\n", 0, m.start()), m.group(1).replace("\n", " "))
            for m in re.finditer(r"(?<!`)`([^`]+)`(?!`)", text)]


def snippets(path):
    """(line number, text) of each shell line of a fenced block and each inline code span."""
    out = []
    fence = None
    paragraph = []
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        line = line.rstrip("\n")
        opened = re.match(r"\s*```\s*([\w+-]*)", line)
        if opened or not line.strip():
            out.extend(spans(paragraph))
            paragraph = []
        if opened:
            fence = None if fence is not None else opened.group(1).lower()
            continue
        if fence is not None:
            if fence not in NOT_SHELL:
                # A synopsis's description follows two spaces or more.
                out.append((number, re.split(r"(?<=\S) {2,}", line.strip())[0]))
            continue
        if line.strip():
            paragraph.append((number, line))
    out.extend(spans(paragraph))
    return out


def commands(text):
    """Each `swell` command in a line: its words after the executable."""
    words = text.split()
    found = []
    for i, word in enumerate(words):
        if not re.fullmatch(r"(?:[\w.~/${}-]*/)?swell", word):
            continue
        if i > 0 and (words[i - 1].startswith("-") or words[i - 1] in {"import", "the", "a", "of", "package"}):
            continue
        args = []
        for arg in words[i + 1:]:
            if arg in ENDS or arg.startswith("#"):
                break
            args.append(arg.rstrip(";"))
            if arg.endswith(";"):
                break
        found.append(args)
    return found


def check(doc, number, args):
    where = f"{os.path.relpath(doc, source)}:{number}"
    shown = " ".join(["swell", *args])
    sub = None
    rest = args
    if args and re.search(r"[(:={}]", args[0]):
        return  # prose or a log line that names swell ("swell view: input: ..."), not a command
    if args and not args[0].startswith(("-", "[")):
        if args[0] in SUBCOMMANDS:
            sub, rest = args[0], args[1:]
        elif not (args[0] == "..." or args[0].isupper()):  # a placeholder: COMMAND, SUB
            if shown not in DOCUMENTED_REFUSALS:
                failures.append(f"{where}: `{shown}`: '{args[0]}' is not a subcommand of swell "
                                f"({', '.join(sorted(SUBCOMMANDS))})")
            return
    for arg in rest:
        name = arg.strip("[]()`',.:").split("=")[0]
        if re.fullmatch(r"--?[A-Za-z][\w-]*", name) and name not in OPTIONS[sub]:
            failures.append(f"{where}: `{shown}`: {name} is not an option of `swell{' ' + sub if sub else ''}` "
                            f"(it has {', '.join(sorted(OPTIONS[sub]))})")


docs = [os.path.join(source, "README.md")] + sorted(glob.glob(os.path.join(source, "docs", "*.md"))) + \
    sorted(glob.glob(os.path.join(source, "docs", "design", "*.md")))
checked = 0
for doc in docs:
    for number, text in snippets(doc):
        for args in commands(text):
            checked += 1
            check(doc, number, args)
if checked < 50:
    failures.append(f"only {checked} swell commands found in the docs: the scan is broken")

for refusal in DOCUMENTED_REFUSALS:
    if run(*refusal.split()[1:]).returncode != 2:
        failures.append(f"`{refusal}`, documented as refused, is not refused with exit 2")

# GETTING_STARTED.md: every preset the program lists, every subcommand.
listing = run("render", "no-such-preset-name", "-o", os.devnull).stderr
presets = re.search(r"are: (.*)", listing)
getting_started = open(os.path.join(source, "docs", "GETTING_STARTED.md"), encoding="utf-8").read()
if not presets:
    failures.append(f"swell did not list the presets for an unknown name: {listing!r}")
else:
    for name in presets.group(1).strip().split(", "):
        if f"`{name}.toml`" not in getting_started:
            failures.append(f"docs/GETTING_STARTED.md's table of presets lacks `{name}.toml`")
for sub in SUBCOMMANDS:
    if not re.search(rf"^swell {sub}\b", getting_started, re.M):
        failures.append(f"docs/GETTING_STARTED.md's summary of the swell executable lacks `swell {sub}`")

# The README's commands leave nothing untracked: their outputs go under out/,
# which .gitignore ignores.
ignored = open(os.path.join(source, ".gitignore"), encoding="utf-8").read().split()
if "/out/" not in ignored:
    failures.append(".gitignore does not ignore /out/, where the README's commands write")
readme = os.path.join(source, "README.md")
for number, text in snippets(readme):
    for args in commands(text):
        for option, value in zip(args, args[1:]):
            if option in {"-o", "--output", "--json", "--out", "--screenshot"} and not value.startswith(("out/", "/")):
                failures.append(f"README.md:{number}: `swell {' '.join(args)}` writes {value} into the clone; "
                                f"write it under out/ (ignored by git)")

print(f"{checked} documented swell commands checked against `swell --help`")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
