"""TOML text of Python values, for the model and study readers: what Python builds in
code is handed to the same readers as a file, and checked by the same rules."""
import json as _json

import numpy as _np

from ._feran import Error


def toml_key(key, where="key"):
    if not isinstance(key, str):
        raise TypeError(f"{where}: keys are text, got {type(key).__name__} {key!r}")
    key = key[:-1] if key.endswith("_") and key[:-1] in ("from",) else key
    return key if key and all(c.isalnum() or c in "_-" for c in key) else _text(key, where)


def _text(value, where):
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as e:
        raise Error(f"{where}: {value!r} is not valid text ({e.reason} at position {e.start})") from None
    # JSON's escapes are TOML's; TOML also escapes DEL, which JSON leaves as it is.
    return _json.dumps(value, ensure_ascii=False).replace("\x7f", "\\u007f")


_DEPTH = 16  # a model's values nest at most four levels (a table law in an inline table)


def toml_value(value, where, depth=0):
    if depth > _DEPTH:
        raise Error(f"{where}: nested more than {_DEPTH} levels deep (a list or dict that holds itself?); "
                    f"a model's values nest at most four")
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return "true" if value else "false"
    if isinstance(value, (int, _np.integer)):
        if not -(1 << 63) <= int(value) < (1 << 63):
            raise Error(f"{where}: {int(value)} is beyond a 64-bit integer; give a number such as {float(value):g}")
        return str(int(value))
    if isinstance(value, (float, _np.floating)):
        x = float(value)
        return "nan" if x != x else ("inf" if x == float("inf") else "-inf" if x == -float("inf") else repr(x))
    if isinstance(value, str):
        return _text(value, where)
    if isinstance(value, dict):
        return "{" + ", ".join(f"{toml_key(k, where)} = {toml_value(v, f'{where}.{k}', depth + 1)}"
                               for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, _np.ndarray)):
        return "[" + ", ".join(toml_value(v, f"{where}[{i}]", depth + 1) for i, v in enumerate(value)) + "]"
    raise TypeError(f"{where}: {type(value).__name__} is not a value of a model (a number, text, true/false, "
                    f"a list or a dict)")


def keys_toml(keys, call):
    if not all(isinstance(k, str) for k in keys):
        raise TypeError(f"{call}: keys are text")
    return "\n".join(f"{toml_key(k)} = {toml_value(v, f'{call}: {k}')}" for k, v in keys.items()) + "\n"
