#include "streaming/block_cache.hpp"

namespace globe::streaming {

template class TileCache<terrain::HeightBlock>;

}  // namespace globe::streaming
