#!/usr/bin/env python3
"""The docs' links between themselves hold: every relative link in README.md,
docs/*.md and docs/design/*.md names a file that exists, and a link to a
section of a Markdown file (FILE.md#anchor, or #anchor in the same file)
names a heading it has, as GitHub makes a heading's anchor (lower case,
punctuation but hyphens dropped, spaces to hyphens, a repeated heading's
anchor numbered). A section moved from one page to another must take its
links with it.

usage: test_docs_links.py SOURCE_DIR
"""
import glob
import os
import re
import sys

source = sys.argv[1]


def without_fences(text):
    return re.sub(r"^\s*```.*?^\s*```", "", text, flags=re.S | re.M)


def without_code(text):
    """The text without fenced blocks and inline code spans, where a link is only an example."""
    return re.sub(r"`[^`\n]*`", "", without_fences(text))


def anchors(path):
    """The anchors of a file's headings (a heading's inline code is part of its anchor)."""
    found, seen = set(), {}
    for line in without_fences(open(path, encoding="utf-8").read()).splitlines():
        heading = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not heading:
            continue
        anchor = re.sub(r"[^\w\- ]", "", heading.group(1).replace("`", "").strip().lower()).replace(" ", "-")
        count = seen.get(anchor, 0)
        seen[anchor] = count + 1
        found.add(anchor if count == 0 else f"{anchor}-{count}")
    return found


docs = [os.path.join(source, "README.md")] + sorted(glob.glob(os.path.join(source, "docs", "*.md"))) + \
    sorted(glob.glob(os.path.join(source, "docs", "design", "*.md")))
failures, checked = [], 0
for doc in docs:
    text = without_code(open(doc, encoding="utf-8").read())
    for match in re.finditer(r"\]\(([^)\s]+)\)", text):
        target = match.group(1)
        if re.match(r"[a-z]+:", target):
            continue  # http:, https:, mailto:
        checked += 1
        path, _, anchor = target.partition("#")
        dest = os.path.normpath(os.path.join(os.path.dirname(doc), path)) if path else doc
        where = os.path.relpath(doc, source)
        if not os.path.exists(dest):
            failures.append(f"{where}: ({target}): no such file {os.path.relpath(dest, source)}")
        elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
            failures.append(f"{where}: ({target}): {os.path.relpath(dest, source)} has no heading with that anchor")
if checked < 50:
    failures.append(f"only {checked} links found in the docs: the scan is broken")
print(f"{checked} links between the docs checked")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
