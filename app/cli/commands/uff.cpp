// mozzi-cli uff: summarise a universal file, or convert it between ASCII and
// binary 58.
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/io/output_file.h"
#include "core/io/uff/uff.h"

namespace mozzi::cli {
namespace {

namespace uff = core::io::uff;

constexpr const char* kUsage =
    "Usage: mozzi-cli uff info FILE [--json]\n"
    "       mozzi-cli uff convert IN OUT [--binary|--ascii]\n";

// NODE:DIR as core::formatDof writes it ("21:+Z"); a scalar channel
// (direction code 0) as "NODE:0".
std::string channelText(const uff::Channel58& c) {
  auto dof = c.dof();
  return dof ? core::formatDof(*dof) : std::to_string(c.node) + ":" + std::to_string(c.direction);
}

std::string ordinateText(uff::OrdinateType t) {
  switch (t) {
    case uff::OrdinateType::RealSingle: return "real single";
    case uff::OrdinateType::RealDouble: return "real double";
    case uff::OrdinateType::ComplexSingle: return "complex single";
    case uff::OrdinateType::ComplexDouble: return "complex double";
  }
  return "unknown";
}

nlohmann::json datasetJson(const uff::Dataset& d) {
  nlohmann::json j;
  j["type"] = d.type;
  j["line"] = d.line;
  if (const auto* f = d.get<uff::Function58>()) {
    j["function_type"] = static_cast<int>(f->functionType);
    j["function_name"] = uff::functionTypeName(f->functionType);
    j["points"] = f->pointCount();
    j["response"] = channelText(f->response);
    j["reference"] = channelText(f->reference);
    j["binary"] = f->binary;
    j["ordinate"] = ordinateText(f->ordinateType);
    j["even_spacing"] = f->evenSpacing;
    const core::Vector x = f->abscissaValues();
    if (x.size() > 0) {
      j["abscissa_first"] = x[0];
      j["abscissa_last"] = x[x.size() - 1];
    }
    j["abscissa_units"] = f->abscissaAxis.unitsLabel;
    j["ordinate_units"] = f->ordinateNumerator.unitsLabel;
    j["denominator_units"] = f->ordinateDenominator.unitsLabel;
  } else if (const auto* h = d.get<uff::Header151>()) {
    j["model_name"] = h->modelName;
    j["program"] = h->uffProgram;
  } else if (const auto* u = d.get<uff::Units164>()) {
    j["units_code"] = u->unitsCode;
    j["units"] = u->description;
    j["length_factor"] = u->lengthFactor;
    j["force_factor"] = u->forceFactor;
  } else if (const auto* n = d.get<uff::NodeSet>()) {
    j["nodes"] = n->nodes.size();
  } else if (const auto* c = d.get<uff::CoordinateSystemSet>()) {
    j["coordinate_systems"] = c->systems.size();
  } else if (const auto* t = d.get<uff::TraceLine82>()) {
    j["trace"] = t->traceNumber;
    j["nodes"] = t->nodes.size();
  } else if (const auto* m = d.get<uff::ModalData55>()) {
    j["analysis_type"] = static_cast<int>(m->analysisType);
    j["nodes"] = m->nodes.size();
    j["mode"] = m->modeNumber();
    if (!m->realValues.empty()) j["record8"] = m->realValues;
  } else if (d.get<uff::SkippedDataset>()) {
    j["skipped"] = true;
  }
  return j;
}

std::string textLine(const uff::Dataset& d) {
  std::string s = "  " + std::to_string(d.type) + " (line " + std::to_string(d.line) + ")";
  if (const auto* f = d.get<uff::Function58>()) {
    s += std::string(f->binary ? " binary" : " ASCII") + " " + uff::functionTypeName(f->functionType) + ", " +
         std::to_string(f->pointCount()) + " points " + ordinateText(f->ordinateType) + ", response " +
         channelText(f->response) + ", reference " + channelText(f->reference) + ", [" +
         f->ordinateNumerator.unitsLabel;
    if (f->ordinateDenominator.unitsLabel != "NONE") s += "/" + f->ordinateDenominator.unitsLabel;
    s += "] over [" + f->abscissaAxis.unitsLabel + "]";
  } else if (const auto* h = d.get<uff::Header151>()) {
    s += " header: model '" + h->modelName + "'";
  } else if (const auto* u = d.get<uff::Units164>()) {
    s += " units: code " + std::to_string(u->unitsCode) + " '" + u->description + "', length factor " +
         std::to_string(u->lengthFactor) + ", force factor " + std::to_string(u->forceFactor);
  } else if (const auto* n = d.get<uff::NodeSet>()) {
    s += " nodes: " + std::to_string(n->nodes.size());
  } else if (const auto* c = d.get<uff::CoordinateSystemSet>()) {
    s += " coordinate systems: " + std::to_string(c->systems.size());
  } else if (const auto* t = d.get<uff::TraceLine82>()) {
    s += " trace line " + std::to_string(t->traceNumber) + ": " + std::to_string(t->nodes.size()) + " nodes";
  } else if (const auto* m = d.get<uff::ModalData55>()) {
    s += " data at nodes: analysis type " + std::to_string(static_cast<int>(m->analysisType)) + ", mode " +
         std::to_string(m->modeNumber()) + ", " + std::to_string(m->nodes.size()) + " nodes";
  } else {
    s += " skipped (not used by Mozzi)";
  }
  return s;
}

// Streams the file: only the summary of each dataset is kept, so a file
// larger than memory can be listed.
int info(const std::string& path, bool json, std::ostream& out, std::ostream& err) {
  auto reader = uff::DatasetReader::open(path);
  if (!reader) {
    err << "mozzi-cli uff info: " << reader.error().describe() << "\n";
    return kExitFailure;
  }
  std::map<int, int> counts;
  nlohmann::json list = nlohmann::json::array();
  std::vector<std::string> lines;
  for (;;) {
    auto d = reader->next();
    if (!d) {
      err << "mozzi-cli uff info: " << d.error().describe() << "\n";
      return kExitFailure;
    }
    if (!d->has_value()) break;
    ++counts[(*d)->type];
    if (json) {
      list.push_back(datasetJson(**d));
    } else {
      lines.push_back(textLine(**d));
    }
  }
  const auto& warnings = reader->warnings();
  if (json) {
    nlohmann::json j;
    j["file"] = path;
    j["datasets"] = std::move(list);
    j["counts"] = nlohmann::json::object();
    for (const auto& [type, n] : counts) j["counts"][std::to_string(type)] = n;
    j["warnings"] = nlohmann::json::array();
    for (const auto& w : warnings) {
      j["warnings"].push_back({{"type", w.datasetType}, {"line", w.line}, {"message", w.message}});
    }
    // Vendor text may be Latin-1: invalid UTF-8 is replaced, not fatal.
    out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return kExitOk;
  }
  out << path << ": " << lines.size() << " datasets\n";
  for (const auto& [type, n] : counts) out << "  dataset " << type << ": " << n << "\n";
  for (const auto& l : lines) out << l << "\n";
  if (!warnings.empty()) {
    out << warnings.size() << " warnings\n";
    for (const auto& w : warnings) out << "  " << w.describe() << "\n";
  }
  return kExitOk;
}

// Streams dataset by dataset: memory follows the largest dataset, not the file.
int convert(const std::string& in, const std::string& outPath, uff::Encoding58 encoding, std::ostream& out,
            std::ostream& err) {
  auto reader = uff::DatasetReader::open(in);
  if (!reader) {
    err << "mozzi-cli uff convert: " << reader.error().describe() << "\n";
    return kExitFailure;
  }
  // The output helper refuses the input itself (also through a symbolic or
  // hard link) and writes a temporary file renamed into place only after a
  // checked flush, fsync and close (core/io/output_file.h).
  auto output = core::io::OutputFile::open(outPath, {in});
  if (!output) {
    err << "mozzi-cli uff convert: " << output.error().describe() << "\n";
    return kExitFailure;
  }
  std::ostream& file = output->stream();
  uff::WriteOptions options;
  options.encoding = encoding;
  int written = 0;
  int skipped = 0;
  for (;;) {
    auto d = reader->next();
    if (!d) {
      err << "mozzi-cli uff convert: " << d.error().describe() << "\n";
      return kExitFailure;
    }
    if (!d->has_value()) break;
    if ((*d)->get<uff::SkippedDataset>()) {
      ++skipped;
      continue;
    }
    if (auto r = uff::writeDataset(file, **d, options); !r) {
      // A failed write is named by commit() (file and system reason).
      err << "mozzi-cli uff convert: " << (file ? r.error() : output->commit().error()).describe() << "\n";
      return kExitFailure;
    }
    ++written;
  }
  if (written == 0) {
    // Nothing to convert: no output file rather than an empty one.
    err << "mozzi-cli uff convert: " << in << " holds no dataset Mozzi can convert; " << outPath << " not written\n";
    return kExitFailure;
  }
  if (auto r = output->commit(); !r) {
    err << "mozzi-cli uff convert: " << r.error().describe() << "\n";
    return kExitFailure;
  }
  for (const auto& w : reader->warnings()) err << "warning: " << w.describe() << "\n";
  out << "wrote " << written << " datasets to " << outPath;
  if (skipped > 0) out << " (" << skipped << " datasets of types Mozzi does not use left out)";
  out << "\n";
  return kExitOk;
}

// No numeric options; OUT of 'convert' is written through the output helper.
const OptionSpec kSpec{{}, {"--json", "--binary", "--ascii"}};

int uffCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed || parsed->positional().empty()) {
    err << "mozzi-cli uff: " << (parsed ? "expected a subcommand" : parsed.error().describe()) << "\n" << kUsage;
    return kExitUsage;
  }
  const auto& pos = parsed->positional();
  const std::string& sub = pos[0];
  if (sub == "info") {
    if (pos.size() != 2 || parsed->flag("--binary") || parsed->flag("--ascii")) {
      err << "mozzi-cli uff info: expected one FILE and at most --json\n" << kUsage;
      return kExitUsage;
    }
    return info(pos[1], parsed->flag("--json"), out, err);
  }
  if (sub == "convert") {
    if (pos.size() != 3 || parsed->flag("--json") || (parsed->flag("--binary") && parsed->flag("--ascii"))) {
      err << "mozzi-cli uff convert: expected IN OUT and at most one of --binary, --ascii\n" << kUsage;
      return kExitUsage;
    }
    const uff::Encoding58 encoding = parsed->flag("--binary")  ? uff::Encoding58::Binary
                                     : parsed->flag("--ascii") ? uff::Encoding58::Ascii
                                                               : uff::Encoding58::AsStored;
    return convert(pos[1], pos[2], encoding, out, err);
  }
  err << "mozzi-cli uff: unknown subcommand '" << sub << "'\n" << kUsage;
  return kExitUsage;
}

const CommandRegistrar kRegistrar({"uff", "info FILE [--json] | convert IN OUT [--binary|--ascii]",
                                   "Summarise a universal file, or convert 58 records between ASCII and binary",
                                   uffCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
