#include "formats/vertical_units.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/ascii_case.hpp"
#include "formats/vertical_units_json.hpp"

namespace globe::formats {
namespace {

constexpr double kFootMeters = 0.3048;
constexpr double kUsSurveyFootMeters = 1200.0 / 3937.0;

std::string_view trimmedUnit(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string unitNumberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::string quotedFileUnit(const VerticalUnits& u) {
  return u.fileUnit.empty() ? "none" : "\"" + u.fileUnit + "\"";
}

constexpr std::array<std::pair<VerticalUnitOrigin, std::string_view>, 5> kVerticalOriginNames{{
    {VerticalUnitOrigin::File, "file"},
    {VerticalUnitOrigin::Default, "default"},
    {VerticalUnitOrigin::Format, "format"},
    {VerticalUnitOrigin::ZUnits, "--z-units"},
    {VerticalUnitOrigin::ZScale, "--z-scale"},
}};

}  // namespace

std::optional<double> metersPerUnitNamed(std::string_view unit) {
  const std::string name = core::asciiLower(trimmedUnit(unit));
  if (name.empty() || name == "m" || name == "metre" || name == "meter" || name == "metres" ||
      name == "meters") {
    return 1.0;
  }
  if (name == "ft" || name == "foot" || name == "feet" || name == "international foot") {
    return kFootMeters;
  }
  if (name == "us survey foot" || name == "ftus" || name == "us-ft" || name == "foot_us") {
    return kUsSurveyFootMeters;
  }
  return std::nullopt;
}

Result<void> checkVerticalOverride(const VerticalOverride& zOverride) {
  if (zOverride.units && !metersPerUnitNamed(*zOverride.units)) {
    return makeError("--z-units must be m, ft or us-ft, not '" + *zOverride.units + "'");
  }
  if (zOverride.metersPerUnit &&
      (!std::isfinite(*zOverride.metersPerUnit) || *zOverride.metersPerUnit == 0)) {
    return makeError("--z-scale must be a finite, non-zero number of metres per stored unit");
  }
  return {};
}

Result<VerticalUnits> resolveVerticalUnits(const std::string& path, std::string_view fileUnit,
                                           double bandScale, double bandOffset,
                                           const VerticalOverride& zOverride, bool formatIsMeters) {
  if (auto checked = checkVerticalOverride(zOverride); !checked) return Error{checked.error()};
  if (!std::isfinite(bandScale) || bandScale == 0 || !std::isfinite(bandOffset)) {
    return makeError(path + ": unusable band scale " + unitNumberText(bandScale) + " / offset " +
                     unitNumberText(bandOffset));
  }
  VerticalUnits u;
  u.fileUnit = std::string(trimmedUnit(fileUnit));
  u.bandScale = bandScale;
  u.bandOffset = bandOffset;
  // A unit the format or the file states wins: the overrides are for inputs that state none (or
  // one this reader does not know), so a base grid tiled beside them keeps its metres.
  const auto known = metersPerUnitNamed(u.fileUnit);
  if (formatIsMeters) {
    u.origin = VerticalUnitOrigin::Format;
  } else if (known && !u.fileUnit.empty()) {
    u.origin = VerticalUnitOrigin::File;
    u.metersPerUnit = *known;
  } else if (zOverride.metersPerUnit) {
    u.origin = VerticalUnitOrigin::ZScale;
    u.metersPerUnit = *zOverride.metersPerUnit;
  } else if (zOverride.units) {
    u.origin = VerticalUnitOrigin::ZUnits;
    u.overrideUnit = *zOverride.units;
    u.metersPerUnit = *metersPerUnitNamed(*zOverride.units);
  } else if (known) {
    u.origin = VerticalUnitOrigin::Default;
  } else {
    return makeError(path + ": unknown vertical unit '" + u.fileUnit +
                     "'; give --z-units m|ft|us-ft or --z-scale FACTOR");
  }
  return u;
}

std::string describe(const VerticalUnits& u) {
  std::string out;
  switch (u.origin) {
    case VerticalUnitOrigin::File:
      out = "unit " + quotedFileUnit(u);
      break;
    case VerticalUnitOrigin::Default:
      out = "no unit (metres)";
      break;
    case VerticalUnitOrigin::Format:
      out = "metres by format";
      break;
    case VerticalUnitOrigin::ZUnits:
      out = "--z-units " + u.overrideUnit + " (file unit " + quotedFileUnit(u) + ")";
      break;
    case VerticalUnitOrigin::ZScale:
      out = "--z-scale (file unit " + quotedFileUnit(u) + ")";
      break;
  }
  out += " -> x" + unitNumberText(u.metersPerUnit) + " m";
  if (u.bandScale != 1 || u.bandOffset != 0) {
    out += ", after band scale " + unitNumberText(u.bandScale) + " and offset " +
           unitNumberText(u.bandOffset);
  }
  return out;
}

std::string_view toString(VerticalUnitOrigin origin) {
  for (const auto& [o, name] : kVerticalOriginNames) {
    if (o == origin) return name;
  }
  return "default";
}

std::optional<VerticalUnitOrigin> parseVerticalUnitOrigin(std::string_view text) {
  for (const auto& [o, name] : kVerticalOriginNames) {
    if (name == text) return o;
  }
  return std::nullopt;
}

nlohmann::json verticalUnitsToJson(const VerticalUnits& u) {
  nlohmann::json j = {
      {"fileUnit", u.fileUnit},           {"appliedBy", std::string(toString(u.origin))},
      {"metersPerUnit", u.metersPerUnit}, {"bandScale", u.bandScale},
      {"bandOffset", u.bandOffset},       {"description", describe(u)}};
  if (u.origin == VerticalUnitOrigin::ZUnits) j["overrideUnit"] = u.overrideUnit;
  return j;
}

}  // namespace globe::formats
