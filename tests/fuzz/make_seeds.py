#!/usr/bin/env python3
"""Writes the seed corpora of the model and identify fuzz targets from the
project's own datasets (datasets/paper/*.json) in the byte formats the targets
read (tests/fuzz/model_fuzzer.cc, tests/fuzz/identify_fuzzer.cc).
Run from the repository root: python3 tests/fuzz/make_seeds.py
The outputs are committed; CI does not need Python."""
import json
import struct
from pathlib import Path

# The 26 parameters in the order of model/parameters.h (and identify_fuzzer's base[]).
PARAMS = ["m_b", "I_ay", "I_by", "I_bx", "I_bz", "F_cz0", "c_bx", "c_bz",
          "c_btheta", "k_bx", "k_bz", "k_btheta", "K_cx", "sigma_cx", "r_e0",
          "k_cz", "c_by", "c_bgamma", "c_bpsi", "k_by", "k_bgamma", "k_bpsi",
          "K_cy", "sigma_cy", "r_l0", "t_0"]
# identify_fuzzer labels its k-th mode with ModeLabel k (model/names.h).
LABELS = ["rotation_in_phase", "rotation_anti_phase", "vertical", "longitudinal",
          "camber", "yaw", "lateral"]
paper = Path("datasets/paper")
out = Path("tests/fuzz/corpus")


def identify_seed(dataset, modes, simplex):
    b = bytearray()
    ties = dataset.get("ties", {})
    for name in PARAMS:
        if name in dataset.get("known", {}):
            b.append(0)
        elif name in ties:
            b += bytes([2, PARAMS.index(ties[name])])
        else:
            b.append(1)
    kept = [m for m in dataset["modes"] if m["label"] in LABELS[:modes]]
    kept.sort(key=lambda m: LABELS.index(m["label"]))
    assert [m["label"] for m in kept] == LABELS[:len(kept)]
    b.append(len(kept) - 1)
    for m in kept:
        b += struct.pack("<d", m["frequency_hz"])
        b.append(1 if "frequency_sigma_hz" in m else 0)
        b.append(0)  # no damping
        b.append(0)  # no shape
    b += bytes([0, 1 if simplex else 0])  # one start; method
    return bytes(b)


def model_seed(parameters, effects_mask):
    values = [parameters[n]["value"] for n in PARAMS]
    return bytes([effects_mask]) + b"".join(struct.pack("<d", v) for v in values)


table1 = json.loads((paper / "table1.json").read_text())
recovery = json.loads((paper / "inertia_recovery.json").read_text())
seeds = {
    "identify/table1-lm": identify_seed(table1, 7, False),
    "identify/table1-simplex": identify_seed(table1, 7, True),
    "identify/table1-in-plane": identify_seed(table1, 4, False),
    "identify/inertia-recovery": identify_seed(recovery, 7, False),
}
parameters = json.loads((paper / "parameters.json").read_text())["parameters"]
seeds["model/paper-parameters"] = model_seed(parameters, 0)
seeds["model/paper-parameters-all-effects"] = model_seed(parameters, 0xFF)
for name, data in seeds.items():
    (out / name).parent.mkdir(parents=True, exist_ok=True)
    (out / name).write_bytes(data)
    print(f"{out / name}: {len(data)} bytes")
