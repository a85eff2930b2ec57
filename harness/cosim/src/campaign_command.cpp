#include "campaign_command.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "aims.hpp"
#include "campaign_error.hpp"
#include "campaign_identity.hpp"
#include "campaign_run.hpp"
#include "collector.hpp"
#include "drivers.hpp"
#include "engine/interrupt.hpp"
#include "engine/output_file.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/system_description.hpp"
#include "mpi_session.hpp"
#include "results_table.hpp"
#include "summary.hpp"

namespace campaign {

namespace {

// An advisory lock (flock) on the campaign's output folder, held while the campaign writes its table: a
// second campaign (a --resume started while the first runs) on the same folder is refused instead of
// interleaving its rows. The folder, not results.csv, is locked: the table is replaced by its sorted copy.
class FolderLock {
public:
    explicit FolderLock(const std::filesystem::path& folder) {
        fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd_ < 0) throw CampaignError("cannot open " + folder.string() + ": " + std::strerror(errno));
        if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            ::close(fd_);
            throw CampaignError(folder.string() + (error == EWOULDBLOCK
                                                       ? " is in use by another campaign (its lock is held): wait "
                                                         "for it to end, or give another --output"
                                                       : ": cannot lock: " + std::string(std::strerror(error))));
        }
    }
    ~FolderLock() { ::close(fd_); }
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int fd_ = -1;
};

// Nothing the campaign writes in its folder may be one of the files it reads (the spec, the system,
// its FMUs and parameter files): `--output .` beside a spec named results.csv, a system named summary.md.
void refuse_overwriting_inputs(const CampaignSetup& setup, const std::vector<std::filesystem::path>& outputs) {
    std::vector<std::filesystem::path> inputs{setup.spec.file};
    const auto more = cosim::system_inputs(setup.description, setup.options.fmu_dirs);
    inputs.insert(inputs.end(), more.begin(), more.end());
    for (const auto& output : outputs) cosim::refuse_overwriting_inputs("--output", output, inputs);
}

CampaignSetup setup_from(const CampaignOptions& options) {
    CampaignSpec spec = read_spec(options.spec);
    if (options.runs) {
        if (*options.runs < 1 || *options.runs > max_runs)
            throw CampaignError("--runs must be from 1 to " + std::to_string(max_runs));
        spec.runs = *options.runs;
    }
    if (options.stop_time) spec.stop_time = options.stop_time;
    if (options.output) spec.output = *options.output;
    return prepare(std::move(spec), options.fmu_dirs, options.settings);
}

int replay(const CampaignSetup& setup, long index, std::ostream& out) {
    if (index < 0 || index >= setup.spec.runs)
        throw CampaignError("--run " + std::to_string(index) + ": the campaign has runs 0 to " +
                            std::to_string(setup.spec.runs - 1));
    std::filesystem::create_directories(setup.spec.output);
    const auto csv = setup.spec.output / ("run_" + std::to_string(index) + ".csv");
    const auto row_file = setup.spec.output / ("run_" + std::to_string(index) + ".row.csv");
    refuse_overwriting_inputs(setup, {csv, row_file});
    const RunResult r = run_one(setup, index, csv);
    std::filesystem::remove(row_file);
    ResultsWriter(row_file, table_header(setup.spec), false).append(format_row(r));
    out << "run " << index << ": " << r.status << (r.message.empty() ? "" : ": " + r.message) << "\n";
    const auto header = table_header(setup.spec);
    const auto cells = split_csv_line(format_row(r));
    for (std::size_t i = 1; i + trailing_columns < header.size(); ++i)
        out << "  " << header[i] << " = " << cells[i] << "\n";
    out << "full CSV: " << csv.string() << "\nits row: " << row_file.string() << "\n";
    return r.status == "failed" ? 1 : 0;  // a replayed failure is a failure of the command
}

int campaign_on_rank0(const CampaignSetup& setup, const CampaignOptions& options, int ranks, std::ostream& out) {
    const auto& spec = setup.spec;
    std::filesystem::create_directories(spec.output);
    const FolderLock lock(spec.output);
    const auto table_file = spec.output / "results.csv";
    refuse_overwriting_inputs(setup, {table_file, spec.output / "campaign.txt", spec.output / "summary.md"});
    const auto header = table_header(spec);
    std::map<long, std::string> rows;
    const bool append = options.resume && std::filesystem::exists(table_file);
    if (!append && std::filesystem::exists(table_file))
        throw CampaignError(table_file.string() +
                            " exists: give --resume to continue that campaign, or another --output");
    record_identity(spec.output, campaign_identity(setup), append);
    if (append) rows = read_results(table_file, header, spec.runs);
    ResultsWriter writer(table_file, header, append);
    RunQueue to_do(spec.runs, rows);
    if (append)
        out << "resuming: " << rows.size() << " runs in " << table_file.string() << ", " << to_do.size() << " to do\n";

    Progress progress = Progress::none;
    if (options.progress && isatty(fileno(stderr)))
        progress = Progress::terminal;
    else if (options.progress && options.progress_lines)
        progress = Progress::log;
    Collector collector(writer, rows, to_do.size(), ranks, progress);
#ifdef PVATT_MPI
    if (ranks > 1)
        run_distributed(setup, to_do, collector, ranks);
    else
        run_sequential(setup, to_do, collector);
#else
    run_sequential(setup, to_do, collector);
#endif
    const CampaignStatistics stats = collector.finish();
    write_sorted(table_file, header, rows);

    const ResultRows table = split_rows(header, rows);
    std::vector<std::filesystem::path> figures;
    std::string note;
    if (options.figures) {
        try {
            figures = draw_figures(spec.output, spec, table);
            if (figures.empty()) note = "no figures: no angle metric has a value in a finished run";
        } catch (const CampaignError& e) {
            note = std::string("figures not drawn: ") + e.what();
            std::cerr << "cosim campaign: " << note << "\n";
        }
    } else {
        note = "figures not drawn (--no-figures)";
    }
    write_summary(spec.output / "summary.md", setup, table, stats, figures, note);
    print_statistics(stats, out);
    print_measures_over_runs(spec, table, out);
    print_aims(spec, judge_aims(spec, table), judge_aims_by_category(spec, table), out);
    out << "results: " << table_file.string() << "\nsummary: " << (spec.output / "summary.md").string() << "\n";
    return 0;
}

}  // namespace

int run_campaign(const CampaignOptions& options, std::ostream& out) {
    MpiSession mpi;
    if (mpi.size() == 1) {
        const CampaignSetup setup = setup_from(options);
        return options.replay ? replay(setup, *options.replay, out) : campaign_on_rank0(setup, options, 1, out);
    }
    // Several ranks: an error on any rank ends the whole job, since the others would wait for it forever.
    try {
        const CampaignSetup setup = setup_from(options);
        if (options.replay) return mpi.rank() == 0 ? replay(setup, *options.replay, out) : 0;
#ifdef PVATT_MPI
        if (mpi.rank() != 0) {
            serve_as_worker(setup);
            return 0;
        }
#endif
        return campaign_on_rank0(setup, options, mpi.size(), out);
    } catch (const std::exception& e) {
        std::cerr << "cosim campaign (rank " << mpi.rank() << "): " << e.what() << "\n";
        // A signal ends the job as it ends a single process: 128 + signal.
        mpi.abort(cosim::interrupt_signal() ? 128 + cosim::interrupt_signal() : 1);
    }
}

}  // namespace campaign
