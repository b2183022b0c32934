"""Plain messages for wrong arguments: the compiled functions refuse an argument they
cannot convert with a list of every signature ("incompatible function arguments");
this names the argument, what it must be and what it was given instead."""
import difflib
import functools
import numbers
import re

_INT_RANGE = (-(1 << 31), (1 << 31) - 1)  # a C++ int; a wider one never fails to convert


def _split(text):
    """@p text split at its top-level commas (not those inside brackets)."""
    parts, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c in "[(":
            depth += 1
        elif c in "])":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _signatures(function):
    """[(name, [(parameter, annotation, has_default, keyword_only)])] from the compiled
    function's docstring (one per overload)."""
    out = []
    for line in (function.__doc__ or "").splitlines():
        m = re.match(r"^(?:\d+\. )?(\w+)\((.*)\) -> ", line)
        if not m or m.group(2) == "*args, **kwargs":
            continue
        parameters, keyword_only = [], False
        for part in _split(m.group(2)):
            if part == "*":
                keyword_only = True
                continue
            name, _, rest = part.partition(":")
            annotation, _, default = rest.partition(" = ")
            parameters.append((name.strip(), annotation.strip(), bool(default), keyword_only))
        out.append((m.group(1), parameters))
    return out


def _describe(annotation):
    """What an annotation asks for, in words."""
    m = re.fullmatch(r"Optional\[(.*)\]", annotation)
    if m:
        return f"{_describe(m.group(1))} or None"
    m = re.fullmatch(r"List\[(.*)\]", annotation)
    if m:
        return f"a list of {_describe(m.group(1)).removeprefix('a ').removeprefix('an ')}s"
    words = {"int": "an integer", "float": "a number", "str": "a string", "bool": "True or False",
             "feran._feran.Model": "a feran.Model (feran.read_model(path) reads one)"}
    if annotation in words:
        return words[annotation]
    return f"a {annotation.split('.')[-1]}"


def _fits(value, annotation):
    """Whether @p value converts to @p annotation (as far as can be told here)."""
    m = re.fullmatch(r"Optional\[(.*)\]", annotation)
    if m:
        return value is None or _fits(value, m.group(1))
    m = re.fullmatch(r"List\[(.*)\]", annotation)
    if m:
        return (not isinstance(value, (str, bytes)) and hasattr(value, "__iter__")
                and all(_fits(v, m.group(1)) for v in value))
    if annotation == "int":  # numpy's integers too
        return (isinstance(value, numbers.Integral) and not isinstance(value, bool)
                and _INT_RANGE[0] <= int(value) <= _INT_RANGE[1])
    if annotation == "float":
        return isinstance(value, numbers.Real) and not isinstance(value, bool)
    if annotation == "str":
        return isinstance(value, str)
    if annotation == "bool":
        return isinstance(value, bool) or type(value).__name__ == "bool_"
    if annotation == "object":
        return True
    if annotation.startswith("feran."):
        return type(value).__name__ == annotation.split(".")[-1]
    return True  # an annotation not known here: not the one to blame


def _given(value):
    text = repr(value)
    return f"{type(value).__name__} {text if len(text) <= 40 else text[:37] + '...'}"


def _problems(name, parameters, args, kwargs):
    """What is wrong with a call of one signature: a list of sentences."""
    problems = []
    positional = [p for p in parameters if not p[3]]
    if positional and positional[0][0] == "self":
        shown = positional[1:]
    else:
        shown = positional
    if len(args) > len(positional):
        problems.append(f"takes {len(shown)} positional argument{'s' if len(shown) != 1 else ''} "
                        f"({', '.join(p[0] for p in shown) or 'none'}); the others are given by name")
    bound = dict(zip((p[0] for p in positional), args))
    names = [p[0] for p in parameters]
    for key, value in kwargs.items():
        if key not in names:
            close = difflib.get_close_matches(key, names, 1)
            others = ", ".join(n for n in names if n != "self")
            problems.append(f"has no argument '{key}'"
                            + (f"; did you mean '{close[0]}'?" if close else f"; its arguments are {others}"))
        elif key in bound:
            problems.append(f"got '{key}' twice")
        else:
            bound[key] = value
    for parameter, annotation, has_default, _ in parameters:
        if parameter not in bound:
            if not has_default and parameter != "self":
                problems.append(f"needs the argument '{parameter}' ({_describe(annotation)})")
            continue
        value = bound[parameter]
        if not _fits(value, annotation):
            if isinstance(value, numbers.Integral) and not isinstance(value, bool) and "int" in annotation:
                problems.append(f"'{parameter}' = {value} is beyond an integer's range "
                                f"({_INT_RANGE[0]} to {_INT_RANGE[1]})")
                continue
            what = "the value" if parameter == "arg1" else "the path" if parameter == "arg0" else f"'{parameter}'"
            problems.append(f"{what} must be {_describe(annotation)}, got {_given(value)}")
    return problems


def explained(function, owner=None):
    """@p function, raising a TypeError that names the wrong argument instead of the
    list of signatures."""
    signatures = _signatures(function)
    call_name = getattr(function, "__name__", "function")
    shown = f"{owner}.{call_name}" if owner else call_name
    if call_name == "__setitem__":
        shown = "model[path] = value"

    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            text = str(error)
            if "incompatible function arguments" not in text and "incompatible constructor arguments" not in text:
                raise
            found = [_problems(name, parameters, args, kwargs) for name, parameters in signatures]
            found = [p for p in found if p]
            if not found:
                raise
            best = min(found, key=len)
            if call_name == "__setitem__" and any("the value" in p for p in best):
                best = [f"the value must be text with its unit ('2e7 N/m') or a number in SI units, "
                        f"got {_given(args[2] if len(args) > 2 else None)}"]
            raise TypeError(f"{shown if call_name == '__setitem__' else shown + '()'}: {'; '.join(best)}") from None

    return call
