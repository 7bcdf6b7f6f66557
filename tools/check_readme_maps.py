#!/usr/bin/env python3
"""Each source folder's README.md is its map and names every file in it (the project's rule).

For every folder under raytracer/ and collision/ that has a README.md, each .cpp/.hpp/.h/.inl
file in it, and in its subfolders that have no README of their own, must be named there: by its
name (`bvh.cpp`), by its stem with a star (`bvh.*`), or by its path from the folder
(`integrators/path.*`). A folder without a README is checked by the nearest ancestor that has
one. Exit 1 with one line per unnamed file; `--root` checks another tree (the test's fixture).
"""
import argparse
import re
import sys
from pathlib import Path

SOURCE = {".cpp", ".hpp", ".h", ".inl"}
TOP = ("raytracer", "collision")


def named(readme_text: str, rel: Path) -> bool:
    candidates = {rel.name, rel.stem + ".*", rel.as_posix(), (rel.parent / (rel.stem + ".*")).as_posix()}
    for c in candidates:
        # A name counts when it stands alone: not as the tail of a longer name (`x_bvh.cpp`).
        if re.search(r"(?<![\w/])" + re.escape(c) + r"(?![\w])", readme_text):
            return True
    return False


def owner(folder: Path, root: Path) -> Path | None:
    while True:
        if (folder / "README.md").is_file():
            return folder
        if folder == root or folder.parent == folder:
            return None
        folder = folder.parent


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=str(Path(__file__).resolve().parent.parent))
    args = ap.parse_args()
    root = Path(args.root)
    missing = []
    checked = 0
    for top in TOP:
        base = root / top
        if not base.is_dir():
            continue
        for f in sorted(base.rglob("*")):
            if f.suffix not in SOURCE or not f.is_file():
                continue
            home = owner(f.parent, base)
            if home is None:
                continue
            checked += 1
            if not named((home / "README.md").read_text(encoding="utf-8"), f.relative_to(home)):
                missing.append(f"{(home / 'README.md').relative_to(root)} does not name "
                               f"{f.relative_to(root)}")
    for line in missing:
        print(line)
    print(f"readme maps: {checked - len(missing)} of {checked} files named")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
