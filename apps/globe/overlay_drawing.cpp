#include "apps/globe/overlay_drawing.hpp"

#include <algorithm>
#include <cctype>

#include "scene/overlay_points.hpp"
#include "scene/overlay_shapes.hpp"

namespace globe::app {
namespace {

constexpr float kLabelSizePixels = 15.0f;
constexpr float kIconSizePixels = 22.0f;
constexpr double kPickRadiusPixels = 6.0;

glm::vec4 colourOf(const overlays::Rgba& c) {
  return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f};
}

const overlays::Placemark& placemarkOf(const scene::TerrainScene& scene,
                                       const overlays::PlacemarkRef& ref) {
  return scene.options().overlays[ref.document]->placemarks[ref.placemark];
}

}  // namespace

Result<std::unique_ptr<OverlayDrawing>> OverlayDrawing::create(const scene::TerrainScene& scene) {
  if (scene.options().overlays.empty()) return std::unique_ptr<OverlayDrawing>();
  auto renderer = render::LabelRenderer::create({});
  if (!renderer) return Error{renderer.error()};
  // Icons the files carry (local or inside a KMZ), each uploaded once under its href; the rest
  // (web icons, which are not fetched) are drawn as the built-in pin.
  for (const auto& document : scene.options().overlays) {
    for (const overlays::Placemark& placemark : document->placemarks) {
      const overlays::Style& style = placemark.style;
      if (style.iconImage && !style.iconHref.empty() && !(*renderer)->hasIcon(style.iconHref)) {
        (*renderer)->setIcon(style.iconHref, *style.iconImage);
      }
    }
  }
  std::unique_ptr<render::WorldOverlayRenderer> shapes;
  if (scene::hasShapes3d(scene.options().overlays)) {
    auto created = render::WorldOverlayRenderer::create({});
    if (!created) return Error{created.error()};
    shapes = std::move(*created);
  }
  return std::unique_ptr<OverlayDrawing>(
      new OverlayDrawing(std::move(*renderer), std::move(shapes)));
}

void OverlayDrawing::draw(const scene::TerrainScene& scene) {
  const terrain::RenderView& view = scene.view();
  if (shapes_) {
    const scene::OverlayShapes3d shapes = scene::overlayShapes3d(
        scene.options().overlays, scene.renderingTileArray(), scene.ellipsoid());
    std::vector<render::WorldTriangles> triangles;
    for (const scene::OverlayTriangles3d& set : shapes.triangles) {
      triangles.push_back({set.ecefMeters, colourOf(set.color)});
    }
    std::vector<render::WorldLine> lines;
    for (const scene::OverlayLine3d& line : shapes.lines) {
      lines.push_back(
          {line.ecefMeters, colourOf(line.color), static_cast<float>(line.widthPixels)});
    }
    shapes_->draw(view, triangles, lines);
  }
  const std::span<const scene::PointMark> marks = scene.pointMarks();
  const auto shown = scene::shownPoints(marks, view, scene.renderingTileArray(), scene.ellipsoid());
  labels_.clear();
  labelMarks_.clear();
  for (const scene::ShownPoint& point : shown) {
    const scene::PointMark& mark = marks[point.mark];
    const overlays::Placemark& placemark = placemarkOf(scene, {mark.document, mark.placemark});
    const overlays::Style& style = placemark.style;
    text::ScreenLabel label;
    label.text = style.labelScale > 0 ? placemark.name : std::string();
    label.anchorPixels = point.anchorPixels;
    label.sizePixels =
        kLabelSizePixels * static_cast<float>(std::clamp(style.labelScale, 0.5, 3.0));
    label.textRgba = colourOf(style.labelColor);
    if (style.iconScale > 0) {
      label.iconKey =
          renderer_->hasIcon(style.iconHref) ? style.iconHref : std::string(render::kPinIconKey);
      label.iconSizePixels =
          kIconSizePixels * static_cast<float>(std::clamp(style.iconScale, 0.25, 4.0));
      label.iconRgba = colourOf(style.iconColor);
    }
    labels_.push_back(std::move(label));
    labelMarks_.push_back(point.mark);
  }
  const glm::ivec2 viewport{view.widthPixels, view.heightPixels};
  placed_ = renderer_->layout(labels_, viewport);
  renderer_->draw(labels_, placed_, viewport);
}

std::optional<overlays::PlacemarkRef> OverlayDrawing::pick(
    const scene::TerrainScene& scene, glm::dvec2 pixel,
    const std::optional<geo::Cartographic>& ground, double metersPerPixel) const {
  // The last placed label is drawn on top.
  for (auto it = placed_.rbegin(); it != placed_.rend(); ++it) {
    if (pixel.x >= it->minPixels.x && pixel.x <= it->maxPixels.x && pixel.y >= it->minPixels.y &&
        pixel.y <= it->maxPixels.y) {
      const scene::PointMark& mark = scene.pointMarks()[labelMarks_[it->index]];
      return overlays::PlacemarkRef{mark.document, mark.placemark};
    }
  }
  if (!ground) return std::nullopt;
  return overlays::pickDraped(scene.options().overlays, ground->longitudeDegrees(),
                              ground->latitudeDegrees(), kPickRadiusPixels * metersPerPixel);
}

void OverlayDrawing::drawPanel(const scene::TerrainScene& scene, int widthPixels,
                               int heightPixels, PlacemarkPanelPlace place) {
  if (!selected_) return;
  const overlays::Placemark& placemark = placemarkOf(scene, *selected_);
  std::vector<std::string> paragraphs{placemark.name.empty() ? "(no name)" : placemark.name};
  const std::string text = descriptionText(placemark.description);
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    if (end > start) paragraphs.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  const float maxWidth =
      std::min({place.maxWidthPixels, 420.0f, 0.4f * static_cast<float>(widthPixels)});
  const glm::vec2 size = renderer_->textPanelSizePixels(paragraphs, maxWidth);
  renderer_->drawTextPanel(paragraphs,
                           {static_cast<float>(widthPixels) - size.x - 12.0f, place.topPixels},
                           maxWidth, {widthPixels, heightPixels});
}

std::string descriptionText(const std::string& html) {
  std::string text;
  text.reserve(html.size());
  for (size_t i = 0; i < html.size();) {
    if (html[i] == '<') {
      const size_t close = html.find('>', i);
      if (close == std::string::npos) break;
      std::string tag = html.substr(i + 1, close - i - 1);
      std::transform(tag.begin(), tag.end(), tag.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (tag.rfind("br", 0) == 0 || tag == "/p" || tag == "/div" || tag == "/tr" || tag == "/li" ||
          tag.rfind("/h", 0) == 0) {
        text += '\n';
      } else if (tag == "/td" || tag == "/th") {
        text += ' ';
      }
      i = close + 1;
      continue;
    }
    if (html[i] == '&') {
      static const std::pair<const char*, const char*> kEntities[] = {
          {"&amp;", "&"}, {"&lt;", "<"},   {"&gt;", ">"},  {"&quot;", "\""},
          {"&#39;", "'"}, {"&apos;", "'"}, {"&nbsp;", " "}};
      bool decoded = false;
      for (const auto& [entity, value] : kEntities) {
        if (html.compare(i, std::char_traits<char>::length(entity), entity) == 0) {
          text += value;
          i += std::char_traits<char>::length(entity);
          decoded = true;
          break;
        }
      }
      if (decoded) continue;
    }
    text += html[i] == '\r' || html[i] == '\t' ? ' ' : html[i];
    ++i;
  }
  // Blanks folded; blank lines dropped; lines trimmed.
  std::string folded;
  bool space = false, lineStart = true;
  for (const char c : text) {
    if (c == '\n') {
      if (!lineStart) folded += '\n';
      lineStart = true;
      space = false;
    } else if (c == ' ') {
      space = !lineStart;
    } else {
      if (space) folded += ' ';
      folded += c;
      space = false;
      lineStart = false;
    }
  }
  while (!folded.empty() && folded.back() == '\n') folded.pop_back();
  return folded;
}

}  // namespace globe::app
