// The overlays drawn over a frame's terrain (their draped part is an imagery layer of the scene):
// lines, walls and stalks at an altitude in 3D (scene/overlay_shapes.hpp); each shown point's icon
// and name, decluttered in file order and hidden behind the terrain (scene/overlay_points.hpp);
// and the panel of the placemark a click picked (its name and description).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "core/result.hpp"
#include "geo/cartographic.hpp"
#include "overlays/overlay_pick.hpp"
#include "render/label_renderer.hpp"
#include "render/world_overlay_renderer.hpp"
#include "scene/terrain_scene.hpp"

namespace globe::app {

// The placemark panel's top edge and its widest (at the window's right edge).
struct PlacemarkPanelPlace {
  float topPixels = 12.0f;
  float maxWidthPixels = 420.0f;
};

class OverlayDrawing {
 public:
  // Needs the GL context current; nullptr when the scene has no overlays.
  static Result<std::unique_ptr<OverlayDrawing>> create(const scene::TerrainScene& scene);

  // Draws the scene's last update's 3D shapes and labels over the frame (the terrain drawn) and
  // keeps the labels' boxes for pick().
  void draw(const scene::TerrainScene& scene);
  // The placemark drawn at a window pixel: an icon or label of the last frame, else a draped line
  // or polygon at the ground point under the pixel (within a few pixels' worth of metres).
  std::optional<overlays::PlacemarkRef> pick(const scene::TerrainScene& scene, glm::dvec2 pixel,
                                             const std::optional<geo::Cartographic>& ground,
                                             double metersPerPixel) const;
  // The panel shown (none: nullopt) and what it says.
  void select(std::optional<overlays::PlacemarkRef> placemark) { selected_ = placemark; }
  std::optional<overlays::PlacemarkRef> selected() const { return selected_; }
  // The selected placemark's name and description (HTML reduced to text), drawn at the top right.
  // place: the view's HUD layout (placemarkPanelPlace).
  void drawPanel(const scene::TerrainScene& scene, int widthPixels, int heightPixels,
                 PlacemarkPanelPlace place = {});

  size_t labelsShown() const { return placed_.size(); }

 private:
  OverlayDrawing(std::unique_ptr<render::LabelRenderer> renderer,
                 std::unique_ptr<render::WorldOverlayRenderer> shapes)
      : renderer_(std::move(renderer)), shapes_(std::move(shapes)) {}
  std::unique_ptr<render::LabelRenderer> renderer_;
  std::unique_ptr<render::WorldOverlayRenderer> shapes_;  // null: nothing in 3D
  std::vector<text::ScreenLabel> labels_;
  std::vector<size_t> labelMarks_;  // per label, its index in scene.pointMarks()
  std::vector<text::PlacedLabel> placed_;
  std::optional<overlays::PlacemarkRef> selected_;
};

// A KML description as plain text: tags dropped (<br> and </p> as line breaks), the common
// entities decoded, runs of blanks folded.
std::string descriptionText(const std::string& html);

}  // namespace globe::app
