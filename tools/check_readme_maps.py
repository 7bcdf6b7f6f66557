#!/usr/bin/env python3
"""Each source folder's README.md is its map and names every file in it (the project's rule), checked.

The rules (each broken one is reported on one line):

  unnamed      Every source file (.cpp, .hpp, .h, .inl) under raytracer/ and collision/ is named
               by the README.md of its folder or, for a folder without one, of its nearest
               ancestor that has one (collision/README.md covers collision/thesis/ and
               collision/detail/).
               A file counts as named when the README holds, standing alone (not as the tail
               of a longer name such as `x_bvh.cpp`, nor after a folder as `other/bvh.cpp`):
               its path from the README's folder, by name or by stem with a star
               (`integrators/path.cpp`, `integrators/path.*`; for a file beside the README
               that is just `bvh.cpp` or `bvh.*`); or its bare name or `stem.*` when that
               bare form fits no other file the README covers. So collision/README.md must
               write `thesis/intersect_sphere.cpp`: `intersect_sphere.cpp` is the default's.
  no map       raytracer/README.md is the map of the stages, not of their files: it covers
               only the files directly in raytracer/, and every folder directly under
               raytracer/ that holds source files (at any depth) has a README.md of its own.
  unlisted     raytracer/README.md's table names every such stage folder (`cli/`), so the
               top map points to each folder's map.
  stale        Every name in the first column of a README's file table (a table whose header
               starts with `file`, `files` or `folder`) is there: a file, `stem.*` with at
               least one file, or a folder (`cli/`), relative to the README's folder. A map
               that names a deleted or renamed file is as wrong as one that misses a file.

Usage:
  check_readme_maps.py [--root DIR]             exit 0 if every rule holds, 1 otherwise
  check_readme_maps.py --root DIR --expect F    self-check: exit 0 only if exactly the lines
                                                listed in F are reported
"""
import argparse
import re
import sys
from pathlib import Path

from self_check import compare_with_expected

SOURCE = {".cpp", ".hpp", ".h", ".inl"}
TOPS = ("raytracer", "collision")
STAGE_MAP = "raytracer"  # its README maps the stage folders; each stage has its own README
TABLE_HEADS = {"file", "files", "folder", "folders"}


def sources_under(folder: Path) -> list[Path]:
    return sorted(f for f in folder.rglob("*") if f.suffix in SOURCE and f.is_file())


def forms(rel: Path) -> tuple[set[str], set[str]]:
    """(path forms, bare forms) a README may use to name the file at `rel` from its folder."""
    stem_star = rel.stem + ".*"
    path_forms = {rel.as_posix(), (rel.parent / stem_star).as_posix()}
    return path_forms, {rel.name, stem_star}


def mentions(text: str, name: str) -> bool:
    # Standing alone: not the tail of a longer name (`x_bvh.cpp`) nor of a path (`a/bvh.cpp`),
    # and not followed by more of a name (`bvh.cpp2`).
    return re.search(r"(?<![\w/.-])" + re.escape(name) + r"(?![\w])", text) is not None


def owner(folder: Path, root: Path) -> Path | None:
    """The folder whose README covers the files in `folder`: its own, else its nearest ancestor's,
    but never the stage map's for a file inside a stage folder. None when there is none."""
    top = root / folder.relative_to(root).parts[0]
    while True:
        if (folder / "README.md").is_file():
            return folder
        if folder == top or (top.name == STAGE_MAP and folder.parent == top):
            return None
        folder = folder.parent


def needs_map(folder: Path, root: Path) -> Path:
    """The folder that should have the README a file in `folder` lacks: its stage, or its top."""
    parts = folder.relative_to(root).parts
    return root.joinpath(*parts[:2]) if parts[0] == STAGE_MAP and len(parts) > 1 else root / parts[0]


def table_entries(text: str) -> list[str]:
    """Backticked names in the first column of the README's file and folder tables."""
    entries = []
    table = None  # None outside a table; else whether this table's rows name files or folders
    for line in text.splitlines():
        if not line.lstrip().startswith("|"):
            table = None
            continue
        first = line.strip().strip("|").split("|")[0].strip()
        if table is None:
            table = first.lower() in TABLE_HEADS  # the header row
        elif table and not set(first) <= set("-: "):  # not the separator row
            entries += re.findall(r"`([^`]+)`", first)
    return entries


def entry_exists(folder: Path, entry: str) -> bool:
    if entry.endswith("/"):
        return (folder / entry).is_dir()
    if entry.endswith(".*"):
        target = folder / entry[:-2]
        return any(p.stem == target.name and p.suffix in SOURCE for p in target.parent.glob(target.name + ".*"))
    return (folder / entry).is_file()


def check(root: Path) -> tuple[list[str], int]:
    """The problems found, and how many source files a README covers."""
    problems = []
    covered: dict[Path, list[Path]] = {}  # README folder -> the files it must name
    unmapped: set[Path] = set()
    for top in TOPS:
        base = root / top
        if not base.is_dir():
            continue
        for f in sources_under(base):
            home = owner(f.parent, root)
            if home is None:
                unmapped.add(needs_map(f.parent, root))
            else:
                covered.setdefault(home, []).append(f)
    for folder in sorted(unmapped):
        problems.append(f"{folder.relative_to(root).as_posix()}/ holds source files but has no README.md")

    stage_map = root / STAGE_MAP
    if (stage_map / "README.md").is_file():
        listed = set(table_entries((stage_map / "README.md").read_text(encoding="utf-8")))
        for stage in sorted(p for p in stage_map.iterdir() if p.is_dir()):
            if sources_under(stage) and stage.name + "/" not in listed:
                problems.append(f"{STAGE_MAP}/README.md does not list {stage.relative_to(root).as_posix()}/ in its table")

    for home, files in sorted(covered.items()):
        readme = home / "README.md"
        text = readme.read_text(encoding="utf-8")
        rels = [f.relative_to(home) for f in files]
        bare_count: dict[str, int] = {}
        for rel in rels:
            for b in forms(rel)[1]:
                bare_count[b] = bare_count.get(b, 0) + 1
        for f, rel in zip(files, rels):
            path_forms, bare_forms = forms(rel)
            usable = path_forms | {b for b in bare_forms if bare_count[b] == 1}
            if not any(mentions(text, name) for name in usable):
                problems.append(f"{readme.relative_to(root).as_posix()} does not name {f.relative_to(root).as_posix()}")

    for top in TOPS:
        if not (root / top).is_dir():
            continue
        for readme in sorted((root / top).rglob("README.md")):
            for entry in table_entries(readme.read_text(encoding="utf-8")):
                if not entry_exists(readme.parent, entry):
                    problems.append(f"{readme.relative_to(root).as_posix()} names `{entry}`, which is not there")
    return problems, sum(len(files) for files in covered.values())


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=str(Path(__file__).resolve().parent.parent))
    ap.add_argument("--expect", help="self-check: the file listing exactly the lines to report")
    args = ap.parse_args()
    problems, files = check(Path(args.root))
    if args.expect:
        return compare_with_expected(args.expect, set(problems), "problem")
    for line in problems:
        print(line)
    if problems:
        print(f"readme maps: {len(problems)} problem(s); {files} source files under a README")
    else:
        print(f"readme maps: every rule holds; {files} source files, each named by its README")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
