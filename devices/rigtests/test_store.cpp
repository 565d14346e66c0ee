#include "devices/rigtests/test_store.h"

#include <chrono>
#include <ctime>
#include <set>
#include <variant>

namespace mozzi::devices::rigtests::detail {

nlohmann::json parametersJson(const ParameterMap& parameters) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, value] : parameters) std::visit([&j, &key = key](const auto& v) { j[key] = v; }, value);
  return j;
}

std::vector<core::io::StoredTransducer> transducersOf(const std::vector<ChannelConfig>& channels) {
  std::vector<core::io::StoredTransducer> out;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const auto& ch = channels[c];
    core::io::StoredTransducer t;
    t.channel = static_cast<int>(c);
    t.quantity = core::signal::transducerKindName(ch.transducer.kind);
    t.unit = ch.transducer.unit;
    // Sensitivity in V per SI unit (the transducer's is mV per unit).
    t.sensitivity = ch.transducer.sensitivityMvPerUnit > 0 ? ch.transducer.sensitivityMvPerUnit / 1000.0 : 1.0;
    t.model = ch.transducer.model.empty() ? ch.name : ch.transducer.model + " (" + ch.name + ")";
    t.serial = ch.transducer.serial;
    out.push_back(t);
  }
  return out;
}

core::Result<std::string> uniqueTestName(const core::io::ProjectStore& store, std::int64_t specimenId, bool tyre,
                                         const std::string& wanted, const std::string& kind) {
  auto tests = tyre ? store.tyreTests() : store.rigTests();
  if (!tests) return tests.error();
  std::set<std::string> taken;
  for (const auto& t : *tests)
    if (t.specimenId == specimenId) taken.insert(t.name);
  std::string base = wanted;
  if (base.empty()) {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &tm);
    base = kind + " test " + text;
  }
  std::string name = base;
  for (int k = 2; taken.count(name); ++k) name = base + " (" + std::to_string(k) + ")";
  return name;
}

std::vector<core::io::StoredRigTest::Result> rigResults(const std::vector<Quantity>& q, std::optional<int> step) {
  std::vector<core::io::StoredRigTest::Result> out;
  for (const auto& x : q) out.push_back({x.key, x.value, x.unit, x.uncertainty, step});
  return out;
}

std::vector<core::io::StoredTyreTest::Parameter> tyreParameters(const std::vector<Quantity>& q,
                                                                std::optional<int> step) {
  std::vector<core::io::StoredTyreTest::Parameter> out;
  for (const auto& x : q) out.push_back({x.key, x.value, x.unit, x.uncertainty, step});
  return out;
}

Eigen::MatrixXf recordOf(const core::Matrix& values, Eigen::Index rows, const std::vector<int>& columns) {
  Eigen::MatrixXf out(rows, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c)
    out.col(static_cast<Eigen::Index>(c)) = values.col(columns[c]).head(rows).cast<float>();
  return out;
}

namespace {
void appendNote(std::string& note, const std::string& text) {
  note += (note.empty() ? "" : "; ") + text;
}
}  // namespace

void collectStoreError(const core::Result<void>& written, std::string& storeErrors) {
  if (!written) appendNote(storeErrors, written.error().describe());
}

void reportStoreErrors(const std::string& storeErrors, Outcome& out) {
  if (storeErrors.empty()) return;
  appendNote(out.note, "not stored: " + storeErrors);
  if (out.status == TestStatus::Complete) out.status = TestStatus::Failed;
}

void reportFinalWrite(const core::Result<void>& finalWrite, Outcome& out) {
  if (!finalWrite) appendNote(out.note, "status not stored: " + finalWrite.error().describe());
}

}  // namespace mozzi::devices::rigtests::detail
