"""Models built in code: the same model as the file says, checked by the same rules;
no memory growth over many analyses; Ctrl-C stops an analysis with its results."""
import os
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import feran

SOURCE = os.environ.get("FERAN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE = os.path.join(SOURCE, "examples", "01_internal_damping", "model.toml")


def internal_damping_rotor():
    """examples/01_internal_damping/model.toml, key for key, in code."""
    m = feran.Model("Internal-damping rotor (Fischer & Strackeljan 2006, sec. 3.2)")
    m.add_material(name="steel", E="210 GPa", nu=0.3, rho=7850.0)
    m.add_shaft(material="steel", start_node="drive",
                sections=[dict(length=0.06, outer_diameter="6 mm", elements=6, end_node="rotor")])
    m.add_fixed(node="drive")
    m.add_rigid_body(name="rotor", node="rotor", mass="9.1 kg", Ja="0.0219 kg*m^2", Jp="0.035 kg*m^2")
    m.add_spring(name="external damping", node="rotor", cy="250 N*s/m", cz="250 N*s/m",
                 cry="0.23 N*m*s/rad", crz="0.23 N*m*s/rad")
    m.add_rotating_damper(name="internal damping", node="rotor", ct="638 N*s/m", cr="0.57 N*m*s/rad")
    m.add_unbalance(node="rotor", mass="0.01 kg", radius="80 mm")
    m.set_table("campbell", start="0 Hz", stop="80 Hz", points=161, modes=6)
    m.set_table("response", start="0 Hz", stop="80 Hz", points=161, probes=["rotor"])
    m.set_table("runup", from_="0 Hz", to="80 Hz", ramp_time="5 s", integrator="trapezoidal", dt="0.1 ms",
                probes=["rotor"])
    return m


def test_a_model_built_in_code_equals_the_file():
    code, file = internal_damping_rotor(), feran.read_model(EXAMPLE)
    assert code == file
    np.testing.assert_array_equal(feran.modal(code).frequency_hz, feran.modal(file).frequency_hz)
    # and through a dict shaped like the file, and back from its own TOML
    assert feran.Model.from_dict(feran_dict()) == file
    assert feran.read_model(code.to_toml()) == file
    code["rigid_bodies[rotor].mass"] = "10 kg"
    assert code != file


def feran_dict():
    return {"title": "Internal-damping rotor (Fischer & Strackeljan 2006, sec. 3.2)",
            "materials": [{"name": "steel", "E": 210e9, "nu": 0.3, "rho": 7850}],
            "shafts": [{"material": "steel", "start_node": "drive",
                        "sections": [{"length": "60 mm", "outer_diameter": "6 mm", "elements": 6,
                                      "end_node": "rotor"}]}],
            "fixed": [{"node": "drive"}],
            "rigid_bodies": [{"name": "rotor", "node": "rotor", "mass": 9.1, "Ja": 0.0219, "Jp": 0.035}],
            "springs": [{"name": "external damping", "node": "rotor", "cy": 250, "cz": 250, "cry": 0.23,
                         "crz": 0.23}],
            "rotating_dampers": [{"name": "internal damping", "node": "rotor", "ct": 638, "cr": 0.57}],
            "unbalances": [{"node": "rotor", "mass": 0.01, "radius": 0.08}],
            "campbell": {"start": 0, "stop": "80 Hz", "points": 161, "modes": 6},
            "response": {"start": "0 Hz", "stop": "80 Hz", "points": 161, "probes": ["rotor"]},
            "runup": {"from": "0 Hz", "to": "80 Hz", "ramp_time": 5, "integrator": "trapezoidal", "dt": 1e-4,
                      "probes": ["rotor"]}}


def test_every_table_of_the_file_is_a_method():
    # Each array of tables of the model file (every [[key]] block of docs/model-format.md
    # but the shafts' sections) is an add_<entry>, each single table a set_table name:
    # the package's methods come from the library's list, none kept by hand.
    doc = open(os.path.join(SOURCE, "docs", "model-format.md"), encoding="utf-8").read()
    documented = {line.split()[2] for line in doc.splitlines() if line.startswith("<!-- keys: ")}
    assert documented - {"shafts.sections"} == set(feran._ENTRIES.values()) | set(feran._TABLES)
    assert feran._ENTRIES["rigid_body"] == "rigid_bodies" and feran._ENTRIES["fixed"] == "fixed"
    for entry in feran._ENTRIES:
        assert callable(getattr(feran.Model, f"add_{entry}"))
    # [drive] was missing from the hand-kept list: a torque-driven rotor built in code.
    m = internal_damping_rotor()
    m.set_table("drive", motor="dc", stall_torque="2 N*m", no_load_speed="100 Hz")
    m.check()
    assert "[drive]" in m.to_toml()


def test_speed_dependent_coefficients_in_code():
    def rotor(ky):
        m = internal_damping_rotor()
        m.add_node(name="housing", x=0.06)
        m.add_rigid_body(name="housing mass", node="housing", mass=2.0, Ja=1e-3, Jp=1e-3)
        m.add_spring(name="mount", node="housing", ky=ky, kz=1e6, krx=1e3, kry=1e3, krz=1e3, kx=1e6)
        m.add_spring(name="link", node="rotor", to="housing", ky=1e5, kz=1e5)
        return m

    law = rotor({"law": "table", "speeds": ["0 Hz", "50 Hz"], "values": ["1e6 N/m", "2e6 N/m"]})
    # A tabulated coefficient is its table's value at each speed: at 0 and at 50 Hz the
    # model is the one with that constant stiffness.
    for speed, ky in (("0 Hz", 1e6), ("50 Hz", 2e6)):
        np.testing.assert_allclose(feran.modal(law, speed=speed).frequency_hz,
                                   feran.modal(rotor(ky), speed=speed).frequency_hz, rtol=1e-12)


def test_errors_of_code_name_the_call():
    with pytest.raises(feran.Error, match=r"add_material\(name='x'\): 'E' has unit 'GPo'"):
        feran.Model().add_material(name="x", E="210 GPo")
    with pytest.raises(feran.Error, match=r"add_rigid_body\(name='disk'\): 'mass' must not be negative"):
        internal_damping_rotor().add_rigid_body(name="disk", node="rotor", mass=-1).check()
    with pytest.raises(feran.Error, match=r"add_spring\(name='s'\): unknown key 'kk'.*did you mean"):
        feran.Model().add_spring(name="s", node=1, kk=1)
    with pytest.raises(TypeError, match="not a value of a model"):
        feran.Model().add_material(name="x", E=object())
    with pytest.raises(feran.Error, match="no table 'bearings'"):
        feran.Model.from_dict({"bearings": []})


def rss_kb():
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith("VmRSS"))


def test_no_memory_growth_over_1000_analyses():
    model = feran.read_model(EXAMPLE)
    for _ in range(50):  # warm up: allocator pools, numpy, the first builds
        feran.response(model, stop="60 Hz", points=5, threads=1).to_dict()
        feran.modal(model, shapes=True).shapes
    before = rss_kb()
    for i in range(1000):
        model["rigid_bodies[rotor].mass"] = 9.0 + i * 1e-3  # rebuilds the model each time
        feran.modal(model, shapes=True).shapes
        feran.response(model, stop="60 Hz", points=5, threads=1).displacement
    growth = rss_kb() - before
    # A leak of one model or result per loop would be tens of kB each: 1000 loops far
    # above 2 MB. 2 MB allows for the allocator's own growth.
    assert growth < 2048, f"resident memory grew by {growth} kB over 1000 analyses"


def test_ctrl_c_stops_a_sweep_and_keeps_its_results(tmp_path):
    script = tmp_path / "sweep.py"
    script.write_text(textwrap.dedent(f"""
        import sys, feran
        model = feran.read_model({EXAMPLE!r})
        print("ready", flush=True)
        try:
            feran.campbell(model, stop="80 Hz", points=200000, threads=1)
        except feran.Interrupted as e:
            r = e.result
            print("interrupted", len(r.speeds), r.complete, isinstance(e, KeyboardInterrupt), flush=True)
    """))
    p = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True, env=os.environ)
    assert p.stdout.readline().strip() == "ready"
    import time
    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    words = out.split()
    assert words[0] == "interrupted"
    assert 0 < int(words[1]) < 200000
    assert words[2] == "False" and words[3] == "True"
