/*
 * A small FMI 2.0 co-simulation master for the cross-platform test of
 * TractionContact: loads the FMU's shared library (LoadLibrary on Windows,
 * dlopen elsewhere), runs fixed scenarios and prints every Real output and
 * the regime after each step as lines "case step name value" with 17
 * significant digits. scripts/fmu_test.sh builds it for Windows (MinGW-w64,
 * run under Wine against binaries/win64) and for Linux (against
 * binaries/linux64) and compares the two listings.
 *
 * Usage: master LIBRARY GUID
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _WIN32
#include <windows.h>
typedef HMODULE lib_t;
static lib_t lib_open(const char *p) { return LoadLibraryA(p); }
static void *lib_sym(lib_t l, const char *n) { return (void *)GetProcAddress(l, n); }
#else
#include <dlfcn.h>
typedef void *lib_t;
static lib_t lib_open(const char *p) { return dlopen(p, RTLD_NOW | RTLD_LOCAL); }
static void *lib_sym(lib_t l, const char *n) { return dlsym(l, n); }
#endif

typedef void *fmi2Component;
typedef unsigned int fmi2ValueReference;
typedef int fmi2Status;
typedef int fmi2Boolean;
typedef int fmi2Integer;
typedef void (*fmi2CallbackLogger)(void *, const char *, fmi2Status, const char *, const char *, ...);
typedef struct {
    fmi2CallbackLogger logger;
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(void *, fmi2Status);
    void *componentEnvironment;
} fmi2CallbackFunctions;

typedef fmi2Component (*instantiate_t)(const char *, int, const char *, const char *,
                                       const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
typedef void (*free_t)(fmi2Component);
typedef fmi2Status (*setup_t)(fmi2Component, fmi2Boolean, double, double, fmi2Boolean, double);
typedef fmi2Status (*call_t)(fmi2Component);
typedef fmi2Status (*real_t)(fmi2Component, const fmi2ValueReference *, size_t, double *);
typedef fmi2Status (*int_t)(fmi2Component, const fmi2ValueReference *, size_t, fmi2Integer *);
typedef fmi2Status (*set_real_t)(fmi2Component, const fmi2ValueReference *, size_t, const double *);
typedef fmi2Status (*set_int_t)(fmi2Component, const fmi2ValueReference *, size_t, const fmi2Integer *);
typedef fmi2Status (*set_bool_t)(fmi2Component, const fmi2ValueReference *, size_t, const fmi2Boolean *);
typedef fmi2Status (*step_t)(fmi2Component, double, double, fmi2Boolean);

static void logger(void *env, const char *name, fmi2Status status, const char *category,
                   const char *message, ...) {
    (void)env;
    /* Messages to stderr only: stdout is the compared listing. */
    fprintf(stderr, "[%s] %d %s: %s\n", name, status, category, message);
}

/* Value references of the FMU's table (fmu/src/variables). */
enum {
    RX1 = 1, NU2 = 8, M_USER = 11, MU_USER = 12, TILT_ANGLE = 13, DEBORAH = 16, Z0 = 17,
    LOAD = 100, OMEGA1 = 101, OMEGA2 = 102, SIDE_SLIP = 103, SKEW = 104, SPIN = 105, INLET = 106,
    FLUID = 300, RHEOLOGY = 301, SPIN_SOURCE = 302, SIDE_SLIP_SOURCE = 303, COMPLIANCE = 304,
    SPIN_PEAK = 306, MAP = 307, REGIME = 310
};

static const char *OUT_NAMES[] = {
    "fx", "fy", "mz", "torque1", "torque2", "traction_coefficient", "side_traction_coefficient",
    "power_loss", "a", "b", "k", "p0", "rolling_speed", "slip_velocity", "side_slip",
    "spin_used", "m", "mu", "mu_force", "J1", "J2", "J3", "J4", "J5", "J6", "J7"};
static const fmi2ValueReference OUT_VRS[] = {200, 201, 202, 203, 204, 205, 206, 207, 208,
                                              209, 210, 211, 212, 213, 214, 215, 216, 217,
                                              218, 221, 222, 223, 224, 225, 226, 227};
#define N_OUT (sizeof OUT_VRS / sizeof OUT_VRS[0])

struct api {
    instantiate_t instantiate;
    free_t free_instance;
    setup_t setup;
    call_t enter, exit_init, terminate;
    real_t get_real;
    set_real_t set_real;
    int_t get_integer;
    set_int_t set_integer;
    set_bool_t set_boolean;
    step_t do_step;
};

/* One scenario: integer and boolean settings, then 40 steps with ramping
 * speeds from omega1 = w0 (the user-fluid cases start through zero speed;
 * the report fluids' correlations start inside their data). */
struct scenario {
    const char *name;
    fmi2ValueReference ivr[4];
    fmi2Integer ival[4];
    size_t ni;
    fmi2ValueReference bvr[3];
    fmi2Boolean bval[3];
    size_t nb;
    fmi2ValueReference rvr[4];
    double rval[4];
    size_t nr;
    double w0; /* omega1 of the first step, rad/s */
};

static int fail(const char *what, int st) {
    fprintf(stderr, "master: %s returned %d\n", what, st);
    return 1;
}

static int run(const struct api *f, const char *guid, const struct scenario *sc) {
    fmi2CallbackFunctions cb = {logger, NULL, NULL, NULL, NULL};
    fmi2Component c = f->instantiate(sc->name, 1, guid, NULL, &cb, 0, 0);
    if (!c) return fail("fmi2Instantiate", -1);
    int st;
    if ((st = f->setup(c, 0, 0.0, 0.0, 1, 1.0)) > 1) return fail("fmi2SetupExperiment", st);
    if (sc->ni && (st = f->set_integer(c, sc->ivr, sc->ni, sc->ival)) > 1) return fail("fmi2SetInteger", st);
    if (sc->nb && (st = f->set_boolean(c, sc->bvr, sc->nb, sc->bval)) > 1) return fail("fmi2SetBoolean", st);
    if (sc->nr && (st = f->set_real(c, sc->rvr, sc->nr, sc->rval)) > 1) return fail("fmi2SetReal", st);
    if ((st = f->enter(c)) > 1) return fail("fmi2EnterInitializationMode", st);
    if ((st = f->exit_init(c)) > 1) return fail("fmi2ExitInitializationMode", st);
    double t = 0.0, h = 0.025;
    for (int k = 0; k < 40; k++) {
        /* Start-up through zero speed, slip up to ~8 %, load and spin vary. */
        fmi2ValueReference in[] = {LOAD, OMEGA1, OMEGA2, SIDE_SLIP, SKEW, SPIN, INLET};
        double w1 = sc->w0 + 5.0 * k;
        double x[] = {500.0, w1, 0.92 * w1 * 0.033 / 0.0714 + 0.5, 0.002 * k,
                      0.0005 * k, 2.0 * k - 10.0, 40.0};
        if ((st = f->set_real(c, in, 7, x)) > 1) return fail("fmi2SetReal", st);
        if ((st = f->do_step(c, t, h, 1)) > 1) return fail("fmi2DoStep", st);
        t += h;
        double out[N_OUT];
        if ((st = f->get_real(c, OUT_VRS, N_OUT, out)) > 1) return fail("fmi2GetReal", st);
        fmi2ValueReference rv = REGIME;
        fmi2Integer regime;
        if ((st = f->get_integer(c, &rv, 1, &regime)) > 1) return fail("fmi2GetInteger", st);
        for (size_t i = 0; i < N_OUT; i++) printf("%s %d %s %.17g\n", sc->name, k, OUT_NAMES[i], out[i]);
        printf("%s %d regime %d\n", sc->name, k, regime);
    }
    if ((st = f->terminate(c)) > 1) return fail("fmi2Terminate", st);
    f->free_instance(c);
    return 0;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: master LIBRARY GUID\n");
        return 2;
    }
    lib_t l = lib_open(argv[1]);
    if (!l) {
        fprintf(stderr, "master: cannot load %s\n", argv[1]);
        return 1;
    }
    struct api f = {
        (instantiate_t)lib_sym(l, "fmi2Instantiate"),
        (free_t)lib_sym(l, "fmi2FreeInstance"),
        (setup_t)lib_sym(l, "fmi2SetupExperiment"),
        (call_t)lib_sym(l, "fmi2EnterInitializationMode"),
        (call_t)lib_sym(l, "fmi2ExitInitializationMode"),
        (call_t)lib_sym(l, "fmi2Terminate"),
        (real_t)lib_sym(l, "fmi2GetReal"),
        (set_real_t)lib_sym(l, "fmi2SetReal"),
        (int_t)lib_sym(l, "fmi2GetInteger"),
        (set_int_t)lib_sym(l, "fmi2SetInteger"),
        (set_bool_t)lib_sym(l, "fmi2SetBoolean"),
        (step_t)lib_sym(l, "fmi2DoStep"),
    };
    void **p = (void **)&f;
    for (size_t i = 0; i < sizeof f / sizeof(void *); i++)
        if (!p[i]) {
            fprintf(stderr, "master: missing FMI function %zu\n", i);
            return 1;
        }
    const struct scenario scenarios[] = {
        /* User fluid, elastic/plastic through the rheology map. */
        {"user_map", {0}, {0}, 0, {MAP}, {1}, 1, {0}, {0}, 0, -20.0},
        /* The same, strips integrated at every step. */
        {"user_direct", {0}, {0}, 0, {MAP}, {0}, 1, {0}, {0}, 0, -20.0},
        /* TDF-88 correlations (clamped), spin peak, disc compliance, skew angle. */
        {"tdf88", {FLUID, SIDE_SLIP_SOURCE}, {2, 2}, 2, {SPIN_PEAK, COMPLIANCE}, {1, 1}, 2,
         {NU2}, {0.28}, 1, 600.0},
        /* Santotrac 50, rigid/plastic, spin from the tilt geometry. */
        {"santotrac_rigid", {FLUID, RHEOLOGY, SPIN_SOURCE}, {1, 2, 2}, 3, {0}, {0}, 0,
         {TILT_ANGLE}, {0.3}, 1, 600.0},
        /* Viscoelastic user fluid. */
        {"viscoelastic", {RHEOLOGY}, {3}, 1, {MAP}, {0}, 1, {DEBORAH, Z0, M_USER, MU_USER},
         {0.5, 0.3, 30.0, 0.06}, 4, -20.0},
    };
    for (size_t i = 0; i < sizeof scenarios / sizeof scenarios[0]; i++)
        if (run(&f, argv[2], &scenarios[i])) return 1;
    return 0;
}
