#pragma once
// Internal to devices/rigtests: how the sequences write the project (rig
// set-up, test row, one transaction per step, the final status).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/io/project_store.h"
#include "devices/common/acquisition.h"
#include "devices/rigtests/rig_sequence.h"

namespace mozzi::devices::rigtests::detail {

// Parameters as JSON (bool, integer, real, text).
nlohmann::json parametersJson(const ParameterMap& parameters);

// The transducers of the configured channels, in configuration order.
std::vector<core::io::StoredTransducer> transducersOf(const std::vector<ChannelConfig>& channels);

// A name not yet used by a test of the specimen: `wanted`, or
// "<kind> test <UTC time>" when empty, with " (2)", " (3)" ... when taken.
core::Result<std::string> uniqueTestName(const core::io::ProjectStore& store, std::int64_t specimenId, bool tyre,
                                         const std::string& wanted, const std::string& kind);

std::vector<core::io::StoredRigTest::Result> rigResults(const std::vector<Quantity>& q, std::optional<int> step);
std::vector<core::io::StoredTyreTest::Parameter> tyreParameters(const std::vector<Quantity>& q,
                                                                std::optional<int> step);

// A store failure during a test does not stop it (the rig is mid-load): the
// errors are collected step by step ...
void collectStoreError(const core::Result<void>& written, std::string& storeErrors);
// ... and said at the end: in the note, and a complete test becomes failed
// since its data are not all in the project; a failed write of the final
// status is added to the note.
void reportStoreErrors(const std::string& storeErrors, Outcome& out);
void reportFinalWrite(const core::Result<void>& finalWrite, Outcome& out);

// Samples of the listed columns as float, SI units, for the record blob.
Eigen::MatrixXf recordOf(const core::Matrix& values, Eigen::Index rows, const std::vector<int>& columns);

}  // namespace mozzi::devices::rigtests::detail
