#include "core/gap/problem_loader.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/gap/stability/stability_problem.h"
#include "core/gap/structural/model_file.h"
#include "core/gap/structural/structural_problem.h"
#include "core/gap/tire/tire_problem.h"
#include "core/io/text_file.h"
#include "core/io/uff/uff.h"

namespace mozzi::core::gap {
namespace {

Result<std::string> readText(const std::string& path, const std::string& what) {
  return io::readTextFile(path, what);  // size cap: core/io/text_file.h
}

bool looksLikeJson(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  return first != std::string::npos && text[first] == '{';
}

Result<std::unique_ptr<GapProblem>> loadStructural(const structural::StructuralModel& model,
                                                   const std::string& measuredPath, const LoadOptions& options) {
  structural::StructuralOptions so;
  so.bandLowHz = options.bandLowHz;
  so.bandHighHz = options.bandHighHz;
  so.reportBands = options.reportBands;
  so.relativeFloor = options.relativeFloor;
  so.additiveFloor = options.additiveFloor;
  using Source = structural::StructuralOptions::NoiseSource;
  if (options.noise == "auto") {
    so.noise = Source::Auto;
  } else if (options.noise == "estimated") {
    so.noise = Source::Estimated;
  } else if (options.noise == "coherence") {
    so.noise = Source::Coherence;
  } else if (options.noise == "stated") {
    so.noise = Source::Stated;
  } else {
    return makeError(ErrorCode::InvalidArgument,
                     "unknown noise model '" + options.noise + "' (auto, estimated, coherence, stated)", "--noise");
  }
  so.averages = options.averages;
  MOZZI_TRY_ASSIGN(const io::uff::UffFile file, io::uff::readFile(measuredPath));
  const bool hasFrf = [&] {
    for (const auto* f : file.all<io::uff::Function58>())
      if (f->functionType == io::uff::FunctionType::Frf) return true;
    return false;
  }();
  if (hasFrf) {
    auto frf = io::uff::toFrfMatrix(file);
    if (!frf) return Error{frf.error().code, frf.error().message, measuredPath + ": " + frf.error().where};
    return structural::makeFrfProblem(model, *frf, so);
  }
  if (!file.all<io::uff::ModalData55>().empty()) {
    auto modes = io::uff::toModalData(file);
    if (!modes) return Error{modes.error().code, modes.error().message, measuredPath + ": " + modes.error().where};
    return structural::makeModesProblem(model, *modes, so);
  }
  return makeError(ErrorCode::NotFound, "the test file holds neither FRFs (dataset 58, function type 4) nor modes (55)",
                   measuredPath);
}

}  // namespace

Result<std::string> modelFileKind(const std::string& modelPath) {
  MOZZI_TRY_ASSIGN(const std::string text, readText(modelPath, "model"));
  if (looksLikeJson(text)) {
    const auto root = nlohmann::json::parse(text, nullptr, false);
    if (root.is_discarded() || !root.is_object()) return makeError(ErrorCode::ParseError, "not valid JSON", modelPath);
    if (!root.contains("schema") || !root["schema"].is_string()) {
      return makeError(ErrorCode::ParseError, "schema: missing (expected e.g. \"mozzi-model/1\")", modelPath);
    }
    return root["schema"].get<std::string>();
  }
  return std::string("uff");
}

Result<std::unique_ptr<GapProblem>> loadGapProblem(const std::string& modelPath, const std::string& measuredPath,
                                                   const LoadOptions& options) {
  if (!(options.bandHighHz > options.bandLowHz)) {
    return makeError(ErrorCode::InvalidArgument, "the band must have LO < HI", "--band");
  }
  MOZZI_TRY_ASSIGN(const std::string kind, modelFileKind(modelPath));
  if (kind == "mozzi-tire-gap/1") return loadTireGapProblem(modelPath, measuredPath);
  if (kind == "mozzi-stability-gap/1") return loadStabilityGapProblem(modelPath, measuredPath);
  if (kind == structural::kModelSchema) {
    MOZZI_TRY_ASSIGN(const structural::StructuralModel model, structural::readModelFile(modelPath));
    return loadStructural(model, measuredPath, options);
  }
  if (kind == "uff") {
    MOZZI_TRY_ASSIGN(const io::uff::UffFile file, io::uff::readFile(modelPath));
    auto modes = io::uff::toModalData(file);
    if (!modes) {
      return makeError(
          ErrorCode::ParseError,
          "the model is neither a JSON model file nor a UFF modal model (dataset 55): " + modes.error().message,
          modelPath);
    }
    MOZZI_TRY_ASSIGN(const structural::StructuralModel model, structural::modelFromModalData(*modes, modelPath));
    return loadStructural(model, measuredPath, options);
  }
  return makeError(ErrorCode::Unsupported,
                   "unknown model schema '" + kind +
                       "' (known: mozzi-model/1, mozzi-tire-gap/1, mozzi-stability-gap/1, UFF 55 modal models)",
                   modelPath);
}

}  // namespace mozzi::core::gap
