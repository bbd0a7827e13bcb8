// Vertical units of elevation rasters: the unit names files state (GDAL's unit type), the
// overrides the tiler's --z-units / --z-scale give, and how stored values become metres.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/result.hpp"

namespace globe::formats {

// What chose the metres per unit of a source.
enum class VerticalUnitOrigin {
  File,     // the unit the file states
  Default,  // the file states none: metres (GeoTIFF's default)
  Format,   // the format defines metres (GTOPO30)
  ZUnits,   // --z-units
  ZScale,   // --z-scale
};

// How a source's stored values become metres:
//   metres = (stored * bandScale + bandOffset) * metersPerUnit
// (bandScale and bandOffset: the band's own scale and offset, e.g. GDAL's).
struct VerticalUnits {
  std::string fileUnit;  // as the file states it, "" when it states none
  VerticalUnitOrigin origin = VerticalUnitOrigin::Default;
  std::string overrideUnit;  // the --z-units name, when origin is ZUnits
  double metersPerUnit = 1;
  double bandScale = 1, bandOffset = 0;

  double toMeters(double stored) const { return (stored * bandScale + bandOffset) * metersPerUnit; }
  bool isIdentity() const { return metersPerUnit == 1 && bandScale == 1 && bandOffset == 0; }
  bool operator==(const VerticalUnits&) const = default;
};

// Metres per unit of a unit name, case-insensitive, surrounding blanks ignored: "" and m, metre(s),
// meter(s) 1; ft, foot, feet, international foot 0.3048; US survey foot, ftUS, us-ft, Foot_US
// 1200/3937. nullopt when unknown.
std::optional<double> metersPerUnitNamed(std::string_view unit);

// The unit the tiler gives the inputs that state none, or one it does not know (unset: metres,
// or an error). A unit the format (GTOPO30: metres) or the file states is kept.
struct VerticalOverride {
  std::optional<std::string> units;     // --z-units: a unit name
  std::optional<double> metersPerUnit;  // --z-scale: metres per stored unit (wins over units)
  bool operator==(const VerticalOverride&) const = default;
};

// Checks an override on its own: a known --z-units name, a finite non-zero --z-scale.
Result<void> checkVerticalOverride(const VerticalOverride& zOverride);

// What to apply to a band whose file states `fileUnit` (origin Format: the format's metres,
// whatever fileUnit says; a known stated unit is kept, the override applies to the others). An
// unknown unit without an override is an error naming the file.
Result<VerticalUnits> resolveVerticalUnits(const std::string& path, std::string_view fileUnit,
                                           double bandScale, double bandOffset,
                                           const VerticalOverride& zOverride,
                                           bool formatIsMeters = false);

// One line saying what was read and applied, e.g. `unit "ft" -> x0.3048 m`.
std::string describe(const VerticalUnits& units);

std::string_view toString(VerticalUnitOrigin origin);
std::optional<VerticalUnitOrigin> parseVerticalUnitOrigin(std::string_view text);

}  // namespace globe::formats
