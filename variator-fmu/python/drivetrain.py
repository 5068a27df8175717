"""Engine -> toroidal variator -> vehicle, co-simulated with FMPy's FMU2Slave.

The engine is speed-governed (it holds omega_in at 300 rad/s and supplies
whatever torque the variator draws). The vehicle is an inertia at the output
disc with road load: mass 1000 kg, wheel radius 0.3 m,
final drive 10, rolling resistance 0.012 and aerodynamic drag 0.5 * 1.2 * 0.7 m^2 * v^2.
The tilt sweeps linearly from +0.5 rad (underdrive, ratio 0.483) to -0.5 rad
(overdrive, ratio 2.07). The master integrates the vehicle with explicit
Euler at step h and feeds omega_out back to the FMU.

Run as a script to plot ratio, efficiency and spin loss against time
(drivetrain.png; needs matplotlib):
    python drivetrain.py ToroidalVariator.fmu variator/docs
"""

import math
import shutil
import sys

MASS, WHEEL, FINAL = 1000.0, 0.3, 10.0
CRR, CDA, RHO, G = 0.012, 0.7, 1.2, 9.81
W_ENGINE = 300.0
J_OUT = MASS * WHEEL**2 / FINAL**2 + 0.05  # vehicle inertia seen at the output disc, kg m^2


def road_torque(w_out):
    """Road load torque at the output disc (N m) for output speed w_out."""
    v = w_out / FINAL * WHEEL
    force = CRR * MASS * G * math.tanh(v / 0.1) + 0.5 * RHO * CDA * v * abs(v)
    return force * WHEEL / FINAL


def tilt_at(t, t_end):
    return 0.5 - 1.0 * min(t / t_end, 1.0)


def run(fmu_path, t_end=8.0, h=5e-3, end_load=20e3):
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    md = read_model_description(fmu_path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzip = extract(fmu_path)
    fmu = FMU2Slave(
        guid=md.guid,
        unzipDirectory=unzip,
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="variator",
    )
    outputs = ["torque_out", "speed_ratio", "power_in", "power_out", "power_loss", "spin_loss", "efficiency"]
    out_vrs = [vr[n] for n in outputs]
    hist = []
    try:
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        # The tilt moves at every step: each step has new contacts, for which
        # the direct rheology is cheaper than filling new interpolation maps.
        fmu.setBoolean([vr["rheology_map"]], [False])
        # Start rolling without creep at the first ratio.
        fmu.setReal(
            [vr["omega_in"], vr["omega_out"], vr["tilt_angle"], vr["end_load"]],
            [W_ENGINE, 0.0, tilt_at(0.0, t_end), end_load],
        )
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        w_out = W_ENGINE * fmu.getReal([vr["speed_ratio"]])[0]
        t = 0.0
        while t < t_end - 1e-12:
            fmu.setReal([vr["omega_in"], vr["omega_out"], vr["tilt_angle"]], [W_ENGINE, w_out, tilt_at(t, t_end)])
            fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h)
            vals = dict(zip(outputs, fmu.getReal(out_vrs)))
            vals.update(time=t, tilt=tilt_at(t, t_end), omega_out=w_out, vehicle_speed=w_out / FINAL * WHEEL)
            hist.append(vals)
            w_out += h * (vals["torque_out"] - road_torque(w_out)) / J_OUT
            t += h
        fmu.terminate()
    finally:
        fmu.freeInstance()
        shutil.rmtree(unzip, ignore_errors=True)
    return hist


def plot(hist, out_dir, name="drivetrain.png",
         title="Engine 300 rad/s -> variator -> 1000 kg vehicle, tilt swept +0.5 -> -0.5 rad"):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = [h["time"] for h in hist]
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].plot(t, [h["speed_ratio"] for h in hist], label="geometric ratio r_in/r_out")
    ax[0].plot(t, [h["omega_out"] / W_ENGINE for h in hist], "--", label="actual omega_out/omega_in")
    ax[0].set_ylabel("speed ratio")
    ax[0].legend()
    ax[1].plot(t, [100 * h["efficiency"] for h in hist])
    ax[1].set_ylabel("efficiency (%)")
    ax[1].set_ylim(80, 100)
    ax[2].plot(t, [h["power_loss"] for h in hist], label="total loss")
    ax[2].plot(t, [h["spin_loss"] for h in hist], label="spin loss")
    ax[2].set_ylabel("power (W)")
    ax[2].set_xlabel("time (s)")
    ax[2].legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(f"{out_dir}/{name}", dpi=90)


if __name__ == "__main__":
    history = run(sys.argv[1])
    plot(history, sys.argv[2] if len(sys.argv) > 2 else ".")
    last = history[-1]
    print(f"final vehicle speed {last['vehicle_speed']:.2f} m/s, efficiency {last['efficiency']:.4f}")
