// The core must not touch the heap at run time (it is meant for a DSP without one). The C allocator is
// replaced in this test program by counting wrappers (malloc_counter.hpp); every solver and one
// whole sample, in float and double, must make zero calls. Skipped under AddressSanitizer, which owns
// malloc itself.
#include <atomic>
#include <cstddef>

#include "attitude_estimator/estimator.hpp"
#include "attitude_estimator/fast_solver.hpp"
#include "attitude_estimator/mekf.hpp"
#include "attitude_estimator/q_method.hpp"
#include "test_support.hpp"

#include "malloc_counter.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreNoAllocation : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreNoAllocation, Scalars, ScalarName);

TYPED_TEST(EstimatorCoreNoAllocation, SolversSunMethodsWholeSampleAndFilterNeverCallMalloc) {
    using T = TypeParam;
    // Inputs prepared before counting starts.
    ObservationSet<T> two, six;
    Random rng(41);
    const Eigen::Matrix3d a = rng.rotation();
    for (int i = 0; i < 6; ++i) {
        const Eigen::Vector3d v = rng.unit();
        if (i < 2) two.add(to_vec<T>(v), to_vec<T>(a * v), T(1));
        six.add(to_vec<T>(v), to_vec<T>(a * v), T(1));
    }
    SampleInputs<T> in;
    in.i_sh = {T(0.6), T(0.0), T(0.8)};
    in.v_mag = {T(2.8), T(2.4), T(2.6)};
    in.sun_ref = {T(1), T(0), T(0)};
    in.mag_ref = {T(0), T(1), T(0)};
    EstimatorConfig<T> fast_config;
    fast_config.solver = SolverKind::fast;
    const EstimatorConfig<T> q_config;  // the default: the Q-method
    // Every face-based sun method, with the Kelly table (the inverse response iterates), on three lit faces
    // and an albedo-lit fourth.
    in.i_face = {T(0.5), T(0.1), T(0.0), T(0.3), T(0.6), T(0.0)};
    std::array<EstimatorConfig<T>, 3> face_configs;
    const SunMethod face_methods[] = {SunMethod::inverse_response, SunMethod::cones, SunMethod::three_faces};
    for (std::size_t m = 0; m < face_configs.size(); ++m) {
        face_configs[m].sun.method = face_methods[m];
        face_configs[m].sun.response = panel_response::kelly<T>();
    }
    SunMethodState<T> sun_state;
    // The filter with every state and Euler propagation: initialisation, propagation, all three updates.
    MekfConfig<T> filter_config;
    filter_config.estimate_scale = true;
    filter_config.inertia = {T(3.2), T(0.05), T(-0.02), T(0.05), T(2.9), T(0.03), T(-0.02), T(0.03), T(3.6)};
    const panel_response::Response<T> kelly = panel_response::kelly<T>();
    MekfSampleInputs<T> filter_in;
    filter_in.attitude_valid = filter_in.sun_valid = filter_in.mag_valid = true;
    filter_in.sun_ref = {T(1), T(0), T(0)};
    filter_in.sun_body = {T(0.6), T(0.0), T(0.8)};
    filter_in.mag_ref = {T(0), T(30e-6), T(0)};
    filter_in.mag_body = {T(0), T(30e-6), T(0)};
    filter_in.face_r = {T(0.6), T(0), T(0), T(0), T(0.8), T(0)};
    filter_in.face_use = 0x11;
    filter_in.response = &kelly;
    MekfState<T> filter_state;
    // Sanity: the counter does count (a malloc made here must register).
    const long before_probe = allocation_count();
    void* volatile probe = std::malloc(16);  // volatile: a malloc/free pair left unused may be elided
    ASSERT_GT(allocation_count(), before_probe);
    std::free(probe);

    const long before = allocation_count();
    T sink = T(0);
    for (int k = 0; k < 100; ++k) {
        sink += solve_q_method(two).loss + solve_q_method(six).loss + solve_fast(two).loss + solve_fast(six).loss;
        sink += estimate_sample(in, fast_config).loss + estimate_sample(in, q_config).loss;
        for (const auto& c : face_configs) sink += estimate_sample(in, c, sun_state).sun_norm;
        filter_in.t = T(0.05) * static_cast<T>(k);
        sink += mekf_sample(filter_state, filter_in, filter_config).bound;
    }
    const long after = allocation_count();
    EXPECT_EQ(after - before, 0) << "heap allocations in the core";
    EXPECT_TRUE(std::isfinite(static_cast<double>(sink)));
}

}  // namespace
}  // namespace attitude_estimator::test
