#!/usr/bin/env python3
"""Writes datasets/examples/car_tire_hammer.uff and its map, a hammer test as a
lab's UFF 58 file would hold it (docs/uff.md), and the uff58 fuzz target's
seeds (tests/fuzz/corpus/uff58/).

The FRFs are closed form, not a measurement: the belt of
datasets/examples/car_tire.json hanging free with the rim held, whose in-plane
coordinates x_b, z_b and theta_b are then three uncoupled damped
single-degree-of-freedom systems (m_b, k_bx, c_bx; m_b, k_bz, c_bz; I_by,
k_btheta, c_btheta). A point force F along d at p drives each coordinate q
with contract §9's coefficient a_q(p, d); a sensor at p' along d' reads
sum_q a_q(p', d') q, so the accelerance is
    H(w) = -w^2 sum_q a_q(p', d') a_q(p, d) / (k_q - w^2 m_q + i w c_q).
Inputs: a tangential blow at the top of the tread (p = (0, 0, -r)) and a
vertical one at its front (p = (r, 0, 0)); outputs: accelerometers along x at
the top, along z at the front, along x at the bottom. r = r_e0.

The file is written as many labs write one: lengths in millimetres (dataset
164 'mm (newton)'), FRFs in mm/s^2 per N with their unit exponents and
labels, a coherence per FRF (0.98 + 0.015 cos(f / 40 Hz)), lines 0 to 250 Hz
by 2.5 Hz (the 0 Hz line is left out on import), and the nodes (dataset 15)
in a z-up lab frame (x forward, y left): the map's axes ["x", "-y", "-z"].
Run from the repository root: python3 scripts/make_hammer_example.py
"""
import cmath
import json
import math
from pathlib import Path

params = {k: v["value"] for k, v in
          json.load(open("datasets/examples/car_tire.json"))["parameters"].items()}
r = params["r_e0"]
# coordinate -> (mass, stiffness, damper)
coords = {"x_b": (params["m_b"], params["k_bx"], params["c_bx"]),
          "z_b": (params["m_b"], params["k_bz"], params["c_bz"]),
          "theta_b": (params["I_by"], params["k_btheta"], params["c_btheta"])}


def combination(p, d):
    """Contract §9's in-plane belt coefficients of point p along d."""
    return {"x_b": d[0], "z_b": d[2], "theta_b": d[2] * p[0] - d[0] * p[2]}


# node -> ringid point (m); the node's UFF direction -> ringid direction
nodes = {1: (0.0, 0.0, -r), 2: (r, 0.0, 0.0), 3: (0.0, 0.0, r)}
inputs = [(1, (1, 0, 0)), (2, (0, 0, 1))]
outputs = [(1, (1, 0, 0)), (2, (0, 0, 1)), (3, (1, 0, 0))]
lines = [2.5 * i for i in range(101)]


def accelerance(out, inp, f):
    w = 2 * math.pi * f
    a_out, a_in = combination(nodes[out[0]], out[1]), combination(nodes[inp[0]], inp[1])
    return sum(-w * w * a_out[q] * a_in[q] / complex(k - w * w * m, w * c)
               for q, (m, k, c) in coords.items())


def lab_direction(d):
    """The lab's (z up, y left) UFF direction of ringid direction d."""
    lab = (d[0], -d[1], -d[2])
    k = max(range(3), key=lambda i: abs(lab[i]))
    return (k + 1) * (1 if lab[k] > 0 else -1)


def axis(kind, length, force, label, units):
    return "%10d%5d%5d%5d %-20s %-20s\n" % (kind, length, force, 0, label, units)


def function58(kind, out, inp, values, name):
    s = "    -1\n    58\n%s\nNONE\nNONE\nNONE\nNONE\n" % name
    s += "%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n" % (
        kind, 1, 0, 0, "NONE", out[0], lab_direction(out[1]), "NONE", inp[0],
        lab_direction(inp[1]))
    complex_data = kind == 4
    s += "%10d%10d%10d%13.5E%13.5E%13.5E\n" % (6 if complex_data else 4, len(values), 1,
                                               lines[0], lines[1] - lines[0], 0.0)
    s += axis(18, 0, 0, "Frequency", "Hz")
    if complex_data:
        s += axis(12, 1, 0, "Acceleration", "mm/s^2") + axis(13, 0, 1, "Force", "N")
    else:
        s += axis(0, 0, 0, "Coherence", "NONE") + axis(0, 0, 0, "NONE", "NONE")
    s += axis(0, 0, 0, "NONE", "NONE")
    flat = []
    for v in values:
        flat += [v.real, v.imag] if complex_data else [v]
    for i in range(0, len(flat), 4):
        s += "".join("%20.12E" % x for x in flat[i:i + 4]) + "\n"
    return s + "    -1\n"


def header(nodes_mm):
    s = "    -1\n   151\ncar_tire_hammer\nringid: closed-form FRFs of car_tire.json's belt, " \
        "hanging free, rim held\nringid scripts/make_hammer_example.py\n" \
        "27-Nov-26 00:00:00\n27-Nov-26 00:00:00\nringid\n27-Nov-26 00:00:00\n    -1\n"
    s += "    -1\n   164\n%10d%-20s%10d\n%25.17E%25.17E%25.17E\n%25.17E\n    -1\n" % (
        10, "mm (newton)", 2, 1000.0, 1.0, 1.0, 0.0)
    s += "    -1\n    15\n"
    for n, p in nodes_mm.items():
        s += "%10d%10d%10d%10d%13.5E%13.5E%13.5E\n" % (n, 0, 0, 8, p[0], -p[1], -p[2])
    return s + "    -1\n"


def write(path, text):
    Path(path).write_text(text)


nodes_mm = {n: tuple(1000 * x for x in p) for n, p in nodes.items()}
text = header(nodes_mm)
for inp in inputs:
    for out in outputs:
        h = [1000 * accelerance(out, inp, f) if f > 0 else 0j for f in lines]
        text += function58(4, out, inp, h, "FRF")
        gamma2 = [0.98 + 0.015 * math.cos(f / 40) for f in lines]
        text += function58(6, out, inp, gamma2, "Coherence")
write("datasets/examples/car_tire_hammer.uff", text)
write("datasets/examples/car_tire_hammer_map.json", json.dumps({
    "format": "ringid-uff-map/2",
    "name": "car-tire-hammer",
    "description": "closed-form hammer test of datasets/examples/car_tire.json's belt, hanging "
                   "free with the rim held (scripts/make_hammer_example.py); not a measurement",
    "axes": ["x", "-y", "-z"],
    "points": [{"node": n, "on": "belt"} for n in nodes],
    "averages": 10}, indent=2) + "\n")

# Seeds of the uff58 fuzz target (its maps place nodes 1, 2 and 3): one FRF
# with its coherence, and one 58b-free file of two FRFs on other lines.
seeds = Path("tests/fuzz/corpus/uff58")
seeds.mkdir(parents=True, exist_ok=True)
del lines[8:]
one = header(nodes_mm) + function58(4, outputs[1], inputs[0],
                                    [1000 * accelerance(outputs[1], inputs[0], f) + 0j
                                     for f in lines], "FRF")
one += function58(6, outputs[1], inputs[0], [0.99] * len(lines), "Coherence")
write(seeds / "frf_coherence.uff", one)
lines[:] = [1.0 + i for i in range(6)]
two = header(nodes_mm) + function58(4, outputs[0], inputs[1],
                                    [accelerance(outputs[0], inputs[1], f) for f in lines], "FRF")
write(seeds / "other_lines.uff", two)
