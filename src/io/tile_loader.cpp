#include "io/tile_loader.hpp"

namespace globe::io {

template class PayloadLoader<terrain::HeightBlock>;

}  // namespace globe::io
