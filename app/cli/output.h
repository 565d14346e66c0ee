#pragma once
// The CLI side of the output rule (docs/cli.md, "Output files"): before any
// work, every file a command will write is checked against its inputs; the
// writing itself goes through core::io::OutputFile (temporary file, checked
// flush + fsync + close, rename), directly or inside core's writers.

#include <ostream>
#include <string>
#include <vector>

#include "app/cli/args.h"

namespace mozzi::cli {

// For every option of spec.outputs present in `args` (and every path in
// `extraOutputs`): refuses one that is the same file as any of `inputs`, or
// the same file as another output. Prints "mozzi-cli CMD: ..." naming the
// file and returns kExitFailure; kExitOk when all is well.
int refuseOutputsOntoInputs(const ParsedArgs& args, const OptionSpec& spec, const std::vector<std::string>& inputs,
                            const std::string& command, std::ostream& err,
                            const std::vector<std::string>& extraOutputs = {});

}  // namespace mozzi::cli
