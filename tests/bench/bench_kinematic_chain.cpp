// metrofit-bench --kinematic-chain [--seeds N] [--repeat R].
//
// For every seed a machine with known actuator errors is drawn (core/sim/circular_sim.h plays it):
// origin uniform in +-10 um per coordinate, the X and Y axis angles a, b uniform in +-0.005 deg
// (+-87 urad); measurement noise N(0, (0.5 um)^2) per coordinate.
//
// The chain (IEEE Access, kinematic compensation algorithm; core/kinematics/spc_actuator.h): an edge
// machined along X and one along Y on that machine (50 points over 200 mm each, simulateAxisFeature),
// actuatorErrorsFromSpc with its defaults (SPC gate k = 2, residual charts in subgroups of 5); the
// derived errors against the true ones (origin in um, angles in urad); then the Eq. 15 references of
// the nominal circle R 100 mm (720 points, CCW and CW) run through the true machine without noise:
// max |P - nominal| before (nominal commands) and after (the references; the nominal commands when
// the gate does not apply the compensation).
//
// Peer of the chain: the plain 2-axis identification (core/kinematics/identification.h, LM) of a
// simulated circular test of the same machine (R 100 mm, 720 points, same noise): the same question
// (the machine's errors) from another measurement, the one the project otherwise uses. Its errors and
// its compensated circle are shown beside the chain's, and its time is the ratio's denominator. The
// data are not the same: 100 edge points against 720 circle points, so the ratio says what one
// answer costs, not which algorithm is faster on equal input.
//
// Three-plane identification (core/kinematics/identification3.h): a three-axis machine drawn the same
// way (origin +-10 um, six angles +-0.005 deg), circular tests in XY, YZ and ZX (720 points each),
// identifyActuatorErrors3: the identified squareness of each plane against the true one (urad). Peer:
// three separate 2-axis identifications of the same three tests (the joint fit's start), squareness
// per plane and time.
//
// Times are the calling thread's CPU time, the median of `repeat` runs per seed, summed over seeds
// and given per run (ms).
#include "bench_kinematic_chain.h"

#include <time.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/common/rng.h"
#include "core/kinematics/cartesian_model.h"
#include "core/kinematics/identification.h"
#include "core/kinematics/identification3.h"
#include "core/kinematics/spc_actuator.h"
#include "core/sim/circular_sim.h"

namespace metrofit::bench {
namespace {

constexpr double kUrad = std::numbers::pi / 180.0 * 1e6;  ///< urad per degree
constexpr double kUm = 1000.0;                            ///< um per mm
constexpr double kOriginRangeMm = 0.010;
constexpr double kAngleRangeDeg = 0.005;
constexpr double kNoiseMm = 0.0005;

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

/// Median thread CPU time of `repeat` runs of f, in ms.
template <class F>
double medianMs(int repeat, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < repeat; ++i) {
    const double a = threadCpuSeconds();
    f();
    t.push_back((threadCpuSeconds() - a) * 1e3);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

/// Mean and max of |values|.
struct AbsStats {
  double sum = 0.0, max = 0.0;
  int n = 0;
  void add(double v) {
    sum += std::abs(v);
    max = std::max(max, std::abs(v));
    ++n;
  }
  double mean() const { return n > 0 ? sum / n : 0.0; }
  nlohmann::json json() const { return {{"mean_abs", mean()}, {"max_abs", max}}; }
};

ActuatorErrors2 drawMachine(Rng& rng) {
  ActuatorErrors2 e;
  e.originMm = Eigen::Vector2d(rng.uniform(-kOriginRangeMm, kOriginRangeMm),
                               rng.uniform(-kOriginRangeMm, kOriginRangeMm));
  e.xAxisAngleDeg = rng.uniform(-kAngleRangeDeg, kAngleRangeDeg);
  e.yAxisAngleDeg = rng.uniform(-kAngleRangeDeg, kAngleRangeDeg);
  return e;
}

ActuatorErrors3 drawMachine3(Rng& rng) {
  ActuatorErrors3 e;
  for (int i = 0; i < 3; ++i) e.originMm(i) = rng.uniform(-kOriginRangeMm, kOriginRangeMm);
  for (std::size_t i = 0; i < 3; ++i) {
    e.uAngleDeg[i] = rng.uniform(-kAngleRangeDeg, kAngleRangeDeg);
    e.vAngleDeg[i] = rng.uniform(-kAngleRangeDeg, kAngleRangeDeg);
  }
  return e;
}

/// Max |P - nominal| (mm) of the true machine (no noise) driven by `commands` for the `nominal` points.
double maxPathErrorMm(const ActuatorErrors2& truth, const std::vector<Eigen::Vector2d>& commands,
                      const std::vector<Eigen::Vector2d>& nominal) {
  const std::vector<Eigen::Vector2d> p = simulateMachine(truth, commands, 0.0, 0);
  double m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) m = std::max(m, (p[i] - nominal[i]).norm());
  return m;
}

/// The errors of `estimate` against `truth`: origin x, y (um), a, b, squareness (urad).
struct ErrorStats {
  AbsStats ox, oy, a, b, s;
  void add(const ActuatorErrors2& estimate, const ActuatorErrors2& truth) {
    ox.add((estimate.originMm.x() - truth.originMm.x()) * kUm);
    oy.add((estimate.originMm.y() - truth.originMm.y()) * kUm);
    a.add((estimate.xAxisAngleDeg - truth.xAxisAngleDeg) * kUrad);
    b.add((estimate.yAxisAngleDeg - truth.yAxisAngleDeg) * kUrad);
    s.add((estimate.squarenessDeg() - truth.squarenessDeg()) * kUrad);
  }
  nlohmann::json json() const {
    return {{"origin_x_um", ox.json()},
            {"origin_y_um", oy.json()},
            {"x_axis_angle_urad", a.json()},
            {"y_axis_angle_urad", b.json()},
            {"squareness_urad", s.json()}};
  }
};

void printRow(const char* what, const AbsStats& chain, const AbsStats& peer) {
  std::printf("  %-28s %10.3f %10.3f   %10.3f %10.3f\n", what, chain.mean(), chain.max, peer.mean(),
              peer.max);
}

}  // namespace

nlohmann::json benchKinematicChain(const KinematicChainBenchOptions& options) {
  const int seeds = std::max(1, options.seeds);
  const int repeat = std::max(1, options.repeat);
  volatile double sink = 0.0;

  CircularSimOptions circle;  // R 100 mm, 360 points per loop, CCW then CW
  const std::vector<Eigen::Vector2d> nominal = circularTestCommands(circle);

  ErrorStats chainErr, peerErr;
  AbsStats before, afterChain, afterChainApplied, afterPeer;
  std::array<AbsStats, 3> jointSq, separateSq;
  int applied = 0, outOfControl = 0;
  double chainMs = 0.0, peerMs = 0.0, jointMs = 0.0, separateMs = 0.0;
  int failures3 = 0;

  for (int seed = 1; seed <= seeds; ++seed) {
    Rng rng(0x6b696eULL + static_cast<std::uint64_t>(seed));
    const ActuatorErrors2 truth = drawMachine(rng);

    // The chain from the two edges.
    EdgeSimOptions edge;
    edge.errors = truth;
    edge.noiseMm = kNoiseMm;
    edge.axis = 'x';
    edge.seed = 1000 + 4 * static_cast<std::uint64_t>(seed);
    const AxisFeatureSeries xEdge = simulateAxisFeature(edge);
    edge.axis = 'y';
    edge.seed += 1;
    const AxisFeatureSeries yEdge = simulateAxisFeature(edge);
    const SpcActuatorResult chain = actuatorErrorsFromSpc(xEdge, yEdge);
    chainMs += medianMs(repeat, [&] { sink = actuatorErrorsFromSpc(xEdge, yEdge).errors.xAxisAngleDeg; });
    chainErr.add(chain.errors, truth);
    if (chain.apply) ++applied;
    if (chain.reason.rfind("not compensated: the residuals", 0) == 0) ++outOfControl;
    before.add(maxPathErrorMm(truth, nominal, nominal) * kUm);
    const std::vector<Eigen::Vector2d> refs =
        chain.apply ? compensatePath(CartesianMachine2::fromErrors(chain.errors), nominal) : nominal;
    afterChain.add(maxPathErrorMm(truth, refs, nominal) * kUm);
    if (chain.apply) afterChainApplied.add(maxPathErrorMm(truth, refs, nominal) * kUm);

    // The peer: the 2-axis identification of a circular test of the same machine.
    CircularSimOptions test = circle;
    test.errors = truth;
    test.noiseMm = kNoiseMm;
    test.seed = 1000 + 4 * static_cast<std::uint64_t>(seed) + 2;
    const MeasuredPath path = simulateCircularTest(test);
    const IdentifyResult id = identifyActuatorErrors(path);
    peerMs += medianMs(repeat, [&] { sink = identifyActuatorErrors(path).rmseMm; });
    peerErr.add(id.errors, truth);
    afterPeer.add(
        maxPathErrorMm(truth, compensatePath(CartesianMachine2::fromErrors(id.errors), nominal), nominal) *
        kUm);

    // Three planes: the joint identification and three separate 2-axis ones.
    const ActuatorErrors3 truth3 = drawMachine3(rng);
    std::array<MeasuredPath, 3> tests;
    for (const TestPlane p : kTestPlanes) {
      CircularSimOptions o = circle;
      o.noiseMm = kNoiseMm;
      o.seed = 5000 + 3 * static_cast<std::uint64_t>(seed) + static_cast<std::uint64_t>(p);
      tests[static_cast<std::size_t>(p)] = simulatePlaneCircularTest(truth3, p, o);
    }
    const Identify3Result joint = identifyActuatorErrors3(tests);
    if (joint.run.termination == Termination::Failed) ++failures3;
    jointMs += medianMs(repeat, [&] { sink = identifyActuatorErrors3(tests).rmseMm; });
    separateMs += medianMs(repeat, [&] {
      double s = 0.0;
      for (const MeasuredPath& t : tests) s += identifyActuatorErrors(t).rmseMm;
      sink = s;
    });
    for (const TestPlane p : kTestPlanes) {
      const auto i = static_cast<std::size_t>(p);
      jointSq[i].add((joint.errors.squarenessDeg(p) - truth3.squarenessDeg(p)) * kUrad);
      const IdentifyResult single = identifyActuatorErrors(tests[i]);
      separateSq[i].add((single.errors.squarenessDeg() - truth3.squarenessDeg(p)) * kUrad);
    }
  }
  (void)sink;
  const double n = seeds;

  std::printf(
      "kinematic chain (IEEE Access, kinematic compensation algorithm: SPC edges -> actuator errors -> Eq. "
      "15), "
      "%d seeds\n"
      "  machines: origin U(+-10 um), axis angles U(+-0.005 deg = +-87.3 urad); noise 0.5 um per coordinate\n"
      "  chain: edges along X and Y, 50 points over 200 mm each; peer: 2-axis identification (LM) of a "
      "720-point\n"
      "  circular test R 100 mm of the same machine\n"
      "                                   chain from SPC          peer: circular test\n"
      "  |estimate - true|               mean        max        mean        max\n",
      seeds);
  printRow("origin x (um)", chainErr.ox, peerErr.ox);
  printRow("origin y (um)", chainErr.oy, peerErr.oy);
  printRow("X axis angle a (urad)", chainErr.a, peerErr.a);
  printRow("Y axis angle b (urad)", chainErr.b, peerErr.b);
  printRow("squareness b - a (urad)", chainErr.s, peerErr.s);
  std::printf(
      "  compensated circle R 100 mm, max |P - nominal| on the true machine (um), mean (max) over seeds:\n"
      "    before %.3f (%.3f) -> after, chain %.3f (%.3f); after, circular test %.3f (%.3f)\n"
      "    the SPC gate applied the compensation in %d of %d seeds (not applied for a residual chart out of "
      "control: %d); after, chain, where applied: %.3f (%.3f)\n",
      before.mean(), before.max, afterChain.mean(), afterChain.max, afterPeer.mean(), afterPeer.max, applied,
      seeds, outOfControl, afterChainApplied.mean(), afterChainApplied.max);
  std::printf(
      "three-plane identification (circular tests in XY, YZ, ZX, 720 points each), %d seeds%s\n"
      "                                   joint 9-parameter fit   peer: 3 separate 2-axis fits\n"
      "  |squareness - true| (urad)      mean        max        mean        max\n",
      seeds, failures3 > 0 ? " (some fits FAILED)" : "");
  for (const TestPlane p : kTestPlanes) {
    const auto i = static_cast<std::size_t>(p);
    const std::string what = std::string("plane ") + planeName(p);
    printRow(what.c_str(), jointSq[i], separateSq[i]);
  }
  std::printf(
      "time (thread CPU, median of %d runs, per run):\n"
      "  chain from SPC %.4f ms, circular-test identification %.4f ms; ratio chain/peer = %.3f\n"
      "  joint three-plane fit %.4f ms, three 2-axis fits %.4f ms; ratio joint/peer = %.3f\n",
      repeat, chainMs / n, peerMs / n, chainMs / peerMs, jointMs / n, separateMs / n, jointMs / separateMs);

  nlohmann::json planes;
  for (const TestPlane p : kTestPlanes) {
    const auto i = static_cast<std::size_t>(p);
    planes[planeName(p)] = {{"joint_squareness_urad", jointSq[i].json()},
                            {"separate_squareness_urad", separateSq[i].json()}};
  }
  return {{"seeds", seeds},
          {"repeat", repeat},
          {"chain", chainErr.json()},
          {"peer", "2-axis identification (LM) of a 720-point circular test of the same machine"},
          {"peer_errors", peerErr.json()},
          {"circle_before_um", before.json()},
          {"circle_after_chain_um", afterChain.json()},
          {"circle_after_chain_applied_um", afterChainApplied.json()},
          {"circle_after_peer_um", afterPeer.json()},
          {"compensation_applied", applied},
          {"not_applied_out_of_control", outOfControl},
          {"chain_ms", chainMs / n},
          {"peer_ms", peerMs / n},
          {"ratio", chainMs / peerMs},
          {"three_planes", planes},
          {"three_planes_failed", failures3},
          {"three_planes_peer", "three separate 2-axis identifications of the same tests"},
          {"joint_ms", jointMs / n},
          {"separate_ms", separateMs / n},
          {"ratio_three_planes", jointMs / separateMs}};
}

}  // namespace metrofit::bench
