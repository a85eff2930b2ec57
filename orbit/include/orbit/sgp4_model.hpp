#pragma once
// The definitions of sgp4.hpp's Sgp4<T>: the near-Earth branch of the reference code's sgp4init (with
// initl) and sgp4 (Vallado et al. 2006, AIAA 2006-6753), in its order of operations so that double
// precision reproduces it to rounding. Variable names follow the reference code. Included by sgp4.hpp.

namespace orbit {

inline const char* describe(Sgp4Status status) noexcept {
    switch (status) {
        case Sgp4Status::ok:
            return "ok";
        case Sgp4Status::mean_eccentricity:
            return "SGP4: mean eccentricity out of [-0.001, 1)";
        case Sgp4Status::mean_motion:
            return "SGP4: mean motion <= 0";
        case Sgp4Status::perturbed_eccentricity:
            return "SGP4: perturbed eccentricity out of [0, 1]";
        case Sgp4Status::semi_latus_rectum:
            return "SGP4: semi-latus rectum < 0";
        case Sgp4Status::decayed:
            return "SGP4: the satellite has decayed (radius below the Earth's)";
        case Sgp4Status::deep_space:
            return "SGP4: period >= 225 min is a deep-space element set, which needs SDP4 (not implemented)";
    }
    return "SGP4: unknown status";
}

namespace sgp4_detail {
// Newton's square root, for constants (std::sqrt is not constexpr in C++20).
constexpr double constexpr_sqrt(double x) noexcept {
    double r = x > 1.0 ? x : 1.0;
    for (int i = 0; i < 100; ++i) r = 0.5 * (r + x / r);
    return r;
}
// Derived WGS-72 constants in the reference code's canonical units (Earth radii, minutes).
template <typename T>
struct Constants {
    static constexpr T radius = static_cast<T>(Wgs72::earth_radius_km);
    static constexpr T j2 = static_cast<T>(Wgs72::j2);
    static constexpr T j4 = static_cast<T>(Wgs72::j4);
    static constexpr T j3oj2 = static_cast<T>(Wgs72::j3 / Wgs72::j2);
    static constexpr T two_pi = static_cast<T>(6.283185307179586476925286766559);
    static constexpr T x2o3 = static_cast<T>(2.0) / static_cast<T>(3.0);
    // xke = 60 / sqrt(R^3 / mu), (Earth radii)^1.5 per minute, folded at compile time so that a float build
    // does no double arithmetic (a Cortex-M4F has no double FPU).
    static constexpr T xke = static_cast<T>(60.0 / constexpr_sqrt(Wgs72::earth_radius_km * Wgs72::earth_radius_km *
                                                                  Wgs72::earth_radius_km / Wgs72::mu_km3_s2));
    // Kepler's equation: the reference code stops at 1e-12 rad; a float cannot resolve that, so it stops at
    // a few of its own ulps (the loop is capped at 10 iterations either way).
    static constexpr T kepler_tolerance = std::is_same_v<T, float> ? static_cast<T>(1e-6) : static_cast<T>(1e-12);
};
}  // namespace sgp4_detail

template <typename T>
Sgp4Status Sgp4<T>::initialize(const MeanElements<T>& el) noexcept {
    using C = sgp4_detail::Constants<T>;
    using std::cos;
    using std::fabs;
    using std::pow;
    using std::sin;
    using std::sqrt;
    initialized_ = false;
    elements_ = el;
    const T xke = C::xke;
    const T j2 = C::j2;
    const T ecco = el.eccentricity;
    const T inclo = el.inclination_rad;

    // initl: recover the original (un-Kozai'd) mean motion and semi-major axis.
    const T eccsq = ecco * ecco;
    const T omeosq = T(1) - eccsq;
    const T rteosq = sqrt(omeosq);
    const T cosio = cos(inclo);
    const T cosio2 = cosio * cosio;
    const T ak = pow(xke / el.mean_motion_rad_per_min, C::x2o3);
    const T d1 = T(0.75) * j2 * (T(3) * cosio2 - T(1)) / (rteosq * omeosq);
    T del = d1 / (ak * ak);
    const T adel = ak * (T(1) - del * del - del * (T(1) / T(3) + T(134) * del * del / T(81)));
    del = d1 / (adel * adel);
    mean_motion_ = el.mean_motion_rad_per_min / (T(1) + del);
    ao_ = pow(xke / mean_motion_, C::x2o3);
    const T sinio = sin(inclo);
    const T po = ao_ * omeosq;
    const T con42 = T(1) - T(5) * cosio2;
    con41_ = -con42 - cosio2 - cosio2;
    const T posq = po * po;
    const T rp = ao_ * (T(1) - ecco);

    if (!(omeosq >= T(0) && mean_motion_ > T(0))) return Sgp4Status::mean_eccentricity;
    if (C::two_pi / mean_motion_ >= static_cast<T>(kDeepSpacePeriodMinutes)) return Sgp4Status::deep_space;

    // sgp4init, near-Earth branch.
    const T ss = T(78) / C::radius + T(1);
    const T qzms2ttemp = (T(120) - T(78)) / C::radius;
    const T qzms2t = qzms2ttemp * qzms2ttemp * qzms2ttemp * qzms2ttemp;
    simple_ = rp < (T(220) / C::radius + T(1));
    T sfour = ss;
    T qzms24 = qzms2t;
    const T perige = (rp - T(1)) * C::radius;
    if (perige < T(156)) {  // a perigee below 156 km: the atmosphere's s parameter follows it down
        sfour = perige - T(78);
        if (perige < T(98)) sfour = T(20);
        const T qzms24temp = (T(120) - sfour) / C::radius;
        qzms24 = qzms24temp * qzms24temp * qzms24temp * qzms24temp;
        sfour = sfour / C::radius + T(1);
    }
    const T pinvsq = T(1) / posq;
    const T tsi = T(1) / (ao_ - sfour);
    eta_ = ao_ * ecco * tsi;
    const T etasq = eta_ * eta_;
    const T eeta = ecco * eta_;
    const T psisq = fabs(T(1) - etasq);
    const T coef = qzms24 * pow(tsi, T(4));
    const T coef1 = coef / pow(psisq, T(3.5));
    const T cc2 = coef1 * mean_motion_ *
                  (ao_ * (T(1) + T(1.5) * etasq + eeta * (T(4) + etasq)) +
                   T(0.375) * j2 * tsi / psisq * con41_ * (T(8) + T(3) * etasq * (T(8) + etasq)));
    const T bstar = el.bstar_per_earth_radius;
    cc1_ = bstar * cc2;
    T cc3 = T(0);
    if (ecco > T(1.0e-4)) cc3 = -T(2) * coef * tsi * C::j3oj2 * mean_motion_ * sinio / ecco;
    x1mth2_ = T(1) - cosio2;
    cc4_ = T(2) * mean_motion_ * coef1 * ao_ * omeosq *
           (eta_ * (T(2) + T(0.5) * etasq) + ecco * (T(0.5) + T(2) * etasq) -
            j2 * tsi / (ao_ * psisq) *
                (-T(3) * con41_ * (T(1) - T(2) * eeta + etasq * (T(1.5) - T(0.5) * eeta)) +
                 T(0.75) * x1mth2_ * (T(2) * etasq - eeta * (T(1) + etasq)) * cos(T(2) * el.arg_perigee_rad)));
    cc5_ = T(2) * coef1 * ao_ * omeosq * (T(1) + T(2.75) * (etasq + eeta) + eeta * etasq);
    const T cosio4 = cosio2 * cosio2;
    const T temp1 = T(1.5) * j2 * pinvsq * mean_motion_;
    const T temp2 = T(0.5) * temp1 * j2 * pinvsq;
    const T temp3 = -T(0.46875) * C::j4 * pinvsq * pinvsq * mean_motion_;
    mdot_ = mean_motion_ + T(0.5) * temp1 * rteosq * con41_ +
            T(0.0625) * temp2 * rteosq * (T(13) - T(78) * cosio2 + T(137) * cosio4);
    argpdot_ = -T(0.5) * temp1 * con42 + T(0.0625) * temp2 * (T(7) - T(114) * cosio2 + T(395) * cosio4) +
               temp3 * (T(3) - T(36) * cosio2 + T(49) * cosio4);
    const T xhdot1 = -temp1 * cosio;
    nodedot_ = xhdot1 + (T(0.5) * temp2 * (T(4) - T(19) * cosio2) + T(2) * temp3 * (T(3) - T(7) * cosio2)) * cosio;
    omgcof_ = bstar * cc3 * cos(el.arg_perigee_rad);
    xmcof_ = T(0);
    if (ecco > T(1.0e-4)) xmcof_ = -C::x2o3 * coef * bstar / eeta;
    nodecf_ = T(3.5) * omeosq * xhdot1 * cc1_;
    t2cof_ = T(1.5) * cc1_;
    // The reference code's guard against division by zero at 180 deg inclination.
    const T one_plus_cosio = fabs(cosio + T(1)) > T(1.5e-12) ? cosio + T(1) : T(1.5e-12);
    xlcof_ = -T(0.25) * C::j3oj2 * sinio * (T(3) + T(5) * cosio) / one_plus_cosio;
    aycof_ = -T(0.5) * C::j3oj2 * sinio;
    const T delmotemp = T(1) + eta_ * cos(el.mean_anomaly_rad);
    delmo_ = delmotemp * delmotemp * delmotemp;
    sinmao_ = sin(el.mean_anomaly_rad);
    x7thm1_ = T(7) * cosio2 - T(1);
    d2_ = d3_ = d4_ = t3cof_ = t4cof_ = t5cof_ = T(0);
    if (!simple_) {
        const T cc1sq = cc1_ * cc1_;
        d2_ = T(4) * ao_ * tsi * cc1sq;
        const T temp = d2_ * tsi * cc1_ / T(3);
        d3_ = (T(17) * ao_ + sfour) * temp;
        d4_ = T(0.5) * temp * ao_ * tsi * (T(221) * ao_ + T(31) * sfour) * cc1_;
        t3cof_ = d2_ + T(2) * cc1sq;
        t4cof_ = T(0.25) * (T(3) * d3_ + cc1_ * (T(12) * d2_ + T(10) * cc1sq));
        t5cof_ = T(0.2) * (T(3) * d4_ + T(12) * cc1_ * d3_ + T(6) * d2_ * d2_ + T(15) * cc1sq * (T(2) * d2_ + cc1sq));
    }
    initialized_ = true;
    // The reference code ends initialization with a propagation to the epoch and returns its error.
    OrbitState<T> at_epoch;
    const Sgp4Status status = propagate(T(0), at_epoch);
    if (status != Sgp4Status::ok) initialized_ = false;
    return status;
}

template <typename T>
Sgp4Status Sgp4<T>::propagate(T t, OrbitState<T>& state) const noexcept {
    using C = sgp4_detail::Constants<T>;
    using std::atan2;
    using std::cos;
    using std::fabs;
    using std::fmod;
    using std::pow;
    using std::sin;
    using std::sqrt;
    if (!initialized_) return Sgp4Status::mean_motion;
    const T xke = C::xke;
    const T vkmpersec = C::radius * xke / T(60);
    const MeanElements<T>& el = elements_;

    // Secular gravity and atmospheric drag.
    const T xmdf = el.mean_anomaly_rad + mdot_ * t;
    const T argpdf = el.arg_perigee_rad + argpdot_ * t;
    const T nodedf = el.raan_rad + nodedot_ * t;
    T argpm = argpdf;
    T mm = xmdf;
    const T t2 = t * t;
    T nodem = nodedf + nodecf_ * t2;
    T tempa = T(1) - cc1_ * t;
    T tempe = el.bstar_per_earth_radius * cc4_ * t;
    T templ = t2cof_ * t2;
    if (!simple_) {
        const T delomg = omgcof_ * t;
        const T delmtemp = T(1) + eta_ * cos(xmdf);
        const T delm = xmcof_ * (delmtemp * delmtemp * delmtemp - delmo_);
        const T temp = delomg + delm;
        mm = xmdf + temp;
        argpm = argpdf - temp;
        const T t3 = t2 * t;
        const T t4 = t3 * t;
        tempa = tempa - d2_ * t2 - d3_ * t3 - d4_ * t4;
        tempe = tempe + el.bstar_per_earth_radius * cc5_ * (sin(mm) - sinmao_);
        templ = templ + t3cof_ * t3 + t4 * (t4cof_ + t * t5cof_);
    }
    T nm = mean_motion_;
    T em = el.eccentricity;
    const T inclm = el.inclination_rad;
    if (nm <= T(0)) return Sgp4Status::mean_motion;
    const T am = pow(xke / nm, C::x2o3) * tempa * tempa;
    nm = xke / pow(am, T(1.5));
    em = em - tempe;
    if (em >= T(1) || em < T(-0.001)) return Sgp4Status::mean_eccentricity;
    if (em < T(1.0e-6)) em = T(1.0e-6);
    mm = mm + mean_motion_ * templ;
    T xlm = mm + argpm + nodem;
    nodem = fmod(nodem, C::two_pi);
    argpm = fmod(argpm, C::two_pi);
    xlm = fmod(xlm, C::two_pi);
    mm = fmod(xlm - argpm - nodem, C::two_pi);

    // Long-period periodics (no deep-space perturbations here: near-Earth only).
    const T sinip = sin(inclm);
    const T cosip = cos(inclm);
    const T ep = em;
    const T axnl = ep * cos(argpm);
    T temp = T(1) / (am * (T(1) - ep * ep));
    const T aynl = ep * sin(argpm) + temp * aycof_;
    const T xl = mm + argpm + nodem + temp * xlcof_ * axnl;

    // Kepler's equation in the equinoctial variables.
    const T u = fmod(xl - nodem, C::two_pi);
    T eo1 = u;
    T tem5 = T(9999.9);
    T sineo1 = T(0);
    T coseo1 = T(1);
    for (int ktr = 1; fabs(tem5) >= C::kepler_tolerance && ktr <= 10; ++ktr) {
        sineo1 = sin(eo1);
        coseo1 = cos(eo1);
        tem5 = T(1) - coseo1 * axnl - sineo1 * aynl;
        tem5 = (u - aynl * coseo1 + axnl * sineo1 - eo1) / tem5;
        if (fabs(tem5) >= T(0.95)) tem5 = tem5 > T(0) ? T(0.95) : T(-0.95);
        eo1 = eo1 + tem5;
    }

    // Short-period periodics.
    const T ecose = axnl * coseo1 + aynl * sineo1;
    const T esine = axnl * sineo1 - aynl * coseo1;
    const T el2 = axnl * axnl + aynl * aynl;
    const T pl = am * (T(1) - el2);
    if (pl < T(0)) return Sgp4Status::semi_latus_rectum;
    const T rl = am * (T(1) - ecose);
    const T rdotl = sqrt(am) * esine / rl;
    const T rvdotl = sqrt(pl) / rl;
    const T betal = sqrt(T(1) - el2);
    temp = esine / (T(1) + betal);
    const T sinu = am / rl * (sineo1 - aynl - axnl * temp);
    const T cosu = am / rl * (coseo1 - axnl + aynl * temp);
    T su = atan2(sinu, cosu);
    const T sin2u = (cosu + cosu) * sinu;
    const T cos2u = T(1) - T(2) * sinu * sinu;
    temp = T(1) / pl;
    const T temp1 = T(0.5) * C::j2 * temp;
    const T temp2 = temp1 * temp;
    const T mrt = rl * (T(1) - T(1.5) * temp2 * betal * con41_) + T(0.5) * temp1 * x1mth2_ * cos2u;
    su = su - T(0.25) * temp2 * x7thm1_ * sin2u;
    const T xnode = nodem + T(1.5) * temp2 * cosip * sin2u;
    const T xinc = inclm + T(1.5) * temp2 * cosip * sinip * cos2u;
    const T mvt = rdotl - nm * temp1 * x1mth2_ * sin2u / xke;
    const T rvdot = rvdotl + nm * temp1 * (x1mth2_ * cos2u + T(1.5) * con41_) / xke;

    // Orientation vectors and the state.
    const T sinsu = sin(su);
    const T cossu = cos(su);
    const T snod = sin(xnode);
    const T cnod = cos(xnode);
    const T sini = sin(xinc);
    const T cosi = cos(xinc);
    const T xmx = -snod * cosi;
    const T xmy = cnod * cosi;
    const Vector3<T> uv(xmx * sinsu + cnod * cossu, xmy * sinsu + snod * cossu, sini * sinsu);
    const Vector3<T> vv(xmx * cossu - cnod * sinsu, xmy * cossu - snod * sinsu, sini * cossu);
    state.position_km = (mrt * uv) * C::radius;
    state.velocity_km_s = (mvt * uv + rvdot * vv) * vkmpersec;
    if (mrt < T(1)) return Sgp4Status::decayed;
    return Sgp4Status::ok;
}

template <typename T>
T Sgp4<T>::period_minutes() const noexcept {
    return sgp4_detail::Constants<T>::two_pi / mean_motion_;
}

template <typename T>
T Sgp4<T>::semi_major_axis_km() const noexcept {
    return ao_ * sgp4_detail::Constants<T>::radius;
}

}  // namespace orbit
