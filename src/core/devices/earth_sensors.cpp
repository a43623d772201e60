// A GNSS receiver and a magnetometer (docs/physics.md §10.9).
#include "rigid_body_sim/core/devices/earth_sensors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bodies/validate.h"

namespace rigid_body_sim::core {

namespace {

constexpr double kDegree = M_PI / 180.0;
// WGS84: the equatorial radius (m) and the flattening.
constexpr double kEquatorialRadius = 6378137.0;
constexpr double kFlattening = 1.0 / 298.257223563;

void requireAxes(const Vec3& v, double lo, double hi, const std::string& field) {
  for (int k = 0; k < 3; ++k) {
    if (!(v[k] >= lo && v[k] <= hi)) {
      throw std::invalid_argument(field + " = " + detail::str(v) + ": each must be within [" + detail::str(lo) + ", " +
                                  detail::str(hi) + "]");
    }
  }
}

}  // namespace

void validateSensorError(const SensorErrorSettings& s, const std::string& key) {
  constexpr double kMost = 1e6;  // of any reading here: m, m/s, or a field
  requireAxes(s.offset, -kMost, kMost, key + ".offset");
  requireAxes(s.drift, 0.0, kMost, key + ".drift");
  requireAxes(s.drift_frequency, 0.0, 1e6, key + ".drift_frequency");
  requireAxes(s.gaussian_noise, 0.0, kMost, key + ".gaussian_noise");
}

SensorError::SensorError(const SensorErrorSettings& settings, std::uint64_t seed)
    : settings_(settings), seed_(seed), rng_(seed) {}

double SensorError::gaussian(double sigma) { return sigma == 0.0 ? 0.0 : sigma * normal_(rng_); }

Vec3 SensorError::sample(double elapsed) {
  const SensorErrorSettings& s = settings_;
  Vec3 e;
  for (int k = 0; k < 3; ++k) {
    // The Gauss-Markov drift over `elapsed` exactly: its memory fades by
    // a = exp(-f t) and it gains the variance that keeps σ = drift once
    // settled. (hector steps it as Euler with the noise times t, so its
    // drift's size depends on the update rate.)
    const double a = std::exp(-s.drift_frequency[k] * elapsed);
    drift_[k] = a * drift_[k] + gaussian(s.drift[k] * std::sqrt(std::max(0.0, 1.0 - a * a)));
    e[k] = s.offset[k] + drift_[k] + gaussian(s.gaussian_noise[k]);
  }
  return e;
}

Vec3 SensorError::variance() const {
  return settings_.drift.cwiseProduct(settings_.drift) +
         settings_.gaussian_noise.cwiseProduct(settings_.gaussian_noise);
}

void SensorError::restart() {
  drift_ = Vec3::Zero();
  rng_.seed(seed_);
  normal_.reset();
}

void validateGeoReference(const GeoReference& r, const std::string& key) {
  // At the poles east has no direction and the prime-vertical radius's cosine is 0.
  detail::requireWithin(r.latitude, -89.0, 89.0, key + ".latitude", "deg");
  detail::requireWithin(r.longitude, -180.0, 180.0, key + ".longitude", "deg");
  detail::requireWithin(r.altitude, -1e5, 1e6, key + ".altitude", "m");
  detail::requireWithin(r.heading, -360.0, 360.0, key + ".heading", "deg");
}

void validateGnss(const GnssSettings& s, const std::string& key) {
  validateGeoReference(s.reference, key);
  validateSensorError(s.position, key);
  validateSensorError(s.velocity, key + ".velocity");
}

GnssFix exactGnssFix(const GeoReference& reference, const Vec3& p_W, const Vec3& v_W) {
  const double e2 = kFlattening * (2.0 - kFlattening);
  const double s = std::sin(reference.latitude * kDegree);
  const double w = 1.0 / (1.0 - e2 * s * s);
  const double prime_vertical = kEquatorialRadius * std::sqrt(w);  // N
  const double meridian = prime_vertical * (1.0 - e2) * w;         // M = a(1-e²)/(1-e² sin²φ)^(3/2)
  const double east_radius = prime_vertical * std::cos(reference.latitude * kDegree);
  const double ch = std::cos(reference.heading * kDegree), sh = std::sin(reference.heading * kDegree);
  // x points at the heading, y 90° anticlockwise from it (z up).
  const double north = ch * p_W.x() + sh * p_W.y();
  const double east = sh * p_W.x() - ch * p_W.y();
  GnssFix fix;
  fix.latitude = reference.latitude + north / meridian / kDegree;
  fix.longitude = reference.longitude + east / east_radius / kDegree;
  fix.altitude = reference.altitude + p_W.z();
  fix.v_NWU = Vec3(ch * v_W.x() + sh * v_W.y(), -sh * v_W.x() + ch * v_W.y(), v_W.z());
  return fix;
}

Gnss::Gnss(const GnssSettings& settings)
    : settings_(settings),
      position_(settings.position, settings.seed),
      velocity_(settings.velocity, settings.seed + 1) {}

GnssFix Gnss::report(const Vec3& p_W, const Vec3& v_W, double elapsed) {
  const Vec3 dv = velocity_.sample(elapsed);
  position_.shiftDrift(elapsed * velocity_.drift());  // a velocity's offset drift moves the position, as hector's
  const Vec3 dp = position_.sample(elapsed);
  GnssFix fix = exactGnssFix(settings_.reference, p_W + dp, v_W + dv);
  // The world-axis variances, turned into east, north, up.
  const double h = settings_.reference.heading * kDegree;
  Mat3 R_EW;                               // world axes -> east, north, up
  R_EW << std::sin(h), -std::cos(h), 0.0,  //
      std::cos(h), std::sin(h), 0.0,       //
      0.0, 0.0, 1.0;
  fix.position_covariance_ENU = R_EW * position_.variance().asDiagonal() * R_EW.transpose();
  return fix;
}

void Gnss::restart() {
  position_.restart();
  velocity_.restart();
}

void validateMagnetometer(const MagnetometerSettings& s, const std::string& key) {
  detail::requireWithin(s.magnitude, 0.0, 1e6, key + ".magnitude", "");
  detail::requireWithin(s.heading, -360.0, 360.0, key + ".heading", "deg");
  detail::requireWithin(s.declination, -180.0, 180.0, key + ".declination", "deg");
  detail::requireWithin(s.inclination, -90.0, 90.0, key + ".inclination", "deg");
  validateSensorError(s.error, key);
}

Vec3 magneticField_W(const MagnetometerSettings& s) {
  // Magnetic north lies (heading - declination) anticlockwise of x.
  const double azimuth = (s.heading - s.declination) * kDegree, dip = s.inclination * kDegree;
  return s.magnitude * Vec3(std::cos(dip) * std::cos(azimuth), std::cos(dip) * std::sin(azimuth), -std::sin(dip));
}

Magnetometer::Magnetometer(const MagnetometerSettings& settings)
    : field_W_(magneticField_W(settings)), error_(settings.error, settings.seed) {}

Vec3 Magnetometer::report(const Quat& q_WS, double elapsed) {
  return q_WS.conjugate() * field_W_ + error_.sample(elapsed);
}

}  // namespace rigid_body_sim::core
