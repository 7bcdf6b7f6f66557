"""The self-check of a tree checker (check_include_rules.py, check_readme_maps.py): run on a
fixture with known breaches planted, it must report exactly the lines its expected file lists,
so a checker that reports nothing, or too much, fails its own test."""


def compare_with_expected(expect_file: str, got: set[str], noun: str) -> int:
    """0 when `got` is exactly the lines of `expect_file` (blank lines and `#` comments skipped),
    else 1 after one line per planted `noun` missed and per line reported but not planted."""
    with open(expect_file, encoding="utf-8") as f:
        expected = {line.strip() for line in f if line.strip() and not line.startswith("#")}
    for line in sorted(expected - got):
        print(f"self-check: planted {noun} not reported: {line}")
    for line in sorted(got - expected):
        print(f"self-check: reported but not planted: {line}")
    if expected != got:
        return 1
    print(f"self-check: all {len(expected)} planted {noun}s reported, nothing else")
    return 0
