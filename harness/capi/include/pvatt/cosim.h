/* The co-simulation engine as a C library: open a system (.ssd, .ssp or a single .fmu), list its
 * components and variables, set values, run it to a time or step it, read its outputs.
 *
 * Stable C ABI: opaque handles, plain C types, no C++ exception ever crosses it. Every function that
 * can fail returns a pvatt_status; on failure the message is pvatt_last_error() (per thread, valid until
 * the next failing call in that thread). Strings returned by the library belong to the handle they
 * came from and stay valid while it is open.
 *
 * Handles. The library keeps a registry of the handles it handed out: a handle closed or freed already
 * (or never returned) is refused with PVATT_INVALID_ARGUMENT and a message, never used; the functions
 * that return no status (pvatt_system_close, pvatt_result_free, pvatt_simulation_free, the counts and
 * names) then do nothing, return 0 / NULL / NaN and leave the reason in pvatt_last_error(). (An address
 * the allocator reuses for a new handle is that new handle.)
 *
 * Threads. A handle is not safe for concurrent use from several threads; distinct handles are (except
 * the process-wide interrupt flag, see pvatt_interrupt). A simulation runs on a thread of its own; the
 * caller's calls on it are refused with PVATT_WRONG_STATE while it is running (another thread during
 * pvatt_advance_to), so only one of the two threads ever touches the run.
 *
 * Re-entrancy. A callback component (pvatt_system_replace) runs inside pvatt_run or pvatt_advance_to.
 * From inside it, pvatt_system_open, pvatt_run, pvatt_start, pvatt_advance_to and pvatt_campaign_run are
 * refused with PVATT_WRONG_STATE, as is any call on the simulation the callback is part of (it is
 * running: pvatt_simulation_free leaves it open and says why in pvatt_last_error). pvatt_interrupt stops
 * the run; other handles may be used. pvatt_system_close of a system a run or a simulation is using (from
 * a callback, or before freeing a paused simulation) closes the handle at once and frees the system when
 * the last of them ends.
 *
 * Variable names are "component.variable" as in a system description ("plant.v_bus", "est.q_est[1]").
 * Values go in and out as doubles (Real, Integer, Boolean as 0/1, Enumeration as its item's number) or
 * as text (any type; an Enumeration by its item's name, "est.sun_method=cones").
 */
#ifndef PVATT_COSIM_H
#define PVATT_COSIM_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define PVATT_API __attribute__((visibility("default")))
#else
#define PVATT_API
#endif

/* Bumped when a declaration in this header changes incompatibly. */
#define PVATT_API_VERSION 1

typedef enum pvatt_status {
    PVATT_OK = 0,
    PVATT_ERROR = 1,            /* the engine refused or failed (bad file, FMU error, solver failure) */
    PVATT_INVALID_ARGUMENT = 2, /* a null handle or pointer, an unknown name, a value of the wrong type */
    PVATT_INTERRUPTED = 3,      /* pvatt_interrupt() (or SIGINT under pvatt_catch_sigint) stopped it */
    PVATT_CALLBACK_FAILED = 4,  /* a callback component returned non-zero */
    PVATT_BUFFER_TOO_SMALL = 5, /* a caller's buffer cannot hold what was asked */
    PVATT_WRONG_STATE = 6       /* e.g. advancing a finished simulation, or backwards in time */
} pvatt_status;

typedef struct pvatt_system pvatt_system;         /* a system description with its FMUs loaded */
typedef struct pvatt_simulation pvatt_simulation; /* a run being stepped */
typedef struct pvatt_result pvatt_result;         /* sampled columns of a finished (or paused) run */

/* Library facts and errors. */
PVATT_API int pvatt_api_version(void);
PVATT_API const char* pvatt_last_error(void); /* "" when nothing failed yet in this thread */

/* Interrupt: a process-wide flag checked by a running simulation between integrator steps, at every
 * event and at every output point; the run then returns PVATT_INTERRUPTED with its rows so far kept.
 * Safe to call from a signal handler or another thread. Every run and advance clears it when it starts. */
PVATT_API void pvatt_interrupt(void);
/* While enabled (non-zero), SIGINT sets the interrupt flag instead of its previous action, for the
 * duration of each blocking call (pvatt_run, pvatt_advance_to); the previous action is restored after.
 * Off by default. */
PVATT_API void pvatt_catch_sigint(int enable);

/* ---- Systems ---- */

/* Opens an .ssd, an .ssp archive, or a single .fmu (then one component named after the FMU's model).
 * fmu_dirs: a list of folders searched for FMUs not found beside the .ssd (NULL when none). */
PVATT_API pvatt_status pvatt_system_open(const char* path, const char* const* fmu_dirs, size_t fmu_dir_count,
                                         pvatt_system** out);
PVATT_API void pvatt_system_close(pvatt_system* system); /* NULL is fine */

/* The description's DefaultExperiment stop time and the default output interval of a run to it;
 * NaN where the description gives none. */
PVATT_API double pvatt_system_default_stop_time(const pvatt_system* system);
PVATT_API double pvatt_system_default_output_interval(const pvatt_system* system, double stop_time);

PVATT_API size_t pvatt_system_component_count(const pvatt_system* system);
PVATT_API const char* pvatt_system_component_name(const pvatt_system* system, size_t component);
PVATT_API size_t pvatt_system_variable_count(const pvatt_system* system, size_t component);

typedef struct pvatt_variable_info {
    const char* name;        /* "q_est[1]" */
    const char* type;        /* "Real", "Integer", "Boolean", "String", "Enumeration" */
    const char* causality;   /* "parameter", "calculatedParameter", "input", "output", "local", "independent" */
    const char* variability; /* "constant", "fixed", "tunable", "discrete", "continuous" */
    const char* unit;        /* "" when none */
    const char* description;
    const char* start;        /* the start value as written, "" when none */
    const char* const* items; /* Enumeration: the item names, item_count of them; NULL otherwise */
    size_t item_count;
    const int* item_values; /* their numbers */
    unsigned int value_reference;
} pvatt_variable_info;

PVATT_API pvatt_status pvatt_system_variable(const pvatt_system* system, size_t component, size_t variable,
                                             pvatt_variable_info* out);

/* A value set before every later run (as `cosim run --set`): "comp.var" and its value as text. Checked
 * against the variable's type at once. Replaces an earlier setting of the same variable. */
PVATT_API pvatt_status pvatt_system_set(pvatt_system* system, const char* name, const char* value);
/* The value set (or, when none, the start value) as text into a caller's buffer of `size` bytes.
 * *needed (if not NULL) gets the size needed with the terminating zero. */
PVATT_API pvatt_status pvatt_system_get(const pvatt_system* system, const char* name, char* buffer, size_t size,
                                        size_t* needed);
PVATT_API void pvatt_system_clear_settings(pvatt_system* system);

/* The system's own parameters (an .ssd's system-level parameter connectors: the date at t = 0, the orbit's
 * elements, ...), each feeding component parameters. pvatt_system_set and pvatt_system_get take their
 * names without a component ("epoch_month", "tle_elements[2]"). */
PVATT_API size_t pvatt_system_parameter_count(const pvatt_system* system);
PVATT_API const char* pvatt_system_parameter_name(const pvatt_system* system, size_t parameter); /* NULL past the end */
/* Every value of an SSP parameter set file (.ssv: system parameters and "comp.var"), as pvatt_system_set
 * would set each in the file's order (so a later pvatt_system_set or file wins). All checked before any is
 * taken: a malformed file, an unknown name or a value of the wrong type is refused with the file, line and
 * name, and nothing changes. */
PVATT_API pvatt_status pvatt_system_load_parameters(pvatt_system* system, const char* path);

/* A callback component: replaces component `component` of the system (its FMU's interface stays: the
 * same variables, connections and units; its binary is not run) by a function sampled every
 * `sample_period` seconds from the start, as the hardware bridge puts a board in place of a block.
 * At each sample instant t it gets the component's inputs (its variables of causality input, in
 * model-description order, as doubles) and writes its outputs (causality output, same order); the
 * outputs hold between samples. A non-zero return stops the run with PVATT_CALLBACK_FAILED. An output
 * its variable cannot hold (a Boolean other than 0 or 1, an Integer that is not a whole 32-bit number,
 * an Enumeration that is no item, a Real that is not finite, anything outside min/max) stops the run
 * with PVATT_ERROR naming the variable and the time: never rounded. What the callback may call is said
 * at the top of this header (Re-entrancy). Pass callback NULL to restore the FMU. A run or simulation
 * started before a replace keeps calling the function it started with: keep it (and user_data) valid
 * until that run ends. */
typedef int (*pvatt_step_callback)(void* user_data, double time, const double* inputs, size_t input_count,
                                   double* outputs, size_t output_count);
PVATT_API pvatt_status pvatt_system_replace(pvatt_system* system, const char* component, double sample_period,
                                            pvatt_step_callback callback, void* user_data);
/* Order at an instant where several components sample: each is called once per round of the master's event
 * iteration, in the system's order, with values passed on between rounds; a callback's one call sees its
 * inputs as they were just before the instant (a sampled source's previous output). With current_inputs
 * non-zero the replaced component's callback is called again at the same instant whenever its inputs
 * changed after its last call there, so that its last call sees the instant's final inputs (a sensor that
 * must follow a command issued at this instant). Call after pvatt_system_replace; 0 restores one call. */
PVATT_API pvatt_status pvatt_system_replace_current_inputs(pvatt_system* system, const char* component,
                                                           int current_inputs);

/* ---- Runs ---- */

typedef struct pvatt_run_options {
    double stop_time;       /* NaN: the description's stop time */
    double output_interval; /* NaN: as `cosim run` chooses (the .ssd's, else the FMUs' step, else span/1000) */
    int reference;          /* non-zero: the reference execution (`cosim run --reference`) */
} pvatt_run_options;

/* Fills the options with NaN / 0 (the defaults). */
PVATT_API void pvatt_run_options_init(pvatt_run_options* options);

/* Runs from the start to the stop time, sampling the columns (names "comp.var"; NULL / 0: every
 * output of every component, as `cosim run`) at the output points, exactly the rows `cosim run`
 * writes. On PVATT_INTERRUPTED or an error after the start, *out (if the run started) holds the rows
 * computed so far; otherwise *out is NULL. Free it with pvatt_result_free. */
PVATT_API pvatt_status pvatt_run(pvatt_system* system, const pvatt_run_options* options, const char* const* columns,
                                 size_t column_count, pvatt_result** out);

/* ---- Results: a rows x columns table of doubles, row-major, column 0 is time ---- */
PVATT_API size_t pvatt_result_rows(const pvatt_result* result);
PVATT_API size_t pvatt_result_columns(const pvatt_result* result); /* time included */
PVATT_API const char* pvatt_result_column_name(const pvatt_result* result, size_t column);
/* The table itself (rows * columns doubles, row-major), owned by the result: read it in place. */
PVATT_API const double* pvatt_result_data(const pvatt_result* result);
/* One column copied into a caller's buffer of `size` doubles (at least the row count). */
PVATT_API pvatt_status pvatt_result_read_column(const pvatt_result* result, size_t column, double* buffer, size_t size);
PVATT_API void pvatt_result_free(pvatt_result* result); /* NULL is fine */
/* What the run reached, computed from the result's columns as `cosim run` and `cosim plot` compute it (the
 * attitude error of each estimate sunlit / in eclipse, after convergence, the filter's NEES/dof and chi2(3)
 * 99 % coverage, when it was first valid, the faults declared): as JSON (as_text 0) or as the lines `cosim
 * run` prints (as_text 1), copied into buffer as pvatt_system_get does. converged_after: where "after
 * convergence" starts (s), NaN for the default (the filter valid with the calibration applied). */
PVATT_API pvatt_status pvatt_result_measures(const pvatt_result* result, double converged_after, int as_text,
                                             char* buffer, size_t size, size_t* needed);

/* ---- Stepping ---- */

/* Initializes a run to options->stop_time (required finite here or in the description) and stops
 * at its start. Output points are every options->output_interval; pvatt_advance_to goes to any of
 * them. The system must outlive the simulation. */
PVATT_API pvatt_status pvatt_start(pvatt_system* system, const pvatt_run_options* options, const char* const* columns,
                                   size_t column_count, pvatt_simulation** out);
/* Runs on to time t (rounded to the nearest output point; at most the stop time) and pauses there. */
PVATT_API pvatt_status pvatt_advance_to(pvatt_simulation* simulation, double t);
PVATT_API double pvatt_simulation_time(const pvatt_simulation* simulation);
PVATT_API int pvatt_simulation_finished(const pvatt_simulation* simulation);
/* Values at the paused instant (as text: an Enumeration by its item name). Setting takes effect from there on: an input not fed by a connection,
 * or a tunable parameter (of a Model Exchange FMU only a continuous input: it is paused in Continuous-Time
 * Mode); a connected input is overwritten by its source at the next step. A set of
 * anything else (an output, a fixed parameter), or of a value outside the variable's type and range (NaN,
 * an Integer that is not whole, a number outside min/max), is refused with PVATT_INVALID_ARGUMENT before
 * the FMU sees it: the simulation can still advance. */
PVATT_API pvatt_status pvatt_simulation_get_real(pvatt_simulation* simulation, const char* name, double* value);
PVATT_API pvatt_status pvatt_simulation_set_real(pvatt_simulation* simulation, const char* name, double value);
PVATT_API pvatt_status pvatt_simulation_get_text(pvatt_simulation* simulation, const char* name, char* buffer,
                                                 size_t size, size_t* needed);
PVATT_API pvatt_status pvatt_simulation_set_text(pvatt_simulation* simulation, const char* name, const char* value);
/* The rows sampled so far (a copy; free it with pvatt_result_free). */
PVATT_API pvatt_status pvatt_simulation_result(const pvatt_simulation* simulation, pvatt_result** out);
/* Ends the run (terminating its components) and frees it; NULL is fine. */
PVATT_API void pvatt_simulation_free(pvatt_simulation* simulation);

/* ---- Campaigns (harness/campaign/README.md: a TOML spec of draws and metrics over many runs) ---- */

typedef struct pvatt_campaign_options {
    long runs;              /* <= 0: the spec's */
    double stop_time;       /* NaN: the spec's */
    const char* output_dir; /* NULL: the spec's */
    int resume;             /* non-zero: keep the rows of an earlier, unfinished campaign in output_dir */
} pvatt_campaign_options;

PVATT_API void pvatt_campaign_options_init(pvatt_campaign_options* options); /* the spec's values */

/* Runs a campaign in this process, its runs one after the other, with the settings ("comp.var=value",
 * after the spec's [set]) and FMU folders given; writes the path of its results table (results.csv in
 * the output folder, one row per run, as `cosim campaign SPEC` writes it; no summary nor figures) into
 * the caller's buffer. Failed runs are rows of the table, not errors. */
PVATT_API pvatt_status pvatt_campaign_run(const char* spec, const pvatt_campaign_options* options,
                                          const char* const* settings, size_t setting_count,
                                          const char* const* fmu_dirs, size_t fmu_dir_count, char* table_path,
                                          size_t size, size_t* needed);

/* A campaign's aims (the [[aim]] entries of its spec: "error_sunlit.p95 < 1" and the like), judged from its
 * results table (results.csv as pvatt_campaign_run or `cosim campaign` wrote it) as `cosim campaign` ends:
 * per aim the runs that meet it and the runs that miss it, how many runs meet every aim, and every aim per
 * kind of scene (an orbit draw's class, a choice of names, a case). As JSON (as_text 0; the keys in
 * harness/campaign/src/aims.hpp, aims_json) or as the command's lines (as_text 1; empty for a spec without
 * aims), copied into buffer as pvatt_system_get does. Only the spec is read, no FMU. Refused: a table that
 * is not a whole campaign table (a last row without its line end: still running), larger than 1 GiB, or
 * without a column an aim judges (another spec's). */
PVATT_API pvatt_status pvatt_campaign_aims(const char* spec, const char* table, int as_text, char* buffer, size_t size,
                                           size_t* needed);

#ifdef __cplusplus
}
#endif

#endif /* PVATT_COSIM_H */
