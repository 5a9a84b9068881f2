#!/usr/bin/env python3
"""Checks that files equal, byte for byte, the fenced code blocks of a doc
that show them: each file must be one of the doc's ``` blocks, in full.

  check_docs_example.py DOC FILE...
"""
import re
import sys

doc_path, files = sys.argv[1], sys.argv[2:]
blocks = re.findall(r"^```[a-z]*\n(.*?)^```$", open(doc_path).read(), re.S | re.M)
failed = False
for path in files:
    text = open(path).read()
    if text not in blocks:
        print(f"{path}: not shown in full in {doc_path}; the docs and the tested example must be the same file")
        failed = True
sys.exit(1 if failed else 0)
