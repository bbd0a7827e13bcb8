#include "io/block_cache.hpp"

namespace globe::io {

template class TileCache<terrain::HeightBlock>;

}  // namespace globe::io
