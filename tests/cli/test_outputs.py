"""The feran command's output files as a script or a user meets them: paths checked
before the analysis runs, nothing written on failure, links and special files written
where they lead, signals ending a run with its results so far, CSV that any reader
parses. Run by ctest (tests/cli/CMakeLists.txt) with the program's path:

    python3 tests/cli/test_outputs.py FERAN EXAMPLE_MODEL
"""
import csv
import glob
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

FERAN = None
EXAMPLE = None


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def read_json(path):
    return json.loads(read(path))


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def run(*args, **kwargs):
    return subprocess.run([FERAN, *args], capture_output=True, text=True, timeout=600, **kwargs)


class OutputTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory(prefix="feran_cli_outputs_")
        self.addCleanup(self.dir.cleanup)
        self.model = self.path("model.toml")
        with open(self.model, "w") as f:
            f.write(read(EXAMPLE))

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def names(self):
        return sorted(os.listdir(self.dir.name))

    def temporaries(self):
        return glob.glob(self.path("*.part-*"))

    def expect_refused(self, args, message, code=1):
        before = {n: read(self.path(n), "rb") for n in self.names() if os.path.isfile(self.path(n))}
        r = run(*args)
        self.assertEqual(r.returncode, code, r.stderr)
        self.assertIn(message, r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        after = {n: read(self.path(n), "rb") for n in self.names() if os.path.isfile(self.path(n))}
        self.assertEqual(before, after, "no file may be written or changed")
        self.assertEqual(self.temporaries(), [])


class Refused(OutputTest):
    def test_the_model_file_is_never_an_output(self):
        self.expect_refused(["modal", self.model, "--json", self.model, "-q"],
                            f"--json '{self.model}': cannot write: it is the model file")
        os.link(self.model, self.path("hard.toml"))
        self.expect_refused(["static", self.model, "--csv", self.path("hard.toml"), "-q"],
                            "cannot write: it is the model file")

    def test_two_outputs_never_share_a_file(self):
        out = self.path("x.json")
        self.expect_refused(["modal", self.model, "--json", out, "--csv", out, "-q"],
                            f"--csv '{out}': cannot write: --json already writes '{out}'")

    def test_every_path_is_checked_before_anything_is_written(self):
        ok = self.path("ok.json")
        with open(ok, "w") as f:
            f.write("the user's results")
        bad = self.path("nodir/x.csv")
        for command in (["modal", self.model], ["campbell", self.model, "--points", "3"],
                        ["response", self.model, "--points", "3"], ["static", self.model],
                        ["runup", self.model, "--speed", "10Hz", "--duration", "0.01s"]):
            self.expect_refused([*command, "--json", ok, "--csv", bad, "-q"],
                                f"--csv '{bad}': cannot write: the directory '{self.path('nodir')}' does not exist")
        self.expect_refused(["modal", self.model, "--json", self.dir.name], "cannot write: it is a directory")

    def test_a_failed_run_writes_nothing(self):
        ok = self.path("ok.json")
        with open(ok, "w") as f:
            f.write("the user's results")
        # An rk3 step above its stability limit is refused before the first step.
        self.expect_refused(["runup", self.model, "--speed", "10Hz", "--duration", "0.1s", "--integrator", "rk3",
                             "--dt", "1e-2s", "--json", ok, "--csv", self.path("r.csv"), "-q"],
                            "stability limit")

    def test_a_device_that_refuses_data_says_why(self):
        r = run("modal", self.model, "--csv", "/dev/full", "-q")
        self.assertEqual(r.returncode, 1)
        self.assertIn("--csv '/dev/full': cannot write: No space left on device", r.stderr)
        self.assertTrue(os.path.exists("/dev/full") and not os.path.isfile("/dev/full"))


class WrittenWhereTheyLead(OutputTest):
    def test_a_symbolic_link_keeps_pointing_at_the_new_file(self):
        os.symlink("real.json", self.path("link.json"))
        r = run("modal", self.model, "--json", self.path("link.json"), "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.islink(self.path("link.json")))
        self.assertEqual(read_json(self.path("real.json"))["analysis"], "modal")

    def test_standard_output_is_written_as_it_is(self):
        r = run("modal", self.model, "--json", "/dev/stdout", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(json.loads(r.stdout)["analysis"], "modal")
        # Appended to a file the shell opened for appending, not truncated.
        log = self.path("log.txt")
        with open(log, "w") as f:
            f.write("before\n")
        with open(log, "a") as f:
            r = subprocess.run([FERAN, "static", self.model, "--csv", "/dev/stdout", "-q"], stdout=f,
                               stderr=subprocess.PIPE, text=True, timeout=600)
        self.assertEqual(r.returncode, 0, r.stderr)
        text = read(log)
        self.assertTrue(text.startswith("before\nelement,end,node,"), text[:80])

    def test_a_fifo_is_written_in_place(self):
        fifo = self.path("pipe")
        os.mkfifo(fifo)
        p = subprocess.Popen([FERAN, "modal", self.model, "--json", fifo, "-q"], stderr=subprocess.PIPE, text=True)
        with open(fifo) as f:
            data = f.read()
        code = p.wait(timeout=600)
        p.stderr.close()
        self.assertEqual(code, 0)
        self.assertEqual(json.loads(data)["analysis"], "modal")
        self.assertFalse(os.path.isfile(fifo))


class Interrupted(OutputTest):
    """A signal during a long run: the run stops at a clean point, every file is
    complete and marked incomplete, no temporary file stays, the exit code is 128 + N."""

    def interrupt(self, args, sig, stream_wait=False):
        p = subprocess.Popen([FERAN, *args, "-q"], stderr=subprocess.PIPE, text=True)
        # The outputs' temporary files exist once the signal handlers are installed.
        deadline = time.time() + 120
        while not self.temporaries() and time.time() < deadline and p.poll() is None:
            time.sleep(0.01)
        time.sleep(0.3)  # well into the run
        p.send_signal(sig)
        code = p.wait(timeout=600)
        stderr = p.stderr.read()
        p.stderr.close()
        self.assertEqual(code, 128 + sig, stderr)
        self.assertIn(f"feran: interrupted by {signal.Signals(sig).name}", stderr)
        self.assertEqual(self.temporaries(), [])
        return stderr

    def check_csv(self, path, rows_expected):
        rows = read_csv(path)
        self.assertEqual(len(rows), rows_expected + 1)
        self.assertEqual({len(r) for r in rows}, {len(rows[0])}, "whole rows only")

    def test_runup(self):
        js, cs = self.path("r.json"), self.path("r.csv")
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            self.interrupt(["runup", self.model, "--speed", "10Hz", "--duration", "500s", "--dt", "1e-4s",
                            "--probe", "rotor", "--json", js, "--csv", cs], sig)
            j = read_json(js)
            self.assertFalse(j["complete"])
            self.assertTrue(j["message"].startswith("stopped on request at t = "), j["message"])
            self.assertLess(j["t_end_s"], 500)
            self.check_csv(cs, len(j["time_s"]))

    def test_campbell_and_response(self):
        for command, key in (("campbell", "speeds_hz"), ("response", "speeds_hz")):
            js, cs = self.path(command + ".json"), self.path(command + ".csv")
            self.interrupt([command, self.model, "--stop", "80Hz", "--points", "100000", "--threads", "2",
                            "--json", js, "--csv", cs], signal.SIGINT)
            j = read_json(js)
            self.assertFalse(j["complete"])
            self.assertEqual(j["solver"]["status"], "interrupted")
            self.assertLess(len(j[key]), 100000)
            self.check_csv(cs, len(j[key]))


class CsvFields(OutputTest):
    """Names with commas, quotes or line breaks are quoted (RFC 4180): the columns
    stay whole for any CSV reader."""

    def setUp(self):
        super().setUp()
        text = read(self.model)
        text = text.replace('"rotor"', r'"rot, \"or\""').replace('"external damping"', r'"ext\ndamping"')
        with open(self.model, "w") as f:
            f.write(text)

    def test_every_csv_keeps_its_columns(self):
        runs = {
            "modal": [], "campbell": ["--points", "5", "--stop", "40Hz"], "static": [],
            "response": ["--points", "5", "--stop", "40Hz", "--probe", "rot, \"or\""],
            "runup": ["--speed", "10Hz", "--duration", "0.01s", "--probe", "rot, \"or\"", "--spring", "ext\ndamping"],
        }
        for command, extra in runs.items():
            out = self.path(command + ".csv")
            r = run(command, self.model, *extra, "--csv", out, "-q")
            self.assertEqual(r.returncode, 0, r.stderr)
            rows = read_csv(out)
            self.assertEqual({len(row) for row in rows}, {len(rows[0])}, command)
            if command in ("response", "runup"):
                self.assertIn('rot,_"or"_magnitude_m' if command == "runup" else 'rot,_"or"_amplitude_m', rows[0])
            if command == "runup":
                self.assertIn("ext\ndamping_fx", rows[0])


class SpeedUnit(OutputTest):
    """--speed-unit rpm: the terminal tables' speed columns in rpm, each 60 times the
    default's Hz, and the frequencies of the motion in cycles per minute (as the
    report's); other columns unchanged."""

    def first_column(self, text, header):
        lines = text.splitlines()
        start = next(i for i, line in enumerate(lines) if line.strip().startswith(header))
        rows = []
        for line in lines[start + 1:]:
            if not line.strip() or not line.split()[0][0].isdigit():
                break
            rows.append(line.split())
        return rows

    def test_campbell_and_response_tables_take_rpm(self):
        for command in ("campbell", "response"):
            hz = run(command, self.model, "--stop", "40Hz", "--points", "5")
            rpm = run(command, self.model, "--stop", "40Hz", "--points", "5", "--speed-unit", "rpm")
            self.assertEqual((hz.returncode, rpm.returncode), (0, 0), rpm.stderr)
            a, b = self.first_column(hz.stdout, "speed [Hz]"), self.first_column(rpm.stdout, "speed [rpm]")
            self.assertEqual(len(a), 5, hz.stdout)
            self.assertEqual(len(a), len(b))
            for x, y in zip(a, b):
                self.assertAlmostEqual(float(y[0]), 60 * float(x[0]), delta=0.6)  # printed to 0.01 Hz, 0.1 rpm
                if command == "campbell":  # natural frequencies: 0.001 Hz against 0.1 cpm
                    for f, g in zip(x[1:], y[1:]):
                        self.assertAlmostEqual(float(g), 60 * float(f), delta=0.1)
                else:
                    self.assertEqual(x[1:], y[1:])  # orbits and phases
            if command == "campbell":
                self.assertIn("Natural frequencies [cpm]", rpm.stdout)
        hz = run("modal", self.model, "--speed", "30Hz")
        rpm = run("modal", self.model, "--speed", "30Hz", "--speed-unit", "rpm")
        self.assertIn("frequency [cpm]", rpm.stdout)

        def frequencies(out):
            rows = (line.split() for line in out.splitlines())
            return [float(row[1]) for row in rows if row[:1] and row[0].isdigit()]
        f_hz, f_cpm = frequencies(hz.stdout), frequencies(rpm.stdout)
        self.assertEqual(len(f_hz), len(f_cpm))
        for f, g in zip(f_hz, f_cpm):
            self.assertAlmostEqual(g, 60 * f, delta=0.01)  # 1e-4 Hz against 0.01 cpm
        r = run("modal", self.model, "--speed", "30Hz", "--speed-unit", "krpm")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("--speed-unit", r.stderr)


class TerminalText(OutputTest):
    """Names that hold control characters are printed visibly: a model cannot move the
    cursor or change colours of the terminal that runs it."""

    def test_names_and_messages_are_printable(self):
        text = read(self.model).replace('"rotor"', r'"rot\u001b[31mor"')
        with open(self.model, "w") as f:
            f.write(text)
        r = run("response", self.model, "--points", "3", "--stop", "10Hz")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("rot\\e[31mor", r.stdout)
        r = run("modal", self.model, "--set", "rigid_bodies[x\x1b[2J].mass=1 kg")
        self.assertEqual(r.returncode, 1)
        self.assertIn("x\\e[2J", r.stderr)
        for out in (r.stdout, r.stderr):
            self.assertNotIn("\x1b", out)


class LargeModel(OutputTest):
    """A model of 30 000 DOF or more is read by the program started again with
    glibc's malloc on transparent huge pages (apps/feran/common.cpp): the run is the
    same as without, its outputs are written once, no temporary file stays behind."""

    def test_the_restarted_program_runs_the_same_command(self):
        # The benchmarks' rotor of 5001 elements (30 006 DOF), beside the examples.
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(EXAMPLE))))
        with open(self.model, "w") as f:
            f.write(read(os.path.join(root, "bench", "models", "friswell_5_9_1_5001.toml")))
        outputs = {}
        for name, tunables in (("restarted", None), ("as_is", "glibc.malloc.hugetlb=0")):
            env = dict(os.environ)
            env.pop("GLIBC_TUNABLES", None)
            if tunables:
                env["GLIBC_TUNABLES"] = tunables  # names the tunable: no restart
            r = run("runup", self.model, "--speed", "10Hz", "--duration", "3e-4s", "--dt", "1e-4s",
                    "--output-interval", "1e-4s", "--json", self.path(name + ".json"),
                    "--csv", self.path(name + ".csv"), "--quiet", env=env)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(self.temporaries(), [])
            data = read_json(self.path(name + ".json"))
            data.pop("inputs", None)
            outputs[name] = (data, read(self.path(name + ".csv")))
        self.assertEqual(outputs["restarted"][1], outputs["as_is"][1])
        self.assertEqual(outputs["restarted"][0]["statistics"], outputs["as_is"][0]["statistics"])
        self.assertEqual(outputs["restarted"][0]["probes"], outputs["as_is"][0]["probes"])


if __name__ == "__main__":
    FERAN, EXAMPLE = sys.argv[1], sys.argv[2]
    unittest.main(argv=[sys.argv[0], *sys.argv[3:]], verbosity=2)
