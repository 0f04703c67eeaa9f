"""Every C++ file of the repository (*.h, *.cxx; the generator's *.in templates aside) is formatted
as .clang-format says: clang-format would change nothing.

Usage: CheckFormatting.py SOURCE_DIR CLANG_FORMAT"""
import os
import subprocess
import sys


def cxx_files(root):
    try:
        listed = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard",
                                 "*.h", "*.cxx"], check=True, capture_output=True, text=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        listed = [os.path.relpath(os.path.join(folder, name), root)
                  for top in ("Source", "Testing", "Plugins")
                  for folder, _, names in os.walk(os.path.join(root, top))
                  for name in names if name.endswith((".h", ".cxx"))]
    return sorted(path for path in listed if os.path.exists(os.path.join(root, path)))


def main(root, clang_format):
    if not os.path.exists(clang_format):
        print("ERROR: clang-format not found (%s); Utilities/setup.sh installs it" % clang_format)
        return 1
    files = cxx_files(root)
    unformatted = []
    for start in range(0, len(files), 50):
        batch = files[start:start + 50]
        result = subprocess.run([clang_format, "--style=file", "--dry-run", "-Werror"] + batch, cwd=root,
                                capture_output=True, text=True)
        if result.returncode != 0:
            unformatted += sorted({line.split(":")[0] for line in result.stderr.splitlines()
                                   if ": error:" in line})
    for path in unformatted:
        print("ERROR: %s is not formatted as .clang-format says (run: %s -i %s)" % (path, clang_format, path))
    print("%d C++ files checked, %d not formatted" % (len(files), len(unformatted)))
    return 1 if unformatted or len(files) < 100 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
