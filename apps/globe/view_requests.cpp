// `globe view`'s requests: what the keys and clicks asked since the last frame, taken one
// handler each (view_session.hpp).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/geometric.hpp>

#include "apps/globe/go_to.hpp"
#include "apps/globe/ruler_overlay.hpp"
#include "apps/globe/view_session.hpp"
#include "camera/saved_views.hpp"
#include "geo/ecef.hpp"

namespace globe::app {
namespace {

// V then a name: the current pose saved under it in the user's views file; what to say back.
std::string saveView(const std::string& name, const camera::CameraPose& pose) {
  if (name.empty()) return "save view: type a name";
  const std::filesystem::path file = camera::userViewsFile();
  auto views = camera::readSavedViews(file);
  if (!views) return "save view: " + views.error();
  camera::putSavedView(*views, {name, pose, false});
  if (auto written = camera::writeSavedViews(file, *views); !written) {
    return "save view: " + written.error();
  }
  std::printf("saved view %s in %s\n", name.c_str(), file.string().c_str());
  std::fflush(stdout);
  return "saved view \"" + name + "\" (" + std::to_string(views->size()) + " in " + file.string() +
         ")";
}

// The user's documents and the ruler's shown in the scene; a new renderer takes their icons and
// keeps the picked placemark when it is still one of the user's.
Result<void> showOverlays(scene::TerrainScene& scene, RendererGpu& gpu, const Documents& user,
                          const std::shared_ptr<const overlays::OverlayDocument>& ruler,
                          std::unique_ptr<OverlayDrawing>& labels) {
  if (auto set = scene.setOverlays(withRuler(user, ruler), gpu); !set) return set;
  const auto selected = labels ? labels->selected() : std::nullopt;
  auto created = OverlayDrawing::create(scene);
  if (!created) return Error{created.error()};
  labels = std::move(*created);
  if (labels && selected && selected->document < user.size()) labels->select(selected);
  return {};
}

// O then a path, or files dropped on the window: each read and shown with the overlays already
// open; what to say back (the files opened, or why one could not be).
std::string openOverlays(scene::TerrainScene& scene, RendererGpu& gpu,
                         const std::vector<std::string>& files, Documents& user,
                         const std::shared_ptr<const overlays::OverlayDocument>& ruler,
                         std::unique_ptr<OverlayDrawing>& labels) {
  Documents documents = user;
  std::string opened;
  for (const std::string& file : files) {
    auto document = overlays::readOverlayFile(file);
    if (!document) return "open: " + document.error();
    for (const std::string& warning : document->warnings) {
      std::fprintf(stderr, "globe view: warning: %s\n", warning.c_str());
    }
    opened += (opened.empty() ? "" : ", ") + std::filesystem::path(file).filename().string();
    documents.push_back(std::make_shared<const overlays::OverlayDocument>(std::move(*document)));
  }
  if (opened.empty()) return "open: type a file's path";
  if (auto shown = showOverlays(scene, gpu, documents, ruler, labels); !shown) {
    return "open: " + shown.error();
  }
  user = std::move(documents);
  std::printf("opened %s\n", opened.c_str());
  std::fflush(stdout);
  return "opened " + opened;
}

// Where a ground point is drawn in the last frame, window pixels; nullopt behind the camera.
std::optional<glm::dvec2> windowPixelOf(const terrain::RenderView& view,
                                        const geo::Ellipsoid& ellipsoid, const RulerPoint& point,
                                        double toWindow) {
  const glm::dvec3 ecef = geo::cartographicToEcef(
      ellipsoid, geo::Cartographic::fromDegrees(point.longitudeDegrees, point.latitudeDegrees,
                                                point.heightMeters));
  const glm::dvec4 clip = view.projection * view.viewMatrix * glm::dvec4(ecef, 1.0);
  if (!(clip.w > 0)) return std::nullopt;
  return glm::dvec2((clip.x / clip.w + 1.0) * 0.5 * view.widthPixels,
                    (1.0 - clip.y / clip.w) * 0.5 * view.heightPixels) *
         toWindow;
}

// What X profiles: the ruler's path (two points or more), else the picked placemark's first line.
std::vector<measure::PathPoint> profilePath(const Ruler& ruler, const scene::TerrainScene& scene,
                                            const OverlayDrawing* labels) {
  if (ruler.points().size() >= 2) return ruler.path();
  if (labels == nullptr || !labels->selected()) return {};
  const overlays::PlacemarkRef ref = *labels->selected();
  return placemarkLine(scene.options().overlays[ref.document]->placemarks[ref.placemark])
      .value_or(std::vector<measure::PathPoint>());
}

// P: starts recording the path, or stops and writes it.
void takeRecordRequest(ViewSession& s, ViewClock::time_point now) {
  if (!s.input.recordToggleRequested) return;
  s.input.recordToggleRequested = false;
  if (s.recorder.recording()) {
    writeRecordedPath(s.options.recordDirectory,
                      s.recorder.stop(s.secondsAt(now), s.controller->pose()));
  } else {
    s.recorder.start(s.secondsAt(now), s.controller->pose());
    std::printf("recording the path (P again stops and writes it)\n");
    std::fflush(stdout);
  }
}

// G then a name: a saved view by that name first (true when it was one).
bool goToSavedView(ViewSession& s, const std::string& name) {
  auto views = camera::readSavedViews(camera::userViewsFile());
  const camera::SavedView* view = views ? camera::findSavedView(*views, name) : nullptr;
  if (view == nullptr) return false;
  camera::CameraPose pose = view->pose;
  if (view->heightAboveTerrain) {
    if (auto ground = s.scene->terrainHeightMeters(pose.position.longitudeRadians,
                                                   pose.position.latitudeRadians)) {
      pose.position.heightMeters += *ground;
    }
  }
  s.navigator->flyToPose(pose);
  s.input.promptMessage.clear();
  std::printf("go to view %s\n", view->name.c_str());
  std::fflush(stdout);
  return true;
}

// Then a place or a position; what was wrong is said on the HUD.
void goToPlace(ViewSession& s, const std::string& text) {
  auto target = parseGoTo(text);
  if (!target) {
    s.input.promptMessage = target.error();
    return;
  }
  s.input.promptMessage.clear();
  s.navigator->goTo(geo::degreesToRadians(target->longitudeDegrees),
                    geo::degreesToRadians(target->latitudeDegrees));
  std::printf("go to %s (%.5f, %.5f)\n", target->name.c_str(), target->latitudeDegrees,
              target->longitudeDegrees);
  std::fflush(stdout);
}

// M with a click: the ground point there added to the ruler (or its ring closed).
void rulerClick(ViewSession& s, glm::dvec2 pixel, int width) {
  const auto ground = s.navigator->groundAt(pixel);
  if (!ground) return;
  const auto at = geo::ecefToCartographic(s.ellipsoid(), *ground);
  if (!at) return;
  const double toWindow = static_cast<double>(s.windowSize().first) / std::max(width, 1);
  const RulerPoint point{at->longitudeDegrees(), at->latitudeDegrees(), at->heightMeters};
  s.ruler.click(point, pixel,
                s.ruler.points().empty() ? std::nullopt
                                         : windowPixelOf(s.scene->view(), s.ellipsoid(),
                                                         s.ruler.points().front(), toWindow));
  if (!s.ruler.closed()) {
    std::printf("ruler point %zu: %.7f,%.7f\n", s.ruler.points().size(), point.longitudeDegrees,
                point.latitudeDegrees);
  }
}

// A click without the ruler: the placemark there picked (its panel shown), or none.
void pickClick(ViewSession& s, glm::dvec2 pixel, int width) {
  if (!s.labels) return;
  const auto [windowWidth, windowHeight] = s.windowSize();
  std::optional<geo::Cartographic> ground;
  double metersPerPixel = 0;
  if (const auto groundEcef = s.navigator->groundAt(pixel)) {
    ground = geo::ecefToCartographic(s.ellipsoid(), *groundEcef);
    metersPerPixel = glm::length(*groundEcef - s.scene->view().cameraEcefMeters) * 2 *
                     std::tan(s.options.scene.fovYRadians / 2) / std::max(windowHeight, 1);
  }
  // Label boxes are in framebuffer pixels, clicks in window pixels.
  const double toFramebuffer = static_cast<double>(width) / std::max(windowWidth, 1);
  const auto picked = s.labels->pick(*s.scene, pixel * toFramebuffer, ground, metersPerPixel);
  // The ruler's own marks are not placemarks to pick.
  s.labels->select(picked && picked->document < s.userOverlays.size() ? picked : std::nullopt);
  if (s.labels->selected()) {
    std::printf(
        "placemark: %s\n",
        s.scene->options().overlays[picked->document]->placemarks[picked->placemark].name.c_str());
    std::fflush(stdout);
  }
}

// X: the chart of profilePath(), remade when it changes; hidden while there is none. True when
// the chart changed.
bool updateProfile(ViewSession& s, int width, int height) {
  ViewInput& input = s.input;
  if (!input.profileVisible) {
    if (!s.profileShown) return false;
    s.profilePanel->clear();
    s.profileShown = false;
    return true;
  }
  bool changed = false;
  const std::vector<measure::PathPoint> path = profilePath(s.ruler, *s.scene, s.labels.get());
  if (path.size() < 2) {
    s.profilePanel->clear();
    if (!s.profileShown) {
      input.promptMessage = "profile: measure a path (M) or pick a line first";
      input.profileVisible = false;
    }
  } else if (auto updated =
                 s.profilePanel->update(path, s.scene->store(), s.ellipsoid(), width, height);
             !updated) {
    input.promptMessage = "profile: " + updated.error();
    input.profileVisible = false;
  } else if (*updated) {
    if (input.promptMessage.starts_with("profile: ")) input.promptMessage.clear();
    std::printf("profile: %zu samples, %.2f m, min %.1f m, max %.1f m\n", (*updated)->samples,
                (*updated)->lengthMeters, (*updated)->lowestMeters, (*updated)->highestMeters);
    std::fflush(stdout);
    changed = true;
  }
  s.profileShown = input.profileVisible;
  return changed;
}

}  // namespace

void takeRequests(ViewSession& s, ViewClock::time_point now) {
  ViewInput& input = s.input;
  takeRecordRequest(s, now);
  if (input.saveViewRequest) {
    input.promptMessage = saveView(*input.saveViewRequest, s.controller->pose());
    input.saveViewRequest.reset();
    input.changed = true;
  }
  if (input.goToRequest) {
    if (!goToSavedView(s, *input.goToRequest)) goToPlace(s, *input.goToRequest);
    input.goToRequest.reset();
    input.changed = true;
  }
  if (!input.openFileRequests.empty()) {
    input.promptMessage = openOverlays(*s.scene, *s.gpu, input.openFileRequests, s.userOverlays,
                                       s.rulerOverlay, s.labels);
    input.openFileRequests.clear();
    input.changed = true;
  }
  // The ruler: M turns it on, or off and clears it; Backspace undoes.
  if (input.rulerOn != s.ruler.active()) s.ruler.setActive(input.rulerOn);
  if (input.rulerUndoRequested) {
    input.rulerUndoRequested = false;
    s.ruler.undo();
  }
}

void takeClick(ViewSession& s, int width) {
  if (!s.input.clickRequest) return;
  if (s.input.rulerOn) {
    rulerClick(s, *s.input.clickRequest, width);
  } else {
    pickClick(s, *s.input.clickRequest, width);
  }
  s.input.clickRequest.reset();
  s.input.changed = true;
}

bool updateRulerAndProfile(ViewSession& s, int width, int height) {
  if (s.ruler.revision() != s.rulerRevisionShown) {
    s.rulerRevisionShown = s.ruler.revision();
    s.rulerOverlay = rulerDocument(s.ruler);
    if (auto shown = showOverlays(*s.scene, *s.gpu, s.userOverlays, s.rulerOverlay, s.labels);
        !shown) {
      s.input.promptMessage = "ruler: " + shown.error();
    }
    std::printf("%s\n", rulerLogLine(s.ruler).c_str());
    std::fflush(stdout);
    s.input.changed = true;
  }
  return updateProfile(s, width, height);
}

}  // namespace globe::app
