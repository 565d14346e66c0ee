#include "app/cli/output.h"

#include "app/cli/command.h"
#include "core/io/output_file.h"

namespace mozzi::cli {

int refuseOutputsOntoInputs(const ParsedArgs& args, const OptionSpec& spec, const std::vector<std::string>& inputs,
                            const std::string& command, std::ostream& err,
                            const std::vector<std::string>& extraOutputs) {
  std::vector<std::string> outputs;
  for (const auto& name : spec.outputs) {
    if (auto path = args.value(name)) {
      if (path->empty()) {
        err << "mozzi-cli " << command << ": option " << name << " names no file (empty value)\n";
        return kExitFailure;
      }
      outputs.push_back(*path);
    }
  }
  outputs.insert(outputs.end(), extraOutputs.begin(), extraOutputs.end());
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    std::vector<std::string> others = inputs;
    others.insert(others.end(), outputs.begin(), outputs.begin() + static_cast<std::ptrdiff_t>(k));
    if (auto r = core::io::refuseInputAsOutput(outputs[k], others); !r) {
      err << "mozzi-cli " << command << ": " << r.error().describe() << "\n";
      return kExitFailure;
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (outputs[j] == outputs[k]) {
        err << "mozzi-cli " << command << ": two outputs name the same file '" << outputs[k] << "'\n";
        return kExitFailure;
      }
    }
  }
  return kExitOk;
}

}  // namespace mozzi::cli
