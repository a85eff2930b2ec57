#pragma once
// Earth albedo on the six box faces.
//
// Model: the Earth is a Lambertian sphere of radius R_E and reflectivity rho. A surface element dA at
// p with outward normal p^ and solar zenith cos z = p^ . s^ > 0 reflects radiance L = rho E_sun cos z / pi.
// The irradiance it gives a face with unit normal n at the satellite r (d = p - r, l = |d|, u = d/l):
//   dE = L cos(a_e) f(n . u) dA / l^2,   cos(a_e) = -p^ . u   (> 0 on the visible cap)
// with f(c) = max(0, c) for an ideal face, or the Kelly response of the panel (AlbedoResponse::kelly), which
// weighs the grazing part of the Earth's disc less: 2.4 % less on the nadir face above the sub-solar point
// at 570 km, 10.6 % less on the side faces, which see the disc only at grazing incidence (test).
// i.e. the exact view factor of a differential element to a differential plate; the sum over the visible
// sunlit cap is done by quadrature in polar coordinates about the sub-satellite point (central angle
// gamma in [0, gamma_max], gamma_max = acos(R_E/r), Gauss-Legendre; azimuth psi, midpoint rule, which is
// spectrally accurate for a periodic integrand; dA = R_E^2 sin gamma dgamma dpsi).
// Shadowing of the Earth by itself is exact (cap = visible hemisphere part); the face is assumed to see
// the whole cap (no self-shadowing by the satellite), and E_sun is the irradiance at the Earth (the
// satellite's own eclipse does not enter).
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

// How a face responds to light arriving at incidence θ: the ideal cos θ, or the Kelly cosine of seed 000
// fig. 4 (panel_response's table, the plant's `kelly`). albedo_face is then the irradiance that, applied at
// normal incidence, gives the panel the same current: what the plant adds after its law for the direct sun.
enum class AlbedoResponse { cosine, kelly };

// How the Earth's reflectivity varies over its surface: one value everywhere, or a zonal shape that rises
// from the equator to the poles, rho(phi) = rho_equator + (rho_pole - rho_equator) sin^2(phi), phi the
// latitude of the reflecting element (the J2000 equator: within 0.4 deg of today's). The shape is the
// simplest that captures the measured zonal means (dark tropical oceans, bright polar ice and cloud); it is
// not a fit to a data set, and its two values are parameters: set them from one (satellite radiation
// budget climatologies give zonal annual means of about 0.2 to 0.3 in the tropics and 0.5 to 0.7 at the
// poles). Real reflectivity maps add longitude (continents, deserts, ocean), season and cloud: the
// albedo-aware sun sensors of the literature use monthly gridded maps from satellite reflectivity data.
enum class ReflectivityModel { uniform = 0, zonal = 1 };

struct AlbedoParams {
    bool enabled = true;
    double reflectivity = 0.3;  // Earth's mean Bond albedo, about 0.3 (uniform model)
    AlbedoResponse response = AlbedoResponse::cosine;
    int rings = 16;    // Gauss-Legendre points in gamma
    int sectors = 36;  // midpoint points in psi
    ReflectivityModel model = ReflectivityModel::uniform;
    double reflectivity_equator = 0.2;  // zonal model (assumed, see above)
    double reflectivity_pole = 0.6;
    // How often the cap is integrated (Environment): 0 = at every evaluation (earth_albedo below); > 0 = its
    // spherical-harmonic expansion to `degree` at nodes this many seconds apart, linear between them, and
    // only the faces' response per evaluation (AlbedoHarmonics). Errors: docs/speed.md, earth_albedo_test.
    double interval = 10.0;  // s
    int degree = 12;
};

/// The reflectivity at a latitude (its sine) under the model.
inline double reflectivity_at(const AlbedoParams& p, double sin_latitude) {
    if (p.model == ReflectivityModel::uniform) return p.reflectivity;
    return p.reflectivity_equator + (p.reflectivity_pole - p.reflectivity_equator) * sin_latitude * sin_latitude;
}

/// Irradiance (W/m^2) on the faces +x, -x, +y, -y, +z, -z. r_sat, sun_direction: ECI (m, unit);
/// solar_irradiance at the Earth (W/m^2); body_from_eci = A (maps ECI to body).
std::array<double, 6> earth_albedo(const AlbedoParams& params, const Eigen::Vector3d& r_sat,
                                   const Eigen::Vector3d& sun_direction, double solar_irradiance,
                                   const Eigen::Matrix3d& body_from_eci);

/// The per-sector directions of the quadrature, kept between calls (allocated when the grid changes).
struct CapScratch {
    int rings = 0, sectors = 0;
    std::vector<double> node, weight, cos_psi, sin_psi;
    std::vector<Eigen::Vector3d> horizontal;
    std::vector<double> sun_horizontal, polar_horizontal;
};

/// The same irradiance in two halves, for an attitude that moves faster than the orbit: the radiance the
/// satellite sees, L(u) over the directions u (ECI), as real spherical harmonics to degree L,
///   c_lm = sum over the quadrature's elements of a_e Y_lm(u_e)       (project: once per node),
/// and a face's response f as its Legendre moments f_l = 2 pi integral_0^1 f(t) P_l(t) dt, so that by the
/// addition theorem (Funk-Hecke) the face with normal n gets
///   E(n) = sum_e a_e f(n . u_e) = sum_l f_l sum_m c_lm Y_lm(n)      (faces: per evaluation, (L+1)^2 terms)
/// exactly up to the truncation at degree L (the kink of f at grazing incidence makes f_l fall as l^-5/2;
/// the error against earth_albedo is measured in earth_albedo_test and stated in docs/speed.md).
/// Owns its buffers: project and faces allocate nothing.
class AlbedoHarmonics {
public:
    static constexpr int kMaxDegree = 40;
    AlbedoHarmonics(const AlbedoParams& params, int degree);
    std::size_t size() const { return size_; }  // (L+1)^2 coefficients
    int degree() const { return degree_; }
    /// c[0 … size) = the coefficients of the sunlit cap seen from r_sat (arguments as earth_albedo).
    void project(const Eigen::Vector3d& r_sat, const Eigen::Vector3d& sun_direction, double solar_irradiance,
                 double* c);
    /// Irradiance on +x, -x, +y, -y, +z, -z from coefficients c (never negative).
    std::array<double, 6> faces(const double* c, const Eigen::Matrix3d& body_from_eci);

private:
    static std::size_t index(int l, int m) { return static_cast<std::size_t>(l * l + l + m); }
    void harmonics(const Eigen::Vector3d& unit, double* y) const;

    AlbedoParams params_;
    int degree_;
    std::size_t size_;
    std::vector<double> norm_, up_, down_;  // K_lm (2m-1)!! and the recursion's two factors
    std::vector<double> response_;          // f_l
    std::vector<double> basis_;             // scratch: Y_lm at one direction
    CapScratch scratch_;
};

}  // namespace environment
