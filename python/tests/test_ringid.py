"""The Python module against the command line: each operation's to_dict()
equals the JSON report `ringid` writes for the same input and flags (to
1e-12, all fields but provenance and timings), and bad input raises
ringid.Error with the command line's line, never a crash."""
import copy
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import ringid
from malformed import malformed_datasets

SOURCE = os.environ.get("RINGID_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("RINGID_BINARY", os.path.join(SOURCE, "build", "ringid"))
TABLE1 = os.path.join(SOURCE, "datasets", "paper", "table1.json")
PARAMETERS = os.path.join(SOURCE, "datasets", "paper", "parameters.json")
ROLLING = os.path.join(SOURCE, "datasets", "examples", "car_tire_rolling.json")
CAR_TIRE = os.path.join(SOURCE, "datasets", "examples", "car_tire.json")
LUG_RESPONSE = os.path.join(SOURCE, "datasets", "examples", "car_tire_lug_response.json")
HAMMER_SPEC = os.path.join(SOURCE, "datasets", "examples", "hammer_spec.json")
TIR = os.path.join(SOURCE, "datasets", "examples", "tno_205_60R15_belt.tir")
TIMINGS = {"seconds", "seconds_per_fit", "fit_seconds", "median_seconds"}


def cli_report(command, *flags):
    """The JSON report of `ringid COMMAND FLAGS --output=...`, and its exit status."""
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "report.json")
        done = subprocess.run([BINARY, command, *flags, "--output=" + out],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if done.returncode not in (0, 1):
            raise AssertionError("ringid %s failed: %s" % (command, done.stderr))
        with open(out) as f:
            return json.load(f)


def cli_error(command, *flags):
    """What `ringid COMMAND FLAGS` prints after "ringid: " when it exits 2."""
    done = subprocess.run([BINARY, command, *flags], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    assert done.returncode == 2, (done.returncode, done.stderr)
    return done.stderr.strip()[len("ringid: "):]


def written(folder, name, text):
    """The path of file NAME in FOLDER, holding TEXT."""
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def without_run(report):
    """The report less its provenance and its timings."""
    report = copy.deepcopy(report)
    report.pop("provenance")

    def strip(node):
        if isinstance(node, dict):
            for key in [k for k in node if k in TIMINGS]:
                del node[key]
            for value in node.values():
                strip(value)
        elif isinstance(node, list):
            for value in node:
                strip(value)
    strip(report)
    return report


class ReportTestCase(unittest.TestCase):
    def assertSameReport(self, module_report, cli, path="", tolerance=1e-12):
        """Equal structure and strings; numbers within tolerance (relative above 1)."""
        if path == "":
            module_report, cli = without_run(module_report), without_run(cli)
        if isinstance(cli, dict):
            self.assertIsInstance(module_report, dict, path)
            self.assertEqual(sorted(module_report), sorted(cli), path)
            for key in cli:
                self.assertSameReport(module_report[key], cli[key], path + "." + key, tolerance)
        elif isinstance(cli, list):
            self.assertIsInstance(module_report, list, path)
            self.assertEqual(len(module_report), len(cli), path)
            for i, (a, b) in enumerate(zip(module_report, cli)):
                self.assertSameReport(a, b, "%s[%d]" % (path, i), tolerance)
        elif isinstance(cli, float) or isinstance(module_report, float):
            self.assertFalse(isinstance(cli, bool) or isinstance(module_report, bool), path)
            scale = max(1.0, abs(cli), abs(module_report))
            self.assertLessEqual(abs(module_report - cli), tolerance * scale, path)
        else:
            self.assertEqual(module_report, cli, path)


class OperationsEqualTheCommandLine(ReportTestCase):
    def test_identify_table1_equals_the_command_line(self):
        self.assertSameReport(ringid.identify(TABLE1).to_dict(),
                              cli_report("identify", "--dataset=" + TABLE1))

    def test_identify_table1_analytic_one_start_equals_the_command_line(self):
        r = ringid.identify(TABLE1, starts=1, derivatives="analytic")
        self.assertSameReport(r.to_dict(), cli_report(
            "identify", "--dataset=" + TABLE1, "--starts=1", "--derivatives=analytic"))

    def test_saved_parameters_equal_the_command_line_ones(self):
        with tempfile.TemporaryDirectory() as scratch:
            cli, module = os.path.join(scratch, "cli.json"), os.path.join(scratch, "module.json")
            subprocess.run([BINARY, "identify", "--dataset=" + TABLE1, "--starts=1",
                            "--save_parameters=" + cli], stdout=subprocess.DEVNULL, check=True)
            fit = ringid.identify(TABLE1, starts=1)
            fit.save_parameters(module)
            with open(cli) as f, open(module) as g:
                self.assertEqual(g.read(), f.read())
        self.assertEqual(fit.parameter_set()["k_bx"], fit.parameters["k_bx"]["value"])

    def test_identify_rolling_equals_the_command_line(self):
        self.assertSameReport(ringid.identify(ROLLING, starts=2).to_dict(),
                              cli_report("identify", "--dataset=" + ROLLING, "--starts=2"))

    def test_identifiability_table1_equals_the_command_line(self):
        self.assertSameReport(ringid.identifiability(TABLE1, starts=1).to_dict(),
                              cli_report("identifiability", "--dataset=" + TABLE1, "--starts=1"))

    def test_identifiability_rolling_equals_the_command_line(self):
        self.assertSameReport(ringid.identifiability(ROLLING, starts=1).to_dict(),
                              cli_report("identifiability", "--dataset=" + ROLLING, "--starts=1"))

    def test_diagnose_table1_equals_the_command_line(self):
        self.assertSameReport(ringid.diagnose(TABLE1, starts=1).to_dict(),
                              cli_report("diagnose", "--dataset=" + TABLE1, "--starts=1"))

    def test_diagnose_rolling_equals_the_command_line(self):
        self.assertSameReport(ringid.diagnose(ROLLING, starts=1).to_dict(),
                              cli_report("diagnose", "--dataset=" + ROLLING, "--starts=1"))

    def test_compare_table1_equals_the_command_line(self):
        self.assertSameReport(ringid.compare(TABLE1, starts=2).to_dict(),
                              cli_report("compare", "--dataset=" + TABLE1, "--starts=2"))

    def test_predict_at_speeds_equals_the_command_line(self):
        r = ringid.predict(parameters=PARAMETERS, speeds=[0, 10, 20.5], lugs_per_revolution=5)
        self.assertSameReport(r.to_dict(), cli_report(
            "predict", "--parameters=" + PARAMETERS, "--speeds=0,10,20.5",
            "--lugs_per_revolution=5"))

    def test_predict_rolling_dataset_equals_the_command_line(self):
        self.assertSameReport(ringid.predict(dataset=ROLLING).to_dict(),
                              cli_report("predict", "--dataset=" + ROLLING))

    def test_predict_tir_with_set_equals_the_command_line(self):
        car = ringid.load_parameters(CAR_TIRE)
        rest = ["I_ay", "F_cz0", "c_bx", "c_bz", "c_btheta", "K_cx", "sigma_cx", "r_e0", "k_cz",
                "c_by", "c_bgamma", "c_bpsi", "K_cy", "sigma_cy", "r_l0", "t_0"]
        given = {name: car[name] for name in rest}
        r = ringid.predict(parameters=TIR, set=given)
        self.assertSameReport(r.to_dict(), cli_report(
            "predict", "--parameters=" + TIR,
            "--set=" + ",".join("%s=%r" % (k, v) for k, v in given.items())))

    def test_forces_equal_the_command_line(self):
        self.assertSameReport(ringid.forces(PARAMETERS, LUG_RESPONSE).to_dict(), cli_report(
            "forces", "--parameters=" + PARAMETERS, "--dataset=" + LUG_RESPONSE))

    def test_forces_from_an_identify_result_equal_those_from_its_report(self):
        fit = ringid.identify(ROLLING, starts=1)
        with tempfile.TemporaryDirectory() as scratch:
            path = written(scratch, "fit.json", fit.to_json())
            from_file = ringid.forces(path, LUG_RESPONSE).to_dict()
        from_result = ringid.forces(fit, LUG_RESPONSE).to_dict()
        from_file["dataset"] = from_result["dataset"]
        self.assertSameReport(from_result, from_file, tolerance=0)

    def test_forces_refuse_set_over_a_fit_as_the_command_line(self):
        # A fit's values carry its covariance: set= over them is refused, from
        # the result held as from its report on the command line.
        fit = ringid.identify(ROLLING, starts=1)
        with tempfile.TemporaryDirectory() as scratch:
            path = written(scratch, "fit.json", fit.to_json())
            line = cli_error("forces", "--parameters=" + path, "--set=I_ay=0.4",
                             "--dataset=" + LUG_RESPONSE)
            with self.assertRaises(ringid.Error) as caught:
                ringid.forces(path, LUG_RESPONSE, set={"I_ay": 0.4})
            self.assertEqual(str(caught.exception), line)
        self.assertTrue(line.startswith("--set: not over an identify report"), line)
        with self.assertRaises(ringid.Error) as caught:
            ringid.forces(fit, LUG_RESPONSE, set={"I_ay": 0.4})
        self.assertEqual(caught.exception.field, "set")

    def test_simulate_equals_the_command_line(self):
        with tempfile.TemporaryDirectory() as scratch:
            output, truth = os.path.join(scratch, "sim.json"), os.path.join(scratch, "truth.json")
            flags = {"seed": 3, "speeds": [0, 10], "effects": "hub_compliance", "shift": 0.04, "set": {"m_a": 10.0}}
            done = subprocess.run(
                [BINARY, "simulate", "--parameters=" + PARAMETERS, "--output=" + output,
                 "--truth=" + truth, "--seed=3", "--speeds=0,10", "--effects=hub_compliance",
                 "--shift=0.04", "--set=m_a=10.0"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(output) as f, open(truth) as g:
                cli = {"dataset": json.load(f), "truth": json.load(g)}
            r = ringid.simulate(PARAMETERS, output=output, truth=truth, **flags)
            self.assertEqual(r.to_dict(), cli)
            self.assertEqual(r.dataset.name, "sim")


class InputsAndResults(ReportTestCase):
    def test_a_dataset_from_a_dict_fits_as_from_its_file(self):
        with open(TABLE1) as f:
            as_dict = json.load(f)
        self.assertSameReport(ringid.identify(as_dict, starts=1).to_dict(),
                              ringid.identify(TABLE1, starts=1).to_dict(), tolerance=0)

    def test_a_loaded_dataset_fits_as_its_path(self):
        d = ringid.load_dataset(TABLE1)
        self.assertEqual(d.name, ringid.identify(d, starts=1).dataset)
        self.assertSameReport(ringid.identify(d, starts=1).to_dict(),
                              ringid.identify(TABLE1, starts=1).to_dict(), tolerance=0)

    def test_a_parameter_set_in_memory_predicts_as_its_file(self):
        from_file = ringid.load_parameters(PARAMETERS)
        in_memory = ringid.ParameterSet(from_file.values)
        np.testing.assert_array_equal(ringid.predict(parameters=in_memory).frequencies,
                                      ringid.predict(parameters=PARAMETERS).frequencies)
        self.assertEqual(ringid.predict(parameters=in_memory).labels,
                         [m["label"] for m in ringid.predict(parameters=PARAMETERS).modes])
        with self.assertRaises(ringid.Error):
            ringid.ParameterSet({"m_bb": 1.0})
        with self.assertRaises(ringid.Error):
            ringid.ParameterSet({"m_b": math.inf})

    def test_attributes_are_the_report_fields(self):
        r = ringid.identify(TABLE1, starts=1)
        d = r.to_dict()
        self.assertEqual(r.cost, d["cost"])
        self.assertEqual(r.parameters, d["parameters"])
        self.assertIn("modes", dir(r))
        with self.assertRaises(AttributeError):
            r.no_such_field

    def test_arrays_hold_the_report_values(self):
        r = ringid.identify(TABLE1, starts=1)
        d = r.to_dict()
        np.testing.assert_array_equal(r.covariance_matrix, np.array(d["covariance"]["matrix"]))
        np.testing.assert_array_equal(r.model_hz, [m["model_hz"] for m in d["modes"]])
        np.testing.assert_array_equal(r.singular_values, d["covariance"]["singular_values"])
        self.assertEqual(r.jacobian.shape, (len(d["modes"]), len(r.coordinate_names)))
        p = ringid.predict(parameters=PARAMETERS)
        np.testing.assert_array_equal(p.frequencies, [m["model_hz"] for m in p.modes])
        self.assertEqual(p.shapes.shape, (len(p.modes), len(p.dofs)))
        self.assertEqual(p.shapes.dtype, np.complex128)

    def test_problem_cost_at_the_fit_is_identify_cost(self):
        r = ringid.identify(TABLE1, starts=1, derivatives="analytic")
        problem = ringid.Problem(TABLE1, derivatives="analytic")
        self.assertEqual(problem.names, r.coordinate_names)
        self.assertAlmostEqual(problem.cost(r.x), r.cost, delta=1e-12)
        self.assertTrue(np.all(problem.lower <= problem.start))
        self.assertTrue(np.all(problem.start <= problem.upper))

    def test_problem_jacobian_matches_central_differences(self):
        problem = ringid.Problem(TABLE1)
        x = problem.start
        j = problem.jacobian(x)
        h = 1e-6
        for i in range(len(x)):
            e = np.zeros_like(x)
            e[i] = h
            column = (problem.residuals(x + e) - problem.residuals(x - e)) / (2 * h)
            np.testing.assert_allclose(j[:, i], column, rtol=1e-5, atol=1e-6)

    def test_every_keyword_is_a_flag_with_its_default_in_the_docstring(self):
        for flag, default in [("starts", "starts=6"), ("method", "method='lm'"),
                              ("derivatives", "derivatives='auto'"), ("shapes", "shapes=")]:
            self.assertIn(default, ringid.identify.__doc__, flag)
        self.assertIn("level=", ringid.diagnose.__doc__)
        self.assertIn("lugs_per_revolution=0", ringid.predict.__doc__)

    def test_fits_in_threads_equal_fits_in_turn_and_leave_the_defaults(self):
        import threading
        options = [{"starts": 1}, {"starts": 2, "seed": 7}, {"starts": 1, "weighting": "relative"},
                   {"starts": 1, "derivatives": "analytic"}]
        alone = [without_run(ringid.identify(TABLE1, **o).to_dict()) for o in options]
        together = [None] * len(options)

        def run(i):
            together[i] = without_run(ringid.identify(TABLE1, **options[i]).to_dict())
        threads = [threading.Thread(target=run, args=(i,)) for i in range(len(options))]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(together, alone)
        self.assertEqual(ringid.identify(TABLE1, threads=1).provenance["command_line"],
                         ["ringid.identify", "--threads=1"])

    def test_an_unknown_keyword_is_a_type_error(self):
        with self.assertRaises(TypeError):
            ringid.identify(TABLE1, start=1)


LUG_FORCES = """{"format": "ringid-lug-forces/1", "name": "tread", "lugs_per_revolution": 20,
  "orders": [{"order": 1, "forces": {"F_x": {"re": 300, "im": 0}, "F_z": {"re": 0, "im": 900},
                                     "F_y": {"re": -150, "im": 50}}},
             {"order": 3, "forces": {"F_z": {"re": 200, "im": -100}}}]}"""
GIVEN_FORCES = {1: {"F_x": 300, "F_z": 900j, "F_y": -150 + 50j}, 3: {"F_z": 200 - 100j}}
# What the .tir cannot hold or does not give, from the car tire (as predict's test).
TIR_REST = ["I_ay", "F_cz0", "c_bx", "c_bz", "c_btheta", "K_cx", "sigma_cx", "r_e0", "k_cz",
            "c_by", "c_bgamma", "c_bpsi", "K_cy", "sigma_cy", "r_l0", "t_0"]


class WhatTheModuleLacked(ReportTestCase):
    """Issue 34: what the module could not do that the command line does."""

    def test_simulate_with_static_stiffnesses_equals_the_command_line_and_identify_fits_them(self):
        with tempfile.TemporaryDirectory() as scratch:
            output, truth = os.path.join(scratch, "sim.json"), os.path.join(scratch, "truth.json")
            done = subprocess.run(
                [BINARY, "simulate", "--parameters=" + CAR_TIRE, "--output=" + output,
                 "--truth=" + truth, "--seed=3", "--static=vertical,lateral", "--static_noise=0"],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(output) as f:
                cli = json.load(f)
            r = ringid.simulate(CAR_TIRE, output=output, truth=truth, seed=3,
                                static=["vertical", "lateral"], static_noise=0)
            self.assertEqual(r.to_dict()["dataset"], cli)
            self.assertEqual(cli["format"], "ringid-dataset/3")
            # Noise-free, the vertical value is docs/tir.md's series formula of the truth.
            with open(CAR_TIRE) as f:
                p = {k: v["value"] if isinstance(v, dict) else v for k, v in json.load(f)["parameters"].items()}
            vertical = [s for s in cli["conditions"][0]["static"] if s["kind"] == "vertical"][0]
            self.assertAlmostEqual(vertical["value"] / (1 / (1 / p["k_bz"] + 1 / p["k_cz"])), 1, places=12)
            fitted = ringid.identify(r.dataset).to_dict()["measurements"]
            self.assertEqual([m["name"] for m in fitted],
                             ["static vertical stiffness", "static lateral stiffness"])

    def test_simulate_with_an_frf_spec_equals_the_command_line_and_identify_fits_it(self):
        with tempfile.TemporaryDirectory() as scratch:
            with open(HAMMER_SPEC) as f:
                spec = json.load(f)
            spec["lines_hz"] = {"from": 10, "to": 150, "step": 10}  # few lines: quick
            spec_path = os.path.join(scratch, "spec.json")
            with open(spec_path, "w") as f:
                json.dump(spec, f)
            output, truth = os.path.join(scratch, "sim.json"), os.path.join(scratch, "truth.json")
            done = subprocess.run(
                [BINARY, "simulate", "--parameters=" + CAR_TIRE, "--output=" + output,
                 "--truth=" + truth, "--seed=4", "--frf=" + spec_path],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(output) as f:
                cli = json.load(f)
            r = ringid.simulate(CAR_TIRE, output=output, truth=truth, seed=4, frf=spec_path)
            self.assertEqual(r.to_dict()["dataset"], cli)
            self.assertEqual(cli["format"], "ringid-dataset/3")
            frf = cli["conditions"][0]["frf"]
            self.assertNotIn("modes", cli["conditions"][0])
            self.assertEqual(len(frf["functions"]), 28)
            self.assertEqual(frf["frequencies_hz"], list(range(10, 151, 10)))
            fitted = ringid.identify(r.dataset, starts=1, derivatives="analytic").to_dict()
            self.assertLess(fitted["fit"]["p_value"], 1.0)
            self.assertGreater(fitted["fit"]["p_value"], 0.001)
            # A spec refused at speed: ringid.Error naming the spec's field.
            with self.assertRaises(ringid.Error) as refused:
                ringid.simulate(CAR_TIRE, output=output, truth=truth, frf=spec_path, speeds=[0, 10])
            self.assertIn(spec_path + ": inputs[0].on: ", str(refused.exception))

    def test_extract_equals_the_command_line_and_its_modes_are_the_models(self):
        with tempfile.TemporaryDirectory() as scratch:
            with open(HAMMER_SPEC) as f:
                spec = json.load(f)
            spec["lines_hz"] = {"from": 5, "to": 250, "step": 1}
            spec["noise"] = 0
            spec_path = written(scratch, "spec.json", json.dumps(spec))
            frfs = os.path.join(scratch, "frfs.json")
            ringid.simulate(CAR_TIRE, output=frfs, truth=os.path.join(scratch, "t.json"),
                            frf=spec_path).write()
            modes = os.path.join(scratch, "modes.json")
            done = subprocess.run([BINARY, "extract", "--dataset=" + frfs, "--output=" + modes],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(modes) as f:
                cli = json.load(f)
            x = ringid.extract(frfs)
            # The module and the command are separately compiled: equal to rounding.
            self.assertSameReport(x.dataset.to_dict(), cli, path="dataset", tolerance=1e-9)
            # Noise-free FRFs: each labelled mode at the model's frequency at the truth.
            model = ringid.predict(CAR_TIRE).to_dict()["modes"]
            truth_hz = {m["label"]: m["model_hz"] for m in model}
            self.assertEqual(cli["format"], "ringid-dataset/3")
            self.assertEqual(len(cli["conditions"][0]["modes"]), 7)
            for m in cli["conditions"][0]["modes"]:
                self.assertAlmostEqual(m["frequency_hz"] / truth_hz[m["label"]], 1, delta=1e-6)
            self.assertEqual([p["label"] is not None for p in x.poles], [True] * 7)
            for p in x.poles:
                self.assertGreater(p["frequency_sigma_hz"], 0)
            self.assertGreaterEqual(len(x.routes), 6)
            # The direct route is identify on the same FRFs (the physics: extract_test.cc).
            direct = ringid.identify(frfs).to_dict()["parameters"]
            for r in x.routes:
                self.assertAlmostEqual(r["direct"] / direct[r["parameter"]]["value"], 1, delta=1e-9)
                self.assertAlmostEqual(r["direct_std"] / direct[r["parameter"]]["std"], 1, delta=1e-6)
            with self.assertRaises(ringid.Error) as refused:
                ringid.extract(TABLE1)
            self.assertIn(TABLE1 + ": conditions: no condition has an frf block", str(refused.exception))

    def test_poles_equals_the_command_line_and_refuses_time_records(self):
        uff = os.path.join(SOURCE, "datasets", "examples", "car_tire_hammer.uff")
        with tempfile.TemporaryDirectory() as scratch:
            out = os.path.join(scratch, "poles.json")
            done = subprocess.run([BINARY, "poles", "--uff=" + uff, "--output=" + out,
                                   "--band=10,240"],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(out) as f:
                cli = json.load(f)
            poles = ringid.poles(uff=uff, band="10,240")
            self.assertSameReport(poles, cli, path="poles", tolerance=1e-9)
            self.assertEqual(poles["conditions"][0]["low_hz"], 10)
            self.assertEqual(poles["conditions"][0]["high_hz"], 240)
            # The example's closed form (scripts/make_hammer_example.py): the belt's x_b, z_b
            # and theta_b, each m s^2 + c s + k; the lowest damped frequency is the first pole.
            with open(CAR_TIRE) as f:
                v = {k: p["value"] for k, p in json.load(f)["parameters"].items()}
            damped = [math.sqrt(k / m - (c / (2 * m)) ** 2) / (2 * math.pi)
                      for m, k, c in [(v["m_b"], v["k_bx"], v["c_bx"]), (v["m_b"], v["k_bz"], v["c_bz"]),
                                      (v["I_by"], v["k_btheta"], v["c_btheta"])]]
            self.assertAlmostEqual(poles["poles"][0]["frequency_hz"] / min(damped), 1, delta=1e-6)
            time = os.path.join(scratch, "time.uff")
            with open(uff) as f:
                text = f.read()
            with open(time, "w") as f:  # the FRFs written as time responses (type 1)
                f.write(text.replace("    4         1    0         0", "    1         1    0         0"))
            with self.assertRaises(ringid.Error) as refused:
                ringid.poles(uff=time)
            self.assertIn("poles need FRFs (function type 4)", str(refused.exception))

    def test_simulate_with_lug_forces_equals_the_command_line_and_forces_recover_them(self):
        with tempfile.TemporaryDirectory() as scratch:
            lugs, out = os.path.join(scratch, "lugs.json"), os.path.join(scratch, "response.json")
            with open(lugs, "w") as f:
                f.write(LUG_FORCES)
            done = subprocess.run(
                [BINARY, "simulate", "--parameters=" + CAR_TIRE, "--lug_forces=" + lugs,
                 "--speeds=8,14", "--response_noise=1e-6", "--seed=3", "--output=" + out],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(out) as f:
                cli = json.load(f)
            r = ringid.simulate(CAR_TIRE, lug_forces=lugs, speeds=[8, 14], response_noise=1e-6,
                                seed=3)
        self.assertEqual(r.to_dict(), {"dataset": cli})
        self.assertIsNone(r.truth)
        forces = ringid.forces(CAR_TIRE, r.dataset).to_dict()
        self.assertEqual(len(forces["conditions"]), 2)
        for condition in forces["conditions"]:
            self.assertEqual([o["order"] for o in condition["orders"]], [1, 3])
            for o in condition["orders"]:
                for name, estimate in o["forces"].items():
                    truth = GIVEN_FORCES[o["order"]].get(name, 0)
                    self.assertLess(abs(complex(estimate["re"], estimate["im"]) - truth), 1e-3 * 900)

    def test_predict_gives_the_frequencies_at_every_speed(self):
        r = ringid.predict(parameters=PARAMETERS, speeds=[20, 0, 10])
        cli = cli_report("predict", "--parameters=" + PARAMETERS, "--speeds=20,0,10")
        np.testing.assert_array_equal(r.speeds_m_s, [0, 10, 20])
        self.assertEqual(r.frequencies.shape, (3, len(r.labels)))
        self.assertEqual(r.damping_ratios.shape, (3, len(r.labels)))
        for i, at in enumerate(cli["speeds"]):
            self.assertEqual(at["speed_m_s"], r.speeds_m_s[i])
            for j, label in enumerate(r.labels):
                hz, zeta = at["modes"][label]
                self.assertLessEqual(abs(r.frequencies[i, j] - hz), 1e-12 * hz)
                self.assertLessEqual(abs(r.damping_ratios[i, j] - zeta), 1e-12)
        np.testing.assert_allclose(r.frequencies[0], [m["model_hz"] for m in cli["modes"]],
                                   rtol=1e-12)
        standing = ringid.predict(parameters=PARAMETERS)
        self.assertEqual(standing.frequencies.shape, (len(standing.labels),))

    def test_a_tir_error_names_the_file_and_the_field(self):
        for call, flags in [(lambda: ringid.predict(parameters=TIR), ["predict", "--parameters=" + TIR]),
                            (lambda: ringid.forces(TIR, LUG_RESPONSE),
                             ["forces", "--parameters=" + TIR, "--dataset=" + LUG_RESPONSE])]:
            with self.subTest(command=flags[0]):
                with self.assertRaises(ringid.Error) as caught:
                    call()
                e = caught.exception
                self.assertEqual(str(e), cli_error(*flags))
                self.assertEqual(e.file, TIR)
                self.assertEqual(e.field, "I_ay")
                self.assertTrue(e.message.startswith("missing (the model needs it; "), e.message)

    def test_forces_take_set_over_a_tir_as_the_command_line(self):
        car = ringid.load_parameters(CAR_TIRE)
        given = {name: car[name] for name in TIR_REST}
        r = ringid.forces(TIR, LUG_RESPONSE, set=given)
        self.assertSameReport(r.to_dict(), cli_report(
            "forces", "--parameters=" + TIR, "--dataset=" + LUG_RESPONSE,
            "--set=" + ",".join("%s=%r" % (k, v) for k, v in given.items())))
        loaded = ringid.forces(ringid.load_parameters(TIR, set=given), LUG_RESPONSE)
        self.assertEqual(loaded.to_dict()["conditions"], r.to_dict()["conditions"])

    def test_problem_jacobian_with_priors_matches_central_differences(self):
        problem = ringid.Problem(os.path.join(SOURCE, "datasets", "paper", "table1_priors.json"))
        x = problem.start
        j = problem.jacobian(x)
        self.assertEqual(j.shape, (problem.num_residuals, len(x)))
        h = 1e-6
        for i in range(len(x)):
            e = np.zeros_like(x)
            e[i] = h
            column = (problem.residuals(x + e) - problem.residuals(x - e)) / (2 * h)
            np.testing.assert_allclose(j[:, i], column, rtol=1e-5, atol=1e-6)


class Installed(unittest.TestCase):
    @unittest.skipUnless(os.environ.get("RINGID_BUILD_DIR"), "run by ctest, which names the build")
    def test_cmake_install_puts_the_module_where_python_finds_it_under_the_prefix(self):
        with tempfile.TemporaryDirectory() as prefix:
            subprocess.run([os.environ["RINGID_CMAKE"], "--install", os.environ["RINGID_BUILD_DIR"],
                            "--prefix", prefix], check=True, stdout=subprocess.DEVNULL)
            site = os.path.join(prefix, os.environ["RINGID_PYTHON_INSTALL_DIR"])
            env = dict(os.environ, PYTHONPATH=site)
            done = subprocess.run(
                [sys.executable, "-c", "import ringid; print(ringid.__file__); "
                 "print(ringid.predict(parameters=%r).frequencies[0])" % PARAMETERS],
                cwd=prefix, env=env, stdout=subprocess.PIPE, text=True, check=True)
            where, first = done.stdout.split()
            self.assertTrue(where.startswith(site), where)
            self.assertEqual(float(first), ringid.predict(parameters=PARAMETERS).frequencies[0])


class Interrupted(unittest.TestCase):
    def test_ctrl_c_stops_a_long_diagnosis_with_keyboard_interrupt(self):
        import signal
        import time
        code = ("import sys, time, ringid\n"
                "print('ready', flush=True)\n"
                "t = time.perf_counter()\n"
                "try:\n"
                "    ringid.diagnose(%r, threads=1)\n"
                "except KeyboardInterrupt:\n"
                "    print('interrupted after %%.2f s' %% (time.perf_counter() - t), flush=True)\n"
                "    sys.exit(3)\n" % ROLLING)
        child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
        self.assertEqual(child.stdout.readline().strip(), "ready")
        time.sleep(1.0)
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=60)
        self.assertEqual(child.returncode, 3, out)
        self.assertLess(float(out.split()[2]), 5.0, out)  # uninterrupted it takes several times that


class Documented(unittest.TestCase):
    def test_every_function_type_and_property_has_a_docstring(self):
        for name in [n for n in dir(ringid) if not n.startswith("_")]:
            item = getattr(ringid, name)
            self.assertTrue((item.__doc__ or "").strip(), name)
            if isinstance(item, type) and name != "Error":
                for member, value in vars(item).items():
                    if isinstance(value, property) or (not member.startswith("_") and callable(value)):
                        self.assertTrue((value.__doc__ or "").strip(), name + "." + member)

    def test_the_example_identifies_table1(self):
        example = os.path.join(SOURCE, "python", "examples", "identify_table1.py")
        with tempfile.TemporaryDirectory() as scratch:
            done = subprocess.run([sys.executable, example, os.path.join(scratch, "modes.png")],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("ringid identify (lm): converged", done.stdout)


class ErrorsAreExceptions(unittest.TestCase):
    def test_error_is_a_value_error(self):
        self.assertTrue(issubclass(ringid.Error, ValueError))

    def test_a_missing_file_raises_the_command_line_line(self):
        missing = os.path.join(SOURCE, "no-such-dataset.json")
        with self.assertRaises(ringid.Error) as caught:
            ringid.identify(missing)
        self.assertEqual(str(caught.exception), cli_error("identify", "--dataset=" + missing))
        self.assertEqual(caught.exception.file, missing)

    def test_a_bad_option_raises_the_command_line_line_naming_the_flag(self):
        with self.assertRaises(ringid.Error) as caught:
            ringid.identify(TABLE1, weighting="loud")
        self.assertEqual(str(caught.exception),
                         cli_error("identify", "--dataset=" + TABLE1, "--weighting=loud"))
        self.assertEqual(caught.exception.field, "weighting")

    def test_a_bad_predict_speed_raises_the_command_line_line(self):
        with self.assertRaises(ringid.Error) as caught:
            ringid.predict(parameters=PARAMETERS, speeds=[-1])
        self.assertEqual(str(caught.exception),
                         cli_error("predict", "--parameters=" + PARAMETERS, "--speeds=-1"))

    def test_every_bad_option_raises_the_command_line_line(self):
        cases = [("identify", {"starts": -5}), ("identify", {"starts": "many"}),
                 ("identify", {"relative_sigma": -1.0}), ("identify", {"relative_sigma": math.nan}),
                 ("identify", {"threads": -1}), ("identify", {"bounds": "k_bx"}),
                 ("identify", {"fix": "nope"}), ("identify", {"effects": "nope"}),
                 ("identify", {"method": ""}), ("diagnose", {"level": 2.0}),
                 ("identifiability", {"shape_convention": "mine"})]
        for command, options in cases:
            flags = ["--%s=%s" % (k, repr(v) if isinstance(v, float) else v)
                     for k, v in options.items()]
            with self.subTest(command=command, options=options):
                with self.assertRaises(ringid.Error) as caught:
                    getattr(ringid, command)(TABLE1, **options)
                self.assertEqual(str(caught.exception),
                                 cli_error(command, "--dataset=" + TABLE1, *flags))
        for options, flags in [({"speeds": [1, 1]}, ["--speeds=1,1"]),
                               ({"lugs_per_revolution": -1, "speeds": [5]},
                                ["--lugs_per_revolution=-1", "--speeds=5"]),
                               ({"set": {"m_b": -1}}, ["--set=m_b=-1"]),
                               ({"effects": "hub_compliance"}, ["--effects=hub_compliance"])]:
            with self.subTest(options=options):
                with self.assertRaises(ringid.Error) as caught:
                    ringid.predict(parameters=PARAMETERS, **options)
                self.assertEqual(str(caught.exception),
                                 cli_error("predict", "--parameters=" + PARAMETERS, *flags))

    def test_every_malformed_dataset_raises_the_command_line_line_naming_its_field(self):
        cases = malformed_datasets()
        self.assertGreater(len(cases), 50)
        with tempfile.TemporaryDirectory() as scratch:
            for i, (what, text, field) in enumerate(cases):
                path = os.path.join(scratch, "bad%d.json" % i)
                with open(path, "w") as f:
                    f.write(text)
                with self.subTest(what=what):
                    with self.assertRaises(ringid.Error) as caught:
                        ringid.identify(path, starts=1)
                    self.assertEqual(caught.exception.file, path)
                    if field:
                        self.assertIn(field, str(caught.exception))
                    self.assertEqual(str(caught.exception),
                                     cli_error("identify", "--dataset=" + path, "--starts=1"))

    def test_every_malformed_dict_raises(self):
        for what, text, _ in malformed_datasets():
            try:
                as_dict = json.loads(text)
            except ValueError:
                continue
            with self.subTest(what=what):
                with self.assertRaises(ringid.Error):
                    ringid.predict(dataset=as_dict)

    def test_a_dict_with_nan_raises(self):
        with open(TABLE1) as f:
            d = json.load(f)
        d["modes"][0]["frequency_hz"] = math.nan
        with self.assertRaises(ringid.Error):
            ringid.load_dataset(d)


if __name__ == "__main__":
    unittest.main()
