// metrofit-bench --matching / --real-matching: the matching targets, measured in one run.
//
// --matching
//  1. Optimum agreement: S-pieces (core/sim/probe_sim.h) with random postures (angles uniform in
//     +-0.5 deg, translations in +-2 mm, noise 0.006 mm), seeds 1..N. The least-squares optimum is
//     Eigen::umeyama on the same points; our closed form (closedFormFit) and SADE with the paper's
//     settings (matchPosture, method sade, seed = the case's seed) must reach its rmse within 1e-6 mm.
//  2. Minimax: on the same cases max |d| of the minimax fit <= max |d| of the least-squares fit; and
//     on small cases against independent exact formulations:
//       (a) rotations locked, 8 points with normals: d_i(t) = a_i - n_i . t is linear, the minimax is
//           the LP  min z s.t. |a_i - n_i . t| <= z, solved here by enumerating every vertex (4 active
//           constraints of the 2n, 4x4 solves), not by GLPK;
//       (b) planar position-only points, free rz, x, y: for a fixed angle the best translation is the
//           centre of the smallest circle enclosing p_i - R(theta) q_i (found by brute force over
//           pairs and triples), minimised over theta by golden-section search.
//  3. Time of SADE with the paper's settings on the 40-point S-piece (median over the seeds).
//  4. Closed form on 10^6 points against Eigen::umeyama in the same run (median of `repeat`).
// --real-matching
//  The SDSS plug-plate reports with the source program's fits (fit_<plate>_<n>_<date>.txt):
//  FitOffset, FitScale, FitRotAngle, ResidRadErrRMS and the per-hole residuals against our
//  closed-form similarity fit (--allow-scale) of the D<plate>_<n> report read by the hole-table reader.
#include "bench_matching.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/common/rng.h"
#include "core/matching/closed_form.h"
#include "core/matching/evaluation.h"
#include "core/matching/fit_input.h"
#include "core/matching/hole_table.h"
#include "core/matching/matching.h"
#include "core/matching/minimax.h"
#include "core/sim/probe_sim.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;
using namespace metrofit::matching;

double secondsSince(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

ProbePointSet randomSPiece(std::uint64_t seed) {
  Rng r(seed * 7919 + 13);
  ProbeSimOptions o = ProbeSimOptions::sPieceDefaults();
  for (double& a : o.rotationDeg) a = r.uniform(-0.5, 0.5);
  for (double& t : o.translationMm) t = r.uniform(-2.0, 2.0);
  o.seed = seed;
  return simulateProbing(o);
}

double rmseOf(const ProbePointSet& set, const Pose& pose) {
  double ss = 0.0;
  for (const ProbePoint& p : set.points) ss += (p.measured - pose.apply(p.nominal)).squaredNorm();
  return std::sqrt(ss / static_cast<double>(set.points.size()));
}

Pose eigenUmeyama(const ProbePointSet& set) {
  Eigen::Matrix3Xd q(3, set.points.size()), p(3, set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    q.col(static_cast<Eigen::Index>(i)) = set.points[i].nominal;
    p.col(static_cast<Eigen::Index>(i)) = set.points[i].measured;
  }
  const Eigen::Matrix4d T = Eigen::umeyama(q, p, false);
  Pose pose;
  pose.rotation = T.topLeftCorner<3, 3>();
  pose.translation = T.topRightCorner<3, 1>();
  return pose;
}

// (a) Translation-only minimax with normals by vertex enumeration.
double minimaxTranslationByVertices(const std::vector<Eigen::Vector3d>& n, const std::vector<double>& a) {
  // Constraints c . (t, z) >= b:  n_i . t + z >= a_i,  -n_i . t + z >= -a_i.
  std::vector<Eigen::Vector4d> c;
  std::vector<double> b;
  for (std::size_t i = 0; i < n.size(); ++i) {
    c.emplace_back(n[i].x(), n[i].y(), n[i].z(), 1.0);
    b.push_back(a[i]);
    c.emplace_back(-n[i].x(), -n[i].y(), -n[i].z(), 1.0);
    b.push_back(-a[i]);
  }
  const std::size_t m = c.size();
  double best = INFINITY;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k)
        for (std::size_t l = k + 1; l < m; ++l) {
          Eigen::Matrix4d A;
          A << c[i].transpose(), c[j].transpose(), c[k].transpose(), c[l].transpose();
          const Eigen::FullPivLU<Eigen::Matrix4d> lu(A);
          if (!lu.isInvertible() || std::abs(lu.determinant()) < 1e-10) continue;
          const Eigen::Vector4d x = lu.solve(Eigen::Vector4d(b[i], b[j], b[k], b[l]));
          bool feasible = true;
          for (std::size_t r = 0; r < m && feasible; ++r) feasible = c[r].dot(x) >= b[r] - 1e-11;
          if (feasible) best = std::min(best, x[3]);
        }
  return best;
}

// (b) Smallest enclosing circle radius of a few 2-D points (brute force, exact).
double enclosingRadius(const std::vector<Eigen::Vector2d>& v) {
  auto covers = [&](const Eigen::Vector2d& c, double r) {
    for (const auto& p : v)
      if ((p - c).norm() > r * (1 + 1e-12) + 1e-12) return false;
    return true;
  };
  double best = INFINITY;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) {
      const Eigen::Vector2d c = 0.5 * (v[i] + v[j]);
      const double r = 0.5 * (v[i] - v[j]).norm();
      if (r < best && covers(c, r)) best = r;
      for (std::size_t k = j + 1; k < v.size(); ++k) {
        const Eigen::Vector2d ab = v[j] - v[i], ac = v[k] - v[i];
        const double d = 2.0 * (ab.x() * ac.y() - ab.y() * ac.x());
        if (std::abs(d) < 1e-14) continue;
        const Eigen::Vector2d u((ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm()) / d,
                                (ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) / d);
        const double rr = u.norm();
        if (rr < best && covers(v[i] + u, rr)) best = rr;
      }
    }
  return best;
}

double planarMinimaxByCircles(const ProbePointSet& set, double thetaCentre) {
  auto F = [&](double th) {
    const Eigen::Rotation2Dd R(th);
    std::vector<Eigen::Vector2d> v;
    for (const ProbePoint& p : set.points) v.push_back(p.measured.head<2>() - R * p.nominal.head<2>());
    return enclosingRadius(v);
  };
  // Scan a bracket of +-0.02 rad around the least-squares angle, then golden section.
  double lo = thetaCentre - 0.02, hi = thetaCentre + 0.02;
  const int scan = 400;
  double bestTh = lo, bestF = INFINITY;
  for (int i = 0; i <= scan; ++i) {
    const double th = lo + (hi - lo) * i / scan;
    const double f = F(th);
    if (f < bestF) bestF = f, bestTh = th;
  }
  double a = bestTh - (hi - lo) / scan, b = bestTh + (hi - lo) / scan;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = F(x1), f2 = F(x2);
  for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = F(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = F(x2);
    }
  }
  return std::min({bestF, f1, f2});
}

}  // namespace

nlohmann::json benchMatching(const MatchingBenchOptions& options) {
  nlohmann::json out;
  // 1 + 2 (vs LS) + 3.
  int sadeWithin = 0, closedWithin = 0, minimaxNotWorse = 0;
  double worstSade = 0.0, worstClosed = 0.0, worstMinimaxExcess = -INFINITY;
  std::vector<double> sadeSeconds;
  for (int s = 1; s <= options.seeds; ++s) {
    const ProbePointSet set = randomSPiece(static_cast<std::uint64_t>(s));
    const double lsRmse = rmseOf(set, eigenUmeyama(set));
    ClosedFormOptions co;
    const double cfRmse = rmseOf(set, closedFormFit(set, co).pose);
    MatchOptions mo;
    mo.method = MatchMethod::Sade;
    mo.toleranceMm = kSPieceToleranceMm;
    mo.seed = static_cast<std::uint64_t>(s);
    const auto t0 = Clock::now();
    const MatchResult sade = matchPosture(set, mo);
    sadeSeconds.push_back(secondsSince(t0));
    const double sadeDiff = sade.after.overall.rmseMm - lsRmse;
    const double cfDiff = std::abs(cfRmse - lsRmse);
    worstSade = std::max(worstSade, sadeDiff);
    worstClosed = std::max(worstClosed, cfDiff);
    sadeWithin += sadeDiff <= 1e-6;
    closedWithin += cfDiff <= 1e-6;
    mo.method = MatchMethod::Minimax;
    const MatchResult mm = matchPosture(set, mo);
    const double lsMax = maxAbsDeviation(set, mm.closedForm->pose);
    worstMinimaxExcess = std::max(worstMinimaxExcess, mm.after.overall.maxAbsMm - lsMax);
    minimaxNotWorse += mm.after.overall.maxAbsMm <= lsMax + 1e-12;
  }
  std::printf(
      "matching  optimum agreement on %d S-pieces (40 points, random posture): closed form within 1e-6 mm "
      "rmse of Eigen::umeyama on %d/%d (worst |diff| %.3g mm); SADE paper settings on %d/%d (worst excess "
      "%.3g mm)\n",
      options.seeds, closedWithin, options.seeds, worstClosed, sadeWithin, options.seeds, worstSade);
  std::printf(
      "matching  minimax max|d| <= least-squares max|d| on %d/%d (largest minimax - LS: %.3g mm, negative = "
      "better)\n",
      minimaxNotWorse, options.seeds, worstMinimaxExcess);
  out["optimum"] = {{"cases", options.seeds},
                    {"closed_form_within_1e-6", closedWithin},
                    {"closed_form_worst_abs_diff_mm", worstClosed},
                    {"sade_within_1e-6", sadeWithin},
                    {"sade_worst_excess_mm", worstSade}};
  out["minimax_vs_ls"] = {{"cases", options.seeds},
                          {"not_worse", minimaxNotWorse},
                          {"largest_minimax_minus_ls_mm", worstMinimaxExcess}};

  // 2 (a) and (b): independent formulations on small cases.
  int aOk = 0, bOk = 0, aCases = 0, bCases = 0;
  double aWorst = 0.0, bWorst = 0.0;
  for (int s = 1; s <= options.seeds; ++s) {
    const ProbePointSet full = randomSPiece(static_cast<std::uint64_t>(100 + s));
    Rng r(static_cast<std::uint64_t>(s));
    // (a) 8 points: 2 plane, 2 of each hole, 1 of each ruled surface (normals span 3-D).
    ProbePointSet small;
    small.source = "small case";
    small.hasNormals = true;
    for (std::size_t idx : {r.below(8), 8 + r.below(4), 12 + r.below(4), 16 + r.below(12), 28 + r.below(12),
                            r.below(8), 8 + r.below(4), 12 + r.below(4)})
      small.points.push_back(full.points[idx]);
    for (std::size_t i = 0; i < small.points.size(); ++i) small.points[i].id = "S" + std::to_string(i);
    std::vector<Eigen::Vector3d> n;
    std::vector<double> a;
    for (const ProbePoint& p : small.points) {
      n.push_back(p.normal);
      a.push_back((p.measured - p.nominal).dot(p.normal));
    }
    try {
      MinimaxOptions mo;
      mo.locks = DofLocks::parse("rx,ry,rz", "bench");
      ClosedFormOptions co;
      co.locks = mo.locks;
      const MinimaxResult ours = minimaxFit(small, closedFormFit(small, co).pose, mo);
      const double indep = minimaxTranslationByVertices(n, a);
      const double diff = std::abs(ours.maxAbsMm - indep);
      aWorst = std::max(aWorst, diff);
      aOk += diff <= 1e-6;
      ++aCases;
    } catch (const std::exception& e) {
      std::printf("matching  small case (a) seed %d skipped: %s\n", s, e.what());
    }
    // (b) 6 planar position-only points.
    ProbePointSet planar;
    planar.source = "planar case";
    planar.planar = true;
    const double th = r.uniform(-0.01, 0.01);
    const Eigen::Vector2d t(r.uniform(-1, 1), r.uniform(-1, 1));
    for (int i = 0; i < 6; ++i) {
      ProbePoint p;
      p.id = "H" + std::to_string(i);
      p.nominal = Eigen::Vector3d(r.uniform(-100, 100), r.uniform(-100, 100), 0.0);
      const Eigen::Vector2d m = Eigen::Rotation2Dd(th) * p.nominal.head<2>() + t +
                                Eigen::Vector2d(r.normal(0.0, 0.01), r.normal(0.0, 0.01));
      p.measured = Eigen::Vector3d(m.x(), m.y(), 0.0);
      planar.points.push_back(p);
    }
    MinimaxOptions mo;
    mo.locks = effectiveLocks(planar, DofLocks{});
    ClosedFormOptions co;
    co.locks = mo.locks;
    const Pose ls = closedFormFit(planar, co).pose;
    const MinimaxResult ours = minimaxFit(planar, ls, mo);
    const double indep = planarMinimaxByCircles(planar, ls.anglesDeg().z() * kRadPerDeg);
    const double diff = std::abs(ours.maxAbsMm - indep);
    bWorst = std::max(bWorst, diff);
    bOk += diff <= 1e-6;
    ++bCases;
  }
  std::printf(
      "matching  minimax vs independent exact formulations: (a) translation LP by vertex enumeration, 8 "
      "points "
      "with normals: %d/%d within 1e-6 mm (worst %.3g mm); (b) planar rz,x,y by enclosing circles + golden "
      "section, 6 points: %d/%d (worst %.3g mm)\n",
      aOk, aCases, aWorst, bOk, bCases, bWorst);
  out["minimax_independent"] = {{"translation_lp_cases", aCases},    {"translation_lp_within_1e-6", aOk},
                                {"translation_lp_worst_mm", aWorst}, {"planar_circle_cases", bCases},
                                {"planar_circle_within_1e-6", bOk},  {"planar_circle_worst_mm", bWorst}};

  const double sadeMs = median(sadeSeconds) * 1e3;
  std::printf(
      "matching  SADE paper settings (NP 30, Gm 200) on the 40-point S-piece: median %.2f ms per run "
      "(rough + fine + evaluation, %d runs)\n",
      sadeMs, options.seeds);
  out["sade_40_points_ms"] = sadeMs;

  // 4. Closed form on many points against Eigen::umeyama.
  {
    const long n = options.largePoints;
    ProbePointSet big;
    big.source = "large";
    big.hasNormals = false;
    big.points.resize(static_cast<std::size_t>(n));
    Rng r(42);
    const Pose truth = Pose::fromAnglesDeg({0.3, -0.2, 0.5}, {1.0, -2.0, 0.5});
    Eigen::Matrix3Xd q(3, n), p(3, n);
    for (long i = 0; i < n; ++i) {
      ProbePoint& pt = big.points[static_cast<std::size_t>(i)];
      pt.nominal = Eigen::Vector3d(r.uniform(0, 500), r.uniform(0, 300), r.uniform(0, 200));
      pt.measured = truth.apply(pt.nominal) +
                    Eigen::Vector3d(r.normal(0, 0.005), r.normal(0, 0.005), r.normal(0, 0.005));
      q.col(i) = pt.nominal;
      p.col(i) = pt.measured;
    }
    std::vector<double> ours, peer;
    Pose ourPose;
    Eigen::Matrix4d peerT;
    for (int k = 0; k < options.repeat; ++k) {
      auto t0 = Clock::now();
      ourPose = closedFormFit(big, ClosedFormOptions{}).pose;
      ours.push_back(secondsSince(t0));
      t0 = Clock::now();
      peerT = Eigen::umeyama(q, p, false);
      peer.push_back(secondsSince(t0));
    }
    const double rotDiff = (ourPose.rotation - peerT.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff();
    const double tDiff = (ourPose.translation - peerT.topRightCorner<3, 1>()).cwiseAbs().maxCoeff();
    const double o = median(ours), e = median(peer);
    std::printf(
        "matching  closed form on %ld points: metrofit %.1f ms, Eigen::umeyama %.1f ms (on ready 3xN "
        "matrices); "
        "ratio metrofit/peer = %.2f; max |R diff| %.2g, max |t diff| %.2g mm\n",
        n, o * 1e3, e * 1e3, o / e, rotDiff, tDiff);
    out["large"] = {{"points", n},    {"metrofit_ms", o * 1e3},       {"umeyama_ms", e * 1e3},
                    {"ratio", o / e}, {"rotation_max_diff", rotDiff}, {"translation_max_diff_mm", tDiff}};
  }
  return out;
}

nlohmann::json benchRealMatching(const std::string& dataDir) {
  namespace fs = std::filesystem;
  nlohmann::json rows = nlohmann::json::array();
  std::vector<fs::path> fits;
  for (const auto& e : fs::directory_iterator(dataDir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("fit_", 0) == 0 && e.path().extension() == ".txt") fits.push_back(e.path());
  }
  std::sort(fits.begin(), fits.end());
  if (fits.empty()) {
    std::printf("real-matching  no fit_*.txt in %s\n", dataDir.c_str());
    return {{"rows", rows}};
  }
  std::printf(
      "real-matching  SDSS plug plates: our closed-form similarity fit (--allow-scale) vs the source "
      "program's FitPlugPlateMeas (fit_*.txt)\n");
  for (const fs::path& fit : fits) {
    // fit_<plate>_<n>_<date>.txt -> D<plate>_<n>
    static const std::regex name(R"(fit_([0-9A-Za-z]+)_([0-9]+)_.*\.txt)");
    std::smatch m;
    const std::string fname = fit.filename().string();
    if (!std::regex_match(fname, m, name)) continue;
    const fs::path report = fs::path(dataDir) / ("D" + m[1].str() + "_" + m[2].str());
    std::ifstream in(fit);
    std::string line;
    double offX = NAN, offY = NAN, scale = NAN, rot = NAN, rms = NAN;
    std::vector<std::array<double, 6>> table;  // NomX NomY MeasX MeasY ResidX ResidY
    bool inTable = false;
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      std::string key;
      ls >> key;
      if (key == "FitOffset")
        ls >> offX >> offY;
      else if (key == "FitScale")
        ls >> scale;
      else if (key == "FitRotAngle")
        ls >> rot;
      else if (key == "ResidRadErrRMS") {
        std::string tag;
        ls >> tag >> rms;
      } else if (key == "NomX")
        inTable = true;
      else if (inTable) {
        std::istringstream rs(line);
        std::array<double, 6> v{};
        if (rs >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5]) table.push_back(v);
      }
    }
    const ProbePointSet set = readProbePointsAnyFormat(report.string(), 3);
    ClosedFormOptions co;
    co.allowScale = true;
    co.locks = effectiveLocks(set, DofLocks{});
    const Pose pose = closedFormFit(set, co).pose;
    const double ourRms = rmseOf(set, pose);
    const double ourRot = pose.anglesDeg().z();
    // Per-hole residuals against the file's table (matched by nominal position).
    double residDiff = 0.0;
    std::size_t matched = 0;
    for (const auto& row : table) {
      for (const ProbePoint& p : set.points) {
        if (std::abs(p.nominal.x() - row[0]) < 5e-4 && std::abs(p.nominal.y() - row[1]) < 5e-4) {
          const Eigen::Vector3d r = p.measured - pose.apply(p.nominal);
          residDiff = std::max({residDiff, std::abs(r.x() - row[4]), std::abs(r.y() - row[5])});
          ++matched;
          break;
        }
      }
    }
    std::printf(
        "real-matching  %-10s %3zu holes: offset ours (%.4f, %.4f) theirs (%.3f, %.3f) mm; rotation ours "
        "%.4f "
        "theirs %.3f deg; scale-1 ours %.2f theirs %.1f ppm; rms ours %.4f theirs %.4f mm; per-hole "
        "residuals "
        "max |ours - theirs| %.4f mm (%zu of %zu holes matched)\n",
        report.filename().string().c_str(), set.points.size(), pose.translation.x(), pose.translation.y(),
        offX, offY, ourRot, rot, (pose.scale - 1.0) * 1e6, (scale - 1.0) * 1e6, ourRms, rms, residDiff,
        matched, table.size());
    rows.push_back({{"report", report.filename().string()},
                    {"holes", set.points.size()},
                    {"offset_mm", {pose.translation.x(), pose.translation.y()}},
                    {"oracle_offset_mm", {offX, offY}},
                    {"rotation_deg", ourRot},
                    {"oracle_rotation_deg", rot},
                    {"scale", pose.scale},
                    {"oracle_scale", scale},
                    {"rmse_mm", ourRms},
                    {"oracle_rmse_mm", rms},
                    {"offset_max_diff_mm",
                     std::max(std::abs(pose.translation.x() - offX), std::abs(pose.translation.y() - offY))},
                    {"rotation_diff_deg", ourRot - rot},
                    {"rmse_diff_mm", ourRms - rms},
                    {"residual_max_diff_mm", residDiff},
                    {"holes_matched", matched}});
  }
  return {{"rows", rows}};
}

}  // namespace metrofit::bench
