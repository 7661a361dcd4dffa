#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora from tests/data into OUT/<target>/.

parse: every tests/data/*.nc and hostile/* file as it is.
run:   the same programs behind a few setup headers (see fuzz/common/mod.rs).
link:  every link of tests/data/golden_links.json.
"""
import hashlib, json, os, struct, sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "fuzz", "target", "seeds")
data = os.path.join(root, "tests", "data")
HEADER = 44
MAX_SEED = 64 * 1024


def value(v):
    return struct.pack("<i", int(round(v * 1000)) + (1 << 23))[:3]


def header(flags=0, more=0, registers=()):
    h = bytearray(HEADER)
    h[0], h[1] = flags, more
    for i, (n, v, z) in enumerate(registers[:4]):
        at = 16 + i * 7
        h[at] = n
        h[at + 1:at + 4] = value(v)
        h[at + 4:at + 7] = value(z)
    return bytes(h)


HEADERS = {
    "default": header(),
    "mill": header(0, 0, [(1, 6.0, 0), (2, 10.0, 0), (3, -5.0, 0), (5, 100.0, 0)]),
    "mill-next-z-mirror": header(16 | 64, 32, [(1, 6.0, 0), (2, 120.5, 0)]),
    "inch-calculator": header(2 | 4, 0, [(1, 0.25, 0)]),
    "lathe": header(1, 0, [(1, 0.4, -0.2), (8, 0.4, -0.2), (2, -1.0, 0.5)]),
    "lathe-radius-skip": header(1 | 8 | 32, 0, [(1, 0.4, -0.2), (8, 0.2, 0.1)]),
}


def write(target, content):
    d = os.path.join(out, target)
    os.makedirs(d, exist_ok=True)
    name = hashlib.sha1(content).hexdigest()
    with open(os.path.join(d, name), "wb") as f:
        f.write(content)


programs = []
for folder in (data, os.path.join(data, "hostile")):
    if os.path.isdir(folder):
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if os.path.isfile(path) and not name.endswith((".json", ".md")):
                with open(path, "rb") as f:
                    programs.append(f.read(MAX_SEED))
for p in programs:
    write("parse", p)
    for h in HEADERS.values():
        write("run", h + p)
with open(os.path.join(data, "golden_links.json")) as f:
    for entry in json.load(f):
        write("link", entry["link"].encode())
        write("link", json.dumps(entry["document"]).encode())
for target in ("parse", "run", "link"):
    print(target, len(os.listdir(os.path.join(out, target))), "seeds")
