"""Malformed datasets for the module's tests: the cases of tests/test_support.cc
(MalformedDatasets), written again in Python as (what, text, field)."""
import copy
import json
import re

RAW = "__RAW_TOKEN__"


def valid_dataset():
    return {
        "format": "ringid-modal-dataset/1", "name": "t", "description": "d",
        "known": {"m_b": 2.37}, "initial": {"k_bx": 3e5}, "ties": {"k_bz": "k_bx"},
        "modes": [{"label": "vertical", "plane": "in_plane", "frequency_hz": 74.5,
                   "frequency_sigma_hz": 0.5, "damping_ratio": 0.08,
                   "damping_sigma": 0.02, "shape": {"z_b": 1.0, "x_b": 0.01},
                   "shape_sigma": 0.05}]}


def _path(field):
    return [int(p) if p.isdigit() else p for p in re.split(r"[.\[\]]+", field) if p]


def _set(d, field, value):
    *parent, last = _path(field)
    for p in parent:
        d = d[p]
    d[last] = value


def _erase(d, field):
    *parent, last = _path(field)
    for p in parent:
        d = d[p]
    del d[last]


FIELDS = [("format", "string", True), ("name", "string", True),
          ("description", "string", False), ("known", "object", False),
          ("initial", "object", False), ("ties", "object", False),
          ("known.m_b", "positive", False), ("initial.k_bx", "positive", False),
          ("ties.k_bz", "string", False), ("modes[0].label", "string", True),
          ("modes[0].plane", "string", False), ("modes[0].frequency_hz", "positive", True),
          ("modes[0].frequency_sigma_hz", "positive", False),
          ("modes[0].damping_ratio", "ratio", False), ("modes[0].damping_sigma", "positive", False),
          ("modes[0].shape", "object", False), ("modes[0].shape.x_b", "number", False),
          ("modes[0].shape_sigma", "positive", False)]
WRONG_TYPES = ["x", 3, True, None, [], {}]


def malformed_datasets():
    out = []

    def add(what, d, field, raw=None):
        text = json.dumps(d, indent=1)
        if raw is not None:
            text = text.replace('"%s"' % RAW, raw)
        out.append((what, text, field))

    for field, kind, required in FIELDS:
        if required:
            d = valid_dataset()
            _erase(d, field)
            add(field + " missing", d, field)
        for bad in WRONG_TYPES:
            is_number = isinstance(bad, (int, float)) and not isinstance(bad, bool)
            fits = ((kind == "string" and isinstance(bad, str)) or
                    (kind == "object" and isinstance(bad, dict)) or
                    (kind not in ("string", "object") and is_number))
            if fits or (isinstance(bad, dict) and kind == "object" and field != "modes[0].shape"):
                continue
            d = valid_dataset()
            _set(d, field, copy.deepcopy(bad))
            add("%s = %s" % (field, json.dumps(bad)), d, field)
        if kind == "string" and field != "description":
            d = valid_dataset()
            _set(d, field, "" if field == "name" else "no-such-thing")
            add(field + " bad value", d, field)
        if kind in ("positive", "ratio", "number"):
            for raw in ["NaN", "Infinity", "1e999", "-1e999"]:
                d = valid_dataset()
                _set(d, field, RAW)
                add("%s = %s" % (field, raw), d, field, raw)
        if kind in ("positive", "ratio"):
            for v in [0.0, -1.0]:
                d = valid_dataset()
                _set(d, field, v)
                add("%s = %g" % (field, v), d, field)
        if kind == "ratio":
            d = valid_dataset()
            _set(d, field, 1.0)
            add(field + " = 1", d, field)
    for field, value in [("modes[0].frequency_hz", 3610), ("modes[0].frequency_hz", 7750),
                         ("modes[0].frequency_hz", 1e30), ("modes[0].frequency_hz", 0.5),
                         ("initial.k_bx", 1e300), ("initial.k_bx", 2e12), ("known.m_b", 1e13)]:
        d = valid_dataset()
        _set(d, field, value)
        add("%s = %g (outside physics)" % (field, value), d, field)
    for what, field in [("unknown top-level key", "extra"),
                        ("unknown parameter in known", "known.k_qq"),
                        ("unknown parameter in initial", "initial.k_qq"),
                        ("unknown key in a mode", "modes[0].freq"),
                        ("unknown degree of freedom", "modes[0].shape.q_b")]:
        d = valid_dataset()
        _set(d, field, 1.0)
        add(what, d, field)
    cases = [("label outside the contract", lambda d: d["modes"][0].update(label="hub_vertical"),
              "modes[0].label"),
             ("label twice", lambda d: d["modes"].append(copy.deepcopy(d["modes"][0])),
              "modes[1].label"),
             ("no modes", lambda d: d.update(modes=[]), "modes"),
             ("damping sigma without ratio", lambda d: d["modes"][0].pop("damping_ratio"),
              "modes[0].damping_sigma"),
             ("shape sigma without shape", lambda d: d["modes"][0].pop("shape"),
              "modes[0].shape_sigma"),
             ("all-zero shape", lambda d: d["modes"][0].update(shape={"z_b": 0.0}),
              "modes[0].shape"),
             ("known and initial", lambda d: d["initial"].update(m_b=2.0), "initial.m_b")]
    for what, change, field in cases:
        d = valid_dataset()
        change(d)
        add(what, d, field)
    for what, source, target, field in [
            ("tie to itself", "k_btheta", "k_btheta", "ties.k_btheta"),
            ("tie to an unknown parameter", "k_btheta", "k_nope", "ties.k_btheta"),
            ("tie from an unknown parameter", "k_nope", "k_bx", "ties.k_nope"),
            ("tie chain", "k_btheta", "k_bz", "ties.k_btheta"),
            ("tied and initial", "k_bx", "k_btheta", "ties.k_bx")]:
        d = valid_dataset()
        d["ties"][source] = target
        add(what, d, field)
    valid = json.dumps(valid_dataset())
    for what, text in [("empty file", ""), ("truncated", valid[:len(valid) // 2]),
                       ("binary", "\x7fELF\x02\x01\x01\x00\x00\xff\xfe"),
                       ("top level array", "[1, 2]"),
                       ("duplicate key", '{"name": "a", "name": "b"}'),
                       ("nested too deep", "[" * 100 + "]" * 100)]:
        out.append((what, text, ""))
    return out
