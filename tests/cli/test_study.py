"""feran study as a user meets it: a study stopped by Ctrl-C continues with --resume to
exactly the evaluations of an uninterrupted run; a directory holding a study is never
overwritten; a mistake in a study file is reported at its line and column.

Usage: test_study.py FERAN SOURCE_DIR SCRATCH (Python's standard library only).
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import time
import unittest

from study_records import records

FERAN, SOURCE, SCRATCH = sys.argv[1], sys.argv[2], sys.argv[3]
STUDY = os.path.join(SOURCE, "tests", "models", "studies", "centrifuge_sobol.toml")


def run(*args, **kw):
    return subprocess.run([FERAN, "study", *args], capture_output=True, text=True, **kw)


class Study(unittest.TestCase):
    def setUp(self):
        self.dirs = [os.path.join(SCRATCH, f"study_{self._testMethodName}_{i}") for i in range(2)]
        for d in self.dirs:
            shutil.rmtree(d, ignore_errors=True)

    def test_interrupted_then_resumed_equals_uninterrupted(self):
        whole, parts = self.dirs
        # A study of 128 designs, so that one thread takes a few seconds.
        with open(STUDY) as f:
            text = f.read().replace("samples = 64", "samples = 128")
        study = os.path.join(SCRATCH, "centrifuge_sobol_128.toml")
        with open(study, "w") as f:
            f.write(text.replace('model = "../../../examples', f'model = "{SOURCE}/examples'))
        done = run(study, "-o", whole, "--threads", "2", "-q")
        self.assertEqual(done.returncode, 0, done.stderr)
        proc = subprocess.Popen([FERAN, "study", study, "-o", parts, "--threads", "1", "--batch", "4", "-q"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        path = os.path.join(parts, "evaluations.jsonl")
        deadline = time.time() + 30
        while time.time() < deadline and (not os.path.exists(path) or os.path.getsize(path) == 0):
            time.sleep(0.02)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=60)
        self.assertEqual(proc.returncode, 128 + signal.SIGINT, err)
        self.assertIn("--resume continues it", err)
        first = records(parts)
        self.assertGreater(len(first), 0)
        self.assertLess(len(first), 128)
        # Without --resume the directory is refused, and left as it was.
        again = run(study, "-o", parts, "-q")
        self.assertEqual(again.returncode, 1)
        self.assertIn("--resume continues it", again.stderr)
        self.assertEqual(records(parts), first)
        resumed = run(study, "-o", parts, "--resume", "--threads", "2")
        self.assertEqual(resumed.returncode, 0, resumed.stderr)
        self.assertIn(f"128 of 128 designs evaluated ({len(first)} resumed)", resumed.stdout)
        self.assertEqual(records(parts), records(whole))  # the same numbers, bit for bit
        with open(os.path.join(parts, "evaluations.csv")) as f:
            self.assertEqual(len(f.readlines()), 129)
        with open(os.path.join(parts, "summary.json")) as f, open(os.path.join(whole, "summary.json")) as g:
            a, b = json.load(f), json.load(g)
            a["best"].pop("seconds"), b["best"].pop("seconds")
            self.assertEqual(a, b)
        # The best design's model file is a model every command reads.
        modal = subprocess.run([FERAN, "modal", os.path.join(parts, "best.toml"), "--quiet"], capture_output=True)
        self.assertEqual(modal.returncode, 0, modal.stderr)

    def test_mistakes_are_located(self):
        bad = os.path.join(SCRATCH, "bad_study.toml")
        with open(STUDY) as f:
            text = f.read().replace('kind = "min_damping_ratio"', 'kind = "min_damping"')
        with open(bad, "w") as f:
            f.write(text.replace('model = "../../../examples', f'model = "{SOURCE}/examples'))
        r = run(bad, "-o", self.dirs[0])
        self.assertEqual(r.returncode, 1)
        self.assertRegex(r.stderr, r"bad_study\.toml:36:8: unknown quantity kind 'min_damping'; "
                                   r"did you mean 'min_damping_ratio'\?")
        self.assertNotIn("terminate", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.dirs[0], "evaluations.jsonl")))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
