// Helpers that build RenderViews in double precision.
#include "terrain/render_view.hpp"

#include <algorithm>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

namespace globe::terrain {

glm::dmat4 makePerspective(double fovYRadians, double aspect, double nearMeters, double farMeters) {
  return glm::perspective(fovYRadians, aspect, nearMeters, farMeters);
}

RenderView makeLookAtView(const glm::dvec3& eyeEcefMeters, const glm::dvec3& targetEcefMeters,
                          const glm::dvec3& upEcef, double fovYRadians, int widthPixels,
                          int heightPixels, const glm::dvec3& sunDirectionEcef, double nearMeters,
                          double farMeters) {
  RenderView view;
  view.cameraEcefMeters = eyeEcefMeters;
  view.viewMatrix = glm::lookAt(eyeEcefMeters, targetEcefMeters, upEcef);
  const double aspect = static_cast<double>(std::max(widthPixels, 1)) /
                        static_cast<double>(std::max(heightPixels, 1));
  view.projection = makePerspective(fovYRadians, aspect, nearMeters, farMeters);
  view.farMeters = farMeters;
  view.widthPixels = widthPixels;
  view.heightPixels = heightPixels;
  view.sunDirectionEcef = glm::normalize(sunDirectionEcef);
  return view;
}

}  // namespace globe::terrain
