// The ranges in which a model makes physical sense: Model's constructor
// refuses anything outside them, naming the key and the range. Each bound is
// far beyond what the bodies people simulate need, and well inside what the
// arithmetic survives (a 1e30 m box, a 1e300 kg mass or a 300,000 s step are
// typos, not scenes). docs/physics.md §5.9 says why each is where it is.
#pragma once

namespace rigid_body_sim::core::ranges {

// -- the world
constexpr double kMinDt = 1e-6;      ///< s (1 MHz)
constexpr double kMaxDt = 0.1;       ///< s (10 Hz: coarser steps miss every contact)
constexpr double kMaxGravity = 1e3;  ///< m/s², |g| (100 g; Jupiter's is 25)
constexpr double kMaxSpeedLimit = 1e4;
/// 1/s: the fastest damping decay rate (v halves in 0.7 µs; beyond, a typo,
/// and live tuning's widest value, 1e9, is refused rather than taken).
constexpr double kMaxDecayRate = 1e6;  ///< m/s and rad/s: SpeedLimits may be set up to this
/// Hz, the slowest a sensor samples or the node publishes: one sample every
/// 100 s of sim time. A slower one is a typo (1e-300 Hz overflowed the step
/// counter that paces it, and sampled at every step).
constexpr double kMinRate = 0.01;
/// Hz, the fastest the node publishes a topic (~publish_rate, a controller's
/// publish_rate): 1e300 was taken, and published at every step.
constexpr double kMaxPublishRate = 1e4;
constexpr double kMaxDuration = 1e6;  ///< s: the sleep time, and the node's durations (11 days)

// -- a sensor (its messages hold float32 ranges and angles: these keep every
// value a setting yields finite in them)
/// rad: |a lidar's angle|, two turns. Not one: real markup rounds a full
/// turn up (TurtleBot3's <max_angle>6.28319</max_angle>, over 2π by 5e-6).
constexpr double kMaxScanAngle = 4.0 * 3.14159265358979323846;
constexpr double kMaxSensorRange = 1e5;  ///< m: a lidar's max_range, a camera's max_depth (100 km)
/// rad: a camera's narrowest horizontal field of view (SDF's own minimum,
/// sdformat's camera.sdf: 1e-320 gave a focal length of inf)
constexpr double kMinFieldOfView = 1e-3;
constexpr double kMaxRays = 1e6;    ///< a lidar's rays, all fans
constexpr double kMaxPixels = 4e6;  ///< a depth camera's width × height

// -- what a controller is commanded (a topic's message; beyond: dropped as
// absurd, since 1e308 is finite but overflows the wheel speeds and the PID
// into inf and NaN)
constexpr double kMaxCommandPosition = 1e6;      ///< rad or m: a position command, a trajectory point
constexpr double kMaxCommandSpeed = 1e4;         ///< rad/s or m/s: a velocity command, a cmd_vel's v and ω
constexpr double kMaxCommandAcceleration = 1e8;  ///< rad/s² or m/s²: a trajectory point's
constexpr double kMaxCommandEffort = 1e6;        ///< N·m or N: an effort command (as apply_joint_effort's)

// -- a body
constexpr double kMinMass = 1e-6;          ///< kg (a milligram)
constexpr double kMaxMass = 1e7;           ///< kg (10,000 t)
constexpr double kMinInertia = 1e-15;      ///< kg·m², smallest principal moment (a milligram of 0.1 mm)
constexpr double kMaxInertia = 1e12;       ///< kg·m², largest principal moment
constexpr double kMaxExtent = 1e3;         ///< m: any collision shape's size, and how far it sits from the link
constexpr double kMaxContactPoints = 1e6;  ///< samples and mesh vertices of one body (memory and time per step)

// -- contacts
constexpr double kMinSampleSpacing = 1e-4;   ///< m
constexpr double kMaxFriction = 10.0;        ///< μ (rubber on rubber is about 1–2)
constexpr double kMaxThresholdSpeed = 1e3;   ///< m/s (restitution threshold, sleep speeds)
constexpr double kMaxBuffer = 1.0;           ///< m (penalty and barrier buffers, position slop)
constexpr double kMaxBarrierStrength = 1e6;  ///< N·m per contact point
/// A penalty spring k on a body of mass m is integrated explicitly: stable
/// only while ω h = √(k/m) h < 2. Refused from k h²/m above this.
constexpr double kMaxPenaltyStiffnessRatio = 1.0;
constexpr int kMaxIterations = 10000;  ///< impulse sweeps and position passes per step

// -- the mesh distance grid (bodies in a world)
constexpr int kMaxGridResolution = 256;  ///< cells along the longest side
/// Cells × triangles the grid may cost to build (100–140 ns each here: at most 10–14 s);
/// the resolution comes down to fit, and a mesh too big for 8 cells is refused.
constexpr double kMaxGridWork = 1e8;
constexpr int kMinGridResolution = 8;

}  // namespace rigid_body_sim::core::ranges
