#include "devices/campaign/campaign_definition.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>

namespace mozzi::devices::campaign {

using core::ErrorCode;
using core::makeError;
using nlohmann::json;

const char* constraintKindName(ConstraintKind kind) {
  switch (kind) {
    case ConstraintKind::FreeFree: return "free-free";
    case ConstraintKind::Clamped: return "clamped";
    case ConstraintKind::OnRig: return "on-rig";
  }
  return "free-free";
}

core::Result<ConstraintKind> parseConstraintKind(const std::string& text) {
  for (auto k : {ConstraintKind::FreeFree, ConstraintKind::Clamped, ConstraintKind::OnRig})
    if (text == constraintKindName(k)) return k;
  return makeError(ErrorCode::ParseError, "unknown constraint '" + text + "' (free-free, clamped, on-rig)",
                   "constraint.kind");
}

const char* excitationKindName(ExcitationKind kind) {
  return kind == ExcitationKind::RovingHammer ? "roving-hammer" : "roving-accelerometer";
}

core::Result<ExcitationKind> parseExcitationKind(const std::string& text) {
  if (text == "roving-hammer") return ExcitationKind::RovingHammer;
  if (text == "roving-accelerometer") return ExcitationKind::RovingAccelerometer;
  return makeError(ErrorCode::ParseError, "unknown excitation '" + text + "' (roving-hammer, roving-accelerometer)",
                   "excitation");
}

namespace {

bool positiveFinite(double x) {
  return std::isfinite(x) && x > 0.0;
}

core::Result<core::signal::TransducerKind> parseTransducerKind(const std::string& text, const std::string& where) {
  using K = core::signal::TransducerKind;
  for (K k : {K::Force, K::Acceleration, K::Velocity, K::Displacement, K::AngularRate, K::Other})
    if (text == core::signal::transducerKindName(k)) return k;
  return makeError(ErrorCode::ParseError, "unknown transducer kind '" + text + "'", where);
}

json parameterJson(const ParameterValue& v) {
  return std::visit([](const auto& x) { return json(x); }, v);
}

}  // namespace

std::int64_t CampaignDefinition::recordScans() const {
  return static_cast<std::int64_t>(std::llround(acquisition.recordSeconds * acquisition.sampleRateHz));
}

std::int64_t CampaignDefinition::preTriggerScans() const {
  // As SoftwareTrigger: round(preTriggerFraction * recordScans).
  return static_cast<std::int64_t>(std::llround(acquisition.preTriggerFraction * static_cast<double>(recordScans())));
}

double CampaignDefinition::storedBandHz() const {
  return frfMaxHz > 0.0 ? frfMaxHz : acquisition.sampleRateHz / 2.56;
}

int CampaignDefinition::forceChannel() const {
  for (std::size_t c = 0; c < channels.size(); ++c)
    if (channels[c].transducer.kind == core::signal::TransducerKind::Force) return static_cast<int>(c);
  return -1;
}

core::Dof CampaignDefinition::channelDof(std::size_t channel, const core::Dof& point) const {
  const auto& ch = channels[channel];
  return ch.roving ? point : ch.dof;
}

std::vector<std::size_t> CampaignDefinition::rovingChannels() const {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < channels.size(); ++c)
    if (channels[c].roving) out.push_back(c);
  return out;
}

core::signal::FrfOptions CampaignDefinition::frfOptions() const {
  using core::signal::WindowKind;
  core::signal::FrfOptions o;
  o.estimator = estimator;
  const int f = forceChannel();
  if (f >= 0) o.referenceChannel = f;
  if (windows.forceWidthS > 0.0) {
    o.referenceWindow.kind = WindowKind::Force;
    o.referenceWindow.forceWidthS = windows.forceWidthS;
    o.referenceWindow.forceTaperS = windows.forceTaperS;
    o.referenceWindow.exponentialTauS = windows.exponentialTauS;
  } else if (windows.exponentialTauS > 0.0) {
    o.referenceWindow.kind = WindowKind::Exponential;
    o.referenceWindow.exponentialTauS = windows.exponentialTauS;
  }
  if (windows.exponentialTauS > 0.0) {
    o.responseWindow.kind = WindowKind::Exponential;
    o.responseWindow.exponentialTauS = windows.exponentialTauS;
  }
  return o;
}

core::Result<void> CampaignDefinition::validate() const {
  if (points.empty()) return makeError(ErrorCode::InvalidArgument, "a campaign needs at least one point", "points");
  {
    std::set<core::Dof> seen;
    for (const auto& p : points)
      if (!seen.insert(p).second)
        return makeError(ErrorCode::InvalidArgument, "point " + core::formatDof(p) + " is listed twice", "points");
  }
  if (constraint.kind == ConstraintKind::Clamped && constraint.clampedNodes.empty())
    return makeError(ErrorCode::InvalidArgument, "a clamped constraint names the clamped nodes",
                     "constraint.clamped_nodes");
  if (channels.size() < 2)
    return makeError(ErrorCode::InvalidArgument, "a campaign needs a force channel and at least one response",
                     "channels");
  int forces = 0, responses = 0;
  std::set<int> inputs;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const auto& ch = channels[c];
    const std::string where = "channels[" + std::to_string(c) + "]";
    if (ch.input < 0 || !inputs.insert(ch.input).second)
      return makeError(ErrorCode::InvalidArgument,
                       "device input " + std::to_string(ch.input) + " invalid or used twice", where + ".input");
    if (!positiveFinite(ch.transducer.sensitivityMvPerUnit))
      return makeError(ErrorCode::InvalidArgument, "sensitivity must be a positive number of mV per unit",
                       where + ".sensitivity_mv_per_unit");
    if (!positiveFinite(ch.conditionerGain))
      return makeError(ErrorCode::InvalidArgument, "conditioner gain must be positive", where + ".conditioner_gain");
    if (ch.transducer.kind == core::signal::TransducerKind::Force)
      ++forces;
    else
      ++responses;
  }
  if (forces != 1)
    return makeError(ErrorCode::InvalidArgument, "exactly one force (hammer) channel is needed", "channels");
  if (responses < 1)
    return makeError(ErrorCode::InvalidArgument, "at least one response channel is needed", "channels");
  const auto roving = rovingChannels();
  const int fc = forceChannel();
  if (excitation == ExcitationKind::RovingHammer) {
    if (roving.size() != 1 || static_cast<int>(roving[0]) != fc)
      return makeError(ErrorCode::InvalidArgument, "a roving-hammer campaign roves the force channel and only it",
                       "channels[].roving");
  } else {
    if (roving.empty() || channels[static_cast<std::size_t>(fc)].roving)
      return makeError(ErrorCode::InvalidArgument,
                       "a roving-accelerometer campaign roves at least one response channel and keeps the hammer fixed",
                       "channels[].roving");
  }
  const auto& a = acquisition;
  if (!positiveFinite(a.sampleRateHz))
    return makeError(ErrorCode::InvalidArgument, "sample rate must be positive", "acquisition.sample_rate_hz");
  if (!positiveFinite(a.recordSeconds) || recordScans() < 16)
    return makeError(ErrorCode::InvalidArgument, "record length must hold at least 16 samples", "acquisition.record_s");
  if (!(a.preTriggerFraction >= 0.0 && a.preTriggerFraction < 0.9))
    return makeError(ErrorCode::InvalidArgument, "pre-trigger must be in [0, 0.9) of the record",
                     "acquisition.pre_trigger_fraction");
  if (!positiveFinite(a.triggerLevel))
    return makeError(ErrorCode::InvalidArgument, "trigger level must be a positive force", "acquisition.trigger_level");
  if (hitsPerPoint < 1 || hitsPerPoint > 1000)
    return makeError(ErrorCode::InvalidArgument, "hits per point must be in 1..1000", "hits_per_point");
  if (!(windows.forceWidthS >= 0.0 && windows.forceTaperS >= 0.0 && windows.exponentialTauS >= 0.0) ||
      !std::isfinite(windows.forceWidthS + windows.forceTaperS + windows.exponentialTauS))
    return makeError(ErrorCode::InvalidArgument, "window widths must be >= 0 s", "windows");
  if (!(frfMaxHz >= 0.0 && frfMaxHz <= a.sampleRateHz / 2.0))
    return makeError(ErrorCode::InvalidArgument, "stored FRF band must lie within 0..Nyquist", "frf_max_hz");
  const auto& r = rules;
  if (!(r.minPeakForceN >= 0.0 && std::isfinite(r.minPeakForceN)) || !std::isfinite(r.minForceSnrDb) ||
      !(r.minCoherence >= 0.0 && r.minCoherence <= 1.0) ||
      !(r.coherenceBandLowHz >= 0.0 && r.coherenceBandHighHz >= r.coherenceBandLowHz) ||
      !std::isfinite(r.coherenceBandHighHz))
    return makeError(ErrorCode::InvalidArgument, "rules out of range (force >= 0, coherence in [0, 1], band LO <= HI)",
                     "rules");
  if (driver.empty())
    return makeError(ErrorCode::InvalidArgument, "the station's driver is not named", "station.driver");
  return {};
}

json definitionToJson(const CampaignDefinition& d) {
  json j;
  j["format"] = "mozzi-campaign";
  j["version"] = 1;
  j["specimen_key"] = d.specimenKey;
  j["mesh_template"] = d.meshTemplate;
  j["points"] = json::array();
  for (const auto& p : d.points) j["points"].push_back(core::formatDof(p));
  j["constraint"] = {{"kind", constraintKindName(d.constraint.kind)},
                     {"clamped_nodes", d.constraint.clampedNodes},
                     {"description", d.constraint.description}};
  j["excitation"] = excitationKindName(d.excitation);
  j["fixed_point"] = d.fixedPoint ? json(core::formatDof(*d.fixedPoint)) : json(nullptr);
  j["channels"] = json::array();
  for (const auto& c : d.channels) {
    j["channels"].push_back({{"input", c.input},
                             {"name", c.name},
                             {"kind", core::signal::transducerKindName(c.transducer.kind)},
                             {"model", c.transducer.model},
                             {"serial", c.transducer.serial},
                             {"sensitivity_mv_per_unit", c.transducer.sensitivityMvPerUnit},
                             {"unit", c.transducer.unit},
                             {"iepe", c.transducer.iepe},
                             {"calibration_date", c.calibrationDate},
                             {"range_code", c.rangeCode},
                             {"conditioner_gain", c.conditionerGain},
                             {"roving", c.roving},
                             {"dof", c.roving ? json(nullptr) : json(core::formatDof(c.dof))}});
  }
  j["acquisition"] = {{"sample_rate_hz", d.acquisition.sampleRateHz},
                      {"record_s", d.acquisition.recordSeconds},
                      {"pre_trigger_fraction", d.acquisition.preTriggerFraction},
                      {"trigger_level", d.acquisition.triggerLevel}};
  j["hits_per_point"] = d.hitsPerPoint;
  j["windows"] = {{"force_width_s", d.windows.forceWidthS},
                  {"force_taper_s", d.windows.forceTaperS},
                  {"exponential_tau_s", d.windows.exponentialTauS}};
  j["estimator"] = core::signal::frfEstimatorName(d.estimator);
  j["frf_max_hz"] = d.frfMaxHz;
  j["rules"] = {{"double_hit", d.rules.doubleHit},
                {"overload", d.rules.overload},
                {"min_peak_force_n", d.rules.minPeakForceN},
                {"min_force_snr_db", d.rules.minForceSnrDb},
                {"min_coherence", d.rules.minCoherence},
                {"coherence_band_hz", {d.rules.coherenceBandLowHz, d.rules.coherenceBandHighHz}}};
  json params = json::object();
  for (const auto& [k, v] : d.deviceParameters) params[k] = parameterJson(v);
  j["station"] = {{"driver", d.driver},
                  {"serial", d.deviceSerial},
                  {"parameters", params},
                  {"seed", std::to_string(d.seed)}};  // text: JSON numbers lose 64-bit integers elsewhere
  return j;
}

namespace {

// Typed field readers that name the field on error.
class Reader {
 public:
  explicit Reader(const json& j, std::string path) : j_(j), path_(std::move(path)) {}

  core::Result<const json*> field(const char* key, bool required = true) const {
    if (!j_.is_object()) return makeError(ErrorCode::ParseError, "expected an object", path_);
    auto it = j_.find(key);
    if (it == j_.end() || it->is_null()) {
      if (required) return makeError(ErrorCode::ParseError, "missing field", at(key));
      return static_cast<const json*>(nullptr);
    }
    return &*it;
  }
  core::Result<double> number(const char* key, std::optional<double> fallback = std::nullopt) const {
    auto f = field(key, !fallback.has_value());
    if (!f) return f.error();
    if (!*f) return *fallback;
    if (!(*f)->is_number()) return makeError(ErrorCode::ParseError, "expected a number", at(key));
    const double v = (*f)->get<double>();
    if (!std::isfinite(v)) return makeError(ErrorCode::ParseError, "not a finite number", at(key));
    return v;
  }
  core::Result<std::int64_t> integer(const char* key, std::optional<std::int64_t> fallback = std::nullopt) const {
    auto f = field(key, !fallback.has_value());
    if (!f) return f.error();
    if (!*f) return *fallback;
    if (!(*f)->is_number_integer()) return makeError(ErrorCode::ParseError, "expected an integer", at(key));
    return (*f)->get<std::int64_t>();
  }
  core::Result<bool> boolean(const char* key, std::optional<bool> fallback = std::nullopt) const {
    auto f = field(key, !fallback.has_value());
    if (!f) return f.error();
    if (!*f) return *fallback;
    if (!(*f)->is_boolean()) return makeError(ErrorCode::ParseError, "expected true or false", at(key));
    return (*f)->get<bool>();
  }
  core::Result<std::string> text(const char* key, std::optional<std::string> fallback = std::nullopt) const {
    auto f = field(key, !fallback.has_value());
    if (!f) return f.error();
    if (!*f) return *fallback;
    if (!(*f)->is_string()) return makeError(ErrorCode::ParseError, "expected text", at(key));
    return (*f)->get<std::string>();
  }
  core::Result<core::Dof> dof(const char* key) const {
    auto t = text(key);
    if (!t) return t.error();
    auto d = core::parseDof(*t);
    if (!d) return makeError(ErrorCode::ParseError, d.error().message, at(key));
    return *d;
  }
  std::string at(const char* key) const { return path_ + "." + key; }

 private:
  const json& j_;
  std::string path_;
};

core::Result<ChannelAssignment> channelFromJson(const json& j, const std::string& path) {
  Reader r(j, path);
  ChannelAssignment c;
  MOZZI_TRY_ASSIGN(auto input, r.integer("input"));
  if (input < 0 || input > 255) return makeError(ErrorCode::ParseError, "input out of 0..255", r.at("input"));
  c.input = static_cast<int>(input);
  MOZZI_TRY_ASSIGN(auto name, r.text("name", std::string()));
  c.name = name;
  MOZZI_TRY_ASSIGN(auto kind, r.text("kind"));
  MOZZI_TRY_ASSIGN(auto k, parseTransducerKind(kind, r.at("kind")));
  c.transducer.kind = k;
  MOZZI_TRY_ASSIGN(auto model, r.text("model", std::string()));
  c.transducer.model = model;
  MOZZI_TRY_ASSIGN(auto serial, r.text("serial", std::string()));
  c.transducer.serial = serial;
  MOZZI_TRY_ASSIGN(auto sens, r.number("sensitivity_mv_per_unit"));
  c.transducer.sensitivityMvPerUnit = sens;
  MOZZI_TRY_ASSIGN(auto unit, r.text("unit", std::string()));
  c.transducer.unit = unit;
  MOZZI_TRY_ASSIGN(auto iepe, r.boolean("iepe", false));
  c.transducer.iepe = iepe;
  MOZZI_TRY_ASSIGN(auto date, r.text("calibration_date", std::string()));
  c.calibrationDate = date;
  MOZZI_TRY_ASSIGN(auto range, r.integer("range_code", 0));
  if (range < 0 || range > 255) return makeError(ErrorCode::ParseError, "range code out of 0..255", r.at("range_code"));
  c.rangeCode = static_cast<std::uint8_t>(range);
  MOZZI_TRY_ASSIGN(auto gain, r.number("conditioner_gain", 1.0));
  c.conditionerGain = gain;
  MOZZI_TRY_ASSIGN(auto roving, r.boolean("roving", false));
  c.roving = roving;
  if (!c.roving) {
    MOZZI_TRY_ASSIGN(auto dof, r.dof("dof"));
    c.dof = dof;
  }
  return c;
}

}  // namespace

core::Result<CampaignDefinition> definitionFromJson(const json& j) {
  Reader r(j, "campaign");
  CampaignDefinition d;
  MOZZI_TRY_ASSIGN(auto format, r.text("format"));
  if (format != "mozzi-campaign")
    return makeError(ErrorCode::ParseError, "not a campaign definition (format '" + format + "')", r.at("format"));
  MOZZI_TRY_ASSIGN(auto version, r.integer("version"));
  if (version != 1)
    return makeError(ErrorCode::Unsupported, "campaign definition version " + std::to_string(version) + " (reads 1)",
                     r.at("version"));
  MOZZI_TRY_ASSIGN(auto key, r.text("specimen_key", std::string()));
  d.specimenKey = key;
  MOZZI_TRY_ASSIGN(auto mesh, r.text("mesh_template", std::string()));
  d.meshTemplate = mesh;
  MOZZI_TRY_ASSIGN(auto points, r.field("points"));
  if (!points->is_array()) return makeError(ErrorCode::ParseError, "expected an array of DOF labels", r.at("points"));
  for (std::size_t i = 0; i < points->size(); ++i) {
    const std::string where = r.at("points") + "[" + std::to_string(i) + "]";
    if (!(*points)[i].is_string()) return makeError(ErrorCode::ParseError, "expected a DOF label", where);
    auto p = core::parseDof((*points)[i].get<std::string>());
    if (!p) return makeError(ErrorCode::ParseError, p.error().message, where);
    d.points.push_back(*p);
  }
  MOZZI_TRY_ASSIGN(auto constraint, r.field("constraint"));
  {
    Reader c(*constraint, r.at("constraint"));
    MOZZI_TRY_ASSIGN(auto kind, c.text("kind"));
    MOZZI_TRY_ASSIGN(auto k, parseConstraintKind(kind));
    d.constraint.kind = k;
    MOZZI_TRY_ASSIGN(auto nodes, c.field("clamped_nodes", false));
    if (nodes) {
      if (!nodes->is_array()) return makeError(ErrorCode::ParseError, "expected node labels", c.at("clamped_nodes"));
      for (const auto& n : *nodes) {
        if (!n.is_number_integer())
          return makeError(ErrorCode::ParseError, "expected a node label", c.at("clamped_nodes"));
        d.constraint.clampedNodes.push_back(n.get<int>());
      }
    }
    MOZZI_TRY_ASSIGN(auto desc, c.text("description", std::string()));
    d.constraint.description = desc;
  }
  MOZZI_TRY_ASSIGN(auto excitation, r.text("excitation"));
  MOZZI_TRY_ASSIGN(auto ex, parseExcitationKind(excitation));
  d.excitation = ex;
  MOZZI_TRY_ASSIGN(auto fixed, r.field("fixed_point", false));
  if (fixed) {
    MOZZI_TRY_ASSIGN(auto fp, r.dof("fixed_point"));
    d.fixedPoint = fp;
  }
  MOZZI_TRY_ASSIGN(auto channels, r.field("channels"));
  if (!channels->is_array()) return makeError(ErrorCode::ParseError, "expected an array", r.at("channels"));
  for (std::size_t i = 0; i < channels->size(); ++i) {
    MOZZI_TRY_ASSIGN(auto c, channelFromJson((*channels)[i], r.at("channels") + "[" + std::to_string(i) + "]"));
    d.channels.push_back(std::move(c));
  }
  MOZZI_TRY_ASSIGN(auto acq, r.field("acquisition"));
  {
    Reader a(*acq, r.at("acquisition"));
    MOZZI_TRY_ASSIGN(auto fs, a.number("sample_rate_hz"));
    MOZZI_TRY_ASSIGN(auto len, a.number("record_s"));
    MOZZI_TRY_ASSIGN(auto pre, a.number("pre_trigger_fraction", 0.1));
    MOZZI_TRY_ASSIGN(auto level, a.number("trigger_level"));
    d.acquisition = AcquisitionSettings{fs, len, pre, level};
  }
  MOZZI_TRY_ASSIGN(auto hits, r.integer("hits_per_point"));
  if (hits < 1 || hits > 1000)
    return makeError(ErrorCode::ParseError, "hits per point must be in 1..1000", r.at("hits_per_point"));
  d.hitsPerPoint = static_cast<int>(hits);
  MOZZI_TRY_ASSIGN(auto windows, r.field("windows", false));
  if (windows) {
    Reader w(*windows, r.at("windows"));
    MOZZI_TRY_ASSIGN(auto fw, w.number("force_width_s", 0.0));
    MOZZI_TRY_ASSIGN(auto ft, w.number("force_taper_s", 0.0));
    MOZZI_TRY_ASSIGN(auto tau, w.number("exponential_tau_s", 0.0));
    d.windows = WindowSettings{fw, ft, tau};
  }
  MOZZI_TRY_ASSIGN(auto estimator, r.text("estimator", std::string("H1")));
  auto est = core::signal::parseFrfEstimator(estimator);
  if (!est) return makeError(ErrorCode::ParseError, est.error().message, r.at("estimator"));
  d.estimator = *est;
  MOZZI_TRY_ASSIGN(auto fmax, r.number("frf_max_hz", 0.0));
  d.frfMaxHz = fmax;
  MOZZI_TRY_ASSIGN(auto rules, r.field("rules", false));
  if (rules) {
    Reader q(*rules, r.at("rules"));
    MOZZI_TRY_ASSIGN(auto dh, q.boolean("double_hit", true));
    MOZZI_TRY_ASSIGN(auto ov, q.boolean("overload", true));
    MOZZI_TRY_ASSIGN(auto minF, q.number("min_peak_force_n", 0.0));
    MOZZI_TRY_ASSIGN(auto snr, q.number("min_force_snr_db", 30.0));
    MOZZI_TRY_ASSIGN(auto coh, q.number("min_coherence", 0.0));
    d.rules = RejectionRules{dh, ov, minF, snr, coh, 0.0, 0.0};
    MOZZI_TRY_ASSIGN(auto band, q.field("coherence_band_hz", false));
    if (band) {
      if (!band->is_array() || band->size() != 2 || !(*band)[0].is_number() || !(*band)[1].is_number())
        return makeError(ErrorCode::ParseError, "expected [LO, HI] in Hz", q.at("coherence_band_hz"));
      d.rules.coherenceBandLowHz = (*band)[0].get<double>();
      d.rules.coherenceBandHighHz = (*band)[1].get<double>();
    }
  }
  MOZZI_TRY_ASSIGN(auto station, r.field("station"));
  {
    Reader s(*station, r.at("station"));
    MOZZI_TRY_ASSIGN(auto driver, s.text("driver"));
    d.driver = driver;
    MOZZI_TRY_ASSIGN(auto serial, s.text("serial", std::string()));
    d.deviceSerial = serial;
    MOZZI_TRY_ASSIGN(auto seed, s.text("seed", std::string("1")));
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(seed.c_str(), &end, 10);
    if (seed.empty() || *end != '\0' || errno != 0 || seed[0] == '-')
      return makeError(ErrorCode::ParseError, "seed must be a non-negative integer (as text)", s.at("seed"));
    d.seed = v;
    MOZZI_TRY_ASSIGN(auto params, s.field("parameters", false));
    if (params) {
      if (!params->is_object()) return makeError(ErrorCode::ParseError, "expected an object", s.at("parameters"));
      for (const auto& [k, v] : params->items()) {
        if (v.is_boolean())
          d.deviceParameters[k] = v.get<bool>();
        else if (v.is_number_integer())
          d.deviceParameters[k] = v.get<std::int64_t>();
        else if (v.is_number())
          d.deviceParameters[k] = v.get<double>();
        else if (v.is_string())
          d.deviceParameters[k] = v.get<std::string>();
        else
          return makeError(ErrorCode::ParseError, "expected a boolean, number or text", s.at("parameters") + "." + k);
      }
    }
  }
  if (auto v = d.validate(); !v) return makeError(v.error().code, v.error().message, "campaign." + v.error().where);
  return d;
}

core::Result<CampaignDefinition> parseDefinition(const std::string& text) {
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) return makeError(ErrorCode::ParseError, "campaign settings are not valid JSON", "campaign");
  return definitionFromJson(j);
}

AcquisitionConfig acquisitionConfigFor(const CampaignDefinition& d, const core::Dof& point,
                                       const ParameterMap& overrides) {
  AcquisitionConfig cfg;
  cfg.sampleRateHz = d.acquisition.sampleRateHz;
  for (std::size_t c = 0; c < d.channels.size(); ++c) {
    const auto& a = d.channels[c];
    ChannelConfig ch;
    ch.input = a.input;
    ch.dof = d.channelDof(c, point);
    ch.name = a.name.empty() ? core::formatDof(ch.dof) : a.name;
    ch.rangeCode = a.rangeCode;
    ch.conditionerGain = a.conditionerGain;
    ch.transducer = a.transducer;
    cfg.channels.push_back(ch);
  }
  cfg.parameters = d.deviceParameters;
  for (const auto& [k, v] : overrides) cfg.parameters[k] = v;
  return cfg;
}

core::signal::TimeRecord timeRecordFor(const CampaignDefinition& d, const core::Dof& point, double sampleRateHz,
                                       const std::vector<double>& fullScale, core::Matrix samples) {
  core::signal::TimeRecord r;
  r.sampleRateHz = sampleRateHz;
  r.preTriggerSamples = d.preTriggerScans();
  for (std::size_t c = 0; c < d.channels.size(); ++c) {
    core::signal::Channel ch;
    ch.dof = d.channelDof(c, point);
    ch.name = d.channels[c].name.empty() ? core::formatDof(ch.dof) : d.channels[c].name;
    ch.transducer = d.channels[c].transducer;
    ch.fullScale = c < fullScale.size() ? fullScale[c] : 0.0;
    r.channels.push_back(std::move(ch));
  }
  r.samples = std::move(samples);
  return r;
}

}  // namespace mozzi::devices::campaign
