// `globe views [--json] [--export FILE.kml] [--import FILE.kml]`: the views saved by name (V in
// the window), listed, written as KML for Google Earth, or read from a KML's Cameras and LookAts.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/globe/subcommands.hpp"
#include "camera/saved_views.hpp"
#include "transport/atomic_file.hpp"

namespace globe::app {
namespace {

struct ViewsArguments {
  bool json = false;
  std::string exportKml;
  std::string importKml;
};

int runViewsCommand(const ViewsArguments& arguments, const CommandContext& context) {
  const std::filesystem::path file = camera::userViewsFile();
  auto views = camera::readSavedViews(file);
  if (!views) {
    std::fprintf(stderr, "globe views: %s\n", views.error().c_str());
    return 1;
  }
  if (!arguments.importKml.empty()) {
    auto imported =
        camera::savedViewsFromKml(arguments.importKml, geo::ellipsoidFor(context.globeModel));
    if (!imported) {
      std::fprintf(stderr, "globe views: %s\n", imported.error().c_str());
      return 1;
    }
    for (const camera::SavedView& v : *imported) camera::putSavedView(*views, v);
    if (auto written = camera::writeSavedViews(file, *views); !written) {
      std::fprintf(stderr, "globe views: %s\n", written.error().c_str());
      return 1;
    }
    std::printf("imported %zu views from %s into %s\n", imported->size(),
                arguments.importKml.c_str(), file.string().c_str());
  }
  if (!arguments.exportKml.empty()) {
    if (auto written =
            transport::writeFileAtomically(arguments.exportKml, camera::savedViewsToKml(*views));
        !written) {
      std::fprintf(stderr, "globe views: %s\n", written.error().c_str());
      return 1;
    }
    std::printf("wrote %zu views to %s\n", views->size(), arguments.exportKml.c_str());
  }
  if (!arguments.importKml.empty() || !arguments.exportKml.empty()) return 0;
  const double deg = 180 / 3.14159265358979323846;
  if (arguments.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const camera::SavedView& v : *views) {
      list.push_back(
          {{"name", v.name},
           {"camera",
            {v.pose.position.longitudeRadians * deg, v.pose.position.latitudeRadians * deg,
             v.pose.position.heightMeters, v.pose.headingRadians * deg, v.pose.pitchRadians * deg,
             v.pose.rollRadians * deg}},
           {"aboveTerrain", v.heightAboveTerrain}});
    }
    std::printf("%s\n", nlohmann::json{{"file", file.string()}, {"views", list}}.dump(2).c_str());
    return 0;
  }
  std::printf("saved views (V in the window; --view NAME): %s\n", file.string().c_str());
  for (const camera::SavedView& v : *views) {
    std::printf("  %-24s --camera %.6f,%.6f,%.1f,%.1f,%.1f,%.1f%s\n", v.name.c_str(),
                v.pose.position.longitudeRadians * deg, v.pose.position.latitudeRadians * deg,
                v.pose.position.heightMeters, v.pose.headingRadians * deg,
                v.pose.pitchRadians * deg, v.pose.rollRadians * deg,
                v.heightAboveTerrain ? " --above-terrain" : "");
  }
  return 0;
}

}  // namespace

Subcommand addViewsCommand(CLI::App& app, CommonArguments& common) {
  auto arguments = std::make_shared<ViewsArguments>();
  CLI::App* views = app.add_subcommand(
      "views",
      "the views saved by name (V in the window): list them, --export them as KML for Google "
      "Earth, or --import a KML's Camera and LookAt views");
  views->add_flag("--json", arguments->json, "machine-readable list");
  views->add_option("--export", arguments->exportKml, "write every saved view to a KML file");
  views->add_option("--import", arguments->importKml,
                    "add the views of a KML file (Placemarks with <Camera> or <LookAt>)");
  addGlobeOption(*views, common);
  return {views, [arguments](const CommandContext& context) {
            return runViewsCommand(*arguments, context);
          }};
}

}  // namespace globe::app
