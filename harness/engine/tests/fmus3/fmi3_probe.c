/* fmi3_probe: an FMI 3.0 FMU written directly against the standard's C API (no runtime of this
 * project), so that the master's FMI 3.0 import is tested against a model whose answers have a
 * closed form (fmi3_probe.xml lists the variables):
 *   x' = -k x          three Dahlquist equations as one array state, x(t) = exp(-k t)
 *   h' = v, v' = -g    a ball bouncing at h = 0 with v := -e v (a state event on h)
 *   counter += pace    at every multiple of 0.25 s (time events)
 *   y32 = 2 u32, u64 = i16 + 10, bin_out = bin_in reversed, label_out = label + "!"
 *   wsum = w[1] + 2 w[2] + 3 w[3]   (an array input)
 * Co-Simulation integrates the same model exactly (parabola, exponential, events at their exact
 * times), with event mode: a tick at the end of a step is reported and handled in Event Mode, and a
 * discrete input set in Step Mode is refused as the standard requires. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3/fmi3Functions.h"

#define EXPORT __attribute__((visibility("default")))
#define TICK 0.25
#define NX 5

enum Mode { INSTANTIATED, INITIALIZATION, EVENT, CONTINUOUS, STEP, TERMINATED };

typedef struct {
    double time, k[3], x[3], h, v, g, e, w[3];
    int counter, pace;
    int resting; /* the ball's bounces have become too small to resolve: it lies at h = 0 */
    float u32;
    int i16;
    unsigned char bin[16];
    size_t bin_size;
    char label[64], label_out[70];
} Values;

typedef struct {
    Values s;
    enum Mode mode;
    int co_simulation, event_mode_used, tick_pending;
    fmi3InstanceEnvironment env;
    fmi3LogMessageCallback log;
    unsigned char bin_out[16];
} Probe;

static fmi3Status fail(Probe* p, const char* why) {
    if (p->log) p->log(p->env, fmi3Error, "logStatusError", why);
    return fmi3Error;
}

static void compute(Probe* p) {
    snprintf(p->s.label_out, sizeof p->s.label_out, "%s!", p->s.label);
}

static double next_tick(const Values* s) {
    return (floor(s->time / TICK + 1e-9) + 1.0) * TICK;
}

static Probe* instantiate(fmi3String token, int cs, int event_mode, fmi3InstanceEnvironment env,
                          fmi3LogMessageCallback log) {
    if (!token || strcmp(token, "{9b1f1c64-fmi3-probe}") != 0) return NULL;
    Probe* p = calloc(1, sizeof *p);
    if (!p) return NULL;
    Values* s = &p->s;
    s->k[0] = 1, s->k[1] = 2, s->k[2] = 3;
    s->x[0] = s->x[1] = s->x[2] = 1;
    s->h = 1, s->v = 0, s->g = 9.81, s->e = 0.7, s->pace = 1, s->bin_size = 1;
    strcpy(s->label, "probe");
    p->co_simulation = cs;
    p->event_mode_used = event_mode;
    p->env = env;
    p->log = log;
    return p;
}

EXPORT const char* fmi3GetVersion(void) {
    return fmi3Version;
}
EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance i, fmi3Boolean on, size_t n, const fmi3String c[]) {
    (void)i, (void)on, (void)n, (void)c;
    return fmi3OK;
}

EXPORT fmi3Instance fmi3InstantiateModelExchange(fmi3String name, fmi3String token, fmi3String resources,
                                                 fmi3Boolean visible, fmi3Boolean logging, fmi3InstanceEnvironment env,
                                                 fmi3LogMessageCallback log) {
    (void)name, (void)resources, (void)visible, (void)logging;
    return instantiate(token, 0, 0, env, log);
}

EXPORT fmi3Instance fmi3InstantiateCoSimulation(fmi3String name, fmi3String token, fmi3String resources,
                                                fmi3Boolean visible, fmi3Boolean logging, fmi3Boolean event_mode,
                                                fmi3Boolean early_return, const fmi3ValueReference required[],
                                                size_t n_required, fmi3InstanceEnvironment env,
                                                fmi3LogMessageCallback log, fmi3IntermediateUpdateCallback update) {
    (void)name, (void)resources, (void)visible, (void)logging, (void)early_return, (void)required, (void)n_required,
        (void)update;
    return instantiate(token, 1, event_mode, env, log);
}

EXPORT void fmi3FreeInstance(fmi3Instance i) {
    free(i);
}

EXPORT fmi3Status fmi3EnterInitializationMode(fmi3Instance i, fmi3Boolean tol_defined, fmi3Float64 tol,
                                              fmi3Float64 start, fmi3Boolean stop_defined, fmi3Float64 stop) {
    (void)tol_defined, (void)tol, (void)stop_defined, (void)stop;
    Probe* p = i;
    if (p->mode != INSTANTIATED) return fail(p, "fmi3EnterInitializationMode: not in Instantiated");
    p->s.time = start;
    p->mode = INITIALIZATION;
    return fmi3OK;
}

EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance i) {
    Probe* p = i;
    if (p->mode != INITIALIZATION) return fail(p, "fmi3ExitInitializationMode: not in Initialization Mode");
    compute(p);
    p->mode = p->co_simulation && !p->event_mode_used ? STEP : EVENT;
    return fmi3OK;
}

EXPORT fmi3Status fmi3EnterEventMode(fmi3Instance i) {
    Probe* p = i;
    if (p->mode != CONTINUOUS && p->mode != STEP) return fail(p, "fmi3EnterEventMode: illegal call sequence");
    if (p->co_simulation && !p->event_mode_used) return fail(p, "fmi3EnterEventMode: event mode not used");
    p->mode = EVENT;
    return fmi3OK;
}

EXPORT fmi3Status fmi3Terminate(fmi3Instance i) {
    ((Probe*)i)->mode = TERMINATED;
    return fmi3OK;
}

EXPORT fmi3Status fmi3Reset(fmi3Instance i) {
    Probe* p = i;
    Probe* fresh = instantiate("{9b1f1c64-fmi3-probe}", p->co_simulation, p->event_mode_used, p->env, p->log);
    if (!fresh) return fmi3Error;
    *p = *fresh;
    free(fresh);
    return fmi3OK;
}

static void bounce(Values* s) {
    s->h = DBL_MIN; /* just above the floor, so the indicator starts positive */
    s->v = -s->e * s->v;
    if (s->v < 1e-6) s->resting = 1, s->h = 0, s->v = 0;
}

/* The events of the ball and the counter, at the current time. */
static void handle_events(Probe* p) {
    Values* s = &p->s;
    if (!s->resting && s->h <= 1e-9 && s->v < 0) bounce(s);
    const double tick = round(s->time / TICK) * TICK;
    if (fabs(s->time - tick) < 1e-9 && tick > 0 && p->tick_pending) {
        s->counter += s->pace;
        p->tick_pending = 0;
    }
}

EXPORT fmi3Status fmi3UpdateDiscreteStates(fmi3Instance i, fmi3Boolean* need_update, fmi3Boolean* terminate,
                                           fmi3Boolean* nominals_changed, fmi3Boolean* values_changed,
                                           fmi3Boolean* next_defined, fmi3Float64* next_time) {
    Probe* p = i;
    if (p->mode != EVENT) return fail(p, "fmi3UpdateDiscreteStates: not in Event Mode");
    const double h = p->s.h, v = p->s.v;
    handle_events(p);
    compute(p);
    *need_update = fmi3False;
    *terminate = fmi3False;
    *nominals_changed = fmi3False;
    *values_changed = h != p->s.h || v != p->s.v;
    *next_defined = fmi3True;
    *next_time = next_tick(&p->s);
    return fmi3OK;
}

EXPORT fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance i) {
    Probe* p = i;
    if (p->mode != EVENT || p->co_simulation) return fail(p, "fmi3EnterContinuousTimeMode: illegal call sequence");
    p->mode = CONTINUOUS;
    return fmi3OK;
}

EXPORT fmi3Status fmi3EnterStepMode(fmi3Instance i) {
    Probe* p = i;
    if (p->mode != EVENT || !p->co_simulation) return fail(p, "fmi3EnterStepMode: illegal call sequence");
    p->mode = STEP;
    return fmi3OK;
}

EXPORT fmi3Status fmi3CompletedIntegratorStep(fmi3Instance i, fmi3Boolean no_set_prior, fmi3Boolean* enter_event,
                                              fmi3Boolean* terminate) {
    (void)i, (void)no_set_prior;
    *enter_event = fmi3False;
    *terminate = fmi3False;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetTime(fmi3Instance i, fmi3Float64 t) {
    Probe* p = i;
    /* A tick is due once time reaches a multiple of TICK from below. */
    if (floor(t / TICK + 1e-9) > floor(p->s.time / TICK + 1e-9)) p->tick_pending = 1;
    p->s.time = t;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetContinuousStates(fmi3Instance i, const fmi3Float64 x[], size_t n) {
    Values* s = &((Probe*)i)->s;
    if (n != NX) return fail(i, "fmi3SetContinuousStates: 5 states");
    memcpy(s->x, x, 3 * sizeof *x);
    s->h = x[3];
    s->v = x[4];
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetContinuousStates(fmi3Instance i, fmi3Float64 x[], size_t n) {
    const Values* s = &((Probe*)i)->s;
    if (n != NX) return fail(i, "fmi3GetContinuousStates: 5 states");
    memcpy(x, s->x, 3 * sizeof *x);
    x[3] = s->h;
    x[4] = s->v;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance i, fmi3Float64 dx[], size_t n) {
    const Values* s = &((Probe*)i)->s;
    if (n != NX) return fail(i, "fmi3GetContinuousStateDerivatives: 5 states");
    for (int j = 0; j < 3; ++j) dx[j] = -s->k[j] * s->x[j];
    dx[3] = s->v;
    dx[4] = s->resting ? 0 : -s->g;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance i, fmi3Float64 nominal[], size_t n) {
    (void)i;
    for (size_t j = 0; j < n; ++j) nominal[j] = 1;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetEventIndicators(fmi3Instance i, fmi3Float64 z[], size_t n) {
    if (n != 1) return fail(i, "fmi3GetEventIndicators: 1 indicator");
    const Values* s = &((Probe*)i)->s;
    z[0] = s->resting ? 1 : s->h;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance i, size_t* n) {
    (void)i;
    *n = 1;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance i, size_t* n) {
    (void)i;
    *n = NX;
    return fmi3OK;
}

/* Co-Simulation: the exact solution from event to event. */
static void advance(Values* s, double to) {
    const double dt = to - s->time;
    for (int j = 0; j < 3; ++j) s->x[j] *= exp(-s->k[j] * dt);
    s->time = to;
    if (s->resting) return;
    s->h += s->v * dt - 0.5 * s->g * dt * dt;
    s->v -= s->g * dt;
}

static double impact_time(const Values* s) {
    /* h + v t - g t^2 / 2 = 0, the positive root. */
    if (s->resting) return INFINITY;
    const double t = (s->v + sqrt(s->v * s->v + 2 * s->g * s->h)) / s->g;
    return s->time + t;
}

EXPORT fmi3Status fmi3DoStep(fmi3Instance i, fmi3Float64 t, fmi3Float64 step, fmi3Boolean no_set_prior,
                             fmi3Boolean* event_needed, fmi3Boolean* terminate, fmi3Boolean* early_return,
                             fmi3Float64* last_time) {
    (void)no_set_prior;
    Probe* p = i;
    Values* s = &p->s;
    if (p->mode != STEP) return fail(p, "fmi3DoStep: not in Step Mode");
    if (fabs(t - s->time) > 1e-9) return fail(p, "fmi3DoStep: currentCommunicationPoint is not the FMU's time");
    const double end = t + step;
    *event_needed = fmi3False;
    for (;;) {
        const double impact = impact_time(s), tick = next_tick(s);
        const double next = fmin(fmin(impact, tick), end);
        advance(s, next);
        if (next == end && next < impact && fabs(next - tick) > 1e-9) break;
        if (next >= impact - 1e-12) bounce(s);
        if (fabs(next - tick) <= 1e-9) {
            p->tick_pending = 1;
            if (p->event_mode_used && fabs(next - end) <= 1e-9) {
                *event_needed = fmi3True; /* handled in Event Mode by the importer */
                break;
            }
            handle_events(p);
        }
        if (next == end) break;
    }
    *terminate = fmi3False;
    *early_return = fmi3False;
    *last_time = s->time;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetOutputDerivatives(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                           const fmi3Int32 order[], fmi3Float64 values[], size_t n) {
    (void)vr, (void)nvr, (void)order, (void)values, (void)n;
    return fail(i, "fmi3GetOutputDerivatives: not provided");
}

/* Values by reference. A Float64 array fills as many values as it has elements. */
EXPORT fmi3Status fmi3GetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 out[],
                                 size_t n) {
    Probe* p = i;
    const Values* s = &p->s;
    size_t at = 0;
    if (p->mode == INSTANTIATED) return fail(p, "fmi3GetFloat64: not allowed in Instantiated (FMI 3.0.2, 2.3.1)");
    for (size_t j = 0; j < nvr; ++j) {
        const double dx[3] = {-s->k[0] * s->x[0], -s->k[1] * s->x[1], -s->k[2] * s->x[2]};
        const double* array = vr[j] == 1 ? s->k : vr[j] == 2 ? s->x : vr[j] == 3 ? dx : vr[j] == 20 ? s->w : NULL;
        if (array) {
            if (at + 3 > n) return fail(p, "fmi3GetFloat64: nValues too small");
            memcpy(out + at, array, sizeof dx);
            at += 3;
            continue;
        }
        if (at + 1 > n) return fail(p, "fmi3GetFloat64: nValues too small");
        switch (vr[j]) {
            case 0:
                out[at++] = s->time;
                break;
            case 4:
                out[at++] = s->h;
                break;
            case 5:
                out[at++] = s->v;
                break;
            case 6:
                out[at++] = s->v;
                break;
            case 7:
                out[at++] = s->resting ? 0 : -s->g;
                break;
            case 8:
                out[at++] = s->g;
                break;
            case 9:
                out[at++] = s->e;
                break;
            case 21:
                out[at++] = s->w[0] + 2 * s->w[1] + 3 * s->w[2];
                break;
            default:
                return fail(p, "fmi3GetFloat64: no such Float64");
        }
    }
    return at == n ? fmi3OK : fail(p, "fmi3GetFloat64: nValues does not match");
}

EXPORT fmi3Status fmi3SetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 in[],
                                 size_t n) {
    Probe* p = i;
    Values* s = &p->s;
    size_t at = 0;
    const int before_init = p->mode == INSTANTIATED || p->mode == INITIALIZATION;
    for (size_t j = 0; j < nvr; ++j) {
        double* array = vr[j] == 1 && p->mode == INSTANTIATED ? s->k
                        : vr[j] == 2 && before_init           ? s->x
                        : vr[j] == 20                         ? s->w
                                                              : NULL;
        if (array) {
            if (at + 3 > n) return fail(p, "fmi3SetFloat64: nValues too small");
            memcpy(array, in + at, 3 * sizeof *in);
            at += 3;
            continue;
        }
        if (at + 1 > n) return fail(p, "fmi3SetFloat64: nValues too small");
        if (vr[j] == 4 && before_init)
            s->h = in[at++];
        else if (vr[j] == 6 && before_init)
            s->v = in[at++];
        else if (vr[j] == 8 && p->mode == INSTANTIATED)
            s->g = in[at++];
        else if (vr[j] == 9)
            s->e = in[at++];
        else
            return fail(p, "fmi3SetFloat64: not settable now");
    }
    return at == n ? fmi3OK : fail(p, "fmi3SetFloat64: nValues does not match");
}

EXPORT fmi3Status fmi3GetFloat32(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3Float32 out[],
                                 size_t n) {
    Probe* p = i;
    if (nvr != n) return fail(p, "fmi3GetFloat32: scalars only");
    for (size_t j = 0; j < nvr; ++j) {
        if (vr[j] == 11)
            out[j] = p->s.u32;
        else if (vr[j] == 12)
            out[j] = 2 * p->s.u32;
        else
            return fail(p, "fmi3GetFloat32: no such Float32");
    }
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetFloat32(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const fmi3Float32 in[],
                                 size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 11) return fail(p, "fmi3SetFloat32: only u32");
    p->s.u32 = in[0];
    return fmi3OK;
}

/* A discrete input changes in Event Mode only when Co-Simulation uses event mode (FMI 3.0.2, 4.2.4). */
static int discrete_input_refused(const Probe* p) {
    return p->co_simulation && p->event_mode_used && p->mode == STEP;
}

EXPORT fmi3Status fmi3GetInt8(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3Int8 out[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 10) return fail(p, "fmi3GetInt8: only counter");
    out[0] = (fmi3Int8)p->s.counter;
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetInt16(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3Int16 out[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 13) return fail(p, "fmi3GetInt16: only i16");
    out[0] = (fmi3Int16)p->s.i16;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetInt16(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const fmi3Int16 in[],
                               size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 13) return fail(p, "fmi3SetInt16: only i16");
    if (discrete_input_refused(p)) return fail(p, "fmi3SetInt16: a discrete input set in Step Mode");
    p->s.i16 = in[0];
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetUInt64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 out[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 14) return fail(p, "fmi3GetUInt64: only u64");
    out[0] = (fmi3UInt64)(p->s.i16 + 10);
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetInt64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3Int64 out[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 15) return fail(p, "fmi3GetInt64: only the enumeration pace");
    out[0] = p->s.pace;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetInt64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const fmi3Int64 in[],
                               size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 15 || p->mode != INSTANTIATED) return fail(p, "fmi3SetInt64: pace, before init");
    if (in[0] != 1 && in[0] != 2) return fail(p, "fmi3SetInt64: pace is 1 or 2");
    p->s.pace = (int)in[0];
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetBinary(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, size_t sizes[],
                                fmi3Binary out[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1) return fail(p, "fmi3GetBinary: scalars only");
    if (vr[0] == 16) {
        sizes[0] = p->s.bin_size;
        out[0] = p->s.bin;
        return fmi3OK;
    }
    if (vr[0] != 17) return fail(p, "fmi3GetBinary: no such Binary");
    for (size_t j = 0; j < p->s.bin_size; ++j) p->bin_out[j] = p->s.bin[p->s.bin_size - 1 - j];
    sizes[0] = p->s.bin_size;
    out[0] = p->bin_out;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetBinary(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const size_t sizes[],
                                const fmi3Binary in[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 16) return fail(p, "fmi3SetBinary: only bin_in");
    if (sizes[0] > sizeof p->s.bin) return fail(p, "fmi3SetBinary: more than maxSize 16");
    if (discrete_input_refused(p)) return fail(p, "fmi3SetBinary: a discrete input set in Step Mode");
    memcpy(p->s.bin, in[0], sizes[0]);
    p->s.bin_size = sizes[0];
    return fmi3OK;
}

EXPORT fmi3Status fmi3GetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3String out[], size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1) return fail(p, "fmi3GetString: scalars only");
    compute(p);
    if (vr[0] == 18)
        out[0] = p->s.label;
    else if (vr[0] == 19)
        out[0] = p->s.label_out;
    else
        return fail(p, "fmi3GetString: no such String");
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const fmi3String in[],
                                size_t n) {
    Probe* p = i;
    if (nvr != 1 || n != 1 || vr[0] != 18 || p->mode != INSTANTIATED)
        return fail(p, "fmi3SetString: label, before init");
    if (strlen(in[0]) >= sizeof p->s.label) return fail(p, "fmi3SetString: label longer than 63 characters");
    strcpy(p->s.label, in[0]);
    return fmi3OK;
}

/* FMU state: a copy of the values. */
EXPORT fmi3Status fmi3GetFMUState(fmi3Instance i, fmi3FMUState* state) {
    Probe* p = i;
    Probe* copy = *state ? *state : malloc(sizeof *copy);
    if (!copy) return fmi3Error;
    *copy = *p;
    *state = copy;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SetFMUState(fmi3Instance i, fmi3FMUState state) {
    Probe* p = i;
    const Probe* copy = state;
    p->s = copy->s;
    p->tick_pending = copy->tick_pending;
    return fmi3OK;
}

EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance i, fmi3FMUState* state) {
    (void)i;
    free(*state);
    *state = NULL;
    return fmi3OK;
}

EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance i, fmi3FMUState state, size_t* size) {
    (void)i, (void)state;
    *size = sizeof(Probe);
    return fmi3OK;
}

EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance i, fmi3FMUState state, fmi3Byte bytes[], size_t size) {
    if (size != sizeof(Probe)) return fail(i, "fmi3SerializeFMUState: wrong size");
    memcpy(bytes, state, size);
    return fmi3OK;
}

EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance i, const fmi3Byte bytes[], size_t size, fmi3FMUState* state) {
    if (size != sizeof(Probe)) return fail(i, "fmi3DeserializeFMUState: wrong size");
    Probe* copy = malloc(sizeof *copy);
    if (!copy) return fmi3Error;
    memcpy(copy, bytes, size);
    *state = copy;
    return fmi3OK;
}

/* The remaining required names: types this model does not have. */
#define ABSENT(name, type)                                                                                  \
    EXPORT fmi3Status name(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, type v[], size_t n) { \
        (void)vr, (void)nvr, (void)v, (void)n;                                                              \
        return fail(i, #name ": the model has no such variable");                                           \
    }
ABSENT(fmi3GetUInt8, fmi3UInt8)
ABSENT(fmi3GetUInt16, fmi3UInt16)
ABSENT(fmi3GetInt32, fmi3Int32)
ABSENT(fmi3GetUInt32, fmi3UInt32)
ABSENT(fmi3GetBoolean, fmi3Boolean)
ABSENT(fmi3SetInt8, const fmi3Int8)
ABSENT(fmi3SetUInt8, const fmi3UInt8)
ABSENT(fmi3SetUInt16, const fmi3UInt16)
ABSENT(fmi3SetInt32, const fmi3Int32)
ABSENT(fmi3SetUInt32, const fmi3UInt32)
ABSENT(fmi3SetUInt64, const fmi3UInt64)
ABSENT(fmi3SetBoolean, const fmi3Boolean)
