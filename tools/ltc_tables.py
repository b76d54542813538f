#!/usr/bin/env python3
"""Vendor the LTC fit tables of Heitz, Dupuy, Hill and Neubelt (2016) for gloss.

Reads fit/results/ltc.js of github.com/selfshadow/ltc_code (BSD licence; the
GGX fit that fitLTC.cpp writes: `g_ltc_1`, the inverse matrix's four free
terms m00, m02, m20, m22 normalised by m11; `g_ltc_2`, the magnitude (the
BRDF's directional albedo with F = 1), the Schlick Fresnel term, 0 and the
horizon-clipped sphere table) and writes each as 64 x 64 x 4 little-endian
f32 (texel (a, t) at index a + 64 t: a the roughness sqrt(alpha) step, t the
sqrt(1 - cos theta_v) step) into src/lighting/ltc_tables/ltc_1.bin and
ltc_2.bin, which src/lighting/ltc.rs includes.

    python3 tools/ltc_tables.py path/to/ltc_code/fit/results/ltc.js
"""
import re
import struct
import sys
from pathlib import Path

N = 64


def table(text, name):
    m = re.search(r"var\s+" + name + r"\s*=\s*\[(.*?)\];", text, re.S)
    if not m:
        sys.exit(f"{name} not found")
    values = [float(v) for v in m.group(1).replace("\n", " ").split(",") if v.strip()]
    if len(values) != N * N * 4:
        sys.exit(f"{name}: expected {N * N * 4} numbers, found {len(values)}")
    return values


def main():
    text = Path(sys.argv[1]).read_text()
    out = Path(__file__).resolve().parent.parent / "src/lighting/ltc_tables"
    for name, file in (("g_ltc_1", "ltc_1.bin"), ("g_ltc_2", "ltc_2.bin")):
        values = table(text, name)
        (out / file).write_bytes(struct.pack(f"<{len(values)}f", *values))
        print(f"{out / file}: {len(values)} floats")


if __name__ == "__main__":
    main()
