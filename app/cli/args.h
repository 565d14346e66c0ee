#pragma once
// Argument parsing shared by the mozzi-cli subcommands: declared options only,
// so a misspelt option is a usage error that names it.

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/common/result.h"

namespace mozzi::cli {

struct OptionSpec {
  std::set<std::string> valued;  // options taking a value: "--out FILE" or "--out=FILE"
  std::set<std::string> flags;   // options without a value: "--json"
};

class ParsedArgs {
 public:
  static core::Result<ParsedArgs> parse(const std::vector<std::string>& args, const OptionSpec& spec);

  const std::vector<std::string>& positional() const { return positional_; }
  bool flag(const std::string& name) const { return flags_.count(name) != 0; }
  std::optional<std::string> value(const std::string& name) const;

  // A value parsed as a finite double; an error names the option and the text.
  core::Result<std::optional<double>> number(const std::string& name) const;

 private:
  std::vector<std::string> positional_;
  std::set<std::string> flags_;
  std::map<std::string, std::string> values_;
};

}  // namespace mozzi::cli
