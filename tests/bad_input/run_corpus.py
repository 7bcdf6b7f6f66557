#!/usr/bin/env python3
"""Runs every case of manifest.tsv (written by generate.py) against the sweeptrace binary.

For each case: a fresh copy of cases/<name>/ in a temporary folder, the setup steps (fifo,
sparse file or a committed header grown to a size, symlink, hard link, a large file written
here rather than committed; several
separated by " ; "), then the command, under `ulimit -v` when a step says `address-space MB`. Asserts the exit code; that stderr is one
line, starting `sweeptrace: error: `, at most 480 bytes, matching the case's pattern (which names
the file and the place); and that no file in the folder appeared, vanished or changed (so no
output, no partial output, no temporary left behind, no input overwritten).

usage: run_corpus.py BINARY [--only SUBSTRING] [--skip NAME,NAME] [--timeout SECONDS] [--quiet]
                     [--no-address-limit]
--no-address-limit skips the cases run under an address-space limit: a sanitizer build reserves
terabytes of shadow address space and cannot start under one (those cases need the plain build).
"""
import gzip
import hashlib
import os
import resource
import struct
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def snapshot(root):
    state = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            p = os.path.join(dirpath, name)
            st = os.lstat(p)
            entry = (st.st_mode, st.st_size, st.st_mtime_ns, st.st_ino)
            if os.path.isfile(p) and not os.path.islink(p) and st.st_size <= (4 << 20):
                with open(p, "rb") as f:
                    entry += (hashlib.sha256(f.read()).hexdigest(),)
            state[os.path.relpath(p, root)] = entry
    return state


def rle_tga(path, side):
    """A side x side 24-bit RLE TGA of one grey: 4 bytes per 128 pixels (2 MiB at 8192)."""
    packets, rest = divmod(side * side, 128)
    with open(path, "wb") as f:
        f.write(struct.pack("<BBBHHBHHHHBB", 0, 0, 10, 0, 0, 0, 0, 0, side, side, 24, 0))
        f.write(b"\xff\x80\x80\x80" * packets)
        if rest:
            f.write(bytes([0x80 | (rest - 1)]) + b"\x80\x80\x80")


def ply_gz_fans(path, faces):
    """A binary .ply.gz of `faces` faces of 255 uchar corners each (256 bytes of data, 253 triangles)."""
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex 255\nproperty float x\nproperty float y\n"
            f"property float z\nelement face {faces}\nproperty list uchar uchar vertex_indices\nend_header\n").encode()
    verts = b"".join(struct.pack("<3f", float(i % 16), float(i // 16), 0.0) for i in range(255))
    face = bytes([255]) + bytes(range(255))
    with gzip.GzipFile(path, "wb", compresslevel=6, mtime=0) as f:
        f.write(head + verts)
        chunk = face * 1024
        for _ in range(faces // 1024):
            f.write(chunk)
        f.write(face * (faces % 1024))


def set_up(work, setup):
    """The setup steps; returns the address-space limit in bytes, or None."""
    limit = None
    for step in filter(None, (s.strip() for s in setup.split(";"))):
        limit = set_up_step(work, step) or limit
    return limit


def set_up_step(work, step):
    op, *rest = step.split()
    if op == "address-space":
        return int(rest[0]) << 20
    if op == "rle-tga":
        rle_tga(os.path.join(work, rest[0]), int(rest[1]))
    elif op == "ply-gz-fans":
        ply_gz_fans(os.path.join(work, rest[0]), int(rest[1]))
    elif op == "fifo":
        os.mkfifo(os.path.join(work, rest[0]))
    elif op == "sparse":
        with open(os.path.join(work, rest[0]), "wb") as f:
            f.truncate(int(rest[1]))
    elif op == "grow":  # a committed file (an image header) extended by zeros, sparse, to a size
        with open(os.path.join(work, rest[0]), "r+b") as f:
            f.truncate(int(rest[1]))
    elif op == "symlink":
        os.symlink(rest[1], os.path.join(work, rest[0]))
    elif op == "hardlink":
        os.link(os.path.join(work, rest[1]), os.path.join(work, rest[0]))
    elif op == "device":  # a character device in place of an input file
        os.symlink(rest[1], os.path.join(work, rest[0]))
    else:
        raise ValueError(f"unknown setup step {step!r}")
    return None


TIMEOUT = 60


def run_case(binary, name, code, pattern, args, setup):
    problems = []
    tmp = tempfile.mkdtemp(prefix="sweeptrace-bad-input-")
    try:
        work = os.path.join(tmp, "work")
        source = os.path.join(HERE, "cases", name)
        if os.path.isdir(source):
            shutil.copytree(source, work, symlinks=True)
        else:  # a case with no files of its own (git keeps no empty folders)
            os.makedirs(work)
        limit = set_up(work, setup)
        before = snapshot(work)

        def address_space():
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

        try:
            r = subprocess.run([binary] + shlex.split(args), cwd=work, stdin=subprocess.DEVNULL,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=TIMEOUT,
                               preexec_fn=address_space if limit else None)
            exit_code, err = r.returncode, r.stderr.decode("utf-8", "replace")
        except subprocess.TimeoutExpired:
            exit_code, err = f"timeout ({TIMEOUT} s)", ""
        if exit_code != code:
            problems.append(f"exit {exit_code}, expected {code}")
        lines = [l for l in err.split("\n") if l]
        if len(lines) != 1:
            problems.append(f"{len(lines)} lines on stderr, expected 1")
        first = lines[0] if lines else ""
        if not first.startswith("sweeptrace: error: "):
            problems.append("message does not start with 'sweeptrace: error: '")
        if len(first) > 480:
            problems.append(f"message is {len(first)} bytes")
        if not re.search(pattern, first):
            problems.append(f"message does not match {pattern!r}")
        after = snapshot(work)
        if after != before:
            changed = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
            problems.append(f"files appeared/changed/vanished: {changed[:5]}")
        return problems, first[:300] if lines else err[:300]
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    binary = os.path.abspath(sys.argv[1])
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else ""
    quiet = "--quiet" in sys.argv
    skip = sys.argv[sys.argv.index("--skip") + 1].split(",") if "--skip" in sys.argv else []
    no_limit = "--no-address-limit" in sys.argv
    global TIMEOUT
    TIMEOUT = float(sys.argv[sys.argv.index("--timeout") + 1]) if "--timeout" in sys.argv else TIMEOUT
    cases = []
    with open(os.path.join(HERE, "manifest.tsv")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            name, code, pattern, args, setup = line.rstrip("\n").split("\t")
            if no_limit and "address-space" in setup:
                print(f"skip {name}: runs under an address-space limit (--no-address-limit)")
            elif only in name and name not in skip:
                cases.append((name, int(code), pattern, args, setup))
    failed = 0
    for c in cases:
        problems, message = run_case(binary, *c)
        if problems:
            failed += 1
            print(f"FAIL {c[0]}: {'; '.join(problems)}\n     got: {message}")
        elif not quiet:
            print(f"ok   {c[0]}")
    print(f"{len(cases) - failed} of {len(cases)} bad-input cases behave as promised")
    return 1 if failed or not cases else 0


if __name__ == "__main__":
    sys.exit(main())
