"""Every relative link of the README and Documentation/ leads somewhere: the file exists and, for
a link with #anchor, the page has a heading with that anchor (GitHub's rule: lowercase, spaces
to hyphens, punctuation dropped).

Usage: CheckDocumentationLinks.py SOURCE_DIR"""
import glob
import os
import re
import sys

LINK = re.compile(r"\]\(([^)\s]+)\)")


def anchors(path):
    found = set()
    with open(path, encoding="utf-8") as f:
        inside_code = False
        for line in f:
            if line.startswith("```"):
                inside_code = not inside_code
            if inside_code or not line.startswith("#"):
                continue
            title = line.lstrip("#").strip().lower()
            slug = re.sub(r"[^\w\- ]", "", title).replace(" ", "-")
            base, n = slug, 1
            while slug in found:
                slug = "%s-%d" % (base, n)
                n += 1
            found.add(slug)
    return found


def main(root):
    pages = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "Documentation", "**", "*.md"),
                                                                 recursive=True))
    failures = []
    links = 0
    for page in pages:
        with open(page, encoding="utf-8") as f:
            text = f.read()
        for target in LINK.findall(text):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, https:, mailto:
            links += 1
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(resolved):
                failures.append("%s links to %s, which does not exist" % (os.path.relpath(page, root), target))
            elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                failures.append("%s links to %s: no such heading" % (os.path.relpath(page, root), target))
    for failure in failures:
        print("ERROR: " + failure)
    print("%d links of %d pages checked" % (links, len(pages)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
