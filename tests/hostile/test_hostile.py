"""A corpus of hostile inputs for the feran command: bad syntax, types, units, ranges,
references, sizes, encodings, special files and option combinations. Each case
states its exit code and the message (with its location, file:line:column, where
the problem is in a file); every case runs in a directory of its own with --json and
--csv asked for, and must leave no file behind. A case ends in one of:

  located   the stated exit code and message (a clear, located error)   -- expected
  crash     a signal, an internal error (exit 4) or a sanitizer report
  hang      no end within the time limit
  accepted  exit 0 for an input that must be refused (nonsense accepted)
  damaged   an output file written, or the model file changed
  other     another exit code or another message

Run by ctest (tests/hostile/CMakeLists.txt), one test per group:

    python3 tests/hostile/test_hostile.py FERAN SOURCE_DIR [GROUP]
    python3 tests/hostile/test_hostile.py FERAN SOURCE_DIR --summary   # counts per outcome, never fails
"""
import os
import re
import signal
import stat
import subprocess
import sys
import tempfile
import time

TIME_LIMIT = 120  # seconds per case; the slowest legitimate refusal takes well under one


class Case:
    def __init__(self, group, name, args, code, message, model=None, files=None, setup=None, signal=None,
                 written=(), python=None):
        self.group, self.name, self.args, self.code, self.message = group, name, args, code, message
        self.model = model  # text (str or bytes) of model.toml, written into the case's directory
        self.files = files or {}  # more files: name -> bytes (or str)
        self.setup = setup  # a function of the directory, for special files
        self.signal = signal  # sent once the run has begun (its outputs' temporary files exist)
        self.written = set(written)  # outputs that may be written (a run stopped by a signal keeps its results)
        self.python = python  # a Python statement run with feran imported and `model` read from model.toml


def base_model():
    with open(os.path.join(SOURCE, "examples", "01_internal_damping", "model.toml"), encoding="utf-8") as f:
        return f.read()


def mutated(old, new, count=1):
    text = base_model()
    assert old in text, old
    return text.replace(old, new, count)


def line_of(text, needle):
    return text[: text.index(needle)].count("\n") + 1


def in_model(group, name, old, new, message, line_needle=None, args=("modal",), code=1, line_offset=0):
    """A case of the example model with @p old replaced by @p new; the message must be
    located at the line holding @p line_needle (default: @p new), plus @p line_offset."""
    text = mutated(old, new)
    line = line_of(text, line_needle if line_needle is not None else new) + line_offset
    return Case(group, name, [args[0], "model.toml", *args[1:]], code,
                rf"model\.toml:{line}:\d+: .*{message}", model=text)


def journal_model():
    with open(os.path.join(SOURCE, "tests", "models", "valid", "journal_rotor.toml"), encoding="utf-8") as f:
        return f.read()


# The journal rotor with its second journal bearing a ball bearing.
ROLLING = """[[rolling_bearings]]
name = "bearing B"
node = "bearing B"
elements = 9
element_diameter = "12 mm"
pitch_diameter = "60 mm"
hertz_constant = 8e9
clearance = "10 um"

"""


def rolling_model():
    text = journal_model()
    a = text.index('[[journal_bearings]]\nname = "bearing B"')
    b = text.index("[[fixed]]")
    return text[:a] + ROLLING + text[b:]


def in_text(group, name, text, old, new, message, line_needle=None, args=("modal",), code=1, count=1):
    """A case of @p text with @p old replaced by @p new (the first @p count times),
    located at the line holding @p line_needle (default @p new)."""
    assert old in text, old
    changed = text.replace(old, new, count)
    line = line_of(changed, line_needle if line_needle is not None else new)
    return Case(group, name, [args[0], "model.toml", *args[1:]], code, rf"model\.toml:{line}:\d+: .*{message}",
                model=changed)


def quantity_cases(group, text, table_line, key, written, unit_kind, positive=True):
    """The hostile values of quantity @p key (written in @p text as `key = written`,
    first after @p table_line): each refused at its line with a plain message."""
    old = f"{key} = {written}"
    start = text.index(table_line)
    at = text.index(old, start)
    head, tail = text[:at], text[at:]

    def case(name, value, message):
        changed = head + tail.replace(old, f"{key} = {value}", 1)
        line = changed[:at].count("\n") + 1
        return Case(group, f"{key}_{name}", ["modal", "model.toml"], 1, rf"model\.toml:{line}:\d+: .*{message}",
                    model=changed)

    sign = "must be positive" if positive else "must not be negative"
    return [
        case("negative", '"-1 mm"' if unit_kind == "length" else "-1", f"'{key}' {sign}"),
        case("boolean", "true", f"'{key}' must be"),
        case("array", "[1, 2]", f"'{key}' must be"),
        case("wrong_unit", '"5 kg"', f"'{key}' has unit 'kg'"),
        case("unknown_unit", '"5 furlong"', f"'{key}' has unit 'furlong'"),
        case("nan", '"nan"', f"'{key}'"),
        case("infinite", '"inf"', f"'{key}'"),
        case("overflow", "1e308" if unit_kind != "length" else '"1e308 km"', f"'{key}'"),
        case("empty_string", '""', f"'{key}'"),
    ]


def cases():
    out = []
    add = out.append
    E = ["modal", "model.toml"]

    # ------------------------------------------------------------------ fixtures
    invalid = os.path.join(SOURCE, "tests", "models", "invalid")
    for name in sorted(os.listdir(invalid)):
        with open(os.path.join(invalid, name), "rb") as f:
            data = f.read()
        head = data.decode("utf-8", "replace").splitlines()
        line = re.match(r"# error-line: (\d+)", head[0]).group(1)
        match = re.match(r"# error-match: (.*)", head[1]).group(1)
        match = match[1:] if match.startswith("^") else ".*" + match
        add(Case("fixtures", name[:-5], ["modal", "model.toml"], 1, rf"model\.toml:{line}:\d+: {match}", model=data))

    # ------------------------------------------------------------------ syntax
    add(in_model("syntax", "unclosed_string", 'name = "steel"', 'name = "steel', "TOML syntax error"))
    add(in_model("syntax", "unclosed_header", "[[springs]]", "[[springs]", "TOML syntax error"))
    add(in_model("syntax", "duplicate_key", 'nu = 0.3', 'nu = 0.3\nnu = 0.4', "TOML syntax error.*redefine", "nu = 0.4"))
    add(in_model("syntax", "missing_equals", 'nu = 0.3', 'nu 0.3', "TOML syntax error"))
    add(in_model("syntax", "missing_value", 'nu = 0.3', 'nu =', "TOML syntax error"))
    add(in_model("syntax", "bad_escape", 'name = "steel"', r'name = "st\qeel"', "TOML syntax error"))
    add(in_model("syntax", "bare_word_value", 'material = "steel"', 'material = steel', "TOML syntax error"))
    add(in_model("syntax", "unclosed_inline_table", 'nu = 0.3', 'nu = {a = 1', "TOML syntax error"))
    add(in_model("syntax", "unclosed_array", 'nu = 0.3', 'nu = [1, 2', "TOML syntax error", "nu = [", line_offset=1))
    add(in_model("syntax", "stray_bracket", 'nu = 0.3', 'nu = 0.3 ]', "TOML syntax error"))
    add(in_model("syntax", "table_redefined", "[campbell]", "[campbell]\n[campbell]", "TOML syntax error",
                 "[campbell]\n[campbell]", line_offset=1))
    add(in_model("syntax", "header_without_name", "[[springs]]", "[[ =springs]]",
                 "a table header must name its table"))
    add(in_model("syntax", "unit_without_quotes", 'length = "60 mm"', 'length = 60 mm', "TOML syntax error"))
    add(in_model("syntax", "micro_unquoted", 'length = "60 mm"', 'length = 60000 µm',
                 "'µ' outside a quoted string or a comment"))
    add(in_model("syntax", "key_too_deep", 'nu = 0.3', "a" + ".a" * 80 + " = 1", "nesting too deep"))
    add(in_model("syntax", "arrays_too_deep", 'nu = 0.3', "nu = " + "[" * 300 + "]" * 300,
                 "exceeded maximum nested value depth"))
    add(in_model("syntax", "unknown_table", "[campbell]", "[campbel]", "unknown key 'campbel' at the top level; did you mean 'campbell'"))
    add(in_model("syntax", "unknown_key", 'nu = 0.3', 'nuu = 0.3', "unknown key 'nuu'.*did you mean 'nu'"))

    # ------------------------------------------------------------------ encodings
    text = base_model()
    add(Case("encodings", "nul_byte", E, 1, r"model\.toml:\d+:\d+: TOML syntax error",
             model=text.replace('nu = 0.3', 'nu = 0\x003').encode()))
    add(Case("encodings", "invalid_utf8_in_string", E, 1, r"model\.toml:\d+:\d+: TOML syntax error",
             model=text.encode().replace(b'name = "steel"', b'name = "st\xffeel"')))
    add(Case("encodings", "invalid_utf8_outside_string", E, 1,
             r"model\.toml:\d+:\d+: the byte \\xff outside a quoted string",
             model=text.encode().replace(b"nu = 0.3", b"nu = 0.3 \xff")))
    add(Case("encodings", "utf16", E, 1, r"model\.toml:1:\d+: ",
             model=text.encode("utf-16")))
    add(Case("encodings", "lone_carriage_return", E, 1, r"model\.toml:\d+:\d+: TOML syntax error",
             model=text.replace("nu = 0.3\n", "nu = 0.3\rrho2 = 1\n")))
    add(Case("encodings", "middle_dot", E, 1, r"model\.toml:1:1: '·' outside a quoted string", model=b"\xc2\xb7"))
    add(Case("encodings", "binary_garbage", E, 1, r"model\.toml:1:\d+: ", model=bytes(range(256)) * 4))
    add(Case("encodings", "empty_file", E, 1, r"model\.toml:1:1: the model has no nodes", model=b""))
    add(Case("encodings", "only_comments", E, 1, r"model\.toml:1:1: the model has no nodes", model=b"# nothing\n"))

    # ------------------------------------------------------------------ types
    add(in_model("types", "boolean_modulus", 'E = "210 GPa"', 'E = true', "'E' must be"))
    add(in_model("types", "string_number", 'nu = 0.3', 'nu = "0.3"', "'nu' must be a number"))
    add(in_model("types", "fractional_count", 'elements = 6', 'elements = 2.5', "'elements' must be an integer"))
    add(in_model("types", "string_count", 'elements = 6', 'elements = "6"', "'elements' must be an integer"))
    add(in_model("types", "list_not_string", 'name = "rotor"', 'name = ["rotor"]', "'name' must be a string"))
    add(in_model("types", "table_not_list", 'probes = ["rotor"]', 'probes = {a = 1}', "'probes' must be"))
    add(in_model("types", "string_not_list", 'probes = ["rotor"]\n\n[runup]', 'probes = "rotor"\n\n[runup]',
                 "'probes' must be", 'probes = "rotor"'))
    add(in_model("types", "date_value", 'nu = 0.3', 'nu = 1979-05-27', "'nu' must be a number"))
    add(in_model("types", "array_of_tables_as_table", '[[fixed]]', '[fixed]', "'fixed' must be an array of tables"))

    # ------------------------------------------------------------------ units
    add(in_model("units", "unknown_unit", 'length = "60 mm"', 'length = "60 mmm"', "'length' has unit 'mmm', expected a length"))
    add(in_model("units", "wrong_quantity", 'length = "60 mm"', 'length = "60 kg"', "'kg' is a unit of mass"))
    add(in_model("units", "no_number", 'length = "60 mm"', 'length = "mm"', "'length' must be a length"))
    add(in_model("units", "compound_wrong", 'rho = "7850 kg/m^3"', 'rho = "7850 kg/m^4"', "'rho'"))
    add(in_model("units", "overflowing_number", 'length = "60 mm"', 'length = "1e400 mm"', "'length'"))
    add(in_model("units", "nan_quantity", 'length = "60 mm"', 'length = "nan mm"', "'length'"))
    add(in_model("units", "inf_quantity", 'length = "60 mm"', 'length = "inf mm"', "'length'"))
    add(in_model("units", "double_sign", 'length = "60 mm"', 'length = "--60 mm"', "'length'"))
    add(in_model("units", "speed_in_seconds", 'stop = "80 Hz"', 'stop = "80 s"', "'stop' has unit 's', expected a speed"))

    # ------------------------------------------------------------------ ranges
    add(in_model("ranges", "modulus_1e308", 'E = "210 GPa"', 'E = "1e308 GPa"', "'E' must be a finite number"))
    add(in_model("ranges", "density_1e308", 'rho = "7850 kg/m^3"', 'rho = "1e308 g/cm^3"', "'rho' must be a finite number"))
    add(in_model("ranges", "length_1e-300", 'length = "60 mm"', 'length = "1e-300 m"', "below the physical range"))
    add(in_model("ranges", "length_1e308", 'length = "60 mm"', 'length = "1e308 m"', "beyond the physical range"))
    add(in_model("ranges", "speed_1e308", 'stop = "80 Hz"\npoints = 161\nmodes', 'stop = "1e308 Hz"\npoints = 161\nmodes',
                 "'stop'", 'stop = "1e308 Hz"'))
    add(in_model("ranges", "mass_1e308", 'mass = "9.1 kg"', 'mass = "1e308 kg"', "beyond the physical range"))
    add(in_model("ranges", "unbalance_1e300", 'mass = "0.01 kg"', 'mass = "1e300 kg"', "beyond the physical range"))
    add(in_model("ranges", "negative_length", 'length = "60 mm"', 'length = "-60 mm"', "'length' must be positive"))
    add(in_model("ranges", "poisson_too_large", 'nu = 0.3', 'nu = 0.6', "'nu'"))
    add(in_model("ranges", "zero_elements", 'elements = 6', 'elements = 0', "'elements' must be at least 1"))
    add(in_model("ranges", "too_many_elements", 'elements = 6', 'elements = 1000000', "'elements' must be at most"))
    add(in_model("ranges", "points_1e9", 'points = 161\nmodes', 'points = 1000000000\nmodes',
                 "'points' must be at most 1000000", "points = 1000000000"))
    add(in_model("ranges", "negative_speed", 'start = "0 Hz"\nstop = "80 Hz"\npoints = 161\nmodes',
                 'start = "-5 Hz"\nstop = "80 Hz"\npoints = 161\nmodes', "'start' must not be negative",
                 'start = "-5 Hz"'))
    add(in_model("ranges", "stop_below_start", 'start = "0 Hz"\nstop = "80 Hz"\npoints = 161\nmodes',
                 'start = "90 Hz"\nstop = "80 Hz"\npoints = 161\nmodes', "'stop'.*must be greater than 'start'",
                 'stop = "80 Hz"\npoints = 161\nmodes'))
    add(in_model("ranges", "inner_above_outer", 'outer_diameter = "6 mm"', 'outer_diameter = "6 mm"\n  inner_diameter = "7 mm"',
                 "inner_diameter", 'inner_diameter = "7 mm"'))
    add(in_model("ranges", "damping_1e300", 'cy = "250 N*s/m"', 'cy = "1e300 N*s/m"', "beyond the physical range"))
    add(in_model("ranges", "runup_dt_1e-300", 'dt = "0.1 ms"', 'dt = "1e-300 s"', "below the physical range"))
    add(in_model("ranges", "runup_duration_1e300", 'ramp_time = "5 s"', 'ramp_time = "5 s"\nduration = "1e300 s"',
                 "beyond the physical range", 'duration = "1e300 s"'))

    # ------------------------------------------------------------------ references
    add(in_model("references", "unknown_material", 'material = "steel"', 'material = "titanium"',
                 "material 'titanium' is not defined; the defined materials are 'steel'"))
    fixed = '[[fixed]]              # clamped at the drive end (all six DOFs)\nnode = "drive"'
    add(in_model("references", "unknown_node", fixed, '[[fixed]]\nnode = "driev"', "'driev' does not exist.*did you mean 'drive'",
                 'node = "driev"'))
    add(in_model("references", "unknown_probe", 'probes = ["rotor"]', 'probes = ["rotr"]', "'rotr'"))
    add(in_model("references", "duplicate_probe", 'probes = ["rotor"]', 'probes = ["rotor", "rotor"]', "appears twice"))
    add(in_model("references", "unknown_dof", '[[fixed]]              # clamped at the drive end (all six DOFs)\nnode = "drive"',
                 '[[fixed]]\nnode = "drive"\ndofs = ["qx"]', "got \"qx\"; did you mean \"rx\"", 'dofs = ["qx"]'))
    add(in_model("references", "unknown_free_motion", '[campbell]', '[options]\nfree_motions = ["wobble"]\n\n[campbell]',
                 "wobble", 'free_motions'))
    add(in_model("references", "unknown_integrator", 'integrator = "trapezoidal"', 'integrator = "euler"', 'got "euler"'))
    add(in_model("references", "node_number_overflow", 'start_node = "drive"', 'start_node = 2147483648', "start_node"))
    long_name = "x" * 100000
    add(in_model("references", "long_unknown_name", fixed, f'[[fixed]]\nnode = "{long_name}"', "does not exist",
                 'node = "xxx'))

    # ------------------------------------------------------------------ bearings
    J = journal_model()
    RB = rolling_model()
    jb = '[[journal_bearings]]\nname = "bearing A"'
    for key, written, kind in [("diameter", '"60 mm"', "length"), ("length", '"30 mm"', "length"),
                               ("clearance", '"0.06 mm"', "length"), ("viscosity", '"20 mPa*s"', "viscosity")]:
        out.extend(quantity_cases("bearings", J, jb, key, written, kind))
    rb = "[[rolling_bearings]]"
    for key, written, kind, positive in [("element_diameter", '"12 mm"', "length", True),
                                         ("pitch_diameter", '"60 mm"', "length", True),
                                         ("clearance", '"10 um"', "length", False)]:
        out.extend(quantity_cases("bearings", RB, rb, key, written, kind, positive))
    visc = 'viscosity = "20 mPa*s"'
    finite = visc + '\ntheory = "finite"'
    add(in_text("bearings", "theory_unknown", J, visc, visc + '\ntheory = "shortt"', 'must be "short", "long" or "finite".*did you mean "short"', 'theory = "shortt"'))
    add(in_text("bearings", "theory_capitalised", J, visc, visc + '\ntheory = "Short"', 'must be "short", "long" or "finite"', 'theory = "Short"'))
    add(in_text("bearings", "theory_number", J, visc, visc + "\ntheory = 1", "'theory' must be a string", "theory = 1"))
    add(in_text("bearings", "cavitation_unknown", J, visc, finite + '\ncavitation = "swift"', 'must be "reynolds" or "gumbel"', 'cavitation = "swift"'))
    add(in_text("bearings", "cavitation_without_finite", J, visc, visc + '\ncavitation = "gumbel"', "applies only to theory = \"finite\"", 'cavitation = "gumbel"'))
    add(in_text("bearings", "cells_without_finite", J, visc, visc + "\naxial_cells = 4", "applies only to theory", "axial_cells = 4"))
    add(in_text("bearings", "evaluation_unknown", J, visc, finite + '\nevaluation = "fast"', 'must be "auto", "table" or "exact"', 'evaluation = "fast"'))
    add(in_text("bearings", "evaluation_without_finite", J, visc, visc + '\nevaluation = "table"', "applies only to theory = \"finite\"", 'evaluation = "table"'))
    add(in_text("bearings", "axial_cells_zero", J, visc, finite + "\naxial_cells = 0", "'axial_cells' must be at least 1", "axial_cells = 0"))
    add(in_text("bearings", "axial_cells_fraction", J, visc, finite + "\naxial_cells = 2.5", "'axial_cells' must be an integer", "axial_cells = 2.5"))
    add(in_text("bearings", "circumferential_cells_few", J, visc, finite + "\ncircumferential_cells = 4", "'circumferential_cells' must be at least 8", "circumferential_cells = 4"))
    add(in_text("bearings", "grid_product_too_large", J, visc, finite + "\ncircumferential_cells = 100000\naxial_cells = 10000",
                r"grid of 100000 × 10000 = 1000000000 cells is too large: at most 250000", "axial_cells = 10000"))
    add(in_text("bearings", "clearance_beyond_radius", J, 'clearance = "0.06 mm"', 'clearance = "40 mm"', "must be smaller than the journal's radius"))
    add(in_text("bearings", "housing_is_journal", J, 'node = "bearing A"\ndiameter', 'node = "bearing A"\nto = "bearing A"\ndiameter', "'to' must be a node other than 'node'", 'to = "bearing A"'))
    add(in_text("bearings", "housing_rotates", J, 'node = "bearing A"\ndiameter', 'node = "bearing A"\nto = "disk 1"\ndiameter', "the housing of a journal bearing must not rotate", 'to = "disk 1"'))
    add(in_text("bearings", "journal_unknown", J, 'node = "bearing A"\ndiameter', 'node = "bearing X"\ndiameter', "node 'bearing X' does not exist; did you mean 'bearing A'", 'node = "bearing X"'))
    add(in_text("bearings", "unknown_key", J, visc, visc + '\nviscosty = "20 mPa*s"', "unknown key 'viscosty'.*did you mean 'viscosity'", 'viscosty ='))
    add(in_text("bearings", "rolling_type_unknown", RB, "hertz_constant = 8e9", 'hertz_constant = 8e9\ntype = "needle"', 'must be "ball" or "roller"', 'type = "needle"'))
    add(in_text("bearings", "rolling_element_beyond_pitch", RB, 'element_diameter = "12 mm"', 'element_diameter = "70 mm"', "must be smaller than the pitch diameter"))
    add(in_text("bearings", "rolling_angle_90", RB, "hertz_constant = 8e9", 'hertz_constant = 8e9\ncontact_angle = "90 deg"', "below 90", 'contact_angle = "90 deg"'))
    add(in_text("bearings", "rolling_angle_negative", RB, "hertz_constant = 8e9", 'hertz_constant = 8e9\ncontact_angle = "-5 deg"', "'contact_angle' must not be negative", 'contact_angle = "-5 deg"'))
    add(in_text("bearings", "rolling_hertz_with_unit", RB, "hertz_constant = 8e9", 'hertz_constant = "8e9 N/m"', "'hertz_constant' must be a number without unit"))
    add(in_text("bearings", "rolling_hertz_zero", RB, "hertz_constant = 8e9", "hertz_constant = 0", "'hertz_constant' must be positive"))
    add(in_text("bearings", "rolling_elements_zero", RB, "elements = 9", "elements = 0", "'elements' must be at least 1"))
    add(in_text("bearings", "rolling_elements_huge", RB, "elements = 9", "elements = 100000", "'elements' must be at most 10000"))
    add(in_text("bearings", "rolling_missing_hertz", RB, "hertz_constant = 8e9\n", "", "missing key 'hertz_constant'", "[[rolling_bearings]]"))
    add(Case("bearings", "static_at_rest", ["static", "model.toml", "--speed", "0Hz"], 1,
             r"the fluid film bearing 'bearing A' carries no load at rest", model=J))
    add(Case("bearings", "modal_at_rest", ["modal", "model.toml", "--speed", "0Hz"], 1,
             r"the fluid film bearing 'bearing A' carries no load at rest", model=J))
    add(Case("bearings", "campbell_from_rest", ["campbell", "model.toml", "--start", "0Hz", "--stop", "100Hz"], 1,
             r"carries no load at rest", model=J))
    add(Case("bearings", "rolling_clearance_never_closed", ["static", "model.toml"], 3,
             r"equilibrium at .* was not found.*likely cause: the rolling bearing 'bearing B' has no stiffness",
             model=RB.replace('clearance = "10 um"', 'clearance = "1 m"')))
    add(Case("bearings", "unbalance_beyond_clearance", ["response", "model.toml"], 0,
             r"warning: the journal orbit in 'bearing A' reaches .* × its clearance",
             model=J.replace('mass = "2 g"', 'mass = "2 kg"')))

    # ------------------------------------------------------------------ api684
    op = 'min_speed = "8000 rpm"\nmax_speed = "10000 rpm"'
    A = ["api684"]
    add(in_text("api684", "min_above_max", J, op, 'min_speed = "11000 rpm"\nmax_speed = "10000 rpm"', r"'max_speed' \(10000 rpm\) must not be below 'min_speed'", 'max_speed = "10000 rpm"', args=A))
    add(in_text("api684", "min_zero", J, op, 'min_speed = "0 rpm"\nmax_speed = "10000 rpm"', "'min_speed' must be positive", 'min_speed = "0 rpm"', args=A))
    add(in_text("api684", "unknown_key", J, op, op + '\nmin_sped = "1 rpm"', "unknown key 'min_sped' in \\[api684\\]; did you mean 'min_speed'", "min_sped", args=A))
    add(in_text("api684", "unbalance_unknown", J, op, op + '\nunbalance = "4W/n"', 'must be "4W/N" or "model"', 'unbalance = "4W/n"', args=A))
    add(in_text("api684", "unbalance_multiple_zero", J, op, op + "\nunbalance_multiple = 0", "'unbalance_multiple' must be positive", "unbalance_multiple = 0", args=A))
    add(in_text("api684", "points_two", J, op, op + "\npoints = 2", "'points' must be at least 3", "points = 2", args=A))
    add(in_text("api684", "modes_zero", J, op, op + "\nmodes = 0", "'modes' must be at least 1", "modes = 0", args=A))
    add(in_text("api684", "map_points_one", J, op, op + "\nmap_points = 1", "'map_points' must be at least 2", "map_points = 1", args=A))
    add(in_text("api684", "map_high_below_low", J, op, op + '\nmap_low = "1e8 N/m"\nmap_high = "1e6 N/m"', "'map_high'", 'map_high', args=A))
    add(in_text("api684", "probe_unknown", J, op, op + '\nprobes = ["disk 3"]', "'disk 3' does not exist", 'probes = ["disk 3"]', args=A))
    add(in_text("api684", "probe_twice", J, op, op + '\nprobes = ["disk 1", "disk 1"]', "appears twice", 'probes = ["disk 1", "disk 1"]', args=A))
    add(in_text("api684", "stop_negative", J, op, op + '\nstop = "-1 rpm"', "'stop' must be positive", 'stop = "-1 rpm"', args=A))
    add(in_text("api684", "stability_node_unknown", J, op, op + '\nstability_node = "disk 9"', "'disk 9' does not exist", 'stability_node = "disk 9"', args=A))
    add(Case("api684", "response_work_unbounded", ["api684", "model.toml", "--points", "1000000"], 1,
             r"unbalance responses would take 2 × 1000000 = 2000000 points .* at most 200000", model=J))
    add(Case("api684", "map_work_unbounded", ["api684", "model.toml", "--map-points", "1000000"], 1,
             r"critical speed map would take 1000000 × 4 = 4000000 critical speeds .* at most 100000", model=J))
    add(Case("api684", "no_operating_range", ["api684", "model.toml"], 1, r"min_speed",
             model=J.replace(op, "")))
    add(Case("api684", "json_is_model", ["api684", "model.toml", "--json", "model.toml"], 1, r"it is the model file",
             model=J))

    # ------------------------------------------------------------------ drives
    with open(os.path.join(SOURCE, "examples", "02_centrifuge", "model_motor.toml"), encoding="utf-8") as f:
        M = f.read()
    dc = 'motor = "dc"'
    stall = 'stall_torque = "4 N*m"   # T = T_s (1 - W/W_0)\n'
    R = ["runup"]
    add(in_text("drives", "motor_unknown", M, dc, 'motor = "stepper"', 'must be "dc", "induction" or "table", got "stepper"', args=R))
    add(in_text("drives", "motor_capitalised", M, dc, 'motor = "DC"', 'must be "dc", "induction" or "table"', args=R))
    add(in_text("drives", "motor_number", M, dc, "motor = 1", "'motor' must be a string", args=R))
    add(in_text("drives", "dc_with_induction_key", M, dc, dc + "\nbreakdown_slip = 0.2", "'breakdown_slip' is not a key of motor = \"dc\"", "breakdown_slip", args=R))
    add(in_text("drives", "stall_negative", M, 'stall_torque = "4 N*m"', 'stall_torque = "-4 N*m"', "'stall_torque' must be positive", args=R))
    add(in_text("drives", "stall_wrong_unit", M, 'stall_torque = "4 N*m"', 'stall_torque = "4 N"', "'stall_torque' has unit 'N'", args=R))
    add(in_text("drives", "no_load_zero", M, 'no_load_speed = "105 Hz"', 'no_load_speed = "0 Hz"', "'no_load_speed' must be positive", args=R))
    add(in_text("drives", "inertia_wrong_unit", M, 'inertia = "5e-4 kg*m^2"', 'inertia = "5e-4 kg"', "'inertia' has unit 'kg'", args=R))
    add(in_text("drives", "inertia_negative", M, 'inertia = "5e-4 kg*m^2"', 'inertia = "-5e-4 kg*m^2"', "'inertia' must not be negative", args=R))
    add(in_text("drives", "viscous_negative", M, 'viscous_torque = "2e-4 N*m*s/rad"', 'viscous_torque = "-2e-4 N*m*s/rad"', "'viscous_torque' must not be negative", args=R))
    add(in_text("drives", "quadratic_with_unit", M, dc, dc + '\nquadratic_torque = "1 N*m"', "'quadratic_torque' must be a number without unit", "quadratic_torque", args=R))
    add(in_text("drives", "friction_negative", M, dc, dc + '\nfriction_torque = "-1 N*m"', "'friction_torque' must not be negative", "friction_torque", args=R))
    add(in_text("drives", "unknown_key", M, dc, dc + '\nstal_torque = "4 N*m"', "unknown key 'stal_torque'.*did you mean 'stall_torque'", "stal_torque", args=R))
    add(Case("drives", "friction_holds_the_rotor", R + ["model.toml", "--duration", "0.01s"], 1,
             r"the drive cannot start the rotor from rest: its motor gives 4 N m at 0 Hz, not more than the friction "
             r"torque 5 N m", model=M.replace(dc, dc + '\nfriction_torque = "5 N*m"')))
    add(Case("drives", "motor_turns_backwards", R + ["model.toml", "--duration", "0.01s"], 1,
             r"the drive's motor gives -2 N m at rest: it would turn the rotor backwards",
             model=M.replace(dc, 'motor = "table"\ntorque = { law = "table", speeds = [0, "100 Hz"], values = ["-2 N*m", "3 N*m"] }')
             .replace(stall, "").replace('no_load_speed = "105 Hz"\n', "")))
    add(in_text("drives", "table_name_misspelt", M, "[drive]", "[drivee]", "unknown key 'drivee' at the top level; did you mean 'drive'", args=R))
    induction = 'motor = "induction"\nsynchronous_speed = "50 Hz"\nbreakdown_torque = "5 N*m"\nbreakdown_slip = {}'
    no_dc = M.replace(stall, "").replace('no_load_speed = "105 Hz"\n', "")
    add(in_text("drives", "breakdown_slip_one", no_dc, dc, induction.format(1), "'breakdown_slip' must be below 1", "breakdown_slip", args=R))
    add(in_text("drives", "breakdown_slip_zero", no_dc, dc, induction.format(0), "'breakdown_slip' must be positive", "breakdown_slip", args=R))
    add(Case("drives", "dc_missing_stall", ["runup", "model.toml"], 1,
             r"model\.toml:\d+:\d+: missing key 'stall_torque' in \[drive\]", model=M.replace(stall, "")))
    add(in_text("drives", "table_motor_not_a_table", no_dc, dc, 'motor = "table"\ntorque = "5 N*m"', "must be a table law of at least two points", "torque =", args=R))

    # ------------------------------------------------------------------ prefixes and echoes
    add(Case("units", "force_prefix_on_unknown_unit", ["response", "model.toml", "--force", "disk 1:y:1MX"], 1,
             r"--force.*has unit 'MX', expected a force in N or kN \(any SI prefix on N too", model=J))
    add(Case("units", "double_prefix", ["response", "model.toml", "--force", "disk 1:y:1kkN"], 1,
             r"has unit 'kkN'", model=J))
    add(Case("units", "speed_limit_in_the_users_unit", ["modal", "model.toml", "--speed", "1e9Hz"], 1,
             r"beyond the physical range of a speed \(at most 159155 Hz in magnitude\)", model=J))
    add(in_text("units", "limit_in_the_users_unit", J, 'length = "30 mm"', 'length = "1e9 km"',
                r"beyond the physical range of a length \(at most 10 km in magnitude\)"))

    # ------------------------------------------------------------------ special files
    def fifo(d):
        os.mkfifo(os.path.join(d, "fifo.toml"))

    def sparse(d):
        with open(os.path.join(d, "big.toml"), "wb") as f:
            f.write(b'title = "x"\n')
            f.truncate((64 << 20) + 1)

    def directory(d):
        os.mkdir(os.path.join(d, "dir.toml"))

    def loop(d):
        os.symlink("loop.toml", os.path.join(d, "loop.toml"))

    add(Case("special", "fifo_without_writer", ["modal", "fifo.toml"], 1, r"'fifo\.toml' is not a regular file \(a FIFO\)",
             setup=fifo))
    add(Case("special", "dev_zero", ["modal", "/dev/zero"], 1, r"is not a regular file \(a character device\)"))
    add(Case("special", "dev_urandom", ["modal", "/dev/urandom"], 1, r"is not a regular file \(a character device\)"))
    add(Case("special", "dev_null", ["modal", "/dev/null"], 1, r"is not a regular file \(a character device\)"))
    add(Case("special", "directory", ["modal", "dir.toml"], 1, r"'dir\.toml' is a directory, not a model file",
             setup=directory))
    add(Case("special", "larger_than_64_mib", ["modal", "big.toml"], 1, r"limited to 67108864 bytes", setup=sparse))
    add(Case("special", "missing", ["modal", "missing.toml"], 1, r"cannot open model file 'missing\.toml'"))
    add(Case("special", "symlink_loop", ["modal", "loop.toml"], 1, r"loop\.toml", setup=loop))

    # ------------------------------------------------------------------ options
    R = ["runup", "model.toml"]
    S = ["response", "model.toml"]
    C = ["campbell", "model.toml"]
    T = ["static", "model.toml"]
    opts = [
        ("speed_without_unit", E + ["--speed", "30"], 1, r"--speed '30': give a speed with its unit"),
        ("speed_bad_unit", E + ["--speed", "30kg"], 1, r"the unit must be Hz, rpm or rad/s"),
        ("speed_negative", E + ["--speed", "-3Hz"], 1, r"--speed: must not be negative, got -3 Hz"),
        ("speed_beyond_range", E + ["--speed", "1e308Hz"], 1, r"beyond the physical range of a speed"),
        ("speed_empty", E + ["--speed", ""], 105, r"--speed: needs a value"),
        ("modes_zero", E + ["--modes", "0"], 1, r"--modes: must be at least 1, got 0"),
        ("modes_text", E + ["--modes", "many"], 1, r"--modes: expected an integer, got 'many'"),
        ("solver_unknown", E + ["--solver", "magic"], 1, r"--solver must be auto, dense or sparse, got 'magic'"),
        ("points_zero", C + ["--points", "0"], 1, r"--points: must be at least 2, got 0"),
        ("threads_too_many", C + ["--threads", "100000"], 105, r"--threads: at most 1024 threads, got 100000"),
        ("threads_negative", S + ["--threads", "-2"], 105, r"--threads: must be non-negative"),
        ("points_huge", C + ["--points", "2000000"], 1, r"--points: must be at most 1000000"),
        ("campbell_stop_below_start", C + ["--start", "50Hz", "--stop", "10Hz"], 1, r"must be above the first"),
        ("campbell_orders_zero", C + ["--orders", "0"], 1, r"--orders: must be at least 1, got 0"),
        ("response_points_huge", S + ["--points", "2000000"], 1, r"--points: must be at most 1000000"),
        ("loss_factor_nan", S + ["--loss-factor", "nan"], 1, r"--loss-factor: must be a finite number, got 'nan'"),
        ("loss_factor_negative", S + ["--loss-factor", "-1"], 1, r"--loss-factor: must not be negative, got -1"),
        ("probe_unknown", S + ["--probe", "rotr"], 1, r"--probe 'rotr'"),
        ("probe_twice", S + ["--probe", "rotor", "--probe", "7"], 1, r"--probe: node 7 \(rotor\) is given twice"),
        ("force_malformed", S + ["--force", "rotor:q:1N"], 1, r"--force"),
        ("freq_start_alone", S + ["--freq-start", "1Hz"], 1, r"needs both --freq-start and --freq-stop"),
        ("gravity_unknown", T + ["--gravity", "sideways"], 1,
         r"--gravity must be \+x, -x, \+y, -y, \+z, -z or none, got 'sideways'"),
        ("gravity_none_with_g", T + ["--gravity", "none", "--g", "5m/s^2"], 1, r"--g cannot be given with --gravity none"),
        ("g_negative", T + ["--g", "-1m/s^2"], 1, r"--g"),
        ("g_beyond_range", T + ["--g", "1e308m/s^2"], 1, r"beyond the physical range of an acceleration"),
        ("static_speed_negative", T + ["--speed", "-1Hz"], 1, r"--speed: must not be negative"),
        ("runup_from_negative", R + ["--from", "-3Hz", "--to", "5Hz", "--ramp-time", "1s"], 1, r"--from: must not be negative"),
        ("runup_ramp_incomplete", R + ["--to", "5Hz"], 1, r"a ramp needs --to and --ramp-time"),
        ("runup_two_profiles", R + ["--speed", "5Hz", "--table", "0s:0Hz,1s:5Hz"], 1, r"give one speed profile"),
        ("runup_table_malformed", R + ["--table", "0s-0Hz"], 1, r"--table"),
        ("runup_table_not_at_zero", R + ["--table", "1s:0Hz,2s:5Hz"], 1, r"--table must start at time 0"),
        ("runup_table_negative", R + ["--table", "0s:0Hz,2s:-5Hz"], 1, r"--table point 2: must not be negative"),
        ("runup_table_not_increasing", R + ["--table", "0s:0Hz,0s:5Hz"], 1, r"strictly increasing"),
        ("runup_dt_zero", R + ["--dt", "0s"], 1, r"--dt"),
        ("runup_dt_tiny", R + ["--dt", "1e-300s"], 1, r"--dt: 1e-300 s is below the physical range"),
        ("runup_duration_huge", R + ["--speed", "1Hz", "--duration", "1e300s"], 1, r"--duration: 1e\+300 s is beyond"),
        ("runup_too_many_samples", R + ["--output-interval", "1e-9s"], 1, r"samples; at most 1e\+07"),
        ("runup_too_many_steps", R + ["--dt", "1e-9s", "--duration", "10s"], 1, r"steps; at most 1e\+09"),
        ("runup_integrator_unknown", R + ["--integrator", "euler"], 1,
         r"--integrator must be trapezoidal, rk3, wolfbrandt or ros34pw2, got 'euler'"),
        ("runup_rk3_unstable", R + ["--speed", "10Hz", "--duration", "0.1s", "--integrator", "rk3", "--dt", "1e-2s"],
         1, r"stability limit"),
        ("runup_spring_unknown", R + ["--spring", "nope"], 1, r"--spring 'nope': no spring-damper has that name"),
        ("runup_spring_twice", R + ["--speed", "1Hz", "--duration", "0.01s", "--spring", "external damping",
                                    "--spring", "external damping"], 1, r"--spring: spring 'external damping' is given twice"),
        ("set_unknown_path", E + ["--set", "springs[0].kyy=1 N/m"], 1, r"did you mean 'ky'"),
        ("set_bad_value", E + ["--set", "rigid_bodies[rotor].mass=-2 kg"], 1, r"'mass' must not be negative"),
        ("set_without_value", E + ["--set", "materials[steel].E"], 1, r"expected PATH=VALUE"),
        ("set_beyond_range", E + ["--set", "materials[steel].E=1e308 GPa"], 1, r"'E' must be a finite number"),
        ("unknown_option", E + ["--sped", "3Hz"], 109, r"--sped"),
        ("unknown_command", ["modl", "model.toml"], 109, r"unknown command 'modl'; did you mean 'modal'\?"),
        ("no_command", [], 106, r"A subcommand is required"),
        ("no_model", ["modal"], 106, r"model is required"),
        ("probe_swallows_nothing", ["response", "--probe", "rotor"], 106, r"model is required"),
    ]
    for name, args, code, message in opts:
        add(Case("options", name, args, code, message, model=base_model()))

    # ------------------------------------------------------------------ outputs
    outputs = [
        ("json_is_model", E + ["--json", "model.toml"], 1, r"--json 'model\.toml': cannot write: it is the model file"),
        ("json_and_csv_same", E + ["--json", "x.json", "--csv", "x.json"], 1, r"--json already writes 'x\.json'"),
        ("csv_missing_directory", E + ["--csv", "nodir/x.csv"], 1, r"the directory 'nodir' does not exist"),
        ("json_directory", E + ["--json", "."], 1, r"--json '\.': cannot write: it is a directory"),
        ("json_empty", E + ["--json", ""], 105, r"--json: needs a value"),
        ("csv_full_device", E + ["--csv", "/dev/full"], 1, r"cannot write: No space left on device"),
        ("runup_csv_missing_directory", R + ["--speed", "1Hz", "--duration", "0.01s", "--csv", "nodir/r.csv"], 1,
         r"the directory 'nodir' does not exist"),
        ("params_json_is_model", ["params", "model.toml", "--json", "model.toml"], 1, r"it is the model file"),
    ]
    for name, args, code, message in outputs:
        add(Case("outputs", name, args, code, message, model=base_model()))

    # ------------------------------------------------------------------ inputs
    # No output may replace any file a command reads: the model, REPORT.toml, a study
    # file, a study's model, the files of a study shown in a report.
    study_model = journal_model()
    study_text = ('title = "t"\nmodel = "MODEL"\n[[variables]]\nname = "c"\npaths = ["journal_bearings[bearing A].viscosity"]\n'
                  'lower = "0.01 Pa*s"\nupper = "0.02 Pa*s"\n[[quantities]]\nname = "f1"\nkind = "natural_frequency"\nn = 1\n'
                  'speed = "100 Hz"\n[[objectives]]\nquantity = "f1"\nsense = "maximise"\n[explore]\nmethod = "grid"\nlevels = 2\n')
    config = '[campbell]\nstop = "50 Hz"\npoints = 5\n'
    shown_study = {"st/study.json": "{}", "st/evaluations.jsonl": "", "st/summary.json": "{}"}

    def study_case(name, study_name, model_name, args, message, setup=None):
        files = {study_name: study_text.replace("MODEL", model_name), model_name: study_model}
        add(Case("inputs", name, ["study", study_name, "-q", *args], 1, message, files=files, setup=setup))

    def link(name, target):
        return lambda d: os.symlink(target, os.path.join(d, name))

    def hard_link(name, target):
        return lambda d: os.link(os.path.join(d, target), os.path.join(d, name))

    def mkdir(name):
        return lambda d: os.makedirs(os.path.join(d, name), exist_ok=True)

    def both(*fs):
        return lambda d: [f(d) for f in fs]

    two = study_text.replace("MODEL", "m.toml").replace("[[quantities]]", '[[variables]]\nname = "d"\npaths = '
                                                        '["journal_bearings[0].viscosity"]\nlower = "0.01 Pa*s"\n'
                                                        'upper = "0.02 Pa*s"\n[[quantities]]')
    add(Case("studies", "study_two_variables_on_one_path", ["study", "s.toml", "-q"], 1,
             r"s\.toml:10:\d+: 'journal_bearings\[0\]\.viscosity' is already set by the variable 'c'",
             files={"s.toml": two, "m.toml": study_model}))
    add(Case("studies", "study_path_tied_to_itself", ["study", "s.toml", "-q"], 1,
             r"s\.toml:5:\d+: 'journal_bearings\[bearing A\]\.viscosity' is given twice in this variable's paths",
             files={"s.toml": study_text.replace("MODEL", "m.toml").replace(
                 'paths = ["journal_bearings[bearing A].viscosity"]',
                 'paths = ["journal_bearings[bearing A].viscosity", "journal_bearings[bearing A].viscosity"]'),
                 "m.toml": study_model}))
    study_case("study_model_named_best", "s.toml", "best.toml", ["-o", "."],
               r"cannot write the study's results in '\.': they would replace its input 'best\.toml'")
    study_case("study_file_named_study_json", "study.json", "m.toml", ["-o", "."],
               r"they would replace its input 'study\.json'")
    study_case("study_model_named_summary", "s.toml", "summary.json", ["-o", "."],
               r"they would replace its input 'summary\.json'")
    study_case("study_model_named_evaluations_csv", "s.toml", "evaluations.csv", ["-o", "."],
               r"they would replace its input 'evaluations\.csv'")
    study_case("study_model_named_pareto", "s.toml", "pareto-12.toml", ["-o", "."],
               r"they would replace its input 'pareto-12\.toml'")
    study_case("study_best_linked_to_model", "s.toml", "m.toml", ["-o", "out"],
               r"its 'best\.toml' is the input 'm\.toml'", setup=both(mkdir("out"), link("out/best.toml", "../m.toml")))
    study_case("study_summary_hard_linked_to_study", "s.toml", "m.toml", ["-o", "out"],
               r"its 'summary\.json' is the input 's\.toml'", setup=both(mkdir("out"), hard_link("out/summary.json", "s.toml")))
    add(Case("inputs", "study_in_its_own_results", ["study", "s.results/study.json", "-o", "s.results", "-q"], 1,
             r"they would replace its input 's\.results/study\.json'",
             files={"s.results/study.json": study_text.replace("MODEL", "m.toml"), "s.results/m.toml": study_model}))
    add(Case("inputs", "report_output_is_config", ["report", "model.toml", "--config", "r.toml", "-o", "r.toml"], 1,
             r"--output 'r\.toml': cannot write: it is the report configuration 'r\.toml'", model=J, files={"r.toml": config}))
    add(Case("inputs", "report_output_links_to_config", ["report", "model.toml", "--config", "r.toml", "-o", "o.html"], 1,
             r"--output 'o\.html': cannot write: it is the report configuration 'r\.toml'", model=J,
             files={"r.toml": config}, setup=link("o.html", "r.toml")))
    add(Case("inputs", "report_output_is_a_study_file", ["report", "model.toml", "--study", "st", "-o", "st/summary.json"], 1,
             r"cannot write: it is a file of the study shown 'st/summary\.json'", model=J, files=shown_study,
             setup=mkdir("st")))
    add(Case("inputs", "report_output_is_the_config_study",
             ["report", "model.toml", "--config", "r.toml", "-o", "st/evaluations.jsonl"], 1,
             r"it is a file of the study shown 'st/evaluations\.jsonl'", model=J,
             files={"r.toml": config + '[study]\ndirectory = "st"\n', **shown_study}, setup=mkdir("st")))
    add(Case("inputs", "report_output_links_to_model", ["report", "model.toml", "-o", "o.html"], 1,
             r"cannot write: it is the model file 'model\.toml'", model=J, setup=link("o.html", "model.toml")))
    add(Case("inputs", "api684_json_hard_linked_to_model", ["api684", "model.toml", "--json", "a.json"], 1,
             r"--json 'a\.json': cannot write: it is the model file", model=J, setup=hard_link("a.json", "model.toml")))
    add(Case("inputs", "runup_csv_links_to_model",
             ["runup", "model.toml", "--speed", "1Hz", "--duration", "0.01s", "--csv", "r.csv"], 1,
             r"--csv 'r\.csv': cannot write: it is the model file", model=J, setup=link("r.csv", "model.toml")))
    add(Case("inputs", "static_json_is_model_by_another_name", ["static", "./model.toml", "--json", "model.toml"], 1,
             r"--json 'model\.toml': cannot write: it is the model file", model=J))

    # ------------------------------------------------------------------ encodings of the other files
    def utf16(text):
        return "\ufeff".encode("utf-16-le") + text.encode("utf-16-le")

    add(Case("encodings", "report_config_utf16", ["report", "model.toml", "--config", "r.toml", "-o", "o.html"], 1,
             r"r\.toml:1:1: the file is in UTF-16 \(little-endian, by its byte-order mark\)", model=J,
             files={"r.toml": utf16(config)}))
    add(Case("encodings", "study_utf16", ["study", "s.toml", "-q"], 1,
             r"s\.toml:1:1: the file is in UTF-16 \(little-endian, by its byte-order mark\)",
             files={"s.toml": utf16(study_text.replace("MODEL", "m.toml")), "m.toml": study_model}))
    add(Case("encodings", "study_model_utf16_be", ["study", "s.toml", "-q"], 1,
             r"m\.toml:1:1: the file is in UTF-16 \(big-endian, by the zero bytes of its first characters\)",
             files={"s.toml": study_text.replace("MODEL", "m.toml"), "m.toml": study_model.encode("utf-16-be")}))
    add(Case("encodings", "report_config_with_bom_read",
             ["report", "model.toml", "--config", "r.toml", "-o", "o.html", "-q"], 0, r"^$", model=J,
             files={"r.toml": b"\xef\xbb\xbf" + config.encode()}))

    # ------------------------------------------------------------------ REPORT.toml
    # A mistake in REPORT.toml is a located error, exit 1, nothing written.
    report_configs = [
        ("unknown_table", '[campbel]\nstop = "50 Hz"\n', 1, r"unknown key 'campbel' at the top level; did you mean 'campbell'"),
        ("unknown_key", '[campbell]\nstpo = "50 Hz"\n', 2, r"unknown key 'stpo'.*did you mean 'stop'"),
        ("speed_without_unit_word", '[campbell]\nstop = "fast"\n', 2, r"'stop' must be a speed"),
        ("points_text", '[campbell]\npoints = "many"\n', 2, r"'points'"),
        ("points_zero", '[campbell]\npoints = 0\n', 2, r"'points'"),
        ("syntax", '[campbell\n', 1, r"TOML syntax error"),
        ("speed_unit_unknown", 'speed_unit = "krpm"\n', 1, r"speed_unit"),
        ("modes_speeds_not_a_list", '[modes]\nspeeds = "0 rpm"\n', 2, r"'speeds'"),
        ("modes_count_negative", '[modes]\ncount = -1\n', 2, r"'count'"),
        ("probe_unknown", '[response]\nprobes = ["rotr"]\n', 2, r"'probes\[0\]': the model has no such node"),
        ("static_enabled_text", '[static]\nenabled = "yes"\n', 2, r"'enabled'"),
        ("api684_unknown_key", '[api684]\nmin_sped = "9000 rpm"\n', 2, r"unknown key 'min_sped'"),
        # Every key of the model file's tables, checked by their field tables.
        ("campbell_solver_unknown", '[campbell]\nsolver = "qr"\n', 2,
         r"\[campbell\] 'solver' must be auto, dense or sparse, got 'qr'"),
        ("api684_speed_negative", '[api684]\nmin_speed = "-3 Hz"\n', 2, r"\[api684\] 'min_speed': must be positive"),
        ("study_not_a_table", 'study = "dir"\n', 1, r"'study' must be a table"),
        ("title_number", 'title = 3\n', 1, r"'title'"),
    ]
    for name, text, line, message in report_configs:
        add(Case("report", name, ["report", "model.toml", "--config", "r.toml", "-o", "o.html"], 1,
                 rf"r\.toml:{line}:\d+: .*{message}", model=J, files={"r.toml": text}))

    # ------------------------------------------------------------------ signals
    # A run stopped by SIGINT, SIGTERM or SIGHUP: exit 128 + N, its results so far
    # written whole and marked incomplete, no temporary file left behind.
    long_runs = [
        ("api684", ["api684", "model.toml", "--points", "20000", "--json", "out.json"], {"out.json"}),
        ("report", ["report", "model.toml", "-o", "o.html"], {"o.html"}),
        ("campbell", ["campbell", "model.toml", "--stop", "200Hz", "--points", "200000"], {"out.json", "out.csv"}),
        ("response", ["response", "model.toml", "--stop", "200Hz", "--points", "900000"], {"out.json", "out.csv"}),
        ("runup", ["runup", "model.toml", "--speed", "100Hz", "--duration", "1000s"], {"out.json", "out.csv"}),
    ]
    for command, args, written in long_runs:
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            add(Case("signals", f"{command}_{signal.Signals(sig).name}", args, 128 + sig,
                     rf"feran: interrupted by {signal.Signals(sig).name}: .*(written|marked incomplete)",
                     model=J, signal=sig, written=written))

    # ------------------------------------------------------------------ Python
    # Every wrong argument raises feran.Error, ModelError, ParameterError or TypeError
    # naming the argument; an invalid model[path] = value fails at that assignment.
    L = 'model["shafts[0].sections[0].length"]'
    python = [
        ("modes_text", 'feran.modal(model, modes="x")', r"TypeError: modal\(\): 'modes' must be an integer or None, got str 'x'"),
        ("modes_float", "feran.modal(model, modes=2.5)", r"TypeError: modal\(\): 'modes' must be an integer or None, got float 2\.5"),
        ("misspelt_keyword", "feran.modal(model, sped=3)", r"TypeError: modal\(\): has no argument 'sped'; did you mean 'speed'\?"),
        ("path_for_model", 'feran.modal("model.toml")', r"TypeError: modal\(\): 'model' must be a feran\.Model \(feran\.read_model"),
        ("no_model", "feran.campbell()", r"TypeError: campbell\(\): needs the argument 'model'"),
        ("positional_option", "feran.modal(model, 3)", r"TypeError: modal\(\): takes 1 positional argument \(model\)"),
        ("points_beyond_int", "feran.campbell(model, points=10**12)", r"Error: campbell: points: must be at most 1000000, got 1000000000000"),
        ("orders_text", 'feran.campbell(model, orders="1")', r"TypeError: campbell\(\): 'orders' must be a list of integers or None, got str"),
        ("threads_negative", "feran.campbell(model, threads=-3)", r"Error: threads: 0 \(all cores\) or a count from 1 to 1024, got -3"),
        ("threads_too_many", "feran.response(model, threads=5000)", r"Error: threads: 0 \(all cores\) or a count from 1 to 1024, got 5000"),
        ("threads_text", 'feran.campbell(model, threads="2")', r"TypeError: campbell\(\): 'threads' must be an integer, got str '2'"),
        ("probes_misspelt", "feran.response(model, probes=[1])", r"TypeError: response\(\): has no argument 'probes'; did you mean 'probe'\?"),
        ("probe_float", "feran.response(model, probe=3.5)",
         r"TypeError: response\(\): 'probe' must be a name or number, or a list of them or None, got float 3\.5"),
        ("loss_factor_text", 'feran.response(model, loss_factor="x")', r"TypeError: response\(\): 'loss_factor' must be a number or None"),
        ("speed_bool", "feran.modal(model, speed=True)",
         r"TypeError: modal\(\): 'speed' must be text with its unit or a number in SI units or None, got bool True"),
        ("runup_speed_dict", 'feran.runup(model, speed={"a": 1})',
         r"TypeError: runup\(\): 'speed' must be text with its unit or a number in SI units or None, got dict"),
        ("gravity_word", 'feran.static(model, gravity="up")', r"Error: static: gravity must be"),
        ("report_speed_unit", 'feran.report(model, speed_unit="krpm")', r"Error: the report's speed unit must be"),
        ("report_into_directory", 'feran.report(model, ".")', r"Error: path '\.': cannot write: it is a directory"),
        ("report_over_model", 'feran.report(model, "model.toml")', r"Error: path 'model\.toml': cannot write: it is the model file"),
        ("api684_speed_word", 'feran.api684(model, min_speed="a")',
         r"Error: api684: min_speed 'a': give a speed with its unit"),
        ("read_model_number", "feran.read_model(5)", r"TypeError: read_model\(\): 'path_or_text' must be a string, got int 5"),
        ("model_title_number", "feran.Model(5)", r"TypeError: Model\.__init__\(\): 'title' must be a string, got int 5"),
        ("text_model_syntax", 'feran.read_model("title = ")', r"ModelError: <string>:1:9: TOML syntax error"),
        ("set_negative_length", L + ' = "-3 mm"', r"ParameterError: model\['shafts\[0\]\.sections\[0\]\.length'\] = '-3 mm': 'length' must be positive, got -3 mm"),
        ("set_nan", L + ' = float("nan")', r"ParameterError: model\['shafts\[0\]\.sections\[0\]\.length'\] = nan: 'length' must be a finite number"),
        ("set_beyond_range", L + ' = "1e9 km"', r"ParameterError: .*'length' is .*beyond the physical range of a length"),
        ("set_wrong_unit", L + ' = "3 kg"', r"ParameterError: parameter 'shafts\[0\]\.sections\[0\]\.length': \"3 kg\" has unit 'kg'"),
        ("set_list", L + " = [1]", r"TypeError: model\[path\] = value: the value must be text with its unit"),
        ("set_unknown_table", 'model["nope.x"] = 1', r"ParameterError: parameter path 'nope\.x': there is no table 'nope'"),
        ("set_path_number", "model[3] = 1", r"TypeError: model\[path\] = value: the path must be a string, got int 3"),
        ("set_then_unchanged", 'before = ' + L + '\ntry:\n    ' + L + ' = "-3 mm"\nexcept feran.Error:\n    assert ' + L +
         ' == before, ' + L + '\n    raise',
         r"ParameterError: model\['shafts\[0\]\.sections\[0\]\.length'\] = '-3 mm'"),
        ("dict_holding_itself", 'd = {"law": "table"}\nd["values"] = d\nmodel.add_spring(name="s", node="disk 1", ky=d)',
         r"Error: add_spring\(name='s'\): ky\.values.*nested more than 16 levels deep"),
        ("lone_surrogate", 'model.add_node(name="a\\ud800b", x=0.1)', r"Error: add_node\(name=.*is not valid text \(surrogates not allowed"),
        ("integer_beyond_64_bits", 'model.add_node(name="n", x=10**30)', r"Error: add_node\(name='n'\): x: 10{30} is beyond a 64-bit integer"),
        ("inner_key_not_text", 'model.add_spring(name="s", node="disk 1", ky={"law": "table", 1: 2})',
         r"TypeError: add_spring\(name='s'\): ky: keys are text, got int 1"),
        ("from_dict_list_expected", 'feran.Model.from_dict({"materials": {"name": "x"}})', r"Error: from_dict: 'materials' is a list of entries"),
    ]
    for name, statement, message in python:
        add(Case("python", name, [], 1, "^" + message, model=J, python=statement,
                 files={"r.toml": config}))
    return out


# The Python door: the statement's exception, printed as "TYPE: message", exit 1.
PYTHON_CASE = '''
import sys
import feran
model = feran.read_model("model.toml")
try:
    exec(sys.argv[1])
except BaseException as e:
    print(f"{type(e).__name__}: {e}", file=sys.stderr)
    sys.exit(1)
'''


def run_case(case):
    """The outcome of @p case and a line saying what happened."""
    with tempfile.TemporaryDirectory(prefix="feran_hostile_") as d:
        if case.model is not None:
            data = case.model.encode() if isinstance(case.model, str) else case.model
            with open(os.path.join(d, "model.toml"), "wb") as f:
                f.write(data)
        for name, content in case.files.items():
            os.makedirs(os.path.dirname(os.path.join(d, name)), exist_ok=True)
            with open(os.path.join(d, name), "wb") as f:
                f.write(content.encode() if isinstance(content, str) else content)
        if case.setup:
            case.setup(d)
        before = snapshot(d)
        args = list(case.args)
        # Ask for outputs where the case has not chosen its own (not for params, or
        # the option parser's own errors, which stop before any command runs).
        if args and args[0] in ("modal", "campbell", "response", "static", "runup", "api684"):
            if "--json" not in args:
                args += ["--json", "out.json"]
            if "--csv" not in args and args[0] not in ("params", "api684"):
                args += ["--csv", "out.csv"]
        command = [FERAN, *args]
        if case.python is not None:
            env = dict(os.environ, PYTHONPATH=PYTHONPATH + os.pathsep + os.environ.get("PYTHONPATH", ""))
            command = [sys.executable, "-c", PYTHON_CASE, case.python]
        else:
            env = None
        try:
            if case.signal is None:
                r = subprocess.run(command, cwd=d, capture_output=True, timeout=TIME_LIMIT, env=env)
            else:
                p = subprocess.Popen(command, cwd=d, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
                # The outputs' temporary files exist once the signal handlers are
                # installed; then well into the run.
                deadline = time.time() + 60
                while (p.poll() is None and time.time() < deadline
                       and not any(".part-" in name for name in os.listdir(d))):
                    time.sleep(0.01)
                time.sleep(0.5)
                p.send_signal(case.signal)
                out, err = p.communicate(timeout=TIME_LIMIT)
                r = subprocess.CompletedProcess(command, p.returncode, out, err)
        except subprocess.TimeoutExpired:
            return "hang", f"no end after {TIME_LIMIT} s"
        stderr = r.stderr.decode("utf-8", "replace")
        after = snapshot(d)
        if case.written:  # outputs a stopped run keeps: written whole, no temporary file left
            leftovers = [name for name in after if ".part-" in name]
            if leftovers:
                return "damaged", f"temporary files left: {leftovers}"
            for name in case.written:
                after.pop(name, None)
        if (r.returncode < 0 or r.returncode == 4 or "Sanitizer" in stderr or "runtime error" in stderr
                or "Traceback" in stderr or "RecursionError" in stderr):
            return "crash", f"exit {r.returncode}: {stderr[-400:]}"
        # Devices a case writes to must stay devices (a program that renames a temporary
        # file over its output replaces /dev/full with a regular file, as root).
        for device in ("/dev/full", "/dev/null"):
            if not stat.S_ISCHR(os.stat(device).st_mode):
                return "damaged", f"{device} is no longer a device"
        touched = sorted(name for name in before if after.get(name) != before[name])
        if touched:
            return "damaged", f"files changed or removed: {touched}"
        if case.code == 0:
            # A value in range but absurd in its context, warned about: exit 0 with the
            # warning, the model file untouched (outputs may be written).
            if r.returncode == 0 and re.search(case.message, stderr):
                return "located", ""
            return "other", f"exit {r.returncode} (expected a warning, exit 0): {stderr.strip()[:400]!r}"
        if r.returncode == 0:
            return "accepted", f"exit 0{', wrote ' + str(sorted(set(after) - set(before))) if after != before else ''}"
        if after != before:
            return "damaged", f"exit {r.returncode}, but wrote {sorted(set(after) - set(before))}"
        if r.returncode != case.code or not re.search(case.message, stderr):
            return "other", f"exit {r.returncode} (expected {case.code}): {stderr.strip()[:400]!r}"
        return "located", ""


def snapshot(d):
    """Name, size and content hash of every file of @p d (links not followed)."""
    out = {}
    for root, dirs, files in os.walk(d):
        for name in files + dirs:
            p = os.path.join(root, name)
            st = os.lstat(p)
            if stat.S_ISREG(st.st_mode) and st.st_size < (1 << 20):
                with open(p, "rb") as f:
                    out[os.path.relpath(p, d)] = hash(f.read())
            else:
                out[os.path.relpath(p, d)] = (st.st_mode, st.st_size)
    return out


def main():
    global FERAN, SOURCE, PYTHONPATH
    FERAN, SOURCE = sys.argv[1], sys.argv[2]
    # The Python package beside the program (build/python).
    PYTHONPATH = os.path.join(os.path.dirname(os.path.abspath(FERAN)), "python")
    selector = sys.argv[3] if len(sys.argv) > 3 else None
    all_cases = cases()
    if selector == "--summary":
        counts = {}
        for c in all_cases:
            outcome, why = run_case(c)
            counts[outcome] = counts.get(outcome, 0) + 1
            if outcome != "located":
                print(f"{c.group}/{c.name}: {outcome}: {why}")
        print(f"{len(all_cases)} cases: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())))
        return 0
    chosen = [c for c in all_cases if selector is None or c.group == selector]
    failures = 0
    for c in chosen:
        outcome, why = run_case(c)
        if outcome != "located":
            failures += 1
            print(f"FAIL {c.group}/{c.name}: {outcome}: {why}")
    print(f"{len(chosen) - failures} of {len(chosen)} cases refused as stated")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
