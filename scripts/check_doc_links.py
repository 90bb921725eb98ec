#!/usr/bin/python3
"""Checks the relative links of every tracked Markdown file.

    scripts/check_doc_links.py [--root DIR]

For each link or image [text](target) outside code, a relative target must name a file or
folder of the repository, and a #anchor in a Markdown target must name one of its
headings (GitHub's rule: lower case, punctuation dropped, spaces to hyphens). Web links
(http:, https:, mailto:) are not checked. Prints one line per broken link and exits 1 when
there is any.
"""
import argparse
import os
import re
import subprocess
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_CODE = re.compile(r"`[^`]*`")
HEADING = re.compile(r"^\s{0,3}#{1,6}\s+(.*?)\s*#*\s*$")


def slug(heading):
    text = re.sub(r"<[^>]+>", "", heading)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link in a heading keeps its text
    text = text.replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def lines_outside_code(path):
    fenced = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if not fenced:
                yield number, line


def anchors(path, cache={}):
    if path not in cache:
        seen = {}
        found = set()
        for _, line in lines_outside_code(path):
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(1))
            n = seen.get(base, 0)
            found.add(base if n == 0 else f"{base}-{n}")
            seen[base] = n + 1
        cache[path] = found
    return cache[path]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    files = subprocess.run(["git", "ls-files", "*.md"], cwd=root, capture_output=True, text=True,
                           check=True).stdout.split()
    broken = checked = 0
    for name in files:
        path = os.path.join(root, name)
        for number, line in lines_outside_code(path):
            for m in LINK.finditer(INLINE_CODE.sub("", line)):
                target = m.group(1)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):
                    continue  # http:, https:, mailto:
                checked += 1
                file_part, _, anchor = target.partition("#")
                resolved = path if not file_part else os.path.normpath(
                    os.path.join(os.path.dirname(path), file_part))
                relative = os.path.relpath(resolved, root)
                where = f"{name}:{number}: {target}"
                if relative.startswith(".."):
                    print(f"{where}: points outside the repository")
                    broken += 1
                elif not os.path.exists(resolved):
                    print(f"{where}: no such file")
                    broken += 1
                elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                    print(f"{where}: no heading #{anchor} in {relative}")
                    broken += 1
    print(f"check_doc_links: {len(files)} files, {checked} relative links, {broken} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
