"""Motor -> toroidal variator -> vehicle in libcosim (libcosimpy), from an OSP
system structure file (OspSystemStructure.xml beside this file).

The motor, the vehicle and the ratio sweep are three small FMUs built here
from parts/parts.c with the system C compiler (cc) and packaged with their
modelDescription.xml: a speed-controlled motor at 300 rad/s, the vehicle of
drivetrain.py (1000 kg, wheel 0.3 m, final drive 10, rolling resistance and
drag) as an inertia on the output disc, and a linear tilt ramp from +0.5 to
-0.5 rad over 8 s. libcosim's fixed-step master (5 ms) exchanges the values
between the four FMUs; a time-series observer records the variator's outputs.

Run as a script to plot ratio, efficiency and losses against time
(drivetrain_libcosim.png; needs matplotlib):
    python drivetrain_libcosim.py ToroidalVariator.fmu variator-fmu/docs
"""

import os
import shutil
import subprocess
import sys
import tempfile
import uuid
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
STEP = 0.005
T_END = 8.0

# name -> (C macro, [(variable, value reference, causality, variability, start, unit, description)])
PARTS = {
    "Motor": (
        "PART_MOTOR",
        [
            ("speed", 0, "parameter", "fixed", 300.0, "rad/s", "governed speed"),
            ("load_torque", 1, "input", "continuous", 0.0, "N.m", "torque of the load on the shaft, positive in the sense of omega"),
            ("omega", 2, "output", "continuous", None, "rad/s", "shaft speed"),
            ("power", 3, "output", "continuous", None, "W", "power delivered to the load"),
        ],
    ),
    "Vehicle": (
        "PART_VEHICLE",
        [
            ("mass", 0, "parameter", "fixed", 1000.0, "kg", "vehicle mass"),
            ("wheel_radius", 1, "parameter", "fixed", 0.3, "m", "wheel radius"),
            ("final_drive", 2, "parameter", "fixed", 10.0, "1", "final drive ratio (output disc to wheel)"),
            ("rolling_resistance", 3, "parameter", "fixed", 0.012, "1", "rolling resistance coefficient"),
            ("drag_area", 4, "parameter", "fixed", 0.7, "m2", "drag coefficient times frontal area"),
            ("air_density", 5, "parameter", "fixed", 1.2, "kg/m3", "air density"),
            ("extra_inertia", 6, "parameter", "fixed", 0.05, "kg.m2", "inertia of the output shaft and disc"),
            ("omega_start", 7, "parameter", "fixed", 0.0, "rad/s", "output-shaft speed at the start"),
            ("torque", 8, "input", "continuous", 0.0, "N.m", "driving torque on the output shaft"),
            ("omega", 9, "output", "continuous", None, "rad/s", "output-shaft speed"),
            ("vehicle_speed", 10, "output", "continuous", None, "m/s", "vehicle speed"),
            ("road_torque", 11, "output", "continuous", None, "N.m", "road load at the output shaft"),
        ],
    ),
    "RatioSweep": (
        "PART_SWEEP",
        [
            ("tilt_start", 0, "parameter", "fixed", 0.5, "rad", "tilt at t = 0"),
            ("tilt_end", 1, "parameter", "fixed", -0.5, "rad", "tilt at t = duration and after"),
            ("duration", 2, "parameter", "fixed", 8.0, "s", "duration of the ramp"),
            ("tilt_angle", 3, "output", "continuous", None, "rad", "commanded roller tilt"),
        ],
    ),
}


def model_description(name, variables):
    """modelDescription.xml of one part (FMI 2.0 co-simulation)."""
    rows, outputs = [], []
    for i, (var, vr, causality, variability, start, unit, desc) in enumerate(variables):
        initial = ' initial="exact"' if causality == "parameter" else ""
        initial = ' initial="calculated"' if causality == "output" else initial
        start_attr = "" if start is None else f' start="{start!r}"'
        rows.append(
            f'    <ScalarVariable name="{var}" valueReference="{vr}" causality="{causality}" '
            f'variability="{variability}"{initial} description="{desc}">\n'
            f'      <Real unit="{unit}"{start_attr}/>\n    </ScalarVariable>'
        )
        if causality == "output":
            outputs.append(f'      <Unknown index="{i + 1}"/>')
    units = sorted({v[5] for v in variables})
    unit_defs = "\n".join(f'    <Unit name="{u}"/>' for u in units)
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="{name}" guid="{{{uuid.uuid5(uuid.NAMESPACE_URL, 'traction/' + name)}}}"
  description="drivetrain example part: {name}" generationTool="drivetrain_libcosim.py" variableNamingConvention="flat"
  numberOfEventIndicators="0">
  <CoSimulation modelIdentifier="{name}" canHandleVariableCommunicationStepSize="true"/>
  <UnitDefinitions>
{unit_defs}
  </UnitDefinitions>
  <DefaultExperiment startTime="0" stopTime="{T_END}" stepSize="{STEP}"/>
  <ModelVariables>
{chr(10).join(rows)}
  </ModelVariables>
  <ModelStructure>
    <Outputs>
{chr(10).join(outputs)}
    </Outputs>
    <InitialUnknowns>
{chr(10).join(outputs)}
    </InitialUnknowns>
  </ModelStructure>
</fmiModelDescription>
"""


def build_parts(out_dir):
    """Compile parts/parts.c into the three part FMUs in out_dir."""
    src = os.path.join(HERE, "parts", "parts.c")
    paths = {}
    for name, (macro, variables) in PARTS.items():
        so = os.path.join(out_dir, f"{name}.so")
        subprocess.run(
            ["cc", "-O2", "-Wall", "-Wextra", "-Werror", "-shared", "-fPIC", "-fvisibility=hidden",
             f"-D{macro}", "-o", so, src, "-lm"],
            check=True,
        )
        fmu = os.path.join(out_dir, f"{name}.fmu")
        with zipfile.ZipFile(fmu, "w", zipfile.ZIP_DEFLATED) as z:
            z.writestr("modelDescription.xml", model_description(name, variables))
            z.write(so, f"binaries/linux64/{name}.so")
        os.remove(so)
        paths[name] = fmu
    return paths


VARIATOR_OUTPUTS = ["speed_ratio", "omega_in", "omega_out", "tilt_angle", "torque_in", "torque_out",
                    "power_in", "power_out", "power_loss", "spin_loss", "efficiency"]


def run(variator_fmu):
    """Run the OSP case; returns one dict per step: time, the variator's
    inputs and outputs, the vehicle speed and the motor power."""
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.WARNING)
    case = tempfile.mkdtemp(prefix="drivetrain_libcosim_")
    try:
        build_parts(case)
        shutil.copy(variator_fmu, os.path.join(case, "ToroidalVariator.fmu"))
        shutil.copy(os.path.join(HERE, "OspSystemStructure.xml"), case)
        ex = CosimExecution.from_osp_config_file(osp_path=os.path.join(case, "OspSystemStructure.xml"))
        obs = CosimObserver.create_last_value()
        ex.add_observer(obs)

        def refs(instance):
            i = ex.slave_index_from_instance_name(instance)
            return i, {v.name.decode(): v.reference for v in ex.slave_variables(i)}

        var, var_vr = refs("variator")
        veh, veh_vr = refs("vehicle")
        mot, mot_vr = refs("motor")
        hist = []
        for k in range(round(T_END / STEP)):
            assert ex.step(), f"libcosim step {k} failed"
            row = dict(zip(VARIATOR_OUTPUTS, obs.last_real_values(var, [var_vr[n] for n in VARIATOR_OUTPUTS])))
            row["vehicle_speed"] = obs.last_real_values(veh, [veh_vr["vehicle_speed"]])[0]
            row["motor_power"] = obs.last_real_values(mot, [mot_vr["power"]])[0]
            row["time"] = (k + 1) * STEP
            hist.append(row)
        return hist
    finally:
        shutil.rmtree(case, ignore_errors=True)


if __name__ == "__main__":
    import drivetrain

    history = run(sys.argv[1])
    drivetrain.plot(
        history,
        sys.argv[2] if len(sys.argv) > 2 else ".",
        name="drivetrain_libcosim.png",
        title="libcosim: motor 300 rad/s -> variator -> 1000 kg vehicle, tilt +0.5 -> -0.5 rad",
    )
    last = history[-1]
    print(f"final vehicle speed {last['vehicle_speed']:.2f} m/s, efficiency {last['efficiency']:.4f}")
