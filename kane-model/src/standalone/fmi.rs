//! The FMI 2.0 functions of an FMU's C source, for Model Exchange and Co-Simulation, over the
//! model's `MODEL_constants`, `MODEL_rhs` and `MODEL_row` and the integrator's `advance`. The
//! standard's types are declared here as the standard defines them (their C layout is the
//! interface); value references are parameters, then states, then their derivatives, then the
//! outputs.

/// The text, with `MODEL` for the model identifier and `GUID_TEXT` for the GUID.
pub(super) const FMI2: &str = r#"
/* FMI 2.0 types, as the standard defines them. */
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
typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...);
typedef void *(*fmi2CallbackAllocateMemory)(size_t, size_t);
typedef void (*fmi2CallbackFreeMemory)(void *);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment, fmi2Status);
typedef struct {
    const fmi2CallbackLogger logger;
    const fmi2CallbackAllocateMemory allocateMemory;
    const fmi2CallbackFreeMemory freeMemory;
    const fmi2StepFinished stepFinished;
    const fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;
typedef struct {
    fmi2Boolean newDiscreteStatesNeeded;
    fmi2Boolean terminateSimulation;
    fmi2Boolean nominalsOfContinuousStatesChanged;
    fmi2Boolean valuesOfContinuousStatesChanged;
    fmi2Boolean nextEventTimeDefined;
    fmi2Real nextEventTime;
} fmi2EventInfo;

#define EXPORT __attribute__((visibility("default")))

/* One instance: its time, state, parameters and what is computed from them. */
typedef struct {
    double t, y[NY], p[NP > 0 ? NP : 1], k[NK], dy[NY], h, tol[2];
    int constants_stale, rates_stale;
    fmi2Type type;
    char name[256];
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment environment;
} Instance;

static void say(Instance *m, fmi2Status status, const char *message) {
    if (m->logger) m->logger(m->environment, m->name, status, status == fmi2OK ? "logAll" : "logStatusError", "%s", message);
}

static void refresh(Instance *m) {
    if (m->constants_stale) MODEL_constants(m->p, m->k);
    if (m->constants_stale || m->rates_stale) MODEL_rhs(m->t, m->y, m->p, m->k, m->dy);
    m->constants_stale = m->rates_stale = 0;
}

EXPORT const char *fmi2GetTypesPlatform(void) { return "default"; }
EXPORT const char *fmi2GetVersion(void) { return "2.0"; }
EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[]) {
    (void)c; (void)on; (void)n; (void)categories;
    return fmi2OK;
}

EXPORT fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,
                                     const fmi2CallbackFunctions *functions, fmi2Boolean visible, fmi2Boolean logging) {
    (void)location; (void)visible; (void)logging;
    if (!guid || strcmp(guid, "GUID_TEXT") != 0) {
        if (functions && functions->logger)
            functions->logger(functions->componentEnvironment, name, fmi2Error, "logStatusError",
                              "the GUID %s is not this FMU's (GUID_TEXT)", guid ? guid : "(none)");
        return NULL;
    }
    Instance *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    snprintf(m->name, sizeof m->name, "%s", name ? name : "MODEL");
    m->type = type;
    m->logger = functions ? functions->logger : NULL;
    m->environment = functions ? functions->componentEnvironment : NULL;
    memcpy(m->p, P0, sizeof P0);
    memcpy(m->y, Y0, sizeof Y0);
    m->tol[0] = RTOL;
    m->tol[1] = ATOL;
    m->constants_stale = m->rates_stale = 1;
    return m;
}

EXPORT void fmi2FreeInstance(fmi2Component c) { free(c); }

EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolerance_defined, fmi2Real tolerance,
                                      fmi2Real start, fmi2Boolean stop_defined, fmi2Real stop) {
    Instance *m = c;
    (void)stop_defined; (void)stop;
    m->t = start;
    if (tolerance_defined && tolerance > 0) m->tol[0] = m->tol[1] = tolerance;
    m->rates_stale = 1;
    return fmi2OK;
}

EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    Instance *m = c;
    m->h = 0.0;
    refresh(m);
    return fmi2OK;
}
EXPORT fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2Reset(fmi2Component c) {
    Instance *m = c;
    memcpy(m->p, P0, sizeof P0);
    memcpy(m->y, Y0, sizeof Y0);
    m->t = 0.0;
    m->constants_stale = m->rates_stale = 1;
    return fmi2OK;
}

EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
    Instance *m = c;
    double row[NCOL > 0 ? NCOL : 1];
    int have_row = 0;
    refresh(m);
    for (size_t i = 0; i < n; i++) {
        size_t r = vr[i];
        if (r < NP) value[i] = m->p[r];
        else if (r < NP + NY) value[i] = m->y[r - NP];
        else if (r < NP + 2 * NY) value[i] = m->dy[r - NP - NY];
        else if (r < NP + 2 * NY + NCOL) {
            if (!have_row) MODEL_row(m->t, m->y, m->p, m->k, row);
            have_row = 1;
            value[i] = row[r - NP - 2 * NY];
        } else {
            say(m, fmi2Error, "fmi2GetReal: no such value reference");
            return fmi2Error;
        }
    }
    return fmi2OK;
}

EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
    Instance *m = c;
    for (size_t i = 0; i < n; i++) {
        size_t r = vr[i];
        if (r < NP) {
            m->p[r] = value[i];
            m->constants_stale = 1;
        } else if (r < NP + NY) {
            m->y[r - NP] = value[i];
            m->rates_stale = 1;
        } else {
            say(m, fmi2Error, "fmi2SetReal: only parameters, inputs and states can be set");
            return fmi2Error;
        }
    }
    return fmi2OK;
}

static fmi2Status no_such_type(fmi2Component c, size_t n) {
    if (n == 0) return fmi2OK;
    say(c, fmi2Error, "the model has Real variables only");
    return fmi2Error;
}
EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) { (void)vr; (void)v; return no_such_type(c, n); }
EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) { (void)vr; (void)v; return no_such_type(c, n); }
EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) { (void)vr; (void)v; return no_such_type(c, n); }
EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) { (void)vr; (void)v; return no_such_type(c, n); }
EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) { (void)vr; (void)v; return no_such_type(c, n); }
EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) { (void)vr; (void)v; return no_such_type(c, n); }

static fmi2Status unsupported(fmi2Component c, const char *what) {
    say(c, fmi2Error, what);
    return fmi2Error;
}
EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)s; return unsupported(c, "FMU states are not supported"); }
EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)s; return unsupported(c, "FMU states are not supported"); }
EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)s; return unsupported(c, "FMU states are not supported"); }
EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) { (void)s; (void)n; return unsupported(c, "FMU states are not supported"); }
EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) { (void)s; (void)b; (void)n; return unsupported(c, "FMU states are not supported"); }
EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s) { (void)s; (void)b; (void)n; return unsupported(c, "FMU states are not supported"); }
EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu, const fmi2ValueReference z[], size_t nz, const fmi2Real dv[], fmi2Real df[]) {
    (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)df;
    return unsupported(c, "directional derivatives are not provided");
}

/* Model Exchange. */
EXPORT fmi2Status fmi2EnterEventMode(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info) {
    (void)c;
    memset(info, 0, sizeof *info);
    return fmi2OK;
}
EXPORT fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean no_set_prior, fmi2Boolean *enter_event, fmi2Boolean *terminate) {
    (void)c; (void)no_set_prior;
    *enter_event = 0;
    *terminate = 0;
    return fmi2OK;
}
EXPORT fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) {
    Instance *m = c;
    m->t = t;
    m->rates_stale = 1;
    return fmi2OK;
}
EXPORT fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t n) {
    Instance *m = c;
    if (n != NY) return unsupported(c, "fmi2SetContinuousStates: wrong number of states");
    memcpy(m->y, x, sizeof m->y);
    m->rates_stale = 1;
    return fmi2OK;
}
EXPORT fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t n) {
    Instance *m = c;
    if (n != NY) return unsupported(c, "fmi2GetDerivatives: wrong number of states");
    refresh(m);
    for (size_t i = 0; i < NY; i++)
        if (!isfinite(m->dy[i])) return unsupported(c, "the derivatives are not finite at this state");
    memcpy(dx, m->dy, sizeof m->dy);
    return fmi2OK;
}
EXPORT fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t n) { (void)c; (void)z; (void)n; return fmi2OK; }
EXPORT fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t n) {
    Instance *m = c;
    if (n != NY) return unsupported(c, "fmi2GetContinuousStates: wrong number of states");
    memcpy(x, m->y, sizeof m->y);
    return fmi2OK;
}
EXPORT fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x[], size_t n) {
    (void)c;
    for (size_t i = 0; i < n; i++) x[i] = 1.0;
    return fmi2OK;
}

/* Co-Simulation: each communication step integrated by the embedded Runge-Kutta method. */
EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer order[], const fmi2Real v[]) {
    (void)vr; (void)order; (void)v;
    return no_such_type(c, n);
}
EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer order[], fmi2Real v[]) {
    (void)vr; (void)order; (void)v;
    return no_such_type(c, n);
}
EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean no_set_prior) {
    Instance *m = c;
    (void)no_set_prior;
    m->t = t;
    m->rates_stale = 1;
    refresh(m);
    if (!(m->h > 0.0)) m->h = fmin(h, 1e-3 * fmax(h, 1e-300));
    double f[NY];
    memcpy(f, m->dy, sizeof f);
    if (advance(&m->t, m->y, f, t + h, &m->h, m->p, m->k, m->tol)) {
        say(m, fmi2Error, "the step size fell to nothing: the solution is singular here");
        return fmi2Error;
    }
    m->rates_stale = 1;
    return fmi2OK;
}
EXPORT fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *v) { (void)s; (void)v; return unsupported(c, "no asynchronous steps"); }
EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *v) {
    Instance *m = c;
    if (s != fmi2LastSuccessfulTime) return unsupported(c, "no asynchronous steps");
    *v = m->t;
    return fmi2OK;
}
EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *v) { (void)s; (void)v; return unsupported(c, "no asynchronous steps"); }
EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *v) { (void)s; (void)v; return unsupported(c, "no asynchronous steps"); }
EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *v) { (void)s; (void)v; return unsupported(c, "no asynchronous steps"); }
"#;
