#include "ssr_plant/angular_response.hpp"

#include "panel_response/kelly.hpp"

namespace ssr_plant {
namespace {

constexpr panel_response::Response<double> kCosine = panel_response::cosine<double>();
constexpr panel_response::Response<double> kKelly = panel_response::kelly<double>();  // knots at compile time

}  // namespace

double cosine_response(double cos_beta) {
    return panel_response::response_from_cos(kCosine, cos_beta);
}

double kelly_response(double beta) {
    return panel_response::response_from_angle(kKelly, beta);
}

double angular_response(AngularResponse law, double cos_beta) {
    return panel_response::response_from_cos(law == AngularResponse::cosine ? kCosine : kKelly, cos_beta);
}

}  // namespace ssr_plant
