"""Design studies from Python (docs/python.md, "Design studies"; docs/study-format.md).

    import feran
    model = feran.read_model("examples/02_centrifuge/model.toml")
    study = feran.Study(model,
        variables=[{"name": "k", "paths": ["springs[foot k11].ky", "springs[foot k11].kz"],
                    "lower": "1e5 N/m", "upper": "1e7 N/m", "scale": "log"}],
        quantities=[{"name": "first", "kind": "critical_speed", "unit": "Hz"},
                    {"name": "cost", "function": lambda m: m["springs[foot k11].ky"] / 1e6}],
        objectives=[{"quantity": "first", "sense": "maximise"}],
        explore={"method": "sobol", "samples": 64})
    result = study.run()                     # all cores; or client=dask.distributed.Client(...)
    result.values, result.quantities         # numpy arrays, one row per design

A study's tables are those of a study file, as lists of dicts: they are written as
TOML and read by the study reader, so they are checked by the same rules and give the
same results as `feran study`. A quantity with a "function" (f(model) -> float, given
the design's feran.Model) is computed by that Python function.
"""
import time as _time

from ._feran import Error, ModelError, _Study, read_model
from ._toml import keys_toml, toml_value

__all__ = ["Study", "read_study"]


def _study_toml(title, settings, tables, explore):
    """The study file's TOML text of these tables, and for each of its lines the path
    of what it holds ("quantities[1].kind"), to name in messages."""
    lines, where = [], []

    def table(header, path, keys):
        lines.append(header)
        where.append(path)
        for key in keys:
            where.append(f"{path}.{key}")
        lines.append(keys_toml(dict(keys), path).rstrip("\n"))

    if title:
        lines.append(f"title = {toml_value(title, 'title')}")
        where.append("title")
    if settings:
        table("[settings]", "settings", settings)
    for key, entries in tables:
        for i, entry in enumerate(entries):
            if not isinstance(entry, dict):
                raise TypeError(f"{key}[{i}]: each entry is a dict of the study file's keys, "
                                f"got {type(entry).__name__}")
            table(f"[[{key}]]", f"{key}[{i}]", entry)
    if explore:
        table("[explore]", "explore", explore)
    return "\n".join(lines) + "\n", where


def _located(error, where):
    """A ModelError of the study reader about the generated text, located instead by
    the path of the argument it came from."""
    line = getattr(error, "line", 0)
    path = where[line - 1] if 0 < line <= len(where) else "Study"
    located = ModelError(f"{path}: {error.message}")
    located.file, located.line, located.column, located.message, located.path = "<code>", 0, 0, error.message, path
    return located


class Study:
    """A design study of a model: design variables (parameter paths with bounds),
    quantities of the analyses or of Python functions, objectives, constraints and how
    to explore (docs/study-format.md for every key).

    model       a feran.Model, or the path of a model file
    variables   [{"name", "path" or "paths", "lower", "upper", "scale"} or {"name", "paths", "values"}]
    quantities  [{"name", "kind", ...}] or [{"name", "function": f}]: f(model) -> float
    objectives  [{"quantity", "sense": "minimise" | "maximise"}]
    constraints [{"quantity", "at_most" | "at_least"}]
    explore     {"method": "grid" | "latin_hypercube" | "sobol" | "optimise" | "pareto", ...}
    settings    {parameter path: value} set on the model first ("campbell.stop": "150 Hz")
    """

    def __init__(self, model, *, variables, quantities, objectives=(), constraints=(), explore=None,
                 settings=None, title=""):
        if isinstance(model, str):
            model = read_model(model)
        where = self._describe(model, variables, quantities, objectives, constraints, explore, settings, title)
        try:
            self._core = _Study.from_code(self._text, model, self._model_name, self._functions)
        except ModelError as e:
            if e.file != "<study>":
                raise
            raise _located(e, where) from None

    def _describe(self, model, variables, quantities, objectives, constraints, explore, settings, title):
        """Keeps what rebuilds the study elsewhere (a dask worker): the model and the
        study as TOML text, the Python functions by quantity name. Returns the path of
        each line of the text, to locate the reader's messages."""
        functions, entries = {}, []
        for i, q in enumerate(quantities):
            q = dict(q)
            f = q.pop("function", None)
            if f is not None:
                if q.setdefault("kind", "function") != "function":
                    raise Error(f"quantities[{i}]: a quantity with a 'function' is of kind \"function\", "
                                f"not {q['kind']!r}")
                if "name" not in q:
                    raise Error(f"quantities[{i}]: a quantity needs a 'name'")
                functions[q["name"]] = f
            entries.append(q)
        self._text, where = _study_toml(title, settings, (("variables", variables), ("quantities", entries),
                                                          ("objectives", objectives), ("constraints", constraints)),
                                        explore)
        self._model_text = model.to_toml()
        self._model_name = model.path if model.path not in ("<code>", "<string>") else "<code>"
        self._functions = functions
        return where

    @classmethod
    def read(cls, path):
        """The study of a study file (its model read relative to it): the file's errors
        are located in it as `feran study` locates them."""
        import tomllib
        study = cls.__new__(cls)
        study._core = _Study.read(path)  # read and checked once, its errors located in the file
        with open(path, "rb") as f:
            data = tomllib.load(f)
        # The base model as read, its settings applied (applying them again on a worker
        # sets the same values).
        study._describe(study._core.base_model(), data.get("variables", ()),
                        data.get("quantities", ()), data.get("objectives", ()), data.get("constraints", ()),
                        data.get("explore"), data.get("settings"), data.get("title", ""))
        study._model_name = data["model"]
        return study

    # -- what it is --------------------------------------------------------------------

    title = property(lambda self: self._core.title)
    variable_names = property(lambda self: self._core.variable_names, doc="the design variables' names")
    quantity_names = property(lambda self: self._core.quantity_names, doc="the quantities' names")
    objectives = property(lambda self: self._core.objectives, doc="(quantity, 'minimise' | 'maximise') pairs")
    method = property(lambda self: self._core.method, doc="how the study explores")
    planned = property(lambda self: self._core.planned, doc="designs it plans (an optimiser: at most)")

    def base_model(self):
        """The base model with the study's settings (a feran.Model)."""
        return self._core.base_model()

    # -- running -----------------------------------------------------------------------

    def run(self, output=None, *, resume=False, threads=0, batch=None, client=None):
        """Evaluates the study's designs and returns a feran.StudyResult.

        output   a directory: every evaluation is appended there as it completes
                 (evaluations.jsonl, evaluations.csv; then summary.json and the best or
                 Pareto models, as `feran study` writes them); None keeps them in memory
        resume   continue the study recorded in `output`, without repeating its designs
        threads  threads of this process (0: all cores); one design per thread
        batch    designs evaluated between two writes (default 4 per thread or worker thread)
        client   a dask.distributed Client: the designs are evaluated on its workers instead

        The results do not depend on threads, batch or the engine. Ctrl-C stops at the
        end of the designs under way and raises feran.Interrupted, its .result holding
        what was evaluated (all of it kept in `output`)."""
        engine = None
        if client is not None:
            engine = _DaskEngine(client, self)
            if batch is None:
                batch = 4 * engine.cores
        return self._core._run(output, resume, threads, batch, engine)

    def __reduce__(self):
        # What a dask worker needs to evaluate designs: the model and the study as text,
        # and the Python functions (pickled by dask's cloudpickle).
        return (_rebuild, (self._model_text, self._model_name, self._text, self._functions))


def _rebuild(model_text, model_name, text, functions):
    study = Study.__new__(Study)
    model = read_model(model_text)
    study._model_text, study._model_name, study._text, study._functions = model_text, model_name, text, functions
    study._core = _Study.from_code(text, model, model_name, functions)
    return study


def read_study(path):
    """The study of a study file (docs/study-format.md)."""
    return Study.read(path)


def _evaluate_on_worker(index, unit, study):
    """One design on a dask worker: its evaluation packed as bytes (exactly)."""
    import numpy as np
    return study._core._evaluate([index], np.asarray(unit, dtype=float).reshape(1, -1), 1)


class _DaskEngine:
    """Evaluates a batch of designs on the workers of a dask.distributed Client, one
    task per design; the study is sent to every worker once. When stopped() turns true
    the designs not yet finished are cancelled and reported as not evaluated (None)."""

    def __init__(self, client, study):
        self.client = client
        self.study = client.scatter(study, broadcast=True, hash=False)
        self.cores = max(1, sum(client.nthreads().values()))

    def __call__(self, indices, units, stopped):
        futures = self.client.map(_evaluate_on_worker, list(indices), [list(u) for u in units],
                                  study=self.study, pure=False)
        while not all(f.done() for f in futures) and not stopped():
            _time.sleep(0.02)
        results = []
        for f in futures:
            if f.done():
                results.append(f.result())
            else:
                f.cancel()
                results.append(None)
        return results
