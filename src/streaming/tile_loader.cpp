#include "streaming/tile_loader.hpp"

namespace globe::streaming {

template class PayloadLoader<terrain::HeightBlock>;

}  // namespace globe::streaming
