"""feran: finite-element rotor dynamics (docs/python.md).

    import feran
    model = feran.read_model("examples/01_internal_damping/model.toml")
    modes = feran.modal(model, speed="30 Hz")
    modes.frequency_hz        # numpy array
"""
import json as _json

from ._feran import (CampbellResult, Error, Interrupted, ModalResult, Model, ModelError, ParameterError,
                     ResponseResult, RunupResult, StaticResult, campbell, modal, read_model, response,
                     runup, static)


def _to_dict(result):
    """The result as the JSON file holds it (docs/output-format.md)."""
    return _json.loads(result.to_json())


for _result in (ModalResult, CampbellResult, ResponseResult, StaticResult, RunupResult):
    _result.to_dict = _to_dict

__all__ = ["CampbellResult", "Error", "Interrupted", "ModalResult", "Model", "ModelError", "ParameterError",
           "ResponseResult", "RunupResult", "StaticResult", "campbell", "modal", "read_model", "response",
           "runup", "static"]
