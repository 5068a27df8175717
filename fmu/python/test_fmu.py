"""Importer tests of TractionContact.fmu (run by scripts/fmu_test.sh).

The FMU path comes from the environment variable TRACTION_FMU.
"""

import csv
import glob
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(__file__))

import drivetrain  # noqa: E402
from reference import PARAMS, hertz_circular, slip_for_traction, traction  # noqa: E402

FMU = os.environ.get("TRACTION_FMU", "")
VENV_BIN = os.path.dirname(sys.executable)


@pytest.fixture(scope="module")
def fmu_path():
    if not os.path.isfile(FMU):
        pytest.fail(f"TRACTION_FMU={FMU!r} is not a file: build it with `traction fmu build --out PATH.fmu`")
    return FMU


def test_fmpy_validate_reports_no_problem(fmu_path):
    from fmpy.validation import validate_fmu

    problems = validate_fmu(fmu_path)
    assert problems == [], problems
    # The command-line form as a user would run it.
    r = subprocess.run([os.path.join(VENV_BIN, "fmpy"), "validate", fmu_path], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_fmutool_check_reports_no_problem(fmu_path):
    r = subprocess.run(
        [os.path.join(VENV_BIN, "fmutool"), "-input", fmu_path, "-check"], capture_output=True, text=True
    )
    text = r.stdout + r.stderr
    print(text)
    assert r.returncode == 0, text
    # Log lines look like "LEVEL    | message": no ERROR or WARNING level allowed.
    levels = [line.split("|", 1)[0].strip() for line in text.splitlines() if "|" in line]
    assert not {"ERROR", "WARNING", "CRITICAL"} & set(levels), text
    assert "compliant with FMI-2.0" in text, text
    assert "No semantic error against the FMI-2 standard" in text, text


def test_model_description_as_fmpy_reads_it(fmu_path):
    from fmpy import read_model_description

    md = read_model_description(fmu_path)
    assert md.fmiVersion == "2.0"
    cs = md.coSimulation
    assert cs.modelIdentifier == "TractionContact"
    assert cs.canHandleVariableCommunicationStepSize and cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    by_name = {v.name: v for v in md.modelVariables}
    assert by_name["fx"].unit == "N" and by_name["fx"].causality == "output"
    assert by_name["torque1"].unit == "N.m"
    assert by_name["omega1"].causality == "input" and by_name["omega1"].unit == "rad/s"
    assert by_name["inlet_temperature"].unit == "degC"
    assert by_name["fluid"].type == "Enumeration"
    units = {u.name for u in md.unitDefinitions}
    assert {"N", "N.m", "Pa", "m", "rad/s", "W", "degC"} <= units
    outputs = [v for v in md.modelVariables if v.causality == "output"]
    assert [o.variable for o in md.outputs] == outputs


def test_simulate_fmu_with_inputs_matches_the_reference(fmu_path):
    from fmpy import simulate_fmu

    h = 1e-3
    # Piecewise-constant inputs: (time, load, omega1, omega2); duplicated time
    # rows make steps. Includes reversal of rolling and zero speed.
    segments = [
        (0.0, 500.0, 1000.0, 400.0),
        (0.1, 800.0, 1002.0, 398.0),
        (0.2, 800.0, -1000.0, -404.0),
        (0.3, 300.0, 0.0, 0.1),
        (0.4, 0.0, 1000.0, 390.0),
        (0.5, 600.0, 1000.0, 400.0),
    ]
    rows = []
    for i, (t, *vals) in enumerate(segments):
        end = segments[i + 1][0] if i + 1 < len(segments) else 0.6
        rows.append((t, *vals))
        rows.append((end, *vals))
    signals = np.array(rows, dtype=[("time", float), ("normal_load", float), ("omega1", float), ("omega2", float)])
    result = simulate_fmu(
        fmu_path,
        fmi_type="CoSimulation",
        start_time=0.0,
        stop_time=0.6,
        step_size=h,
        output_interval=h,
        start_values=PARAMS,
        input=signals,
        output=["fx", "a", "p0", "torque1", "torque2", "power_loss", "normal_load", "omega1", "omega2"],
    )
    checked = 0
    for seg_start, load, w1, w2 in segments:
        # rows well inside the segment (inputs held for several steps)
        sel = result[(result["time"] > seg_start + 5 * h) & (result["time"] < seg_start + 0.1 - 5 * h)]
        assert len(sel) > 50
        for row in sel:
            # FMPy interpolates the inputs (500.00000000000006 for 500): use
            # the values it recorded, which are the ones the step used.
            assert abs(row["normal_load"] - load) <= 1e-9 * max(load, 1.0)
            assert abs(row["omega1"] - w1) <= 1e-9 * max(abs(w1), 1.0)
            fx_ref, _ = traction(row["normal_load"], row["omega1"], row["omega2"])
            a_ref, p0_ref = hertz_circular(row["normal_load"]) if load > 0 else (0.0, 0.0)
            assert abs(row["fx"] - fx_ref) <= 1e-9 * max(1.0, abs(fx_ref)), (row, fx_ref)
            assert abs(row["a"] - a_ref) <= 1e-9 * max(a_ref, 1e-12)
            assert abs(row["p0"] - p0_ref) <= 1e-6 * max(p0_ref, 1.0)
            assert abs(row["torque1"] + row["fx"] * PARAMS["rolling_radius1"]) < 1e-12 * max(1, abs(row["fx"]))
            assert abs(row["torque2"] - row["fx"] * PARAMS["rolling_radius2"]) < 1e-12 * max(1, abs(row["fx"]))
            assert row["power_loss"] >= 0.0
            checked += 1
    assert checked > 300
    # Variable step size: FMPy shortens the last step to hit stop_time exactly.
    r2 = simulate_fmu(fmu_path, fmi_type="CoSimulation", stop_time=0.0105, step_size=1e-3, output=["fx"])
    assert abs(r2["time"][-1] - 0.0105) < 1e-12


def test_drivetrain_slip_settles_on_the_steady_traction_curve(fmu_path):
    t_load, load = 0.9, 500.0
    hist = drivetrain.run(fmu_path, t_end=1.0, h=1e-4, load=load, t_load=t_load)
    t, w1, w2, fx, du, u = hist[-1]
    # Steady state: the contact transmits the load torque ...
    fx_steady = t_load / PARAMS["rolling_radius2"]
    assert abs(fx - fx_steady) < 1e-6 * fx_steady, (fx, fx_steady)
    # ... at the slip the reference traction curve gives for that force.
    du_ref = slip_for_traction(load, u, fx_steady)
    assert abs(du - du_ref) < 1e-6 * du_ref, (du, du_ref)
    assert 0.0 < fx_steady < PARAMS["mu_user"] * load
    # The slip grows from 0 (start without slip) and settles: the last 10 %
    # of the run vary by less than 1e-9 m/s.
    assert hist[0][4] < du
    tail = [row[4] for row in hist[int(0.9 * len(hist)) :]]
    assert max(tail) - min(tail) < 1e-9


def test_libcosimpy_runs_two_instances(fmu_path):
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave

    from fmpy import read_model_description

    vr = {v.name: v.valueReference for v in read_model_description(fmu_path).modelVariables}
    step_ns = 1_000_000  # 1 ms
    ex = CosimExecution.from_step_size(step_size=step_ns)
    obs = CosimObserver.create_last_value()
    ex.add_observer(obs)
    cases = {"contact_a": (500.0, 1000.0, 398.0), "contact_b": (900.0, 1000.0, 401.0)}
    idx = {}
    for name in cases:
        idx[name] = ex.add_local_slave(CosimLocalSlave(fmu_path=fmu_path, instance_name=name))
        assert idx[name] >= 0
    assert ex.num_slaves() == 2
    for name, (load, w1, w2) in cases.items():
        for p, v in PARAMS.items():
            assert ex.real_initial_value(idx[name], vr[p], v)
        assert ex.real_initial_value(idx[name], vr["normal_load"], load)
        assert ex.real_initial_value(idx[name], vr["omega1"], w1)
        assert ex.real_initial_value(idx[name], vr["omega2"], w2)
    assert ex.simulate_until(target_time=100 * step_ns)
    results = {}
    for name, (load, w1, w2) in cases.items():
        fx, a = obs.last_real_values(idx[name], [vr["fx"], vr["a"]])
        fx_ref, _ = traction(load, w1, w2)
        assert abs(fx - fx_ref) < 1e-9 * abs(fx_ref), (name, fx, fx_ref)
        assert abs(a - hertz_circular(load)[0]) < 1e-12
        results[name] = fx
    assert results["contact_a"] > 0 > results["contact_b"]


def test_ecos_simulate(fmu_path, tmp_path):
    import ecospy

    ecos = os.path.join(os.path.dirname(ecospy.__file__), "binaries", "ecos")
    os.chmod(ecos, 0o755)  # the wheel may ship it without the execute bit
    r = subprocess.run(
        [ecos, "simulate", "--path", os.path.abspath(fmu_path), "--stopTime", "0.1", "--stepSize", "0.001"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    text = r.stdout + r.stderr
    print(text)
    assert r.returncode == 0, text
    csvs = glob.glob(os.path.join(tmp_path, "**", "*.csv"), recursive=True)
    assert csvs, f"ecos wrote no CSV in {tmp_path}: {text}"
    with open(csvs[0]) as f:
        rows = list(csv.reader(f))
    header = rows[0]
    col = [i for i, h in enumerate(header) if h.strip().endswith("::p0[REAL]")]
    assert col, header
    # Defaults: load 500 N on the default twin-disc geometry -> P0 ~ 1.1 GPa.
    p0 = float(rows[-1][col[0]])
    assert 0.5e9 < p0 < 2e9, p0
    assert len(rows) > 50


def test_bad_input_is_an_error_with_a_logged_message_and_the_instance_recovers(fmu_path):
    from fmpy import extract, read_model_description
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

    md = read_model_description(fmu_path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    log = []

    def logger(env, name, status, category, message):
        log.append((status, category.decode(), message.decode()))

    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(logger)
    fmu = FMU2Slave(
        guid=md.guid, unzipDirectory=extract(fmu_path), modelIdentifier="TractionContact", instanceName="bad"
    )
    fmu.instantiate(callbacks=callbacks)
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    fmu.doStep(0.0, 1e-3)
    state = fmu.getFMUState()
    with pytest.raises(FMICallException):
        fmu.setReal([vr["normal_load"]], [float("nan")])
    assert log and log[-1][0] == 3 and log[-1][1] == "logStatusError", log
    assert "normal_load" in log[-1][2]
    # Restoring a saved state continues the simulation (fmi2Error is recoverable
    # through fmi2SetFMUstate, as the standard allows).
    fmu.setFMUState(state)
    fmu.doStep(1e-3, 1e-3)
    assert all(math.isfinite(x) for x in fmu.getReal([vr["fx"], vr["p0"]]))
    fmu.freeFMUState(state)
    # Spin gives a spin moment (traction-contact's J+T model with spin).
    fmu.setReal([vr["spin"], vr["omega1"], vr["omega2"]], [10.0, 600.0, 270.0])
    fmu.doStep(2e-3, 1e-3)
    mz, loss = fmu.getReal([vr["mz"], vr["power_loss"]])
    assert mz != 0.0 and loss >= 0.0
    fmu.terminate()
    fmu.freeInstance()


def test_viscoelastic_and_spin_peak_through_fmpy(fmu_path):
    """The new parameters through a real importer: a negative Deborah number is
    fmi2Error with a logged message naming `deborah`; D = inf gives the
    elastic/plastic forces; use_spin_peak scales the forces by mu_spin_user."""
    from fmpy import extract, read_model_description
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

    md = read_model_description(fmu_path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzipped = extract(fmu_path)
    log = []

    def logger(env, name, status, category, message):
        log.append((status, category.decode(), message.decode()))

    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(logger)

    def run(reals, ints=(), bools=(), outputs=("fx", "mz", "mu_force", "J4"), step=False):
        fmu = FMU2Slave(
            guid=md.guid, unzipDirectory=unzipped, modelIdentifier="TractionContact", instanceName="visco"
        )
        fmu.instantiate(callbacks=callbacks)
        fmu.setupExperiment(startTime=0.0)
        for name, x in reals:
            fmu.setReal([vr[name]], [x])
        for name, x in ints:
            fmu.setInteger([vr[name]], [x])
        for name, x in bools:
            fmu.setBoolean([vr[name]], [x])
        fmu.setReal([vr["omega1"], vr["omega2"], vr["spin"]], [600.0, 270.0, 20.0])
        fmu.enterInitializationMode()
        try:
            fmu.exitInitializationMode()
            if step:
                fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.01)
            return fmu.getReal([vr[name] for name in outputs])
        finally:
            fmu.freeInstance()

    with pytest.raises(FMICallException):
        run([("deborah", -1.0)], ints=[("rheology_model", 3)])
    assert log and log[-1][0] == 3 and log[-1][1] == "logStatusError", log
    assert "deborah" in log[-1][2], log[-1]
    ep = run([])
    inf = run([("deborah", float("inf"))], ints=[("rheology_model", 3)])
    assert inf == ep
    visco = run([("deborah", 0.5), ("z0", 0.3)], ints=[("rheology_model", 3)])
    assert visco[0] < 0.99 * ep[0]
    spin_peak = run([("mu_spin_user", 0.06)], bools=[("use_spin_peak", True)])
    assert spin_peak[2] == 0.06
    # Same J groups, forces scaled by mu_s/mu (1e-12 relative).
    assert abs(spin_peak[0] / ep[0] - 0.06 / 0.075) < 1e-12
    assert abs(spin_peak[3] / ep[3] - 1.0) < 1e-12
    # Thermal contact: the film heats (temperature_rise > 0, read back
    # through FMPy) and the traction falls; off, the rise is exactly 0.
    def rise_and_fx(bools):
        return run([], bools=bools, outputs=("temperature_rise", "fx"), step=True)

    cold = rise_and_fx([])
    hot = rise_and_fx([("thermal", True)])
    assert cold[0] == 0.0 and hot[0] > 1.0, (cold, hot)
    assert abs(hot[1]) < abs(cold[1]), (cold, hot)
