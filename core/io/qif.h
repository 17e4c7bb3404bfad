#pragma once
// QIF 3.0 Results files (ANSI/DMSC Quality Information Framework, XML, namespace
// http://qifstandards.org/xsd/qif3), as CMM software exports them (PC-DMIS, Calypso, CheckMate ...).
// What is read (everything else is skipped):
//
//   * FileUnits/PrimaryUnits/LinearUnit: "mm" (kept), "inch"/"in" (x 25.4), "m"/"meter" (x 1000), any
//     other unit through its UnitConversion/Factor to metre. Every length below is in mm. AngularUnit
//     "degree" (kept) or "radian" (converted to degrees) for angle characteristics.
//   * The feature chain: <T>FeatureDefinition (Diameter, InternalExternal) <- <T>FeatureNominal
//     (FeatureDefinitionId; Location + Normal, or Axis/AxisPoint + Axis/Direction for cylinders) <-
//     <T>FeatureItem (FeatureNominalId, FeatureName) <- <T>FeatureMeasurement in each
//     MeasurementResults/MeasuredFeatures (FeatureItemId; the actual Location / Normal or Axis, Diameter).
//     T is the element type (Point, EdgePoint, Circle, Cylinder, Plane, ... any other type is read too,
//     with whatever location it has).
//   * The characteristic chain: <T>CharacteristicDefinition (Tolerance/MinValue, MaxValue, DefinedAsLimit:
//     limits relative to the nominal when false, absolute when true; or ToleranceValue, a GD&T zone, with
//     OuterDisposition for profiles) <- <T>CharacteristicNominal (CharacteristicDefinitionId, TargetValue)
//     <- <T>CharacteristicItem (CharacteristicNominalId, Name, FeatureItemIds) <-
//     <T>CharacteristicMeasurement in each MeasurementResults/MeasuredCharacteristics (CharacteristicItemId,
//     Value, Status/CharacteristicStatusEnum, FeatureMeasurementIds). A measurement names its features
//     through FeatureMeasurementIds, which may differ from its item's FeatureItemIds (a pattern: the item
//     lists one feature, its measurements point to each measured member); one item may be measured several
//     times in one result (point profiles: the deviation, then 0).
//   * Each MeasurementResults is one measured part: its id, InspectionStatus, and the SerialNumber and
//     status of its ActualComponent (ActualComponentIds -> Results/ActualComponentSets).
//
// Errors are one line, ParseError / ValidationError naming the file and the line (and the element id
// where there is one): XML that is not well formed (a truncated file), a root that is not a QIF 3
// QIFDocument, no FileUnits, an id referenced but absent, a duplicate id, a number that is not one, a
// file without MeasurementResults.
//
// A QifFile becomes a CMM report (qifCmmReport, core/io/cmm_text_report.h: one run per part, one feature
// per characteristic) and probe points (qifProbePoints, core/matching/qif_points.h). Plan files (no
// Results) and the Plan/Product pairing by FeatureName are not read yet.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace metrofit {

struct QifFeature {
  std::string name;  ///< FeatureName
  std::string type;  ///< element type: "Point", "EdgePoint", "Circle", "Cylinder", "Plane", ...
  long itemId = 0, nominalId = 0, definitionId = 0;
  std::optional<Eigen::Vector3d> location;   ///< nominal Location, or Axis/AxisPoint (mm)
  std::optional<Eigen::Vector3d> direction;  ///< nominal Normal, or Axis/Direction (as written)
  std::optional<double> diameter;            ///< nominal Diameter of the definition (mm)
  std::string internalExternal;              ///< INTERNAL, EXTERNAL, NOT_APPLICABLE or empty
  long line = 0;                             ///< the line of the FeatureItem
  bool set = false;  ///< DeterminationMode Set: given (a reference feature), not measured
  /// A Point, EdgePoint or Plane: its direction is a surface normal. Circles, cylinders and the other
  /// types carry an axis (or nothing) instead.
  bool hasSurfaceNormal() const;
};

struct QifFeatureMeasurement {
  long id = 0;
  std::size_t feature = 0;                   ///< index into QifFile::features
  std::optional<Eigen::Vector3d> location;   ///< actual Location / Axis/AxisPoint (mm)
  std::optional<Eigen::Vector3d> direction;  ///< actual Normal / Axis/Direction
  std::optional<double> diameter;            ///< actual Diameter (mm)
  long line = 0;
};

struct QifCharacteristic {
  std::string name;  ///< Name of the item
  std::string type;  ///< "Diameter", "Position", "PointProfile", "DistanceBetween", ...
  long itemId = 0, nominalId = 0, definitionId = 0;
  std::optional<double> target;    ///< TargetValue of the nominal (mm, or degrees for angles)
  std::optional<double> minValue;  ///< Tolerance/MinValue as written (converted to mm / degrees)
  std::optional<double> maxValue;  ///< Tolerance/MaxValue
  bool definedAsLimit = false;     ///< Min/MaxValue are absolute limits (else relative to the nominal)
  std::optional<double> zone;      ///< ToleranceValue: a GD&T tolerance zone
  std::optional<double> outerDisposition;  ///< OuterDisposition of a profile zone
  std::vector<std::size_t> features;       ///< FeatureItemIds as indices into QifFile::features
  bool angle = false;                      ///< an angle characteristic (degrees), else a length (mm)
  long line = 0;                           ///< the line of the CharacteristicItem

  /// The nominal: TargetValue; for a Diameter characteristic without one, the nominal diameter of its
  /// (first) feature; for a GD&T zone without one, 0 (the value is a deviation or a form).
  std::optional<double> nominalValue(const std::vector<QifFeature>& all) const;
  /// The limits relative to nominalValue(): Tolerance (converted when DefinedAsLimit); a zone t gives
  /// [-t/2, +t/2] for profiles (or [d - t, d] with OuterDisposition d), [0, t] for every other zone.
  /// Empty when the characteristic has no tolerance, or absolute limits but no nominal.
  std::optional<double> lowerLimit(const std::vector<QifFeature>& all) const;
  std::optional<double> upperLimit(const std::vector<QifFeature>& all) const;
};

struct QifCharacteristicMeasurement {
  long id = 0;
  std::size_t characteristic = 0;     ///< index into QifFile::characteristics
  std::optional<double> value;        ///< Value (mm, or degrees for angles); empty when not given
  std::string status;                 ///< CharacteristicStatusEnum: PASS, FAIL, BASIC_OR_TED, ...
  std::vector<std::size_t> measured;  ///< FeatureMeasurementIds as indices into the part's `features`
  long line = 0;
};

struct QifPart {
  long resultsId = 0;  ///< the MeasurementResults id
  std::string serial;  ///< SerialNumber of its ActualComponent (empty when none)
  std::string status;  ///< InspectionStatusEnum of the results (else of the ActualComponent)
  std::vector<QifFeatureMeasurement> features;
  std::vector<QifCharacteristicMeasurement> characteristics;
  long line = 0;
};

struct QifFile {
  std::string source;
  std::string linearUnit = "mm";                   ///< as written; every length here is converted to mm
  std::vector<QifFeature> features;                ///< in file order of the FeatureItems
  std::vector<QifCharacteristic> characteristics;  ///< in file order of the CharacteristicItems
  std::vector<QifPart> parts;                      ///< one per MeasurementResults, in file order

  /// Index of the feature / characteristic with that FeatureName / Name, or nullopt.
  std::optional<std::size_t> feature(std::string_view name) const;
  std::optional<std::size_t> characteristic(std::string_view name) const;
  /// The measurement of feature `feature` in part `part`, or nullptr.
  const QifFeatureMeasurement* measurement(std::size_t part, std::size_t feature) const;
};

/// True when the text is XML whose root element is QIFDocument.
bool looksLikeQif(std::string_view text);
/// Reads a QIF 3 Results document (see above); `source` names it in errors.
QifFile qifFromText(std::string_view text, const std::string& source);
QifFile readQifFile(const std::string& path);

}  // namespace metrofit
