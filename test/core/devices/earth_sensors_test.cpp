// A GNSS fix and a magnetometer's field (core/devices/earth_sensors.h)
// against the lengths of a degree on WGS84 and the field's geometry, and
// their error model's statistics.
#include "rigid_body_sim/core/devices/earth_sensors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace rigid_body_sim::core {
namespace {

// The length of a degree on WGS84 (m), from the series in Wikipedia's
// "Latitude" and "Longitude" articles: a degree of latitude is
// 111132.954 - 559.822 cos 2φ + 1.175 cos 4φ; of longitude at 0° and 45°,
// 111319.491 and 78846.8.
double degreeOfLatitude(double phi_deg) {
  const double p = phi_deg * M_PI / 180.0;
  return 111132.954 - 559.822 * std::cos(2.0 * p) + 1.175 * std::cos(4.0 * p);
}

TEST(Gnss, ADegreeOfLatitudeAndOfLongitudeIsWgs84sLength) {
  for (double phi : {0.0, 45.0}) {
    GeoReference at{phi, 10.0, 0.0, 0.0};  // heading 0: x north, y west
    const GnssFix north = exactGnssFix(at, Vec3(degreeOfLatitude(phi), 0.0, 0.0), Vec3::Zero());
    EXPECT_NEAR(north.latitude, phi + 1.0, 1e-6) << phi;
    EXPECT_NEAR(north.longitude, 10.0, 1e-12) << phi;
  }
  const GeoReference equator{0.0, 10.0, 0.0, 0.0};
  EXPECT_NEAR(exactGnssFix(equator, Vec3(0.0, -111319.491, 0.0), Vec3::Zero()).longitude, 11.0, 1e-6);  // -y: east
  const GeoReference mid{45.0, 10.0, 0.0, 0.0};
  EXPECT_NEAR(exactGnssFix(mid, Vec3(0.0, 78846.8, 0.0), Vec3::Zero()).longitude, 9.0, 1e-6);  // y: west
}

TEST(Gnss, HeadingTurnsTheWorldAndAltitudeAddsUp) {
  const GeoReference enu{49.9, 8.9, 100.0, 90.0};  // x east, y north: ENU, as Husky's markup sets it
  const GnssFix east = exactGnssFix(enu, Vec3(50.0, 0.0, 2.5), Vec3(1.0, 0.0, 0.0));
  EXPECT_NEAR(east.latitude, 49.9, 1e-12);
  EXPECT_GT(east.longitude, 8.9);
  EXPECT_EQ(east.altitude, 102.5);
  // hector's velocity axes: north, west, up.
  EXPECT_NEAR(east.v_NWU.x(), 0.0, 1e-15);
  EXPECT_NEAR(east.v_NWU.y(), -1.0, 1e-15);
  const GnssFix north = exactGnssFix(enu, Vec3(0.0, 50.0, 0.0), Vec3(0.0, 2.0, 0.5));
  EXPECT_GT(north.latitude, 49.9);
  EXPECT_NEAR(north.longitude, 8.9, 1e-12);
  EXPECT_NEAR(north.v_NWU.x(), 2.0, 1e-15);
  EXPECT_NEAR(north.v_NWU.y(), 0.0, 1e-15);
  EXPECT_EQ(north.v_NWU.z(), 0.5);
}

TEST(Gnss, ItsNoiseIsSeededAndItsCovarianceIsInEastNorthUp) {
  GnssSettings s;
  s.reference.heading = 90.0;
  s.position.gaussian_noise = Vec3(0.3, 0.1, 0.2);  // x east, y north
  s.seed = 4;
  Gnss a(s), b(s);
  const GnssFix truth = exactGnssFix(s.reference, Vec3(3.0, 4.0, 0.0), Vec3::Zero());
  const double m_per_lat = degreeOfLatitude(49.9);
  double sum = 0.0, squares = 0.0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const GnssFix fa = a.report(Vec3(3.0, 4.0, 0.0), Vec3::Zero(), 0.25);
    const GnssFix fb = b.report(Vec3(3.0, 4.0, 0.0), Vec3::Zero(), 0.25);
    ASSERT_EQ(fa.latitude, fb.latitude);
    const double north_m = (fa.latitude - truth.latitude) * m_per_lat;
    sum += north_m;
    squares += north_m * north_m;
    if (k == 0) {
      EXPECT_NEAR(fa.position_covariance_ENU(0, 0), 0.09, 1e-12);  // east: world x
      EXPECT_NEAR(fa.position_covariance_ENU(1, 1), 0.01, 1e-12);  // north: world y
      EXPECT_NEAR(fa.position_covariance_ENU(2, 2), 0.04, 1e-12);
      EXPECT_NEAR(fa.position_covariance_ENU(0, 1), 0.0, 1e-12);
    }
  }
  EXPECT_NEAR(sum / n, 0.0, 4.0 * 0.1 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(squares / n), 0.1, 0.004);
}

TEST(SensorError, ItsDriftSettlesAtItsSigmaWhateverTheRateAndRestartsFromZero) {
  SensorErrorSettings s;
  s.drift = Vec3(2.0, 0.0, 0.0);
  s.drift_frequency = Vec3::Constant(1.0);  // a memory of 1 s
  s.offset = Vec3(0.0, 5.0, 0.0);
  for (double period : {0.01, 0.5}) {
    SensorError e(s, 11);
    double squares = 0.0;
    int n = 0;
    for (double t = 0.0; t < 20000.0; t += period) {
      const Vec3 x = e.sample(period);
      ASSERT_EQ(x.y(), 5.0);
      if (t > 10.0) squares += x.x() * x.x(), ++n;
    }
    // Samples 1 s apart are correlated by e^-1: the estimate's error is larger than iid.
    EXPECT_NEAR(std::sqrt(squares / n), 2.0, 0.06) << period;
    e.restart();
    EXPECT_EQ(e.drift(), Vec3::Zero());
  }
  // Correlation over one memory time: e^-1.
  SensorError e(s, 12);
  double xy = 0.0, xx = 0.0, previous = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double x = e.sample(1.0).x();
    if (k > 10) xy += x * previous, xx += previous * previous;
    previous = x;
  }
  EXPECT_NEAR(xy / xx, std::exp(-1.0), 0.01);
}

TEST(Gnss, ItsVelocitysDriftMovesItsPositionAsHectorsDoes) {
  GnssSettings s;  // heading 0: x north
  s.velocity.drift = Vec3(1.0, 0.0, 0.0);
  s.velocity.drift_frequency = Vec3::Constant(1.0);
  s.position.drift_frequency = Vec3::Zero();  // the position's drift keeps what it is given
  s.seed = 3;
  Gnss g(s);
  const double m_per_lat = degreeOfLatitude(s.reference.latitude);
  double integral = 0.0;
  bool moved = false;
  for (int k = 0; k < 100; ++k) {
    const GnssFix f = g.report(Vec3::Zero(), Vec3::Zero(), 0.1);
    integral += 0.1 * f.v_NWU.x();  // the velocity's error is its drift alone here
    EXPECT_NEAR((f.latitude - s.reference.latitude) * m_per_lat, integral, 1e-6) << k;
    moved = moved || std::abs(integral) > 0.01;
  }
  EXPECT_TRUE(moved);
  g.restart();
  EXPECT_EQ(g.report(Vec3::Zero(), Vec3::Zero(), 0.0).latitude, s.reference.latitude);
}

TEST(Gnss, RefusesAPoleAWorldAwayAndANegativeSigmaNamingTheField) {
  GnssSettings s;
  s.reference.latitude = 90.0;
  try {
    validateGnss(s, "gps");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gps.latitude"), std::string::npos) << e.what();
  }
  s.reference.latitude = 10.0;
  s.velocity.gaussian_noise.y() = -1.0;
  try {
    validateGnss(s, "gps");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gps.velocity.gaussian_noise"), std::string::npos) << e.what();
  }
  s.velocity.gaussian_noise.y() = 0.0;
  s.position.drift_frequency.x() = std::nan("");
  EXPECT_THROW(validateGnss(s, "gps"), std::invalid_argument);
}

TEST(Magnetometer, ItsFieldPointsAtMagneticNorthAndDipsByItsInclination) {
  MagnetometerSettings s;  // hector's defaults: heading 90 (x east), inclination 60°
  Magnetometer level(s);
  const Vec3 f = level.report(Quat::Identity(), 0.01);
  EXPECT_NEAR(f.x(), 0.0, 1e-15);
  EXPECT_NEAR(f.y(), 0.5, 1e-15);  // north is y
  EXPECT_NEAR(f.z(), -std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_NEAR(f.norm(), 1.0, 1e-15);
  // A sensor turned 90° left (facing north) reads north along its x.
  Magnetometer turned(s);
  const Vec3 g = turned.report(Quat(Eigen::AngleAxisd(M_PI / 2.0, Vec3::UnitZ())), 0.01);
  EXPECT_NEAR(g.x(), 0.5, 1e-15);
  EXPECT_NEAR(g.y(), 0.0, 1e-15);
  // A declination of 10° east turns magnetic north 10° clockwise: towards +x (east).
  s.declination = 10.0;
  s.magnitude = 4.8e-5;  // tesla, as sensor_msgs/MagneticField carries it
  const Vec3 d = magneticField_W(s);
  EXPECT_NEAR(std::atan2(d.x(), d.y()) * 180.0 / M_PI, 10.0, 1e-12);
  EXPECT_NEAR(d.norm(), 4.8e-5, 1e-18);
  s.inclination = 91.0;
  EXPECT_THROW(validateMagnetometer(s, "mag"), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::core
