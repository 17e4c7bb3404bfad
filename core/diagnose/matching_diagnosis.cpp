#include "core/diagnose/matching_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <set>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "core/common/error.h"
#include "core/diagnose/loop.h"
#include "core/matching/closed_form.h"
#include "core/matching/fit_input.h"

namespace metrofit::diagnose {
namespace {

enum class Mode { Normal, Planar, Full };
enum class Kind { Scale, Offset, Distortion, Generic };

struct EffectDef {
  std::string name;
  Kind kind = Kind::Scale;
  int surface = -1;
  int params = 1;
  /// Generic (`unexplained:<against>`): the displacement of each of its parameters at every point
  /// (rows 3i..3i+2 = point i, part frame; GenericBasis) and its shape.
  std::shared_ptr<const struct GenericBasis> generic;
  std::optional<GenericForm> shape;
};

using A = PhraseArg;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

/// The fixed data of a set.
struct Problem {
  const ProbePointSet* set = nullptr;
  Mode mode = Mode::Full;
  Eigen::Vector3d qMean = Eigen::Vector3d::Zero();
  std::vector<std::string> surfaces;
  std::vector<int> surfaceOf;
  int perPoint = 3;  ///< observations per point
  int rigid = 6;     ///< rigid parameters (rotation increments, translation)
  std::size_t points() const { return set->points.size(); }
  std::size_t observations() const { return points() * static_cast<std::size_t>(perPoint); }
};

/// The problem of a point set: observation mode, observations per point, rigid parameters, nominal
/// centroid, surfaces in order of appearance.
Problem makeProblem(const ProbePointSet& set) {
  Problem pb;
  pb.set = &set;
  pb.mode = set.hasNormals ? Mode::Normal : (set.planar ? Mode::Planar : Mode::Full);
  pb.perPoint = pb.mode == Mode::Normal ? 1 : (pb.mode == Mode::Planar ? 2 : 3);
  pb.rigid = pb.mode == Mode::Planar ? 3 : 6;
  for (const ProbePoint& p : set.points) pb.qMean += p.nominal;
  pb.qMean /= static_cast<double>(set.points.size());
  for (const ProbePoint& p : set.points) {
    auto it = std::find(pb.surfaces.begin(), pb.surfaces.end(), p.surface);
    if (it == pb.surfaces.end()) {
      pb.surfaces.push_back(p.surface);
      it = pb.surfaces.end() - 1;
    }
    pb.surfaceOf.push_back(static_cast<int>(it - pb.surfaces.begin()));
  }
  return pb;
}

/// A generic effect's basis as the loop fits it. The shape's basis G (points x q, a function of one
/// variable: variableBasis) spread over the observed directions (along the normal: G n; else one
/// set of q columns per coordinate: `raw` = q * dims columns) and then PROJECTED OFF what the
/// posture and the catalogue's effects can do: the rigid motions and the displacements of every
/// named effect (scale, surface offsets, distortion), observed as the fit observes them. So a
/// generic effect explains only what neither the posture nor a named effect can, its coefficients
/// cannot trade against a named effect's (a bowed top face is not reported as a scale of -790 ppm
/// plus a generic effect cancelling it), and the named effects keep the share their columns
/// explain. Directions of G that the projection removes (singular value below 1e-6 of the largest
/// of the unprojected spread basis) are dropped: `displacement` has the r kept directions
/// (rows 3i..3i+2: point i, part frame), `toRaw` (raw x r) maps its coefficients to coefficients
/// of the spread basis (Candidate::genericCoefficients, read by matchingGenericDisplacement).
struct GenericBasis {
  Eigen::MatrixXd displacement;  ///< 3 n x r
  Eigen::MatrixXd observed;      ///< per n x r: `displacement` as the fit observes it (part frame)
  Eigen::MatrixXd toRaw;         ///< raw x r
};

int observedDims(const Problem& pb) {
  return pb.mode == Mode::Normal ? 1 : (pb.mode == Mode::Planar ? 2 : 3);
}

/// What the fit observes of displacement d at point i (part frame): the component along the nominal
/// normal, or the in-plane coordinates, or all three.
void observeAt(const Problem& pb, std::size_t i, const Eigen::Vector3d& d, Eigen::Ref<Eigen::VectorXd> out) {
  if (pb.mode == Mode::Normal)
    out(0) = pb.set->points[i].normal.dot(d);
  else
    out = d.head(pb.perPoint);
}

/// The displacement at point i of an observed vector (the inverse of observeAt on its directions).
Eigen::Vector3d unobserveAt(const Problem& pb, std::size_t i, const Eigen::Ref<const Eigen::VectorXd>& o) {
  if (pb.mode == Mode::Normal) return o(0) * pb.set->points[i].normal;
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  d.head(pb.perPoint) = o;
  return d;
}

void effectColumns(const Problem& pb, const EffectDef& e, std::size_t i, std::vector<Eigen::Vector3d>& out);

/// The named effects the catalogue offers for a set: scale, a surface offset per surface (with
/// normals), distortion.
std::vector<EffectDef> namedEffects(const Problem& pb) {
  std::vector<EffectDef> defs;
  defs.push_back({"scale", Kind::Scale, -1, 1, nullptr, std::nullopt});
  if (pb.set->hasNormals)
    for (std::size_t s = 0; s < pb.surfaces.size(); ++s)
      defs.push_back(
          {"surface_offset:" + pb.surfaces[s], Kind::Offset, static_cast<int>(s), 1, nullptr, std::nullopt});
  defs.push_back({"distortion", Kind::Distortion, -1, 2, nullptr, std::nullopt});
  return defs;
}

/// An orthonormal basis (per n rows) of what the posture and the named effects can do, observed.
Eigen::MatrixXd postureAndNamedSpace(const Problem& pb, const std::vector<EffectDef>& named) {
  const std::size_t n = pb.points();
  const int per = pb.perPoint;
  std::size_t k = 0;
  std::vector<std::vector<Eigen::Vector3d>> at(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d qc = pb.set->points[i].nominal - pb.qMean;
    std::vector<Eigen::Vector3d>& g = at[i];
    if (pb.mode == Mode::Planar) {
      g = {Eigen::Vector3d(-qc.y(), qc.x(), 0.0), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    } else {
      g = {Eigen::Vector3d::UnitX().cross(qc), Eigen::Vector3d::UnitY().cross(qc),
           Eigen::Vector3d::UnitZ().cross(qc), Eigen::Vector3d::UnitX(),
           Eigen::Vector3d::UnitY(),           Eigen::Vector3d::UnitZ()};
    }
    for (const EffectDef& e : named) effectColumns(pb, e, i, g);
    k = g.size();
  }
  Eigen::MatrixXd B(static_cast<Eigen::Index>(n) * per, static_cast<Eigen::Index>(k));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < k; ++j)
      observeAt(pb, i, at[i][j],
                B.block(static_cast<Eigen::Index>(i) * per, static_cast<Eigen::Index>(j), per, 1));
  for (Eigen::Index j = 0; j < B.cols(); ++j)
    if (const double nrm = B.col(j).norm(); nrm > 0.0) B.col(j) /= nrm;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(B);
  const Eigen::Index rank = qr.rank();
  return Eigen::MatrixXd(qr.householderQ()).leftCols(rank);
}

/// The shape's basis spread over the observed directions (raw: q * dims columns, coordinate-major
/// as Candidate::genericCoefficients), observed (per n rows).
Eigen::MatrixXd spreadObserved(const Problem& pb, const Eigen::MatrixXd& G) {
  const std::size_t n = pb.points();
  const int per = pb.perPoint, dims = observedDims(pb);
  const Eigen::Index q = G.cols();
  Eigen::MatrixXd O = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n) * per, q * dims);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    for (int c = 0; c < dims; ++c)
      for (Eigen::Index j = 0; j < q; ++j) {
        const Eigen::Vector3d d =
            G(row, j) * (pb.mode == Mode::Normal ? pb.set->points[i].normal : Eigen::Vector3d::Unit(c));
        observeAt(pb, i, d, O.block(row * per, c * q + j, per, 1));
      }
  }
  return O;
}

GenericBasis projectedGeneric(const Problem& pb, const Eigen::MatrixXd& G, const Eigen::MatrixXd& space) {
  const Eigen::MatrixXd O = spreadObserved(pb, G);
  const Eigen::MatrixXd P = O - space * (space.transpose() * O);
  GenericBasis b;
  const Eigen::BDCSVD<Eigen::MatrixXd> raw(O);
  const double top = raw.singularValues().size() ? raw.singularValues()(0) : 0.0;
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(P, Eigen::ComputeThinU | Eigen::ComputeThinV);
  Eigen::Index r = 0;
  while (r < svd.singularValues().size() && svd.singularValues()(r) > 1e-6 * top) ++r;
  b.toRaw = svd.matrixV().leftCols(r);
  b.observed = P * b.toRaw;
  const std::size_t n = pb.points();
  const int per = pb.perPoint;
  b.displacement.resize(3 * static_cast<Eigen::Index>(n), r);
  for (std::size_t i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < r; ++k)
      b.displacement.block<3, 1>(3 * static_cast<Eigen::Index>(i), k) =
          unobserveAt(pb, i, b.observed.block(static_cast<Eigen::Index>(i) * per, k, per, 1));
  return b;
}

/// Displacement columns of effect `e` at point i (part frame), one per parameter.
void effectColumns(const Problem& pb, const EffectDef& e, std::size_t i, std::vector<Eigen::Vector3d>& out) {
  const ProbePoint& p = pb.set->points[i];
  const Eigen::Vector3d qc = p.nominal - pb.qMean;
  switch (e.kind) {
    case Kind::Scale:
      out.push_back(1e-6 * qc);
      break;
    case Kind::Offset:
      out.push_back(pb.surfaceOf[i] == e.surface ? p.normal : Eigen::Vector3d::Zero());
      break;
    case Kind::Distortion:
      out.push_back(1e-6 * Eigen::Vector3d(qc.x(), -qc.y(), 0.0));
      out.push_back(1e-6 * Eigen::Vector3d(qc.y(), qc.x(), 0.0));
      break;
    case Kind::Generic: {
      const Eigen::MatrixXd& D = e.generic->displacement;
      const auto row = 3 * static_cast<Eigen::Index>(i);
      for (Eigen::Index k = 0; k < D.cols(); ++k) out.push_back(D.block<3, 1>(row, k));
      break;
    }
  }
}

struct FitState {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::VectorXd beta;
  Eigen::VectorXd r;                          ///< observation residuals
  std::vector<Eigen::Vector3d> partResidual;  ///< per point R^T (p - f(q)), part frame
  std::vector<double> deviation;              ///< per point: along the normal, or |residual|
  Eigen::MatrixXd rigidJ, effectJ;            ///< d model / d parameters at the optimum
  EffectEstimate est;                         ///< statistics of the linearised model
  double rss = 0.0;
  int iterations = 0;
};

class Fitter {
 public:
  Fitter(const Problem& pb, int maxIterations) : pb_(pb), maxIterations_(maxIterations) {}

  FitState fit(const std::vector<EffectDef>& effects, const Eigen::Matrix3d& R0,
               const Eigen::Vector3d& t0) const {
    int k = 0;
    for (const EffectDef& e : effects) k += e.params;
    FitState s;
    s.R = R0;
    s.t = t0;
    s.beta = Eigen::VectorXd::Zero(k);
    evaluate(effects, s);
    for (int it = 0; it < maxIterations_; ++it) {
      Eigen::MatrixXd A(s.r.size(), pb_.rigid + k);
      A.leftCols(pb_.rigid) = s.rigidJ;
      if (k > 0) A.rightCols(k) = s.effectJ;
      // Column scaling, then the minimum-norm (rank-revealing) Gauss-Newton step.
      Eigen::VectorXd scale(A.cols());
      for (Eigen::Index j = 0; j < A.cols(); ++j) {
        scale(j) = A.col(j).norm();
        if (scale(j) > 0.0) A.col(j) /= scale(j);
      }
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
      cod.setThreshold(1e-10);
      cod.compute(A);
      Eigen::VectorXd step = cod.solve(s.r);
      for (Eigen::Index j = 0; j < step.size(); ++j) step(j) = scale(j) > 0.0 ? step(j) / scale(j) : 0.0;
      FitState next = s;
      applyStep(step, next);
      evaluate(effects, next);
      ++s.iterations;
      const double change = s.rss - next.rss;
      if (next.rss <= s.rss) {
        next.iterations = s.iterations;
        s = std::move(next);
      } else {
        break;  // no further decrease: converged to rounding
      }
      if (change <= 1e-13 * std::max(s.rss, 1e-300) || s.rss == 0.0) break;
    }
    // Statistics on the model linearised at the optimum: y_lin = r + Z beta.
    const ColumnSpace declared(s.rigidJ);
    const Eigen::VectorXd yLin = k > 0 ? Eigen::VectorXd(s.r + s.effectJ * s.beta) : s.r;
    s.est = estimateEffects(declared, yLin, k > 0 ? s.effectJ : Eigen::MatrixXd(s.r.size(), 0));
    return s;
  }

 private:
  void applyStep(const Eigen::VectorXd& step, FitState& s) const {
    Eigen::Vector3d w = Eigen::Vector3d::Zero(), dt = Eigen::Vector3d::Zero();
    if (pb_.mode == Mode::Planar) {
      w.z() = step(0);
      dt.x() = step(1);
      dt.y() = step(2);
    } else {
      w = step.segment<3>(0);
      dt = step.segment<3>(3);
    }
    const double angle = w.norm();
    if (angle > 0.0) s.R = s.R * Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
    s.t += dt;
    s.beta += step.tail(s.beta.size());
  }

  void evaluate(const std::vector<EffectDef>& effects, FitState& s) const {
    const std::size_t n = pb_.points();
    const int per = pb_.perPoint;
    const auto k = s.beta.size();
    s.r.resize(static_cast<Eigen::Index>(n) * per);
    s.rigidJ.resize(s.r.size(), pb_.rigid);
    s.effectJ.resize(s.r.size(), k);
    s.partResidual.resize(n);
    s.deviation.resize(n);
    std::vector<Eigen::Vector3d> cols;
    for (std::size_t i = 0; i < n; ++i) {
      const ProbePoint& p = pb_.set->points[i];
      cols.clear();
      for (const EffectDef& e : effects) effectColumns(pb_, e, i, cols);
      Eigen::Vector3d qd = p.nominal;
      for (Eigen::Index j = 0; j < k; ++j) qd += s.beta(j) * cols[static_cast<std::size_t>(j)];
      const Eigen::Vector3d f = s.R * qd + s.t;
      const Eigen::Vector3d e = p.measured - f;
      s.partResidual[i] = s.R.transpose() * e;
      const Eigen::Matrix3d dRot = -s.R * skew(qd);  // d f / d w (right increment R Exp(w))
      const auto row = static_cast<Eigen::Index>(i) * per;
      if (pb_.mode == Mode::Normal) {
        const Eigen::Vector3d nr = s.R * p.normal;
        s.r(row) = nr.dot(e);
        s.deviation[i] = s.r(row);
        s.rigidJ.block(row, 0, 1, 3) = nr.transpose() * dRot;
        s.rigidJ.block(row, 3, 1, 3) = nr.transpose();
        for (Eigen::Index j = 0; j < k; ++j)
          s.effectJ(row, j) = nr.dot(s.R * cols[static_cast<std::size_t>(j)]);
      } else if (pb_.mode == Mode::Planar) {
        s.r.segment<2>(row) = e.head<2>();
        s.deviation[i] = e.head<2>().norm();
        s.rigidJ.block(row, 0, 2, 1) = dRot.block<2, 1>(0, 2);
        s.rigidJ.block(row, 1, 2, 2) = Eigen::Matrix2d::Identity();
        for (Eigen::Index j = 0; j < k; ++j)
          s.effectJ.block(row, j, 2, 1) = (s.R * cols[static_cast<std::size_t>(j)]).head<2>();
      } else {
        s.r.segment<3>(row) = e;
        s.deviation[i] = e.norm();
        s.rigidJ.block(row, 0, 3, 3) = dRot;
        s.rigidJ.block(row, 3, 3, 3) = Eigen::Matrix3d::Identity();
        for (Eigen::Index j = 0; j < k; ++j)
          s.effectJ.block(row, j, 3, 1) = s.R * cols[static_cast<std::size_t>(j)];
      }
    }
    s.rss = s.r.squaredNorm();
  }

  const Problem& pb_;
  int maxIterations_;
};

ErrorSummary summarise(const FitState& s, std::size_t points) {
  ErrorSummary e;
  e.rmse = std::sqrt(s.rss / static_cast<double>(std::max<std::size_t>(points, 1)));
  for (double d : s.deviation) e.maxAbs = std::max(e.maxAbs, std::abs(d));
  return e;
}

/// The value plotted for a point: along the normal, or the in-plane radial component about the centroid.
double radialValue(const Problem& pb, const FitState& s, std::size_t i) {
  if (pb.mode == Mode::Normal) return s.deviation[i];
  const Eigen::Vector3d qc = pb.set->points[i].nominal - pb.qMean;
  const double r = qc.head<2>().norm();
  return r > 0.0 ? s.partResidual[i].head<2>().dot(qc.head<2>()) / r : 0.0;
}

ResidualPlot makePlot(const Problem& pb, const EffectDef& e, const FitState& before, const FitState& after) {
  ResidualPlot plot;
  const std::size_t n = pb.points();
  const bool normal = pb.mode == Mode::Normal;
  switch (e.kind) {
    case Kind::Scale:
      plot.setLabels({Phrase("distance from the centroid (mm)")},
                     {Phrase(normal ? "deviation along the normal (mm)" : "radial residual (mm)")});
      for (std::size_t i = 0; i < n; ++i) {
        plot.x.push_back((pb.set->points[i].nominal - pb.qMean).norm());
        plot.before.push_back(radialValue(pb, before, i));
        plot.after.push_back(radialValue(pb, after, i));
      }
      break;
    case Kind::Offset:
      plot.setLabels({Phrase("surface")}, {Phrase("deviation along the normal (mm)")});
      plot.categories = pb.surfaces;
      for (std::size_t i = 0; i < n; ++i) {
        plot.x.push_back(pb.surfaceOf[i]);
        plot.before.push_back(before.deviation[i]);
        plot.after.push_back(after.deviation[i]);
      }
      break;
    case Kind::Distortion:
      plot.setLabels({Phrase("polar angle (deg)")},
                     {Phrase(normal ? "deviation along the normal (mm)" : "radial residual (mm)")});
      for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d qc = pb.set->points[i].nominal - pb.qMean;
        plot.x.push_back(std::atan2(qc.y(), qc.x()) * 180.0 / std::numbers::pi);
        plot.before.push_back(radialValue(pb, before, i));
        plot.after.push_back(radialValue(pb, after, i));
        const Eigen::Vector3d& q = pb.set->points[i].nominal;
        const Eigen::Vector3d& d = before.partResidual[i];
        plot.vectors.push_back({q.x(), q.y(), d.x(), d.y()});
      }
      break;
    case Kind::Generic:
      break;  // plotted from its variable (runMatching)
  }
  return plot;
}

/// Parameters of an effect from its slice of beta / covariance.
std::vector<Parameter> parameters(const EffectDef& e, const Eigen::VectorXd& beta, const Eigen::MatrixXd& cov,
                                  Eigen::Index at) {
  std::vector<Parameter> out;
  auto se = [&](Eigen::Index j) { return std::sqrt(std::max(0.0, cov(j, j))); };
  switch (e.kind) {
    case Kind::Scale:
      out.push_back({"ppm", beta(at), se(at)});
      break;
    case Kind::Offset:
      out.push_back({"mm", beta(at), se(at)});
      break;
    case Kind::Distortion: {
      const double c = beta(at), s = beta(at + 1);
      const double ppm = std::hypot(c, s);
      double angle = 0.5 * std::atan2(s, c) * 180.0 / std::numbers::pi;
      if (angle <= -90.0) angle += 180.0;
      const Eigen::Matrix2d C = cov.block<2, 2>(at, at);
      std::optional<double> sePpm, seAngle;
      if (ppm > 0.0) {
        const Eigen::Vector2d g(c / ppm, s / ppm);
        const Eigen::Vector2d h(-s / (ppm * ppm), c / (ppm * ppm));
        sePpm = std::sqrt(std::max(0.0, g.dot(C * g)));
        seAngle = 0.5 * std::sqrt(std::max(0.0, h.dot(C * h))) * 180.0 / std::numbers::pi;
      }
      out.push_back({"ppm", ppm, sePpm});
      out.push_back({"angle_deg", angle, seAngle});
      break;
    }
    case Kind::Generic:
      break;  // genericParameters
  }
  return out;
}

/// "ppm = 12.3 +- 0.45, angle_deg = ..." (the parameter keys as they are).
Phrases describe(const std::vector<Parameter>& ps) {
  Phrases s;
  for (const Parameter& p : ps) {
    const bool first = s.empty();
    if (p.standardError)
      s.push_back(
          Phrase(first ? "%1 = %2 +- %3" : ", %1 = %2 +- %3",
                 {A::name(p.name), A::number(std::get<double>(p.value), 4), A::number(*p.standardError, 2)}));
    else
      s.push_back(Phrase(first ? "%1 = %2" : ", %1 = %2",
                         {A::name(p.name), A::number(std::get<double>(p.value), 4)}));
  }
  return s;
}

/// The residual variables of a point set (docs/file-formats.md#residual_check): row (file order), the
/// nominal coordinates x, y (z when it varies), the polar angle about the centroid, the surface
/// (one level each), the nominal normal's components nx, ny, nz, and per surface with at least 6
/// points surface:<s> = the position along the surface's longest principal direction (NaN on the
/// other points).
std::vector<ResidualVariable> matchingVariables(const Problem& pb, const std::vector<std::size_t>& orig) {
  const std::size_t n = pb.points();
  std::vector<ResidualVariable> vars;
  auto add = [&](std::string name, Phrases label, auto value, bool order = false) {
    ResidualVariable v;
    v.name = std::move(name);
    v.label = std::move(label);
    v.naturalOrder = order;
    for (std::size_t i = 0; i < n; ++i) v.values.push_back(value(i));
    const auto [lo, hi] = std::minmax_element(v.values.begin(), v.values.end());
    if (n > 0 && *hi - *lo > 1e-9 * std::max(1.0, std::abs(*hi))) vars.push_back(std::move(v));
  };
  const auto& P = pb.set->points;
  add(
      "row", {Phrase("data row")}, [&](std::size_t i) { return static_cast<double>(orig[i] + 1); }, true);
  add("x", {Phrase("x (mm)")}, [&](std::size_t i) { return P[i].nominal.x(); });
  add("y", {Phrase("y (mm)")}, [&](std::size_t i) { return P[i].nominal.y(); });
  add("z", {Phrase("z (mm)")}, [&](std::size_t i) { return P[i].nominal.z(); });
  {
    ResidualVariable a;
    a.name = "angle";
    a.kind = ResidualVariable::Kind::Angle;
    a.label = {Phrase("polar angle (deg)")};
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d qc = P[i].nominal - pb.qMean;
      a.values.push_back(std::atan2(qc.y(), qc.x()) * 180.0 / std::numbers::pi);
    }
    vars.push_back(std::move(a));
  }
  if (pb.surfaces.size() > 1) {
    ResidualVariable s;
    s.name = "surface";
    s.kind = ResidualVariable::Kind::Category;
    s.label = {Phrase("surface")};
    s.levels = pb.surfaces;
    for (std::size_t i = 0; i < n; ++i) s.values.push_back(pb.surfaceOf[i]);
    vars.push_back(std::move(s));
  }
  if (pb.set->hasNormals) {
    add("nx", {Phrase("normal x")}, [&](std::size_t i) { return P[i].normal.x(); });
    add("ny", {Phrase("normal y")}, [&](std::size_t i) { return P[i].normal.y(); });
    add("nz", {Phrase("normal z")}, [&](std::size_t i) { return P[i].normal.z(); });
  }
  for (std::size_t s = 0; s < pb.surfaces.size() && pb.surfaces.size() > 1; ++s) {
    std::vector<std::size_t> on;
    for (std::size_t i = 0; i < n; ++i)
      if (pb.surfaceOf[i] == static_cast<int>(s)) on.push_back(i);
    if (on.size() < 6) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t i : on) mean += P[i].nominal;
    mean /= static_cast<double>(on.size());
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (std::size_t i : on) C += (P[i].nominal - mean) * (P[i].nominal - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
    const Eigen::Vector3d dir = es.eigenvectors().col(2);
    ResidualVariable v;
    v.name = "surface:" + pb.surfaces[s];
    v.label = {Phrase("position along surface %1 (mm)", {A::name(pb.surfaces[s])})};
    v.values.assign(n, std::nan(""));
    for (std::size_t i : on) v.values[i] = (P[i].nominal - mean).dot(dir);
    vars.push_back(std::move(v));
  }
  return vars;
}

/// The residual check input of a fit: one observation per coordinate the fit uses, the variables
/// repeated on the coordinates of a point, units = points.
ResidualCheckInput matchingCheckInput(const Problem& pb, const FitState& s,
                                      const std::vector<ResidualVariable>& vars,
                                      const std::vector<std::size_t>& orig) {
  ResidualCheckInput in;
  const int per = pb.perPoint;
  in.components = per;
  in.residual = s.r;
  in.modelColumns.resize(s.r.size(), s.rigidJ.cols() + s.effectJ.cols());
  in.modelColumns << s.rigidJ, s.effectJ;
  for (const ResidualVariable& v : vars) {
    ResidualVariable w = v;
    w.values.clear();
    for (double x : v.values)
      for (int c = 0; c < per; ++c) w.values.push_back(x);
    in.variables.push_back(std::move(w));
  }
  for (std::size_t i = 0; i < pb.points(); ++i) {
    for (int c = 0; c < per; ++c) in.unitOf.push_back(i);
    in.unitRow.push_back(static_cast<long>(orig[i] + 1));
    in.unitId.push_back(pb.set->points[i].id);
  }
  return in;
}

/// Parameters of a generic effect from its coefficients: the rms and range of what it adds to the
/// observations (the projected basis is no function of the variable alone, so its summary is that
/// of its contribution; summariseContribution).
std::vector<Parameter> genericParameters(const EffectDef& e, const Eigen::VectorXd& beta, Eigen::Index at,
                                         Phrases* text) {
  std::vector<Parameter> out = {Parameter{"form", std::string(formName(e.shape->form)), std::nullopt}};
  const Eigen::VectorXd contribution = e.generic->observed * beta.segment(at, e.params);
  const GenericSummary gs = summariseContribution(*e.shape, contribution, "mm");
  for (const auto& [k, val] : gs.numbers) out.push_back({k, val, std::nullopt});
  if (text) *text = gs.text;
  return out;
}

}  // namespace

bool MatchingDiagnosisOptions::isValid(std::string* why) const {
  if (!acceptance.isValid(why)) return false;
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(toleranceMm > 0.0) || !std::isfinite(toleranceMm)) return no("the tolerance must be positive");
  if (!(relevantFractionOfTolerance >= 0.0 && relevantFractionOfTolerance <= 1.0))
    return no("the relevant fraction of the tolerance must be in [0, 1]");
  if (maxRounds < 0 || maxRounds > 1000) return no("max rounds must be in 0..1000");
  if (maxIterations < 1 || maxIterations > 10000) return no("max iterations must be in 1..10000");
  return true;
}

namespace {

LoopRun runMatching(const ProbePointSet& set, const std::vector<std::size_t>& orig,
                    const MatchingDiagnosisOptions& options, const std::set<std::string>& excluded,
                    Observer* observer) {
  const matching::DofLocks locks = matching::effectiveLocks(set, {});
  matching::requireDeterminable(set, locks, false, matching::FitKind::LeastSquares, "matching diagnosis");

  const Problem pb = makeProblem(set);
  const std::size_t nPts = pb.points();

  const std::vector<EffectDef> defs = namedEffects(pb);
  // The generic bases are projected off the posture and the named effects of this run (not those
  // keepNamedOnlyWhenNeeded excluded: without a named effect, a generic one may take its share).
  std::vector<EffectDef> open;
  std::vector<std::string> openNames;
  if (!excluded.count(kEveryNamedEffect))
    for (const EffectDef& e : defs)
      if (!excluded.count(e.name)) {
        open.push_back(e);
        openNames.push_back(e.name);
      }
  const Eigen::MatrixXd space = postureAndNamedSpace(pb, open);

  matching::ClosedFormOptions cf;
  cf.locks = locks;
  const matching::ClosedFormResult start = matching::closedFormFit(set, cf);
  const Fitter fitter(pb, options.maxIterations);

  AcceptanceOptions acceptance = options.acceptance;
  acceptance.minAbsoluteReduction =
      std::max(acceptance.minAbsoluteReduction, options.relevantFractionOfTolerance * options.toleranceMm);

  Diagnosis result;
  result.domain = "matching";
  result.units = "mm";
  std::vector<EffectDef> acceptedDefs;
  FitState current = fitter.fit(acceptedDefs, start.pose.rotation, start.pose.translation);
  result.baseline = summarise(current, nPts);
  {
    matching::Pose pose;
    pose.rotation = current.R;
    pose.translation = current.t;
    const Eigen::Vector3d a = pose.anglesDeg();
    const char* fitted = pb.mode == Mode::Normal
                             ? "the deviations along the nominal normals"
                             : (pb.mode == Mode::Planar ? "the in-plane residuals (planar, position-only)"
                                                        : "the residual vectors (position-only)");
    result.addNote({Phrase("declared model: rigid posture p = R q + t fitted to %1, %2 points",
                           {A::text({Phrase(fitted)}), A::integer(static_cast<long long>(nPts))})});
    result.addNote(
        {Phrase("declared fit: rotation_deg [%1, %2, %3], translation_mm [%4, %5, %6]",
                {A::fixed(a.x(), 5), A::fixed(a.y(), 5), A::fixed(a.z(), 5), A::fixed(current.t.x(), 4),
                 A::fixed(current.t.y(), 4), A::fixed(current.t.z(), 4)})});
  }

  const std::vector<ResidualVariable> vars = matchingVariables(pb, orig);

  /// The matching domain of the shared loop (loop.h): the rigid posture plus effects, fitted by
  /// Gauss-Newton, the evidence from the model linearised at the optimum.
  class Domain final : public LoopDomain {
   public:
    Domain(const Problem& pb, const Fitter& fitter, const AcceptanceOptions& acceptance,
           const std::vector<EffectDef>& defs, const Eigen::MatrixXd& space,
           const std::vector<std::string>& spaceNames, const std::vector<ResidualVariable>& vars,
           const std::vector<std::size_t>& orig, FitState start)
        : pb_(pb),
          fitter_(fitter),
          acceptance_(acceptance),
          defs_(defs),
          space_(space),
          spaceNames_(spaceNames),
          vars_(vars),
          orig_(orig),
          current_(std::move(start)),
          used_(defs.size(), false) {}

    std::vector<std::string> namedCandidates(const std::set<std::string>& excluded) override {
      std::vector<std::string> names;
      for (const auto& d : defs_) names.push_back(d.name);
      return openNamedEffects(names, used_, excluded);
    }
    // The variables of the named effects (loop.h, "a generic effect of the same variable explains
    // clearly more"): a surface's offset is a function of that surface (surface:<s>, the surface
    // category); scale and distortion are functions of the position (x, y, z; distortion also of the
    // polar angle).
    std::vector<std::string> namedVariables(const Candidate& c) const override {
      if (c.name.starts_with("surface_offset:")) return {"surface:" + c.name.substr(15), "surface"};
      if (c.name == "scale") return {"x", "y", "z"};
      if (c.name == "distortion") return {"x", "y", "angle"};
      return {};
    }
    double clearMargin() const override { return acceptance_.bicThreshold; }
    ResidualCheck roundCheck() override {
      return checkResidual(matchingCheckInput(pb_, current_, vars_, orig_));
    }
    std::optional<GenericForm> prepareGeneric(const GenericForm& g) override {
      if (!findVariable(vars_, g.against)) return std::nullopt;
      GenericForm f = g;
      f.components = 1;  // per point; effectColumns spreads it over the coordinates
      return f;
    }
    bool beginRound(int) override {
      slots_.clear();
      return true;
    }
    std::optional<LoopTrial> tryNamed(const std::string& name, int, std::size_t slot) override {
      for (const EffectDef& e : defs_)
        if (e.name == name) return fit(e, 0.0, slot);
      return std::nullopt;
    }
    std::optional<LoopTrial> tryGeneric(const GenericForm& g, double penalty, int,
                                        std::size_t slot) override {
      EffectDef e;
      e.name = "unexplained:" + g.against;
      e.kind = Kind::Generic;
      e.generic = std::make_shared<const GenericBasis>(
          projectedGeneric(pb_, variableBasis(g, *findVariable(vars_, g.against)), space_));
      e.shape = g;
      e.shape->projectedOff = spaceNames_;
      e.params = static_cast<int>(e.generic->displacement.cols());
      if (e.params == 0) {  // all of it is posture or a named effect
        LoopTrial t;
        t.candidate.name = e.name;
        t.candidate.generic = e.shape;
        t.candidate.rmseBefore = t.candidate.rmseAfter = summarise(current_, pb_.points()).rmse;
        t.candidate.parameters = {Parameter{"form", std::string(formName(g.form)), std::nullopt}};
        t.candidate.setEvidence(
            {Phrase("not identifiable: the posture and the catalogue's effects explain all of it")});
        if (slots_.size() <= slot) slots_.resize(slot + 1);
        slots_[slot] = Slot{e, current_};
        return t;
      }
      return fit(e, penalty, slot);
    }
    void accept(std::size_t slot, Candidate&) override {
      Slot& s = slots_[slot];
      for (std::size_t c = 0; c < defs_.size(); ++c)
        if (defs_[c].name == s.def.name && s.def.kind != Kind::Generic) used_[c] = true;
      accepted_.push_back(s.def);
      current_ = std::move(s.state);
    }
    double currentError() const override { return summarise(current_, pb_.points()).rmse; }
    void finish(Diagnosis& d, std::vector<Candidate*> accepted, bool) override {
      // Accepted effects carry the parameters of the final joint fit.
      Eigen::Index at = 0;
      for (std::size_t j = 0; j < accepted.size(); ++j) {
        accepted[j]->parameters = accepted_[j].kind == Kind::Generic
                                      ? genericParameters(accepted_[j], current_.beta, at, nullptr)
                                      : parameters(accepted_[j], current_.beta, current_.est.covariance, at);
        if (accepted_[j].kind == Kind::Generic) {
          const Eigen::VectorXd w =
              accepted_[j].generic->toRaw * current_.beta.segment(at, accepted_[j].params);
          accepted[j]->genericCoefficients.assign(w.data(), w.data() + w.size());
        }
        at += accepted_[j].params;
      }
      d.final = summarise(current_, pb_.points());
      d.residualCheck = checkResidual(matchingCheckInput(pb_, current_, vars_, orig_));
    }
    double dataCriterion() const override {
      const auto n = static_cast<double>(pb_.observations());
      return n * std::log(std::max(current_.rss, 1e-300) / n);
    }

   private:
    struct Slot {
      EffectDef def;
      FitState state;
    };
    LoopTrial fit(const EffectDef& e, double penalty, std::size_t slot) {
      const std::size_t nObs = pb_.observations(), nPts = pb_.points();
      const bool generic = e.kind == Kind::Generic;
      std::vector<EffectDef> trial = accepted_;
      trial.push_back(e);
      FitState st = fitter_.fit(trial, current_.R, current_.t);
      LoopTrial t;
      Candidate& cand = t.candidate;
      cand.name = e.name;
      const double rmseBefore = summarise(current_, nPts).rmse;
      cand.rmseBefore = rmseBefore;
      const auto at = static_cast<Eigen::Index>(st.beta.size() - e.params);
      if (!st.est.identifiable) {
        cand.rmseAfter = rmseBefore;
        cand.parameters = parameters(e, Eigen::VectorXd::Zero(st.beta.size()),
                                     Eigen::MatrixXd::Zero(st.beta.size(), st.beta.size()), at);
        for (Parameter& p : cand.parameters) p.standardError.reset();
        cand.setEvidence({Phrase("not identifiable: %1 (the rigid posture explains it with these points)",
                                 {A::text({Phrase(st.est.why)})})});
      } else {
        t.estimable = true;
        Phrases genericText;
        cand.parameters = generic ? genericParameters(e, st.beta, at, &genericText)
                                  : parameters(e, st.beta, st.est.covariance, at);
        cand.rmseAfter = summarise(st, nPts).rmse;
        const AcceptanceDecision dec = decideAcceptance(acceptance_, current_.rss, st.rss, nObs,
                                                        current_.est.dof, e.params, "mm", nPts, penalty);
        cand.score = deltaBic(current_.rss, st.rss, nObs, current_.est.dof, e.params, penalty);
        cand.setEvidence({Phrase("%1; %2", {A::text(generic ? genericText : describe(cand.parameters)),
                                            A::text(dec.reasonParts)})});
        if (generic)
          cand.generic = e.shape;
        else
          cand.plot = makePlot(pb_, e, current_, st);
        t.passes = dec.accepted;
        t.complexity = e.params * std::log(static_cast<double>(nObs)) + penalty;
      }
      if (slots_.size() <= slot) slots_.resize(slot + 1);
      slots_[slot] = Slot{e, std::move(st)};
      return t;
    }

    const Problem& pb_;
    const Fitter& fitter_;
    const AcceptanceOptions& acceptance_;
    const std::vector<EffectDef>& defs_;
    const Eigen::MatrixXd& space_;
    const std::vector<std::string>& spaceNames_;
    const std::vector<ResidualVariable>& vars_;
    const std::vector<std::size_t>& orig_;
    FitState current_;
    std::vector<bool> used_;
    std::vector<EffectDef> accepted_;
    std::vector<Slot> slots_;
  };

  Domain domain(pb, fitter, acceptance, defs, space, openNames, vars, orig, std::move(current));
  LoopStyle style;
  style.maxRounds = options.maxRounds;
  style.tiesWithPoints = true;
  return runLoop(domain, style, excluded, observer, std::move(result));
}

/// The declared (rigid) fit's residual per observation, for the outlier search.
FitState declaredFit(const ProbePointSet& set, const Problem& pb, const MatchingDiagnosisOptions& options) {
  matching::ClosedFormOptions cf;
  cf.locks = matching::effectiveLocks(set, {});
  const matching::ClosedFormResult start = matching::closedFormFit(set, cf);
  return Fitter(pb, options.maxIterations).fit({}, start.pose.rotation, start.pose.translation);
}

}  // namespace

Diagnosis diagnoseMatching(const ProbePointSet& set, const MatchingDiagnosisOptions& options,
                           Observer* observer) {
  requireValid(options, "matching diagnosis options");
  const matching::DofLocks locks = matching::effectiveLocks(set, {});
  matching::requireDeterminable(set, locks, false, matching::FitKind::LeastSquares, "matching diagnosis");
  // Gross errors (`outliers`, docs/file-formats.md#residual_check): found on the rigid fit's residual (robust
  // z per coordinate, see residual_check.h), the points excluded and the loop run without them.
  const Problem pb = makeProblem(set);
  const FitState declared = declaredFit(set, pb, options);
  std::vector<std::size_t> all(set.points.size());
  std::iota(all.begin(), all.end(), 0);
  ResidualCheckInput in;
  in.residual = declared.r;
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    for (int c = 0; c < pb.perPoint; ++c) in.unitOf.push_back(i);
    in.unitRow.push_back(static_cast<long>(i + 1));
    in.unitId.push_back(set.points[i].id);
  }
  double threshold = 0.0;
  std::vector<Outlier> outliers = findOutliers(in, {}, &threshold);
  std::vector<bool> excluded(set.points.size(), false);
  for (const Outlier& o : outliers) excluded[o.unit] = true;
  ProbePointSet kept = set;
  kept.points.clear();
  std::vector<std::size_t> orig;
  for (std::size_t i = 0; i < set.points.size(); ++i)
    if (!excluded[i]) {
      kept.points.push_back(set.points[i]);
      orig.push_back(i);
    }
  if (!outliers.empty()) {
    // The rest must still determine the posture; otherwise keep every point.
    try {
      matching::requireDeterminable(kept, matching::effectiveLocks(kept, {}), false,
                                    matching::FitKind::LeastSquares, "matching diagnosis");
    } catch (const std::exception&) {
      kept = set;
      orig = all;
      outliers.clear();
    }
  }
  Diagnosis result = keepNamedOnlyWhenNeeded(
      [&](const std::set<std::string>& ex) { return runMatching(kept, orig, options, ex, observer); },
      options.acceptance.bicThreshold, /*genericDependsOnNamed=*/true);
  attachOutliers(result, std::move(outliers), threshold, [](const Outlier& o) {
    return Phrase(" point %1 (row %2, %3 mm)",
                  {A::name(o.id.value_or("")), A::integer(o.row.value_or(0)), A::number(o.residual, 3)});
  });
  return result;
}

std::vector<Eigen::Vector3d> matchingGenericDisplacement(const ProbePointSet& set, const GenericForm& shape,
                                                         const std::vector<double>& coefficients) {
  if (set.points.empty()) return {};
  const Problem pb = makeProblem(set);
  std::vector<std::size_t> orig(set.points.size());
  std::iota(orig.begin(), orig.end(), 0);
  const std::vector<ResidualVariable> vars = matchingVariables(pb, orig);
  const ResidualVariable* v = findVariable(vars, shape.against);
  if (!v) return {};
  GenericForm f = shape;
  f.components = 1;
  const Eigen::MatrixXd O = spreadObserved(pb, variableBasis(f, *v));
  if (static_cast<Eigen::Index>(coefficients.size()) != O.cols()) return {};
  // What the loop fitted (projectedGeneric): the spread basis with the coefficients, without what
  // the posture and the named effects of its run (shape.projectedOff) can do.
  std::vector<EffectDef> named;
  for (const EffectDef& e : namedEffects(pb))
    if (std::find(shape.projectedOff.begin(), shape.projectedOff.end(), e.name) != shape.projectedOff.end())
      named.push_back(e);
  const Eigen::MatrixXd space = postureAndNamedSpace(pb, named);
  const Eigen::VectorXd c = Eigen::Map<const Eigen::VectorXd>(coefficients.data(), O.cols());
  Eigen::VectorXd o = O * c;
  o -= space * (space.transpose() * o);
  const std::size_t n = set.points.size();
  std::vector<Eigen::Vector3d> d(n);
  for (std::size_t i = 0; i < n; ++i)
    d[i] = unobserveAt(pb, i, o.segment(static_cast<Eigen::Index>(i) * pb.perPoint, pb.perPoint));
  return d;
}

}  // namespace metrofit::diagnose
