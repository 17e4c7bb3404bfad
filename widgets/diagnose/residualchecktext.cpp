#include "widgets/diagnose/residualchecktext.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

#include "widgets/diagnose/coretexts.h"

namespace metrofit {
namespace {

struct ResidualCheckText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ResidualCheck)
};

bool startsWith(const std::string& s, const char* prefix, std::string* rest) {
  const std::string p = prefix;
  if (s.size() <= p.size() || s.compare(0, p.size(), p) != 0) return false;
  *rest = s.substr(p.size());
  return true;
}

QString q(const std::string& s) {
  return QString::fromStdString(s);
}

QString unitText(const std::string& units) {
  return displayUnit(q(units));
}

}  // namespace

QString residualTestName(const std::string& name) {
  if (name == "ljung_box") return ResidualCheckText::tr("Ljung-Box");
  if (name == "f_test") return ResidualCheckText::tr("F test");
  return q(name);
}

QString residualVariableName(const std::string& against) {
  std::string rest;
  if (against == "time") return ResidualCheckText::tr("time");
  if (against == "row") return ResidualCheckText::tr("file row");
  if (against == "angle") return ResidualCheckText::tr("path angle");
  if (against == "direction") return ResidualCheckText::tr("loop direction");
  if (against == "reversal") return ResidualCheckText::tr("samples since reversal");
  if (against == "normal") return ResidualCheckText::tr("along the normal");
  if (against == "part") return ResidualCheckText::tr("part");
  if (against == "dimension") return ResidualCheckText::tr("dimension");
  if (against == "surface") return ResidualCheckText::tr("surface");
  if (against == "nx" || against == "ny" || against == "nz")
    return ResidualCheckText::tr("normal %1").arg(q(against.substr(1)));
  if (startsWith(against, "surface:", &rest)) return ResidualCheckText::tr("surface %1").arg(q(rest));
  if (startsWith(against, "dimension:", &rest)) return ResidualCheckText::tr("dimension %1").arg(q(rest));
  return q(against);  // x, y, z and the columns of the file keep their names
}

QString residualVariableWords(const std::string& against) {
  std::string rest;
  // In a sentence ("depends on %1", "a smooth curve in %1"): German dative, Polish genitive.
  if (against == "time") return ResidualCheckText::tr("time", "in a sentence");
  if (against == "row") return ResidualCheckText::tr("the order of the rows in the file");
  if (against == "angle") return ResidualCheckText::tr("the path angle");
  if (against == "direction")
    return ResidualCheckText::tr("the direction of the loop (counter-clockwise or clockwise)");
  if (against == "reversal") return ResidualCheckText::tr("the number of samples since an axis reversed");
  if (against == "x" || against == "y" || against == "z")
    return ResidualCheckText::tr("the nominal %1 coordinate").arg(q(against));
  if (against == "normal") return ResidualCheckText::tr("the position along the nominal normal");
  if (against == "part") return ResidualCheckText::tr("the part");
  if (against == "dimension") return ResidualCheckText::tr("the dimension");
  if (against == "surface") return ResidualCheckText::tr("the surface");
  if (against == "nx" || against == "ny" || against == "nz")
    return ResidualCheckText::tr("the %1 component of the nominal normal").arg(q(against.substr(1)));
  if (startsWith(against, "surface:", &rest))
    return ResidualCheckText::tr("the position on surface %1").arg(q(rest));
  if (startsWith(against, "dimension:", &rest))
    return ResidualCheckText::tr("dimension %1", "in a sentence").arg(q(rest));
  return ResidualCheckText::tr("column %1").arg(q(against));
}

QString dependenceFormName(const std::string& form) {
  if (form == "linear") return ResidualCheckText::tr("linear");
  if (form == "smooth") return ResidualCheckText::tr("smooth");
  if (form == "step") return ResidualCheckText::tr("step");
  if (form == "periodic") return ResidualCheckText::tr("periodic");
  if (form == "level") return ResidualCheckText::tr("per level");
  if (form == "spike") return ResidualCheckText::tr("spike");
  return q(form);
}

QString dependenceFormName(diagnose::DependenceForm form) {
  return dependenceFormName(std::string(diagnose::formName(form)));
}

QString periodText(const diagnose::GenericForm& shape, const QLocale& locale) {
  if (shape.form != diagnose::DependenceForm::Periodic || !(shape.period > 0.0)) return {};
  const QString value = localNumber(shape.period, 1, 'f', locale);
  // The thermal log's time is in minutes (docs/file-formats.md#thermal-log).
  return shape.against == "time" ? ResidualCheckText::tr("%1 min", "a period").arg(value) : value;
}

QString dependenceFormLabel(const diagnose::GenericForm& shape, const QLocale& locale) {
  const QString period = periodText(shape, locale);
  if (period.isEmpty()) return dependenceFormName(shape.form);
  return ResidualCheckText::tr("periodic, period %1").arg(period);
}

QString dependenceFormLabel(const diagnose::StructureItem& item, const QLocale& locale) {
  diagnose::GenericForm shape = item.shape;
  shape.form = item.form;
  shape.against = item.against;
  return dependenceFormLabel(shape, locale);
}

namespace {

QString formWords(const diagnose::GenericForm& shape, const QLocale& locale) {
  const diagnose::DependenceForm form = shape.form;
  const std::vector<double>& knots = shape.knots;
  if (const QString period = periodText(shape, locale); !period.isEmpty())
    return ResidualCheckText::tr("a cycle with a period of %1").arg(period);
  switch (form) {
    case diagnose::DependenceForm::Linear:
      return ResidualCheckText::tr("a linear trend");
    case diagnose::DependenceForm::Smooth:
      return ResidualCheckText::tr("a smooth curve");
    case diagnose::DependenceForm::Step:
      return knots.empty()
                 ? ResidualCheckText::tr("a step")
                 : ResidualCheckText::tr("a step at %1").arg(localNumber(knots.front(), 4, 'g', locale));
    case diagnose::DependenceForm::Periodic:
      return ResidualCheckText::tr("a periodic pattern");
    case diagnose::DependenceForm::Level:
      return ResidualCheckText::tr("a different level per group");
  }
  return {};
}

}  // namespace

QString dependenceFormWords(const diagnose::StructureItem& item, const QLocale& locale) {
  // The change point of a step and the period of a cycle are in the shape (StructureItem::shape), when
  // core filled it.
  diagnose::GenericForm shape = item.shape;
  shape.form = item.form;
  shape.against = item.against;
  if (item.form != diagnose::DependenceForm::Step) shape.knots.clear();
  return formWords(shape, locale);
}

QString dependenceFormWords(const diagnose::GenericForm& form, const QLocale& locale) {
  diagnose::GenericForm shape = form;
  if (form.form != diagnose::DependenceForm::Step) shape.knots.clear();
  return formWords(shape, locale);
}

QString formatPValue(double p, const QLocale& locale) {
  if (!std::isfinite(p)) return localNumber(p, 3, 'g', locale);
  if (p <= 0.0) return QStringLiteral("< ") + locale.toString(1e-300, 'g', 1);
  if (p >= 0.001) return locale.toString(p, 'g', 3);
  return locale.toString(p, 'e', 1);
}

QString residualCheckVerdict(const diagnose::ResidualCheck& c) {
  // With structure: the list made here, so that the variables' names are translated too ("Zeit",
  // "Bahnwinkel"; core's summary keeps the names of docs/file-formats.md). Otherwise core's summary (white,
  // serial correlation only, too few observations), translated.
  if (!c.white && !c.structure.empty()) {
    constexpr std::size_t kShown = 3;
    const QLocale locale;
    QStringList items;
    for (std::size_t i = 0; i < c.structure.size() && i < kShown; ++i) {
      const diagnose::StructureItem& s = c.structure[i];
      items << ResidualCheckText::tr("%1 (%2, %3 % of the residual variance)")
                   .arg(residualVariableName(s.against), dependenceFormName(s.form),
                        locale.toString(100.0 * s.share, 'g', 2));
    }
    QString list = items.join(QStringLiteral(", "));
    if (c.structure.size() > kShown)
      list += ResidualCheckText::tr(" and %n more", nullptr, static_cast<int>(c.structure.size() - kShown));
    return ResidualCheckText::tr("not white: still depends on %1").arg(list);
  }
  if (!c.summaryParts.empty() || !c.summary.empty()) return coreText(c.summaryParts, c.summary);
  return c.white
             ? ResidualCheckText::tr("white: no test finds structure")
             : ResidualCheckText::tr("not white: the tests find structure that no single variable explains");
}

QString outlierWhere(const diagnose::Outlier& o, const QLocale& locale) {
  QStringList parts;
  if (o.row) parts << ResidualCheckText::tr("row %1").arg(locale.toString(static_cast<qlonglong>(*o.row)));
  if (o.part) parts << ResidualCheckText::tr("part %1").arg(q(*o.part));
  if (o.dimension) parts << ResidualCheckText::tr("dimension %1").arg(q(*o.dimension));
  if (o.id) parts << ResidualCheckText::tr("point %1").arg(q(*o.id));
  if (parts.isEmpty())
    parts
        << ResidualCheckText::tr("observation %1").arg(locale.toString(static_cast<qulonglong>(o.unit + 1)));
  return parts.join(QStringLiteral(", "));
}

QStringList residualCheckSentences(const diagnose::Diagnosis& d, const QLocale& locale, int maxOutliers) {
  QStringList out;
  if (!d.residualCheck) return out;
  const diagnose::ResidualCheck& c = *d.residualCheck;
  const QString u = unitText(d.units);
  const QString level = locale.toString(100.0 * c.level, 'g', 3);
  const int tests = static_cast<int>(c.tests.size());
  const auto rejectedLjungBox =
      std::find_if(c.tests.begin(), c.tests.end(),
                   [](const diagnose::ResidualTest& t) { return t.rejected && t.name == "ljung_box"; });

  if (c.white) {
    out << ResidualCheckText::tr(
               "What is left unexplained: nothing that the tests can find. None of the %n test(s) of the "
               "final "
               "residual (against every variable the data offer, and of its serial correlation) finds a "
               "dependence at the %1 % family-wise level: the residual looks like noise.",
               nullptr, tests)
               .arg(level);
  } else if (!c.structure.empty()) {
    QStringList items;
    for (const diagnose::StructureItem& s : c.structure) {
      items << ResidualCheckText::tr("%1 (%2, %3 % of the residual variance, p = %4)")
                   .arg(residualVariableWords(s.against), dependenceFormWords(s, locale),
                        locale.toString(100.0 * s.share, 'f', 1), formatPValue(s.p, locale));
    }
    QString list;
    if (items.size() == 1) {
      list = items.front();
    } else {
      const QString last = items.takeLast();
      list = ResidualCheckText::tr("%1 and %2").arg(items.join(QStringLiteral("; ")), last);
    }
    out << ResidualCheckText::tr(
               "What is left unexplained: the final residual still depends on %1. No effect of the catalogue "
               "explains this (tests at the %2 % family-wise level).")
               .arg(list, level);
  } else if (rejectedLjungBox != c.tests.end()) {
    out << ResidualCheckText::tr(
               "What is left unexplained: the final residual is serially correlated in the order of %1 "
               "(Ljung-Box test, p = %2), but no single variable of the data explains it.")
               .arg(residualVariableWords(rejectedLjungBox->against),
                    formatPValue(rejectedLjungBox->p, locale));
  } else {
    out << ResidualCheckText::tr(
               "What is left unexplained: the tests find structure in the final residual at the %1 % "
               "family-wise level that no single variable explains.")
               .arg(level);
  }

  QStringList generic;
  for (const diagnose::Candidate* e : d.accepted()) {
    if (!e->generic) continue;
    generic << ResidualCheckText::tr("%1 in %2")
                   .arg(dependenceFormWords(*e->generic, locale), residualVariableWords(e->generic->against));
  }
  if (!generic.isEmpty()) {
    out << ResidualCheckText::tr(
               "No effect of the catalogue explains part of this structure, so the model was given a generic "
               "term for it instead of a wrong name: %1.")
               .arg(generic.join(QStringLiteral("; ")));
  }

  const int n = static_cast<int>(c.outliers.size());
  const QString threshold = locale.toString(c.outlierThreshold, 'g', 3);
  if (n == 0) {
    out << (c.outlierThreshold > 0.0
                ? ResidualCheckText::tr("No measurement was excluded as a gross error (robust z above %1).")
                      .arg(threshold)
                : ResidualCheckText::tr("No measurement was excluded as a gross error."));
  } else {
    QStringList items;
    for (int i = 0; i < n && i < maxOutliers; ++i) {
      const diagnose::Outlier& o = c.outliers[static_cast<std::size_t>(i)];
      items << ResidualCheckText::tr("%1 (residual %2 %3, robust z %4)")
                   .arg(outlierWhere(o, locale), locale.toString(o.residual, 'g', 3), u,
                        locale.toString(o.robustZ, 'g', 3));
    }
    QString list = items.join(QStringLiteral("; "));
    if (n > maxOutliers) list += ResidualCheckText::tr(" and %n more", nullptr, n - maxOutliers);
    out << ResidualCheckText::tr(
               "%n measurement(s) excluded from the fit as gross errors (robust z above %1): %2.", nullptr, n)
               .arg(threshold, list);
  }
  if (d.baseline.heldoutRmse && d.final.heldoutRmse && !d.accepted().empty() &&
      *d.final.heldoutRmse > *d.baseline.heldoutRmse)
    out << ResidualCheckText::tr(
               "Warning: the held-out error rose from %1 to %2 %3 with the accepted effects. They describe "
               "the "
               "fit rows but do not carry over to the rows they did not see: do not compensate with them.")
               .arg(locale.toString(*d.baseline.heldoutRmse, 'g', 3),
                    locale.toString(*d.final.heldoutRmse, 'g', 3), u);
  if (d.heldoutCheck) {
    // Thermal: the held-out rows chose nothing; their own check says what the model misses there.
    const diagnose::ResidualCheck& h = *d.heldoutCheck;
    if (h.white) {
      out << ResidualCheckText::tr(
          "On the held-out rows, which only report the error, the residual looks like noise as well.");
    } else if (!h.structure.empty()) {
      QStringList items;
      for (const diagnose::StructureItem& s : h.structure)
        items << ResidualCheckText::tr("%1 (%2, %3 % of the residual variance, p = %4)")
                     .arg(residualVariableWords(s.against), dependenceFormWords(s, locale),
                          locale.toString(100.0 * s.share, 'f', 1), formatPValue(s.p, locale));
      out << ResidualCheckText::tr(
                 "On the held-out rows, which only report the error, the residual still depends on %1: the "
                 "model misses something there that the fit rows did not show.")
                 .arg(items.join(QStringLiteral("; ")));
    }
    const int m = static_cast<int>(h.outliers.size());
    if (m > 0) {
      QStringList items;
      for (int i = 0; i < m && i < maxOutliers; ++i)
        items << outlierWhere(h.outliers[static_cast<std::size_t>(i)], locale);
      out << ResidualCheckText::tr(
                 "%n held-out measurement(s) left out of the held-out error as gross errors: %1.", nullptr, m)
                 .arg(items.join(QStringLiteral("; ")));
    }
  }
  return out;
}

}  // namespace metrofit
