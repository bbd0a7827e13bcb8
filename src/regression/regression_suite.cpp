#include "regression/regression_suite.hpp"

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "transport/read_file.hpp"

namespace globe::regression {
namespace {

using nlohmann::json;

bool validViewName(const std::string& name) {
  if (name.empty() || name.size() > 100 || name[0] == '.' || name[0] == '-') return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

Result<double> numberIn(const json& object, const char* key, double lowest, double highest,
                        double fallback, const std::string& where) {
  if (!object.contains(key)) return fallback;
  const json& value = object.at(key);
  const double number = value.is_number() ? value.get<double>() : lowest - 1;
  if (!(number >= lowest && number <= highest)) {
    std::ostringstream text;
    text << where << ": \"" << key << "\" must be a number from " << lowest << " to " << highest;
    return makeError(text.str());
  }
  return number;
}

Result<void> onlyKeys(const json& object, const std::set<std::string>& known,
                      const std::string& where) {
  for (const auto& [key, value] : object.items()) {
    if (!known.contains(key)) return makeError(where + ": unknown field \"" + key + "\"");
  }
  return {};
}

Result<Tolerance> toleranceIn(const json& object, const Tolerance& base, const std::string& where) {
  if (!object.contains("tolerance")) return base;
  const json& t = object.at("tolerance");
  if (!t.is_object()) return makeError(where + ": \"tolerance\" must be an object");
  if (auto known = onlyKeys(t, {"channel", "fraction", "ssim"}, where + " tolerance"); !known) {
    return makeError(known.error());
  }
  auto channel = numberIn(t, "channel", 0, 255, base.channelThreshold, where + " tolerance");
  auto fraction = numberIn(t, "fraction", 0, 1, base.differingFraction, where + " tolerance");
  auto ssim = numberIn(t, "ssim", -1, 1, base.minimumSsim, where + " tolerance");
  for (const auto* r : {&channel, &fraction, &ssim}) {
    if (!*r) return makeError(r->error());
  }
  return Tolerance{static_cast<int>(*channel), *fraction, *ssim};
}

Result<std::vector<std::string>> snapshotArgumentsIn(const json& view, const std::string& where) {
  if (!view.contains("snapshot") || !view.at("snapshot").is_array() ||
      view.at("snapshot").empty()) {
    return makeError(where + ": \"snapshot\" must be a non-empty list of arguments");
  }
  std::vector<std::string> arguments;
  for (const json& argument : view.at("snapshot")) {
    if (!argument.is_string()) return makeError(where + ": \"snapshot\" holds a non-string");
    const std::string text = argument.get<std::string>();
    if (text == "-o" || text.starts_with("--output") || text.starts_with("-o=")) {
      return makeError(where + ": \"snapshot\" must not give -o (globe regress writes the image)");
    }
    arguments.push_back(text);
  }
  return arguments;
}

Result<RegressionView> viewIn(const json& view, const Tolerance& suiteTolerance, size_t index,
                              const std::string& file) {
  std::string where = file + ": view " + std::to_string(index + 1);
  if (!view.is_object()) return makeError(where + " is not an object");
  const json name = view.value("name", json());
  if (!name.is_string() || !validViewName(name.get<std::string>())) {
    return makeError(where + ": \"name\" must be 1-100 letters, digits, '_', '-' or '.' "
                             "(not starting with '.' or '-')");
  }
  where += " (" + name.get<std::string>() + ")";
  if (auto known = onlyKeys(view, {"name", "snapshot", "tolerance"}, where); !known) {
    return makeError(known.error());
  }
  auto arguments = snapshotArgumentsIn(view, where);
  if (!arguments) return makeError(arguments.error());
  auto tolerance = toleranceIn(view, suiteTolerance, where);
  if (!tolerance) return makeError(tolerance.error());
  return RegressionView{name.get<std::string>(), std::move(*arguments), *tolerance};
}

Result<RegressionSuite> suiteFromJson(const json& root, const std::filesystem::path& file) {
  const std::string where = file.string();
  if (!root.is_object()) return makeError(where + ": the suite must be a JSON object");
  if (auto known = onlyKeys(root, {"tolerance", "timeoutSeconds", "views"}, where); !known) {
    return makeError(known.error());
  }
  RegressionSuite suite;
  suite.folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  auto timeout = numberIn(root, "timeoutSeconds", 1, 86400, suite.timeoutSeconds, where);
  auto tolerance = toleranceIn(root, Tolerance{}, where);
  if (!timeout) return makeError(timeout.error());
  if (!tolerance) return makeError(tolerance.error());
  suite.timeoutSeconds = static_cast<int>(*timeout);
  const json views = root.value("views", json());
  if (!views.is_array() || views.empty() || views.size() > kMaxSuiteViews) {
    return makeError(where + ": \"views\" must be a list of 1 to " +
                     std::to_string(kMaxSuiteViews) + " views");
  }
  std::set<std::string> names;
  for (size_t i = 0; i < views.size(); ++i) {
    auto view = viewIn(views[i], *tolerance, i, where);
    if (!view) return makeError(view.error());
    if (!names.insert(view->name).second) {
      return makeError(where + ": two views are named \"" + view->name + "\"");
    }
    suite.views.push_back(std::move(*view));
  }
  return suite;
}

}  // namespace

Result<RegressionSuite> parseRegressionSuite(const std::string& text,
                                             const std::filesystem::path& file) {
  const json root = json::parse(text, nullptr, false);
  if (root.is_discarded()) return makeError(file.string() + ": not valid JSON");
  return suiteFromJson(root, file);
}

Result<RegressionSuite> loadRegressionSuite(const std::filesystem::path& file) {
  auto text = transport::readFileBounded(file, kMaxSuiteBytes);
  if (!text) return makeError(text.error() + " (a regression suite)");
  return parseRegressionSuite(*text, file);
}

std::filesystem::path referencePath(const RegressionSuite& suite, const std::string& viewName) {
  return suite.folder / "references" / (viewName + ".png");
}

}  // namespace globe::regression
