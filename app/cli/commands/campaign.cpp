// mozzi-cli campaign: run an impact campaign on a simulated station with
// automatic decisions, resuming the unfinished one, and list campaigns with
// their progress (docs/cli/campaign.md).
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <set>
#include <string>

#include "app/cli/args.h"
#include "app/cli/command.h"
#include "core/io/project_store.h"
#include "devices/campaign/campaign_engine.h"
#include "devices/campaign/virtual_campaign.h"
#include "devices/common/driver.h"
#include "devices/sim/specimen_catalogue.h"

namespace mozzi::cli {
namespace {

namespace cp = devices::campaign;
using nlohmann::json;

constexpr const char* kUsage =
    "Usage: mozzi-cli campaign run PROJECT.mozzi --specimen NAME --rig sim-hammer [--constraint C] [--hits N]\n"
    "                              [--new] [--seed S] [--json]\n"
    "       mozzi-cli campaign status PROJECT.mozzi [--json]\n"
    "  --specimen    virtual specimen key as `mozzi-cli rig list` prints it (fork-a-with-wheel,\n"
    "                frame-a-front-constrained) or the name of a specimen of the project\n"
    "  --constraint  with a specimen name: which of its constraints (front-constrained, ...)\n"
    "  --hits N      accepted hits per point (default 5)\n"
    "  --new         start another campaign instead of resuming the unfinished one\n"
    "  --seed S      seed of the simulated hits (default 1): same seed, same hits\n";

int usage(std::ostream& err, const std::string& why) {
  err << "mozzi-cli campaign: " << why << "\n" << kUsage;
  return kExitUsage;
}

int fail(std::ostream& err, const core::Error& e) {
  err << "mozzi-cli campaign: " << e.describe() << "\n";
  return kExitFailure;
}

// Which virtual specimen (catalogue key) and which project specimen a
// --specimen argument names.
struct SpecimenChoice {
  std::string key;
  std::optional<std::int64_t> specimenId;  // empty: not in the project yet
  std::string name, kind;
};

core::Result<SpecimenChoice> chooseSpecimen(const core::io::ProjectSummary& summary, const std::string& arg,
                                            const std::optional<std::string>& constraint) {
  const auto& catalogue = devices::sim::specimenCatalogue();
  auto inProject = [&](const std::string& name) -> std::optional<std::int64_t> {
    for (const auto& s : summary.specimens)
      if (s.name == name) return s.id;
    return std::nullopt;
  };
  // A catalogue key: the project specimen of that name, or of the name
  // before its constraint ("Frame A, front-constrained" -> "Frame A").
  if (const auto* e = devices::sim::findSpecimen(arg)) {
    if (constraint && arg.find(*constraint) == std::string::npos)
      return core::makeError(core::ErrorCode::InvalidArgument,
                             "--constraint '" + *constraint + "' does not match specimen key '" + arg + "'",
                             "--constraint");
    SpecimenChoice c{e->key, inProject(e->name), e->name, e->kind};
    if (!c.specimenId) {
      const auto comma = e->name.find(", ");
      if (comma != std::string::npos) {
        c.specimenId = inProject(e->name.substr(0, comma));
        if (c.specimenId) c.name = e->name.substr(0, comma);
      }
    }
    return c;
  }
  // A project specimen's name: the catalogue entries of that name, or of
  // that name with a constraint.
  const auto id = inProject(arg);
  if (!id)
    return core::makeError(core::ErrorCode::NotFound,
                           "'" + arg +
                               "' is neither a virtual specimen key (mozzi-cli rig list) nor a specimen of the "
                               "project (mozzi-cli project info)",
                           "--specimen");
  std::vector<const devices::sim::SpecimenEntry*> matches;
  for (const auto& e : catalogue)
    if (e.name == arg || e.name.rfind(arg + ", ", 0) == 0) matches.push_back(&e);
  if (constraint) {
    std::vector<const devices::sim::SpecimenEntry*> kept;
    for (const auto* e : matches)
      if (e->key.find(*constraint) != std::string::npos) kept.push_back(e);
    matches = kept;
  }
  if (matches.empty())
    return core::makeError(core::ErrorCode::NotFound,
                           "specimen '" + arg + "' has no virtual specimen" +
                               (constraint ? " with constraint '" + *constraint + "'" : std::string()) +
                               " to simulate it",
                           "--specimen");
  if (matches.size() > 1) {
    std::string keys;
    for (const auto* e : matches) keys += (keys.empty() ? "" : ", ") + e->key;
    return core::makeError(core::ErrorCode::InvalidArgument,
                           "specimen '" + arg + "' has several constraints: name one with --constraint (" + keys + ")",
                           "--constraint");
  }
  return SpecimenChoice{matches[0]->key, id, arg, matches[0]->kind};
}

// Prints a progress bar on a terminal; collects the counts for the summary.
class CliObserver final : public cp::CampaignObserver {
 public:
  explicit CliObserver(bool bar) : bar_(bar) {}
  void onProgress(const cp::EngineProgress& p) override {
    if (!bar_) return;
    const int width = 30;
    const int filled = static_cast<int>(p.schedule.fraction() * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %d/%d points, %d hits accepted, %d rejected ",
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(width - filled), '.').c_str(),
                 p.schedule.pointsDone + p.schedule.pointsSkipped, p.schedule.pointCount, p.schedule.acceptedHits,
                 p.schedule.rejectedHits);
    std::fflush(stderr);
  }
  void onError(const core::Error& e) override {
    std::lock_guard<std::mutex> l(mu_);
    errors_.push_back(e);
  }
  void endBar() const {
    if (bar_) std::fprintf(stderr, "\n");
  }
  std::vector<core::Error> errors() const {
    std::lock_guard<std::mutex> l(mu_);
    return errors_;
  }

 private:
  bool bar_;
  mutable std::mutex mu_;
  std::vector<core::Error> errors_;
};

int runCampaign(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  if (a.positional().size() != 2) return usage(err, "expected one project file");
  const std::string path = a.positional()[1];
  const auto specimenArg = a.value("--specimen");
  if (!specimenArg) return usage(err, "--specimen is required");
  const auto rig = a.value("--rig");
  if (!rig) return usage(err, "--rig is required (sim-hammer)");
  if (*rig != "sim-hammer")
    return usage(err, "--rig '" + *rig +
                          "': the command line runs campaigns on the simulated hammer station (sim-hammer); a real "
                          "station is driven from the workbench");
  cp::VirtualCampaignOptions options;
  // Ranges checked by the parser (kSpec).
  if (auto hits = a.number("--hits"); hits && hits->has_value()) options.hitsPerPoint = static_cast<int>(**hits);
  if (auto seed = a.number("--seed"); seed && seed->has_value()) options.seed = static_cast<std::uint64_t>(**seed);
  const bool asJson = a.flag("--json");

  auto store = core::io::ProjectStore::open(path);
  if (!store) return fail(err, store.error());
  if (store->isReadOnly())
    return fail(err,
                core::makeError(core::ErrorCode::Locked, "cannot run a campaign: " + store->readOnlyReason(), path));
  auto summary = store->summary();
  if (!summary) return fail(err, summary.error());
  auto choice = chooseSpecimen(*summary, *specimenArg, a.value("--constraint"));
  if (!choice) return fail(err, choice.error());
  bool addedSpecimen = false;
  if (!choice->specimenId) {
    auto id = store->addSpecimen(choice->name, choice->kind,
                                 "virtual specimen " + choice->key + " (added by mozzi-cli campaign run)");
    if (!id) return fail(err, id.error());
    choice->specimenId = *id;
    addedSpecimen = true;
  }

  // The unfinished campaign of this virtual specimen, unless --new.
  std::optional<std::int64_t> campaignId;
  bool resumed = false;
  auto existing = cp::loadCampaigns(*store, *choice->specimenId);
  if (!existing) return fail(err, existing.error());
  if (!a.flag("--new")) {
    for (const auto& c : *existing)
      if (c.definition.specimenKey == choice->key && !c.finished()) {
        campaignId = c.campaign.id;
        resumed = true;
        if ((a.value("--hits") && c.definition.hitsPerPoint != options.hitsPerPoint) ||
            (a.value("--seed") && c.definition.seed != options.seed))
          err << "mozzi-cli campaign: resuming campaign " << c.campaign.id << " with its own settings ("
              << c.definition.hitsPerPoint << " hits per point, seed " << c.definition.seed
              << "); --new starts another\n";
      }
  }
  if (!campaignId) {
    auto def = cp::virtualSpecimenCampaign(choice->key, options);
    if (!def) return fail(err, def.error());
    std::set<std::string> names;
    for (const auto& c : *existing) names.insert(c.campaign.name);
    auto all = store->campaigns(*choice->specimenId);
    if (!all) return fail(err, all.error());
    for (const auto& c : *all) names.insert(c.name);
    std::string name;
    for (int n = 1; name.empty() || names.count(name); ++n) name = choice->key + " hammer " + std::to_string(n);
    auto id = cp::createCampaign(*store, *choice->specimenId, name, *def,
                                 "mozzi-cli campaign run, seed " + std::to_string(options.seed));
    if (!id) return fail(err, id.error());
    campaignId = *id;
  }

  cp::EngineOptions eo;
  eo.autoDecide = true;
  eo.autoArm = true;
  eo.deviceOverrides["sim.realtime"] = false;
  auto engine =
      cp::CampaignEngine::open(*store, *campaignId, cp::makeDriverStation(devices::builtinDrivers(), *rig), eo);
  if (!engine) return fail(err, engine.error());
  CliObserver observer(!asJson && ::isatty(STDERR_FILENO));
  (*engine)->addObserver(&observer);
  const auto t0 = std::chrono::steady_clock::now();
  (*engine)->start();
  // The simulated station cannot disappear: wait for the end, or for the
  // engine to stop making progress (an error it cannot get past).
  int idlePolls = 0;  // with autoArm, Idle is a passing state; twice in a row with an error means stuck
  for (;;) {
    if ((*engine)->waitUntilFinished(std::chrono::seconds(1))) break;
    const auto s = (*engine)->state();
    idlePolls = s == cp::EngineState::Idle && !observer.errors().empty() ? idlePolls + 1 : 0;
    if (s == cp::EngineState::WaitingForDevice || idlePolls >= 2) {
      (*engine)->stop();
      observer.endBar();
      const auto errors = observer.errors();
      return fail(err, errors.empty() ? core::makeError(core::ErrorCode::IoError, "the station went away", *rig)
                                      : errors.back());
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto p = (*engine)->progress();
  (*engine)->stop();
  observer.endBar();
  if (!p.frfSetId) return fail(err, core::makeError(core::ErrorCode::InvalidArgument, "no FRF set was stored", path));
  auto loaded = cp::loadCampaign(*store, *campaignId);
  if (!loaded) return fail(err, loaded.error());
  json reasons = json::object();
  // Rejections by reason over the whole campaign (this run and the earlier ones).
  std::map<std::string, int> byReason;
  for (const auto& h : loaded->hits) {
    if (h.accepted) continue;
    for (std::size_t start = 0; start < h.qualityReasons.size();) {
      auto end = h.qualityReasons.find("; ", start);
      std::string r = h.qualityReasons.substr(start, end == std::string::npos ? std::string::npos : end - start);
      // The kind: the words before the details (the channel, whose DOF text has a ':' too).
      ++byReason[r.substr(0, std::min(r.find(':'), r.find(" on channel")))];
      if (end == std::string::npos) break;
      start = end + 2;
    }
  }
  for (const auto& [r, n] : byReason) reasons[r] = n;
  const auto sp = loaded->schedule.progress();
  if (asJson) {
    json j = {{"campaign_id", *campaignId},
              {"name", loaded->campaign.name},
              {"specimen", choice->key},
              {"specimen_id", *choice->specimenId},
              {"resumed", resumed},
              {"seed", std::to_string(loaded->definition.seed)},
              {"hits_per_point", loaded->definition.hitsPerPoint},
              {"points", {{"count", sp.pointCount}, {"done", sp.pointsDone}, {"skipped", sp.pointsSkipped}}},
              {"hits", {{"accepted", sp.acceptedHits}, {"rejected", sp.rejectedHits}, {"rejected_by_reason", reasons}}},
              {"frf_set_id", *p.frfSetId},
              {"seconds", seconds}};
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  if (addedSpecimen) out << "added specimen '" << choice->name << "' to the project\n";
  out << (resumed ? "resumed" : "ran") << " campaign " << *campaignId << " '" << loaded->campaign.name << "' on "
      << choice->key << ": " << sp.pointsDone << "/" << sp.pointCount << " points done, " << sp.pointsSkipped
      << " skipped\n";
  out << "hits: " << sp.acceptedHits << " accepted, " << sp.rejectedHits << " rejected";
  if (!byReason.empty()) {
    out << " (";
    bool first = true;
    for (const auto& [r, n] : byReason) {
      out << (first ? "" : ", ") << r << " " << n;
      first = false;
    }
    out << ")";
  }
  out << "\nFRF set " << *p.frfSetId << "\n";
  return kExitOk;
}

int status(const ParsedArgs& a, std::ostream& out, std::ostream& err) {
  if (a.positional().size() != 2) return usage(err, "expected one project file");
  const std::string path = a.positional()[1];
  auto store = core::io::ProjectStore::open(path, core::io::ProjectStore::OpenMode::ReadOnly);
  if (!store) return fail(err, store.error());
  auto summary = store->summary();
  if (!summary) return fail(err, summary.error());
  json list = json::array();
  for (const auto& s : summary->specimens) {
    auto campaigns = cp::loadCampaigns(*store, s.id);
    if (!campaigns) return fail(err, campaigns.error());
    for (const auto& c : *campaigns) {
      const auto p = c.schedule.progress();
      json j = {{"campaign_id", c.campaign.id},
                {"name", c.campaign.name},
                {"specimen", s.name},
                {"specimen_key", c.definition.specimenKey},
                {"excitation", cp::excitationKindName(c.definition.excitation)},
                {"constraint", cp::constraintKindName(c.definition.constraint.kind)},
                {"started_utc", c.campaign.startedUtc},
                {"hits_per_point", c.definition.hitsPerPoint},
                {"points", {{"count", p.pointCount}, {"done", p.pointsDone}, {"skipped", p.pointsSkipped}}},
                {"hits", {{"accepted", p.acceptedHits}, {"rejected", p.rejectedHits}}},
                {"next_point", p.next ? json(core::formatDof(c.schedule.point(*p.next).dof)) : json(nullptr)},
                {"finished", c.finished()},
                {"frf_set_id", c.frfSetCurrent ? json(*c.frfSetId) : json(nullptr)}};
      json skipped = json::array();
      for (const auto& pt : c.schedule.points())
        if (pt.skipped) skipped.push_back({{"point", core::formatDof(pt.dof)}, {"reason", pt.skipReason}});
      j["skipped_points"] = skipped;
      list.push_back(j);
    }
  }
  if (a.flag("--json")) {
    out << json{{"project", path}, {"campaigns", list}}.dump(2) << "\n";
    return kExitOk;
  }
  if (list.empty()) {
    out << "no campaigns in " << path << "\n";
    return kExitOk;
  }
  char buf[512];
  std::snprintf(buf, sizeof buf, "%-4s %-36s %-28s %-9s %-9s %-14s %s\n", "id", "campaign", "specimen", "points",
                "hits", "state", "FRF set");
  out << buf;
  for (const auto& j : list) {
    const std::string points =
        std::to_string(j["points"]["done"].get<int>()) + "/" + std::to_string(j["points"]["count"].get<int>()) +
        (j["points"]["skipped"].get<int>() ? "+" + std::to_string(j["points"]["skipped"].get<int>()) + "s" : "");
    const std::string hitsText =
        std::to_string(j["hits"]["accepted"].get<int>()) + "/" + std::to_string(j["hits"]["rejected"].get<int>());
    const std::string state =
        j["finished"].get<bool>()
            ? "finished"
            : (j["next_point"].is_null() ? "FRFs missing" : "next " + j["next_point"].get<std::string>());
    std::snprintf(buf, sizeof buf, "%-4lld %-36s %-28s %-9s %-9s %-14s %s\n",
                  static_cast<long long>(j["campaign_id"].get<std::int64_t>()), j["name"].get<std::string>().c_str(),
                  j["specimen"].get<std::string>().c_str(), points.c_str(), hitsText.c_str(), state.c_str(),
                  j["frf_set_id"].is_null() ? "-" : std::to_string(j["frf_set_id"].get<std::int64_t>()).c_str());
    out << buf;
  }
  out << "(points: done/count, +Ns skipped; hits: accepted/rejected)\n";
  return kExitOk;
}

// The option table: hits per point as the campaign definition allows; the
// seed within what a JSON summary carries exactly (2^53).
const OptionSpec kSpec{{"--specimen", "--rig", "--constraint"},
                       {"--new", "--json"},
                       {{"--hits", wholeNumber(1, 1000), "accepted hits per point"},
                        {"--seed", wholeNumber(0, 9007199254740992.0), "seed of the simulated hits"}}};

int campaignCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto parsed = ParsedArgs::parse(args, kSpec);
  if (!parsed) {
    if (exitCodeFor(parsed.error()) == kExitUsage) return usage(err, parsed.error().message);
    err << "mozzi-cli campaign: " << parsed.error().describe() << "\n";
    return kExitFailure;
  }
  const auto& pos = parsed->positional();
  if (pos.empty()) return usage(err, "expected run or status");
  if (pos[0] == "run") return runCampaign(*parsed, out, err);
  if (pos[0] == "status") {
    for (const char* o : {"--specimen", "--rig", "--constraint", "--hits", "--seed"})
      if (parsed->value(o)) return usage(err, std::string(o) + " is an option of campaign run");
    if (parsed->flag("--new")) return usage(err, "--new is an option of campaign run");
    return status(*parsed, out, err);
  }
  return usage(err, "unknown subcommand '" + pos[0] + "' (run, status)");
}

const CommandRegistrar kRegistrar({"campaign",
                                   "run PROJECT.mozzi --specimen NAME --rig sim-hammer [--constraint C] [--hits N] "
                                   "[--new] [--seed S] [--json] | status PROJECT.mozzi [--json]",
                                   "impact campaigns on the simulated hammer station: run (or resume) with automatic "
                                   "decisions, list progress",
                                   campaignCommand, &kSpec});

}  // namespace
}  // namespace mozzi::cli
