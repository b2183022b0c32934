"""feran: finite-element rotor dynamics (docs/python.md).

    import feran
    model = feran.read_model("examples/01_internal_damping/model.toml")
    modes = feran.modal(model, speed="30 Hz")
    modes.frequency_hz        # numpy array
"""
import inspect as _inspect
import json as _json

import numpy as _np

from ._toml import keys_toml as _keys_toml

from ._feran import (Api684Result, CampbellResult, Error, Interrupted, ModalResult, Model, ModelError,
                     OrbitsResult, ParameterError, ResponseResult, RunupResult, StaticResult, StudyResult, api684,
                     campbell, modal, orbits, read_model, report, response, runup, static)
from ._feran import __version__  # noqa: F401 -- re-exported
from .study import Study, read_study
from ._arguments import explained as _explained

from ._feran import _analysis_options, _model_tables

# Every compiled function and Model method names a wrong argument in its TypeError.
read_model, report = (_explained(f) for f in (read_model, report))


_MISSING = object()


def _analysis(compiled, options):
    """The analysis @p compiled (feran.<name>(model, **options)) with the signature and
    help its options' field table gives it: every option a keyword, None (the model's
    own table, else the analysis's default) unless given."""
    name = compiled.__name__
    summary = [line for line in (compiled.__doc__ or "").splitlines()[1:] if line.strip()]

    def function(model=_MISSING, *positional, **keywords):
        if model is _MISSING:
            raise TypeError(f"{name}(): needs the argument 'model' (a feran.Model: feran.read_model(path) reads one)")
        if positional:
            raise TypeError(f"{name}(): takes 1 positional argument (model); the others are given by name")
        if not isinstance(model, Model):
            text = repr(model)
            raise TypeError(f"{name}(): 'model' must be a feran.Model (feran.read_model(path) reads one), got "
                            f"{type(model).__name__} {text if len(text) <= 40 else text[:37] + '...'}")
        return compiled(model, **keywords)

    parameters = [_inspect.Parameter("model", _inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    lines = []
    for key, _kind, doc, default in options:
        parameters.append(_inspect.Parameter(key, _inspect.Parameter.KEYWORD_ONLY, default=None))
        default = {"true": "True", "false": "False"}.get(default, default)
        lines.append(f"    {key}: {doc.replace('`', '')}" + (f" (default {default})" if default else ""))
    function.__name__ = function.__qualname__ = name
    function.__signature__ = _inspect.Signature(parameters)
    function.__doc__ = "\n".join(summary) + (
        f", as feran {name} does.\n\nOptions (None: the model's [{name}] table, else the default): a string is read "
        "as on the command line ('30 Hz'), a number is in SI units (speeds in rad/s).\n" + "\n".join(lines))
    return function


# The analyses made from their faces (analyses/list.hpp in the library).
modal = _analysis(modal, _analysis_options["modal"])
campbell = _analysis(campbell, _analysis_options["campbell"])
static = _analysis(static, _analysis_options["static"])
response = _analysis(response, _analysis_options["response"])
runup = _analysis(runup, _analysis_options["runup"])
api684 = _analysis(api684, _analysis_options["api684"])
orbits = _analysis(orbits, _analysis_options["orbits"])
for _method in ("__init__", "__getitem__", "__setitem__", "geometry", "_add"):
    setattr(Model, _method, _explained(getattr(Model, _method), "Model"))


def _to_dict(result):
    """The result as the JSON file holds it (docs/output-format.md)."""
    return _json.loads(result.to_json())


_DOFS = ("u", "v", "w", "rx", "ry", "rz")
_HZ = 1 / (2 * _np.pi)


def _modal_frame(r):
    """One row per mode."""
    return _pd().DataFrame({"frequency_hz": r.frequency_hz, "damping_ratio": r.damping_ratio,
                            "log_decrement": r.log_decrement, "directivity": r.directivity,
                            "whirl": r.whirl, "type": r.type, "eigenvalue": r.eigenvalues})


def _campbell_frame(r):
    """One row per mode and speed (long form: group by 'label' for each mode's curve)."""
    n_modes, n_speeds = r.frequency_hz.shape
    return _pd().DataFrame({
        "speed_hz": _np.tile(r.speeds_hz, n_modes),
        "label": _np.repeat(_np.array(r.labels, dtype=object), n_speeds),
        "frequency_hz": r.frequency_hz.ravel(), "damping_ratio": r.damping_ratio.ravel(),
        "log_decrement": r.log_decrement.ravel(), "directivity": r.directivity.ravel(),
        "whirl": _np.array(r.whirl_at, dtype=object).ravel() if n_speeds else []})


def _response_frame(r):
    """One row per probe and point: speed and frequency [Hz], the orbit, and the complex
    amplitude of each DOF."""
    n_probes, n_points, _ = r.displacement.shape
    columns = {"probe": _np.repeat(_np.array(r.probes, dtype=object), n_points),
               "speed_hz": _np.tile(r.speeds * _HZ, n_probes),
               "frequency_hz": _np.tile(r.frequencies * _HZ, n_probes),
               "orbit_major": r.orbit_major.ravel(), "orbit_minor": r.orbit_minor.ravel()}
    for d, name in enumerate(_DOFS):
        columns[name] = r.displacement[:, :, d].ravel()
    return _pd().DataFrame(columns)


def _study_frame(r):
    """One row per design: index, the variables' values and the quantities (SI; NaN
    for a design that failed), evaluated, feasible, message and seconds."""
    columns = {"index": r.index}
    for j, name in enumerate(r.variable_names):
        columns[name] = r.values[:, j]
    for j, name in enumerate(r.quantity_names):
        columns[name] = r.quantities[:, j]
    columns.update(evaluated=r.evaluated, feasible=r.feasible, message=r.messages, seconds=r.seconds)
    return _pd().DataFrame(columns)


def _static_frame(r):
    """One row per node: x and the six displacements."""
    frame = _pd().DataFrame(r.displacement, columns=list(_DOFS))
    frame.insert(0, "x", r.x)
    frame.insert(0, "node", r.nodes)
    return frame


def _runup_frame(r):
    """One row per sample: time, speed [Hz], then per probe 'PROBE.u' … 'PROBE.rz' and
    'PROBE.r' (|r|), and per recorded spring 'SPRING.fx' … 'SPRING.mz'."""
    columns = {"time": r.time, "speed_hz": r.speed * _HZ}
    for i, probe in enumerate(r.probes):
        for d, name in enumerate(_DOFS):
            columns[f"{probe}.{name}"] = r.displacement[i, :, d]
        columns[f"{probe}.r"] = r.magnitude[i]
    for i, spring in enumerate(r.springs):
        for d, name in enumerate(("fx", "fy", "fz", "mx", "my", "mz")):
            columns[f"{spring}.{name}"] = r.spring_force[i, :, d]
    return _pd().DataFrame(columns)


def _orbits_frame(r):
    """One row per steady state of every branch: branch, parameter, speed_hz,
    frequency_hz, stable, largest_multiplier, then per probe 'PROBE.amplitude' and
    'PROBE.largest' [m]."""
    rows = []
    for b in r.branches:
        for k in range(len(b["parameter"])):
            row = {"branch": b["name"], "parameter": b["parameter"][k], "speed_hz": b["speed"][k] * _HZ,
                   "frequency_hz": b["frequency"][k] * _HZ, "stable": bool(b["stable"][k]),
                   "largest_multiplier": b["largest_multiplier"][k]}
            for i, probe in enumerate(r.probes):
                row[f"{probe}.amplitude"] = b["amplitude"][k, i]
                row[f"{probe}.largest"] = b["largest"][k, i]
            rows.append(row)
    return _pd().DataFrame(rows)


# -- building a model in code ----------------------------------------------------------
# Each add_<entry>(**keys) adds one entry of a model file's array of tables, with the
# file's keys (docs/model-format.md); set_table(name, **keys) sets a single table. The
# keys are handed to the model reader as TOML, so they are checked by the same rules
# as a file's; values are numbers in SI units or text with a unit ("210 GPa").

def _entry_word(table):
    """The name of one entry of an array of tables: rigid_bodies → rigid_body, springs → spring,
    friction and fixed as they are."""
    return table[:-3] + "y" if table.endswith("ies") else table[:-1] if table.endswith("s") else table


# The model file's tables, from the library's one list of them.
_ENTRIES = {_entry_word(key): key for key, array, _ in _model_tables() if array}
_TABLES = tuple(key for key, array, _ in _model_tables() if not array)


def _call_name(method, keys):
    name = keys.get("name", keys.get("node"))
    return f"{method}({'name' if 'name' in keys else 'node'}={name!r})" if name is not None else f"{method}()"


def _adder(entry, table):
    def add(self, **keys):
        call = _call_name(f"add_{entry}", keys)
        self._add(table, _keys_toml(keys, call), call)
        return self

    add.__name__ = f"add_{entry}"
    add.__doc__ = (f"Adds a [[{table}]] entry with the keys of docs/model-format.md (numbers in SI units or "
                   f"text with a unit); returns the model, so that calls chain.")
    return add


for _entry, _table in _ENTRIES.items():
    setattr(Model, f"add_{_entry}", _adder(_entry, _table))


def _set_table(self, table, **keys):
    """Sets a single table ([options], [modal], [campbell], [response], [static], [runup],
    [api684], [orbits], [drive]: feran._TABLES) to these keys (those not given take their defaults);
    returns the model."""
    if table not in _TABLES:
        raise Error(f"set_table({table!r}): expected one of {', '.join(_TABLES)}")
    call = f"set_table({table!r})"
    self._add(table, _keys_toml(keys, call), call)
    return self


def _from_dict(data):
    """A model from a dict shaped like the model file: {"title": …, "materials": [{…}],
    "shafts": [{…, "sections": [{…}]}], "campbell": {…}, …}."""
    data = dict(data)
    model = Model(data.pop("title", ""))
    tables = {t: e for e, t in _ENTRIES.items()}
    for key, value in data.items():
        if key in tables:
            if not isinstance(value, (list, tuple)):
                raise Error(f"from_dict: '{key}' is a list of entries (an array of tables)")
            for entry in value:
                getattr(model, f"add_{tables[key]}")(**entry)
        elif key in _TABLES:
            model.set_table(key, **value)
        else:
            raise Error(f"from_dict: no table '{key}' in a model (docs/model-format.md)")
    return model


Model.set_table = _set_table
Model.from_dict = staticmethod(_from_dict)


def _pd():
    try:
        import pandas
    except ImportError as e:  # pandas is optional: everything else works without it
        raise ImportError("to_pandas() needs pandas (Debian: apt-get install python3-pandas)") from e
    return pandas


for _result, _frame in ((ModalResult, _modal_frame), (CampbellResult, _campbell_frame),
                        (ResponseResult, _response_frame), (StaticResult, _static_frame),
                        (RunupResult, _runup_frame), (OrbitsResult, _orbits_frame), (StudyResult, _study_frame)):
    if hasattr(_result, "to_json"):
        _result.to_dict = _to_dict
    _result.to_pandas = _frame


# Every speed a result holds in rad/s is also given in Hz and in rpm: NAME_hz, NAME_rpm.
_SPEEDS = {ModalResult: ("speed",), CampbellResult: ("speeds",), ResponseResult: ("speeds", "first_unstable_speed"),
           RunupResult: ("speed", "envelope_speed"), Api684Result: ("min_speed", "max_speed", "undamped_criticals")}


def _speed_in(name, factor, unit):
    def get(self):
        value = getattr(self, name)
        if value is None:
            return None
        return (_np.asarray(value, dtype=float) * factor) if not _np.isscalar(value) else float(value) * factor

    return property(get, doc=f"{name} in {unit}")


for _result, _names in _SPEEDS.items():
    for _name in _names:
        if not hasattr(_result, f"{_name}_hz"):
            setattr(_result, f"{_name}_hz", _speed_in(_name, _HZ, "Hz"))
        setattr(_result, f"{_name}_rpm", _speed_in(_name, 60 * _HZ, "rpm"))

__all__ = ["CampbellResult", "Error", "Interrupted", "ModalResult", "Model", "ModelError", "OrbitsResult",
           "ParameterError", "ResponseResult", "RunupResult", "StaticResult", "Study", "StudyResult", "campbell",
           "modal", "orbits", "read_model", "read_study", "response", "runup", "static"]
