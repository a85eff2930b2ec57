// A detection metric's arithmetic, apart from the system that feeds it (so that the tests can feed it a
// table by hand): fault words read at every output point, each element's declarations (a word turning
// nonzero, at the time its time column gives), and per run what they say against the fault the run's
// case injected — detected, time to detect, isolated right, declarations counted as false alarms.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace campaign {

struct DetectionOutcome {
    double detected = 0.0;  // 1 when anything was declared at or after the onset (or in the whole window)
    double time = 0.0;      // first declaration at or after the onset minus the onset (s); NaN: none, or no onset
    double isolated = 0.0;  // 1 when the elements declared at or after the onset are exactly the expected ones
    double declared = 0.0;  // declarations at or after the onset (without onset: from the window's start)
    double before = 0.0;    // declarations before the onset (false alarms of a faulty run)
    double orbits = 0.0;    // the span the declarations were counted over, in periods
    std::string which;      // "element=word" of each declaration counted in `declared`, by time, space-separated
    // With an observable time (the first output point from the onset on where the case's fault could be seen):
    // that time minus the onset, and the first declaration from the onset on minus it (negative: declared
    // before the condition held). NaN without one.
    double observable = 0.0;
    double time_observable = 0.0;
};

class DetectionTracker {
public:
    // `elements`: the names of the fault words in reading order ("est.fault_face[1]", ...).
    explicit DetectionTracker(std::vector<std::string> elements);
    // One output point: each element's word and its declaration time (NaN or negative: take t).
    void sample(double t, const std::vector<double>& words, const std::vector<double>& times);
    // `expected`: indices into `elements`; `after`: declarations before it are ignored (a transient);
    // `period`: the rate's unit (s).
    DetectionOutcome outcome(std::optional<double> onset, const std::vector<std::size_t>& expected, double after,
                             double period, std::optional<double> observable = std::nullopt) const;

private:
    struct Declaration {
        std::size_t element;
        double time, word;
    };
    std::vector<std::string> elements_;
    std::vector<double> last_;       // each element's word at the previous output point
    std::vector<std::size_t> open_;  // each element's declaration while its word is nonzero
    std::vector<Declaration> declarations_;
    std::optional<double> first_t_, last_t_;
};

}  // namespace campaign
