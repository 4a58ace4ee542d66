#!/usr/bin/env python3
"""Identifies the paper's Table 1 in-process and plots the fitted modes.

Usage: python3 python/examples/identify_table1.py [FIGURE.png]
(with the module importable: installed, or PYTHONPATH=build/python). The
figure needs matplotlib (python3-matplotlib); without it the script prints.
"""
import os
import sys

import numpy as np

import ringid

HERE = os.path.dirname(os.path.abspath(__file__))
TABLE1 = os.path.join(HERE, "..", "..", "datasets", "paper", "table1.json")


def main():
    fit = ringid.identify(TABLE1, derivatives="analytic")
    print(fit.text)
    # The fitted values as a parameter set, and their modes with shapes.
    modes = ringid.predict(parameters=fit.parameter_set())
    labels = [m["label"] for m in modes.modes]
    for label, hz, zeta in zip(labels, modes.frequencies, modes.damping_ratios):
        print("%-22s %8.3f Hz  zeta %.3f" % (label, hz, zeta))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib is not installed: no figure)")
        return
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7))
    x = np.arange(len(fit.modes))
    top.bar(x - 0.2, fit.measured_hz, 0.4, label="measured (Table 1)")
    top.bar(x + 0.2, fit.model_hz, 0.4, label="identified model")
    top.set_xticks(x, [m["label"] for m in fit.modes], rotation=30, ha="right")
    top.set_ylabel("Hz")
    top.legend()
    shapes = np.abs(modes.shapes)
    shapes /= shapes.max(axis=1, keepdims=True)
    image = bottom.imshow(shapes, aspect="auto", cmap="viridis")
    bottom.set_yticks(range(len(labels)), labels)
    bottom.set_xticks(range(len(modes.dofs)), modes.dofs, rotation=30)
    bottom.set_title("|mode shape| of the identified model (each mode scaled to 1)")
    fig.colorbar(image, ax=bottom)
    fig.tight_layout()
    out = sys.argv[1] if len(sys.argv) > 1 else "table1_modes.png"
    fig.savefig(out)
    print("wrote", out)


if __name__ == "__main__":
    main()
