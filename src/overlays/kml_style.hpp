// KML's style cascade: shared <Style>s and <StyleMap>s by id, a feature's styleUrl and its inline
// <Style> merged over the shared one, Google Earth's defaults for what no style says.
#pragma once

#include <tinyxml2.h>

#include <map>
#include <string>
#include <string_view>

#include "overlays/overlay_images.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

class KmlStyles {
 public:
  // Records a <Style id> or <StyleMap id> (the first of an id wins); ignores anything else.
  void add(const tinyxml2::XMLElement& styleOrMap);

  // The style of a feature with this styleUrl ("#id"; empty or another file's: none) and inline
  // <Style> or <StyleMap> (may be null). A StyleMap counts as its "normal" pair. The icon href is
  // resolved and its image decoded through `images`.
  Style resolve(std::string_view styleUrl, const tinyxml2::XMLElement* inlineStyle,
                OverlayImages& images) const;

 private:
  // Applies what the referenced style says over `style`; depth bounds StyleMap chains (and
  // cycles) in hostile files.
  void applyUrl(std::string_view styleUrl, Style& style, std::string& iconHref, int depth) const;
  void applySelector(const tinyxml2::XMLElement& selector, Style& style, std::string& iconHref,
                     int depth) const;

  std::map<std::string, const tinyxml2::XMLElement*, std::less<>> byId_;
};

}  // namespace globe::overlays
