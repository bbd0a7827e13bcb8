// The `globe-tiler imagery` command line: options parsed, the tiler run, a one-line summary.
#pragma once

namespace globe::tiler_app {

// argv[0] is "imagery".
int runImageryCommand(int argc, char** argv);

}  // namespace globe::tiler_app
