// Every input of a pyramid measured as source_fidelity.hpp does: each at its finest level,
// against the inputs coarser than it (the sea check) and as fine as it (their joins are no
// edges). What globe-source-fidelity prints and the fidelity tests assert.
#pragma once

#include <string>
#include <vector>

#include "streaming/tile_store.hpp"
#include "tools/fidelity/source_fidelity.hpp"

namespace globe::fidelity {

struct InputFidelity {
  std::string argument;  // the input as given
  SourceFidelity fidelity;
};

// inputs and noDataIsSea as given to globe-tiler; finest first, whole-globe inputs (no edge)
// left out.
Result<std::vector<InputFidelity>> measureInputs(streaming::TileStore& store,
                                                 const std::vector<std::string>& inputs,
                                                 bool noDataIsSea = false,
                                                 double edgeBandDegrees = 0.1);

}  // namespace globe::fidelity
