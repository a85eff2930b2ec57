#pragma once
// The definitions of frames.hpp's templates. Included by frames.hpp.

namespace orbit {

namespace frames_detail {
template <typename T>
constexpr T arcsec = static_cast<T>(3.14159265358979323846 / (180.0 * 3600.0));
template <typename T>
constexpr T two_pi = static_cast<T>(6.283185307179586476925286766559);

// Passive (frame) rotations about x, y, z.
template <typename T>
Matrix3<T> r1(T a) noexcept {
    const T c = std::cos(a), s = std::sin(a);
    Matrix3<T> m;
    m << T(1), T(0), T(0), T(0), c, s, T(0), -s, c;
    return m;
}
template <typename T>
Matrix3<T> r2(T a) noexcept {
    const T c = std::cos(a), s = std::sin(a);
    Matrix3<T> m;
    m << c, T(0), -s, T(0), T(1), T(0), s, T(0), c;
    return m;
}
template <typename T>
Matrix3<T> r3(T a) noexcept {
    const T c = std::cos(a), s = std::sin(a);
    Matrix3<T> m;
    m << c, s, T(0), -s, c, T(0), T(0), T(0), T(1);
    return m;
}

// A Delaunay argument: arcseconds polynomial plus whole revolutions per century, reduced to one turn
// before the sum so that float keeps its precision (the revolutions term alone is 8e3 rad per century).
template <typename T>
T delaunay(T t, T c0, T c1, T c2, T c3, T turns_per_century) noexcept {
    const T poly = ((c3 * t + c2) * t + c1) * t + c0;
    const T turns = std::fmod(turns_per_century * t, T(1));
    return std::fmod(poly * arcsec<T>, two_pi<T>) + turns * two_pi<T>;
}
}  // namespace frames_detail

template <typename T>
Vector3<T> precession_angles_iau1976(T t) noexcept {
    // Lieske et al. (1977), arcseconds, T in Julian centuries from J2000.
    const T zeta = ((T(0.017998) * t + T(0.30188)) * t + T(2306.2181)) * t;
    const T z = ((T(0.018203) * t + T(1.09468)) * t + T(2306.2181)) * t;
    const T theta = ((-T(0.041833) * t - T(0.42665)) * t + T(2004.3109)) * t;
    return Vector3<T>(zeta, z, theta) * frames_detail::arcsec<T>;
}

template <typename T>
Matrix3<T> mod_from_j2000(T t) noexcept {
    using namespace frames_detail;
    const Vector3<T> a = precession_angles_iau1976(t);
    return r3(-a.y()) * r2(a.z()) * r3(-a.x());
}

template <typename T>
Nutation<T> nutation_iau1980(T t, int terms) noexcept {
    using namespace frames_detail;
    // Fundamental arguments of the 1980 theory (Seidelmann 1982): arcseconds and revolutions per century.
    const T l = delaunay<T>(t, 485866.733, 715922.633, 31.310, 0.064, 1325.0);
    const T lp = delaunay<T>(t, 1287099.804, 1292581.224, -0.577, -0.012, 99.0);
    const T f = delaunay<T>(t, 335778.877, 295263.137, -13.257, 0.011, 1342.0);
    const T d = delaunay<T>(t, 1072261.307, 1105601.328, -6.891, 0.019, 1236.0);
    const T om = delaunay<T>(t, 450160.280, -482890.539, 7.455, 0.008, -5.0);
    const int n = std::clamp(terms, 1, kIau1980NutationTerms);
    // Smallest terms first, so that the sum loses the least to rounding.
    T dpsi = T(0);
    T deps = T(0);
    for (int i = n - 1; i >= 0; --i) {
        const Iau1980NutationTerm<T>& k = kIau1980NutationAs<T>[static_cast<std::size_t>(i)];
        const T arg = static_cast<T>(k.l) * l + static_cast<T>(k.lp) * lp + static_cast<T>(k.f) * f +
                      static_cast<T>(k.d) * d + static_cast<T>(k.om) * om;
        dpsi += (k.a + k.b * t) * std::sin(arg);
        deps += (k.c + k.dt * t) * std::cos(arg);
    }
    Nutation<T> out;
    out.dpsi = dpsi * T(1.0e-4) * arcsec<T>;
    out.deps = deps * T(1.0e-4) * arcsec<T>;
    // IAU 1980 mean obliquity (Lieske et al. 1977).
    out.mean_obliquity = (((T(0.001813) * t - T(0.00059)) * t - T(46.8150)) * t + T(84381.448)) * arcsec<T>;
    return out;
}

template <typename T>
Matrix3<T> tod_from_mod(const Nutation<T>& n) noexcept {
    using namespace frames_detail;
    return r1(-(n.mean_obliquity + n.deps)) * r3(-n.dpsi) * r1(n.mean_obliquity);
}

template <typename T>
T equation_of_equinoxes(const Nutation<T>& n) noexcept {
    return n.dpsi * std::cos(n.mean_obliquity);
}

template <typename T>
Matrix3<T> j2000_from_teme(T t, int nutation_terms) noexcept {
    using namespace frames_detail;
    const Nutation<T> n = nutation_iau1980(t, nutation_terms);
    const Matrix3<T> tod_from_teme = r3(-equation_of_equinoxes(n));
    return mod_from_j2000(t).transpose() * tod_from_mod(n).transpose() * tod_from_teme;
}

template <typename T>
OrbitState<T> teme_to_j2000(const OrbitState<T>& teme, T t, int nutation_terms) noexcept {
    const Matrix3<T> m = j2000_from_teme(t, nutation_terms);
    OrbitState<T> out;
    out.position_km = m * teme.position_km;
    out.velocity_km_s = m * teme.velocity_km_s;
    return out;
}

}  // namespace orbit
