"""feran study under MPI: the same evaluations, bit for bit, from 1, 2 and 3 processes
as from one process without MPI; a killed process ends the job, and --resume (with
another number of processes) completes it to the uninterrupted run's evaluations; a
mistake in the study file is reported once, not by every process.

Usage: test_study_mpi.py FERAN MPIEXEC SOURCE_DIR SCRATCH (Python's standard library only).
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

FERAN, MPIEXEC, SOURCE, SCRATCH = sys.argv[1:5]
STUDIES = os.path.join(SOURCE, "tests", "models", "studies")
# As root in a container, and more processes than cores.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def study_copy(name, *replacements):
    """The study file @p name with its model path made absolute and @p replacements made."""
    with open(os.path.join(STUDIES, name)) as f:
        text = f.read()
    text = text.replace('model = "../../../examples', f'model = "{SOURCE}/examples')
    text = text.replace('model = "bearing_damping.toml"', f'model = "{STUDIES}/bearing_damping.toml"')
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new)
    path = os.path.join(SCRATCH, "mpi_" + name)
    with open(path, "w") as f:
        f.write(text)
    return path


def feran(*args, processes=0):
    command = [FERAN, "study", *args]
    if processes:
        command = [MPIEXEC, "-np", str(processes), *command]
    return subprocess.run(command, capture_output=True, text=True, env=ENV, timeout=300)


def summary(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        s = json.load(f)
    for design in [s.get("best")] + s.get("pareto", []):
        if design:
            design.pop("seconds", None)
    return s


class StudyUnderMpi(unittest.TestCase):
    def directory(self, label):
        d = os.path.join(SCRATCH, f"mpi_{self._testMethodName}_{label}")
        shutil.rmtree(d, ignore_errors=True)
        return d

    def test_any_number_of_processes_gives_the_same_evaluations(self):
        study = study_copy("centrifuge_sobol.toml")
        alone = self.directory("alone")
        r = feran(study, "-o", alone, "--threads", "2", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        for n in (1, 2, 3):
            d = self.directory(n)
            r = feran(study, "-o", d, "--threads", "1", processes=n)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(records(d), records(alone), f"{n} processes")
            self.assertEqual(summary(d), summary(alone), f"{n} processes")
            # One summary, from the first process.
            self.assertEqual(r.stdout.count("64 of 64 designs evaluated"), 1, r.stdout)
            if n > 1:
                self.assertIn(f"{n} processes, 1 thread each", r.stdout)

    def test_an_optimiser_under_mpi_gives_the_same_pareto_set(self):
        study = study_copy("bearing_damping_pareto.toml", ("generations = 40", "generations = 6"))
        alone, spread = self.directory("alone"), self.directory("spread")
        r = feran(study, "-o", alone, "--threads", "1", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        r = feran(study, "-o", spread, "--threads", "1", "-q", processes=3)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(records(alone)), 32 * 7)
        self.assertEqual(records(spread), records(alone))
        self.assertEqual(summary(spread), summary(alone))

    def test_a_killed_process_ends_the_job_and_resume_completes_it(self):
        study = study_copy("centrifuge_sobol.toml", ("samples = 64", "samples = 256"))
        whole, parts = self.directory("whole"), self.directory("parts")
        r = feran(study, "-o", whole, "--threads", "2", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        job = subprocess.Popen([MPIEXEC, "-np", "2", FERAN, "study", study, "-o", parts, "--threads", "1",
                                "--batch", "4", "-q"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=ENV)
        path = os.path.join(parts, "evaluations.jsonl")
        deadline = time.time() + 60
        while time.time() < deadline and (not os.path.exists(path) or os.path.getsize(path) == 0):
            time.sleep(0.02)
        # The second process (the one that does not write) dies without a word.
        children = subprocess.run(["ps", "-o", "pid=", "--ppid", str(job.pid)], capture_output=True,
                                  text=True).stdout.split()
        ranks = sorted(int(p) for p in children)
        self.assertEqual(len(ranks), 2, children)
        os.kill(ranks[1], signal.SIGKILL)
        job.communicate(timeout=120)
        self.assertNotEqual(job.returncode, 0)
        first = records(parts)
        self.assertGreater(len(first), 0)
        self.assertLess(len(first), 256)
        resumed = feran(study, "-o", parts, "--resume", "--threads", "1", processes=3)
        self.assertEqual(resumed.returncode, 0, resumed.stderr)
        self.assertIn(f"256 of 256 designs evaluated ({len(first)} resumed)", resumed.stdout)
        self.assertEqual(records(parts), records(whole))
        with open(os.path.join(parts, "evaluations.csv")) as f:
            self.assertEqual(len(f.readlines()), 257)

    def test_a_mistake_is_reported_once(self):
        bad = study_copy("centrifuge_sobol.toml", ('kind = "min_damping_ratio"', 'kind = "min_damping"'))
        d = self.directory("bad")
        r = feran(bad, "-o", d, processes=2)
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(r.stderr.count("unknown quantity kind 'min_damping'"), 1, r.stderr)
        self.assertNotIn("terminate called", r.stderr)  # no uncaught exception
        self.assertFalse(os.path.exists(os.path.join(d, "evaluations.jsonl")))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
