// What a run reached (analysis/run_measures.hpp) for a result of the C API: the same numbers and text as
// the end of `cosim run` and `cosim plot`'s page, from the one definition (pvatt.analysis calls this).
#include <cmath>
#include <sstream>

#include "analysis/run_measures.hpp"
#include "capi_error.hpp"
#include "capi_handles.hpp"
#include "pvatt/cosim.h"

using namespace pvatt_capi;

pvatt_status pvatt_result_measures(const pvatt_result* result, double converged_after, int as_text, char* buffer,
                                   size_t size, size_t* needed) {
    return guarded([&] {
        required(result, "result");
        cosim::CsvTable table;
        table.names = result->names;
        const std::size_t n = result->rows(), columns = result->names.size();
        table.columns.assign(columns, std::vector<double>(n));
        for (std::size_t r = 0; r < n; ++r)
            for (std::size_t c = 0; c < columns; ++c) table.columns[c][r] = result->data[r * columns + c];
        analysis::MeasureOptions options;
        if (!std::isnan(converged_after)) {
            if (!std::isfinite(converged_after))
                throw InvalidArgument("converged_after must be finite or NaN (none), got " +
                                      std::to_string(converged_after));
            options.converged_after = converged_after;
        }
        const analysis::RunMeasures m = analysis::measure_run(table, options);
        std::string text;
        if (as_text) {
            std::ostringstream out;
            analysis::print_measures(m, out);
            text = out.str();
        } else {
            text = analysis::measures_json(m);
        }
        copy_text(text, buffer, size, needed);
    });
}
