"""TOML text of Python values, for the model and study readers: what Python builds in
code is handed to the same readers as a file, and checked by the same rules."""
import json as _json

import numpy as _np


def toml_key(key):
    key = key[:-1] if key.endswith("_") and key[:-1] in ("from",) else key
    return key if key and all(c.isalnum() or c in "_-" for c in key) else _json.dumps(key)


def toml_value(value, where):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, _np.integer)):
        return str(int(value))
    if isinstance(value, (float, _np.floating)):
        x = float(value)
        return "nan" if x != x else ("inf" if x == float("inf") else "-inf" if x == -float("inf") else repr(x))
    if isinstance(value, str):
        return _json.dumps(value)  # JSON's escapes are TOML's
    if isinstance(value, dict):
        return "{" + ", ".join(f"{toml_key(k)} = {toml_value(v, f'{where}.{k}')}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, _np.ndarray)):
        return "[" + ", ".join(toml_value(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    raise TypeError(f"{where}: {type(value).__name__} is not a value of a model (a number, text, true/false, "
                    f"a list or a dict)")


def keys_toml(keys, call):
    if not all(isinstance(k, str) for k in keys):
        raise TypeError(f"{call}: keys are text")
    return "\n".join(f"{toml_key(k)} = {toml_value(v, f'{call}: {k}')}" for k, v in keys.items()) + "\n"
