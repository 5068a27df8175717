/*
 * Two small FMI 2.0 co-simulation models for the libcosim drivetrain
 * example (drivetrain_libcosim.py builds each into its own FMU):
 *
 *   PART_MOTOR    "Motor":      speed-controlled motor (ideal governor): holds
 *                               `omega` at the parameter `speed`; reports the
 *                               power it delivers against `load_torque`.
 *   PART_VEHICLE  "Vehicle":    vehicle as an inertia at the output disc with road
 *                               load (rolling resistance, aerodynamic drag),
 *                               integrated over each step with explicit Euler
 *                               sub-steps; input `torque`, output `omega`.
 *   PART_SWEEP    "RatioSweep": the ratio command: `tilt_angle` ramps linearly from
 *                               `tilt_start` to `tilt_end` over `duration` seconds.
 *
 * Value references are the indices into the instance's value array v[];
 * drivetrain_libcosim.py writes the matching modelDescription.xml.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef void *fmi2Component;
typedef void *fmi2ComponentEnvironment;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char *fmi2String;
typedef char fmi2Byte;
typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef enum { fmi2DoStepStatus, fmi2PendingStatus, fmi2LastSuccessfulTime, fmi2Terminated } fmi2StatusKind;
typedef struct {
    void (*logger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...);
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(fmi2ComponentEnvironment, fmi2Status);
    fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

#define EXPORT __attribute__((visibility("default")))
#define NV 12

#if defined(PART_MOTOR)
/* parameters */
#define SPEED 0
/* input */
#define LOAD_TORQUE 1
/* outputs */
#define OMEGA 2
#define POWER 3
static const double START[NV] = {300.0, 0.0, 300.0, 0.0};
#elif defined(PART_VEHICLE)
#define MASS 0
#define WHEEL 1
#define FINAL 2
#define CRR 3
#define CDA 4
#define RHO 5
#define J_EXTRA 6
#define OMEGA_START 7
#define TORQUE 8
#define OMEGA 9
#define SPEED_OUT 10
#define ROAD_TORQUE 11
static const double START[NV] = {1000.0, 0.3, 10.0, 0.012, 0.7, 1.2, 0.05, 0.0, 0.0, 0.0, 0.0, 0.0};
#elif defined(PART_SWEEP)
#define TILT_START 0
#define TILT_END 1
#define DURATION 2
#define TILT 3
static const double START[NV] = {0.5, -0.5, 8.0, 0.5};
#else
#error "define PART_MOTOR, PART_VEHICLE or PART_SWEEP"
#endif

typedef struct {
    double v[NV];
    double time;
} Instance;

#ifdef PART_VEHICLE
/* Road load at the output disc (N m) at output speed w (rad/s): rolling
 * resistance (smoothed through zero speed over 0.1 m/s) and drag. */
static double road(const Instance *c, double w) {
    const double *v = c->v;
    double speed = w / v[FINAL] * v[WHEEL];
    double force = v[CRR] * v[MASS] * 9.81 * tanh(speed / 0.1) + 0.5 * v[RHO] * v[CDA] * speed * fabs(speed);
    return force * v[WHEEL] / v[FINAL];
}
#endif

/* Outputs from the state and inputs. */
static void outputs(Instance *c) {
    double *v = c->v;
#if defined(PART_MOTOR)
    v[OMEGA] = v[SPEED];
    v[POWER] = -v[LOAD_TORQUE] * v[OMEGA];
#elif defined(PART_VEHICLE)
    v[SPEED_OUT] = v[OMEGA] / v[FINAL] * v[WHEEL];
    v[ROAD_TORQUE] = road(c, v[OMEGA]);
#else
    double s = v[DURATION] > 0.0 ? c->time / v[DURATION] : 1.0;
    if (s > 1.0) s = 1.0;
    v[TILT] = v[TILT_START] + (v[TILT_END] - v[TILT_START]) * s;
#endif
}

EXPORT const char *fmi2GetTypesPlatform(void) { return "default"; }
EXPORT const char *fmi2GetVersion(void) { return "2.0"; }
EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cats[]) {
    (void)c; (void)on; (void)n; (void)cats;
    return fmi2OK;
}

EXPORT fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,
                                     const fmi2CallbackFunctions *cb, fmi2Boolean visible, fmi2Boolean logging) {
    (void)name; (void)guid; (void)location; (void)cb; (void)visible; (void)logging;
    if (type != fmi2CoSimulation) return NULL;
    Instance *c = calloc(1, sizeof(Instance));
    if (!c) return NULL;
    memcpy(c->v, START, sizeof(START));
    return c;
}

EXPORT void fmi2FreeInstance(fmi2Component c) { free(c); }

EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tol_on, fmi2Real tol, fmi2Real start,
                                      fmi2Boolean stop_on, fmi2Real stop) {
    (void)tol_on; (void)tol; (void)stop_on; (void)stop;
    if (!c) return fmi2Error;
    ((Instance *)c)->time = start;
    return fmi2OK;
}

EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) { return c ? fmi2OK : fmi2Error; }

EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    if (!c) return fmi2Error;
#ifdef PART_VEHICLE
    ((Instance *)c)->v[OMEGA] = ((Instance *)c)->v[OMEGA_START];
#endif
    outputs(c);
    return fmi2OK;
}

EXPORT fmi2Status fmi2Terminate(fmi2Component c) { return c ? fmi2OK : fmi2Error; }

EXPORT fmi2Status fmi2Reset(fmi2Component c) {
    if (!c) return fmi2Error;
    memcpy(((Instance *)c)->v, START, sizeof(START));
    ((Instance *)c)->time = 0.0;
    return fmi2OK;
}

EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
    if (!c || (n && (!vr || !value))) return fmi2Error;
    Instance *inst = c;
    outputs(inst);
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= NV) return fmi2Error;
        value[i] = inst->v[vr[i]];
    }
    return fmi2OK;
}

EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
    if (!c || (n && (!vr || !value))) return fmi2Error;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= NV || !isfinite(value[i])) return fmi2Error;
        ((Instance *)c)->v[vr[i]] = value[i];
    }
    return fmi2OK;
}

EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean new_step) {
    (void)new_step;
    if (!c || !(h >= 0.0)) return fmi2Error;
    Instance *inst = c;
#ifdef PART_VEHICLE
    /* The vehicle's inertia seen at the output disc: m (r_w/i)^2 + J_extra. */
    double *v = inst->v;
    double j = v[MASS] * v[WHEEL] * v[WHEEL] / (v[FINAL] * v[FINAL]) + v[J_EXTRA];
    const int sub = 10;
    for (int k = 0; k < sub; k++) v[OMEGA] += h / sub * (v[TORQUE] - road(inst, v[OMEGA])) / j;
#endif
    inst->time = t + h;
    outputs(inst);
    return fmi2OK;
}

/* Not supported by these models: no Integer, Boolean or String variables, no
 * FMU state, no derivatives; every call reports fmi2Error (no variable of
 * that type exists; the capability flags in modelDescription.xml are false). */
EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) {
    (void)c; (void)vr; (void)v;
    return n ? fmi2Error : fmi2OK;
}
EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) {
    (void)c; (void)vr; (void)v;
    return n ? fmi2Error : fmi2OK;
}
EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) {
    (void)c; (void)vr; (void)v;
    return n ? fmi2Error : fmi2OK;
}
EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) {
    (void)c; (void)vr; (void)v;
    return n ? fmi2Error : fmi2OK;
}
EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) {
    (void)c; (void)vr; (void)v;
    return n ? fmi2Error : fmi2OK;
}
EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) {
    (void)c; (void)vr; (void)v;
    return n ? fmi2Error : fmi2OK;
}
EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; return fmi2Error; }
EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)c; (void)s; return fmi2Error; }
EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; return fmi2Error; }
EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) {
    (void)c; (void)s; (void)n;
    return fmi2Error;
}
EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) {
    (void)c; (void)s; (void)b; (void)n;
    return fmi2Error;
}
EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s) {
    (void)c; (void)b; (void)n; (void)s;
    return fmi2Error;
}
EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                               const fmi2ValueReference z[], size_t nz, const fmi2Real dv[],
                                               fmi2Real dz[]) {
    (void)c; (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz;
    return fmi2Error;
}
EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                              const fmi2Integer order[], const fmi2Real v[]) {
    (void)c; (void)vr; (void)n; (void)order; (void)v;
    return fmi2Error;
}
EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                               const fmi2Integer order[], fmi2Real v[]) {
    (void)c; (void)vr; (void)n; (void)order; (void)v;
    return fmi2Error;
}
EXPORT fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }
EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status *v) {
    (void)c; (void)k; (void)v;
    return fmi2Discard;
}
EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real *v) {
    if (!c || !v || k != fmi2LastSuccessfulTime) return fmi2Discard;
    *v = ((Instance *)c)->time;
    return fmi2OK;
}
EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer *v) {
    (void)c; (void)k; (void)v;
    return fmi2Discard;
}
EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean *v) {
    (void)c; (void)k; (void)v;
    return fmi2Discard;
}
EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String *v) {
    (void)c; (void)k; (void)v;
    return fmi2Discard;
}
