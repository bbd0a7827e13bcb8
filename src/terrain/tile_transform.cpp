#include "terrain/tile_transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "terrain/tile_mesh.hpp"

namespace globe::terrain {

TileTransform tileTransform(const RenderView& view, uint32_t level,
                            const glm::dvec3& centerEcefMeters) {
  const double quantum = originQuantumMeters(level);
  const glm::dvec3 eye = quantizedEcefMeters(view.cameraEcefMeters, quantum);
  const glm::dvec3 origin = centerEcefMeters - eye;  // multiples of the quantum: exact in double
  TileTransform transform;
  transform.levelView = glm::mat4(view.viewMatrix * glm::translate(glm::dmat4(1.0), eye));
  transform.origin = glm::vec3(origin);
  transform.exact = glm::dvec3(transform.origin) == origin;
  return transform;
}

}  // namespace globe::terrain
