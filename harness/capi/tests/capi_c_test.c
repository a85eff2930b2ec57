/* The C API from C (compiled as C11): the header is plain C, a lone FMU opens, runs and reports
 * errors. Exit code 0 on success; prints what failed otherwise. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pvatt/cosim.h"

static int failures = 0;

#define CHECK(condition)                                                                                    \
    do {                                                                                                    \
        if (!(condition)) {                                                                                 \
            fprintf(stderr, "%s:%d: %s failed (%s)\n", __FILE__, __LINE__, #condition, pvatt_last_error()); \
            ++failures;                                                                                     \
        }                                                                                                   \
    } while (0)

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s test_gain.fmu\n", argv[0]);
        return 2;
    }
    CHECK(pvatt_api_version() == PVATT_API_VERSION);
    pvatt_system* system = NULL;
    CHECK(pvatt_system_open(argv[1], NULL, 0, &system) == PVATT_OK);
    if (!system) return 1;
    CHECK(pvatt_system_component_count(system) == 1);
    CHECK(strcmp(pvatt_system_component_name(system, 0), "test_gain") == 0);

    CHECK(pvatt_system_set(system, "test_gain.k", "2.5") == PVATT_OK);
    CHECK(pvatt_system_set(system, "test_gain.u", "4") == PVATT_OK);
    CHECK(pvatt_system_set(system, "test_gain.k", "two") == PVATT_INVALID_ARGUMENT);
    CHECK(strstr(pvatt_last_error(), "two") != NULL);

    pvatt_run_options options;
    pvatt_run_options_init(&options);
    CHECK(isnan(options.stop_time));
    options.stop_time = 1.0;
    options.output_interval = 0.5;
    const char* columns[] = {"test_gain.y"};
    pvatt_result* result = NULL;
    CHECK(pvatt_run(system, &options, columns, 1, &result) == PVATT_OK);
    if (result) {
        double y[3] = {0, 0, 0};
        CHECK(pvatt_result_rows(result) == 3);
        CHECK(strcmp(pvatt_result_column_name(result, 1), "test_gain.y") == 0);
        CHECK(pvatt_result_read_column(result, 1, y, 3) == PVATT_OK);
        CHECK(y[0] == 10.0 && y[2] == 10.0); /* y = k u */
    }
    pvatt_result_free(result);

    const char* unknown[] = {"test_gain.nothing"};
    result = NULL;
    CHECK(pvatt_run(system, &options, unknown, 1, &result) == PVATT_INVALID_ARGUMENT);
    CHECK(strstr(pvatt_last_error(), "nothing") != NULL);
    CHECK(result == NULL); /* no table for a column that does not exist */
    pvatt_result_free(result);
    pvatt_system_close(system);
    if (failures == 0) printf("capi_c_test: all checks passed\n");
    return failures == 0 ? 0 : 1;
}
