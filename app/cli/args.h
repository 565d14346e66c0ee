#pragma once
// Argument parsing shared by the mozzi-cli subcommands: declared options only,
// so a misspelt option is a usage error that names it; numeric options carry
// their valid range, declared once per command (the range table) and used by
// the parser, --help and docs/cli.md.

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/common/result.h"

namespace mozzi::cli {

// The valid range of one number: [min, max], either end open, optionally a
// whole number. Every numeric option and field of an input file has one.
struct NumberRange {
  NumberRange() = default;
  NumberRange(double lo, double hi, bool loOpen = false, bool hiOpen = false, bool whole = false, std::string u = {})
      : min(lo), max(hi), minOpen(loOpen), maxOpen(hiOpen), integer(whole), unit(std::move(u)) {}

  double min = 0.0;
  double max = 0.0;
  bool minOpen = false;  // (min, ...: min itself excluded
  bool maxOpen = false;  // ..., max): max itself excluded
  bool integer = false;
  std::string unit;  // SI unit shown with the range ("kg", "Hz"); empty if none

  // "(0, 1000] kg", "whole number in [8, 400]".
  std::string text() const;
  bool contains(double v) const;
};

// Range constructors for the tables: closed [a, b], open-below (a, b], whole numbers.
NumberRange closed(double min, double max, std::string unit = {});
NumberRange aboveTo(double min, double max, std::string unit = {});  // (min, max]
NumberRange wholeNumber(double min, double max);

// A numeric option. A scalar by default; with `fields` the value is a list of
// numbers separated by `separator` (e.g. "--fork-bending k,c,hW" or
// "--band LO:HI"), each field with its own range; with `repeated`, several
// such tuples separated by ',' (e.g. "--modes k:f:zeta,k:f:zeta").
struct NumberOption {
  struct Field {
    std::string name;
    NumberRange range;
  };
  // A scalar option.
  NumberOption(std::string optionName, NumberRange valid, std::string what)
      : name(std::move(optionName)), range(std::move(valid)), help(std::move(what)) {}
  // A list option: fields separated by `sep`; `many`: tuples separated by ','.
  NumberOption(std::string optionName, std::string what, std::vector<Field> tupleFields, char sep = ',',
               bool many = false, std::size_t most = 10000)
      : name(std::move(optionName)),
        help(std::move(what)),
        fields(std::move(tupleFields)),
        separator(sep),
        repeated(many),
        maxTuples(most) {}

  std::string name;  // "--fork-mass"
  NumberRange range;
  std::string help;  // what it is, for --help: "fork mass"
  std::vector<Field> fields;
  char separator = ',';
  bool repeated = false;
  std::size_t maxTuples = 10000;  // cap on a repeated list's length

  std::string rangeText() const;  // "(0, 1000] kg" or "k (0, 1e9] Nm/rad, c [0, 1e6] Nms/rad"
};

struct OptionSpec {
  OptionSpec() = default;
  OptionSpec(std::set<std::string> valuedOptions, std::set<std::string> flagOptions,
             std::vector<NumberOption> numberOptions = {}, std::set<std::string> outputOptions = {})
      : valued(std::move(valuedOptions)),
        flags(std::move(flagOptions)),
        numbers(std::move(numberOptions)),
        outputs(std::move(outputOptions)) {}

  std::set<std::string> valued;       // options taking a value: "--out FILE" or "--out=FILE"
  std::set<std::string> flags;        // options without a value: "--json"
  std::vector<NumberOption> numbers;  // numeric options (valued too): parsed and range-checked by parse()
  std::set<std::string> outputs;      // options naming a file the command writes (checked by the output helper)

  const NumberOption* numberOption(const std::string& name) const;
  // The option table of --help: every numeric option with its range, and the outputs.
  std::string helpText() const;
};

// The longest option value or positional argument accepted (a path or a list
// of numbers): longer is an error naming it, not a slow parse.
inline constexpr std::size_t kMaxArgumentLength = 65536;

class ParsedArgs {
 public:
  // Errors: a malformed command line (unknown option, missing value) has code
  // ParseError and is a usage error (exit 2); a value outside its declared
  // range or not a number has code InvalidArgument (exit 1). exitCodeFor()
  // maps them.
  static core::Result<ParsedArgs> parse(const std::vector<std::string>& args, const OptionSpec& spec);

  const std::vector<std::string>& positional() const { return positional_; }
  bool flag(const std::string& name) const { return flags_.count(name) != 0; }
  std::optional<std::string> value(const std::string& name) const;

  // A declared numeric option's value, already range-checked by parse(); for
  // an undeclared option, the value parsed as a finite double.
  core::Result<std::optional<double>> number(const std::string& name) const;
  // A declared list option's numbers (fields in order, tuples one after the
  // other); empty when the option is absent.
  std::vector<double> numbers(const std::string& name) const;

 private:
  std::vector<std::string> positional_;
  std::set<std::string> flags_;
  std::map<std::string, std::string> values_;
  std::map<std::string, std::vector<double>> numbers_;
};

// The text as the user typed it, quoted and shortened for a message (a 1 GB
// argument must not end up in an error message).
std::string quotedArg(const std::string& text);

// Exit code for an error from ParsedArgs::parse (see there).
int exitCodeFor(const core::Error& e);

// Parses `text` as one finite number and checks it against `range`; the error
// names `what` (an option, or file:line and column) and states the range.
core::Result<double> parseInRange(const std::string& text, const NumberRange& range, const std::string& what);
// Checks an already parsed number.
core::Result<void> checkInRange(double value, const NumberRange& range, const std::string& what);

}  // namespace mozzi::cli
