"""Drivetrain example: motor -> input inertia -> traction contact FMU ->
output inertia with a load torque, run by FMPy's FMU2Slave in a fixed-step
master loop (explicit Euler for the two inertias).

    J1 dw1/dt = T_motor(w1) + torque1      T_motor = k_m (w_ref - w1)
    J2 dw2/dt = torque2 - T_load           T_load constant

The slip settles where the contact transmits T_load: fx = T_load / r2, on the
steady traction curve. Run: python drivetrain.py path/to/TractionContact.fmu
"""

import sys

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

from reference import PARAMS


def run(fmu_path, t_end=1.0, h=1e-4, load=500.0, t_load=0.9, w_ref=1000.0):
    md = read_model_description(fmu_path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzipdir = extract(fmu_path)
    fmu = FMU2Slave(
        guid=md.guid,
        unzipDirectory=unzipdir,
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="contact",
    )
    j1, j2, k_m = 0.002, 0.01, 2.0
    r1, r2 = PARAMS["rolling_radius1"], PARAMS["rolling_radius2"]
    w1 = w_ref
    w2 = w_ref * r1 / r2  # rolling without slip at start
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0)
    names = list(PARAMS)
    fmu.setReal([vr[n] for n in names], [PARAMS[n] for n in names])
    fmu.enterInitializationMode()
    fmu.setReal([vr["normal_load"], vr["omega1"], vr["omega2"]], [load, w1, w2])
    fmu.exitInitializationMode()
    out = [vr["torque1"], vr["torque2"], vr["fx"], vr["slip_velocity"], vr["rolling_speed"]]
    t, history = 0.0, []
    while t < t_end - 1e-12:
        fmu.setReal([vr["omega1"], vr["omega2"]], [w1, w2])
        fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h)
        tq1, tq2, fx, du, u = fmu.getReal(out)
        w1 += h * (k_m * (w_ref - w1) + tq1) / j1
        w2 += h * (tq2 - t_load) / j2
        t += h
        history.append((t, w1, w2, fx, du, u))
    fmu.terminate()
    fmu.freeInstance()
    return history


if __name__ == "__main__":
    hist = run(sys.argv[1])
    for row in hist[:: len(hist) // 20]:
        print("t=%.4f s  w1=%.2f  w2=%.2f rad/s  fx=%.3f N  dU=%.5f m/s  U=%.3f m/s" % row)
