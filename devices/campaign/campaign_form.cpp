#include "devices/campaign/campaign_form.h"

#include <sstream>

namespace mozzi::devices::campaign {
namespace {

ParameterSpec choice(std::string key, std::string label, std::vector<std::string> choices, std::string help) {
  ParameterSpec s{std::move(key), std::move(label), ParameterType::Choice, "", std::nullopt, std::nullopt,
                  choices,        choices.front(),  std::move(help)};
  return s;
}

ParameterSpec real(std::string key, std::string label, std::string unit, double min, double max, double def,
                   std::string help) {
  return ParameterSpec{std::move(key), std::move(label), ParameterType::Real, std::move(unit), min, max, {}, def,
                       std::move(help)};
}

ParameterSpec text(std::string key, std::string label, std::string help) {
  return ParameterSpec{std::move(key), std::move(label), ParameterType::Text, "", std::nullopt, std::nullopt, {},
                       std::string(),  std::move(help)};
}

ParameterSpec flag(std::string key, std::string label, bool def, std::string help) {
  return ParameterSpec{std::move(key), std::move(label), ParameterType::Bool, "", std::nullopt, std::nullopt, {}, def,
                       std::move(help)};
}

std::string nodesText(const std::vector<int>& nodes) {
  std::string out;
  for (int n : nodes) out += (out.empty() ? "" : " ") + std::to_string(n);
  return out;
}

core::Result<std::vector<int>> parseNodes(const std::string& text, const std::string& key) {
  std::vector<int> nodes;
  std::string cleaned = text;
  for (char& c : cleaned)
    if (c == ',' || c == ';') c = ' ';
  std::istringstream in(cleaned);
  std::string word;
  while (in >> word) {
    try {
      std::size_t used = 0;
      const int v = std::stoi(word, &used);
      if (used != word.size() || v <= 0) throw std::invalid_argument(word);
      nodes.push_back(v);
    } catch (const std::exception&) {
      return core::makeError(core::ErrorCode::InvalidArgument, "'" + word + "' is not a node label (a number > 0)",
                             key);
    }
  }
  return nodes;
}

const std::vector<std::string>& estimatorChoices() {
  static const std::vector<std::string> c = {"H1", "H2", "Hv"};
  return c;
}

}  // namespace

std::vector<ParameterSpec> formSpecs(FormSection section) {
  switch (section) {
    case FormSection::Constraint:
      return {choice("constraint.kind", "Constraint", {"free-free", "clamped", "on-rig"},
                     "how the specimen is held during the test (thesis §1.4)"),
              text("constraint.clamped_nodes", "Clamped nodes",
                   "node labels held fixed, separated by spaces (clamped only)"),
              text("constraint.description", "Constraint description",
                   "in words, for the report: what is clamped and how")};
    case FormSection::Excitation: {
      ParameterSpec hits{"campaign.hits_per_point",
                         "Hits per point",
                         ParameterType::Integer,
                         "",
                         1.0,
                         1000.0,
                         {},
                         std::int64_t{5},
                         "accepted hits averaged at each point (thesis §1.6: five)"};
      return {choice("excitation.kind", "Excitation", {"roving-hammer", "roving-accelerometer"},
                     "roving hammer: one row of the FRF matrix; roving accelerometer: one column (thesis eq. 21)"),
              text("excitation.fixed_point", "Fixed point",
                   "the fixed hammer (roving accelerometer) or reference accelerometer DOF, e.g. 3:+Y"),
              hits};
    }
    case FormSection::Acquisition:
      return {
          real("acquisition.sample_rate", "Sample rate", "Hz", 128.0, 100000.0, 4096.0,
               "scans per second on every channel"),
          real("acquisition.record_s", "Record length", "s", 0.1, 60.0, 2.0, "long enough for the response to die out"),
          real("acquisition.pre_trigger", "Pre-trigger", "", 0.0, 0.5, 0.1,
               "fraction of the record kept before the trigger (common practice 10%)"),
          real("acquisition.trigger_level", "Trigger level", "N", 0.01, 100000.0, 10.0,
               "force that starts a hit (rising slope on the hammer channel)"),
          real("acquisition.frf_max_hz", "FRF band", "Hz", 0.0, 50000.0, 0.0,
               "FRF lines stored up to here; 0 = sample rate / 2.56"),
          choice("acquisition.estimator", "Estimator", estimatorChoices(),
                 "H1 (noise on the response), H2 (noise on the force) or Hv"),
          flag("rules.double_hit", "Reject double hits", true, "a second impact after the main pulse"),
          flag("rules.overload", "Reject overloads", true, "a channel at the converter's full scale"),
          real("rules.min_peak_force", "Minimum peak force", "N", 0.0, 100000.0, 0.0,
               "force too low: a hit below this is rejected (0 = only the noise check)"),
          real("rules.min_force_snr", "Minimum force SNR", "dB", 0.0, 120.0, 30.0,
               "peak force over the pre-trigger noise"),
          real("rules.min_coherence", "Minimum coherence", "", 0.0, 1.0, 0.0,
               "poor coherence: mean coherence of the point's average, from the second hit (0 = off)")};
    case FormSection::Channel:
      return {text("channel.name", "Channel name", "shown on the traces and in the report"),
              text("channel.model", "Transducer model", "e.g. PCB 086C03 (hammer), PCB M352C65 (accelerometer)"),
              text("channel.serial", "Serial number", "of the transducer, for the calibration record"),
              real("channel.sensitivity", "Sensitivity", "mV/EU", 0.001, 100000.0, 10.0,
                   "from the calibration sheet: mV per N (hammer) or per m/s^2 (accelerometer)"),
              flag("channel.iepe", "IEPE supply", true, "constant-current supply on for this input"),
              text("channel.calibration_date", "Calibration date", "ISO 8601 date of the last calibration"),
              text("channel.dof", "Measured DOF", "where it measures, e.g. 7:+Y (ignored on the roving channel)")};
  }
  return {};
}

ParameterMap formValues(const CampaignDefinition& d, FormSection section, std::size_t index) {
  ParameterMap m;
  switch (section) {
    case FormSection::Constraint:
      m["constraint.kind"] = std::string(constraintKindName(d.constraint.kind));
      m["constraint.clamped_nodes"] = nodesText(d.constraint.clampedNodes);
      m["constraint.description"] = d.constraint.description;
      break;
    case FormSection::Excitation:
      m["excitation.kind"] = std::string(excitationKindName(d.excitation));
      m["excitation.fixed_point"] = d.fixedPoint ? core::formatDof(*d.fixedPoint) : std::string();
      m["campaign.hits_per_point"] = std::int64_t{d.hitsPerPoint};
      break;
    case FormSection::Acquisition:
      m["acquisition.sample_rate"] = d.acquisition.sampleRateHz;
      m["acquisition.record_s"] = d.acquisition.recordSeconds;
      m["acquisition.pre_trigger"] = d.acquisition.preTriggerFraction;
      m["acquisition.trigger_level"] = d.acquisition.triggerLevel;
      m["acquisition.frf_max_hz"] = d.frfMaxHz;
      m["acquisition.estimator"] = std::string(core::signal::frfEstimatorName(d.estimator));
      m["rules.double_hit"] = d.rules.doubleHit;
      m["rules.overload"] = d.rules.overload;
      m["rules.min_peak_force"] = d.rules.minPeakForceN;
      m["rules.min_force_snr"] = d.rules.minForceSnrDb;
      m["rules.min_coherence"] = d.rules.minCoherence;
      break;
    case FormSection::Channel: {
      if (index >= d.channels.size()) break;
      const ChannelAssignment& c = d.channels[index];
      m["channel.name"] = c.name;
      m["channel.model"] = c.transducer.model;
      m["channel.serial"] = c.transducer.serial;
      m["channel.sensitivity"] = c.transducer.sensitivityMvPerUnit;
      m["channel.iepe"] = c.transducer.iepe;
      m["channel.calibration_date"] = c.calibrationDate;
      m["channel.dof"] = c.roving ? std::string() : core::formatDof(c.dof);
      break;
    }
  }
  return m;
}

core::Result<void> applyForm(CampaignDefinition& definition, FormSection section, const ParameterMap& values,
                             std::size_t index) {
  if (section == FormSection::Channel && index >= definition.channels.size())
    return core::makeError(core::ErrorCode::InvalidArgument, "no channel " + std::to_string(index), "channel");
  // Every value checked against its spec, over the definition's own.
  ParameterMap m = formValues(definition, section, index);
  const auto specs = formSpecs(section);
  for (const auto& [key, value] : values) {
    const ParameterSpec* spec = nullptr;
    for (const auto& s : specs)
      if (s.key == key) spec = &s;
    if (!spec) return core::makeError(core::ErrorCode::InvalidArgument, "unknown campaign parameter", key);
    auto checked = validateParameter(*spec, value);
    if (!checked) return checked.error();
    m[key] = *checked;
  }
  CampaignDefinition d = definition;
  switch (section) {
    case FormSection::Constraint: {
      auto kind = parseConstraintKind(parameterText(m, "constraint.kind", "free-free"));
      if (!kind) return core::makeError(kind.error().code, kind.error().message, "constraint.kind");
      auto nodes = parseNodes(parameterText(m, "constraint.clamped_nodes", ""), "constraint.clamped_nodes");
      if (!nodes) return nodes.error();
      d.constraint.kind = *kind;
      d.constraint.clampedNodes = *nodes;
      d.constraint.description = parameterText(m, "constraint.description", "");
      break;
    }
    case FormSection::Excitation: {
      auto kind = parseExcitationKind(parameterText(m, "excitation.kind", "roving-hammer"));
      if (!kind) return core::makeError(kind.error().code, kind.error().message, "excitation.kind");
      d.excitation = *kind;
      const std::string fixed = parameterText(m, "excitation.fixed_point", "");
      if (fixed.empty()) {
        d.fixedPoint.reset();
      } else {
        auto dof = core::parseDof(fixed);
        if (!dof) return core::makeError(dof.error().code, dof.error().message, "excitation.fixed_point");
        d.fixedPoint = *dof;
      }
      d.hitsPerPoint = static_cast<int>(parameterInteger(m, "campaign.hits_per_point", 5));
      break;
    }
    case FormSection::Acquisition: {
      d.acquisition.sampleRateHz = parameterReal(m, "acquisition.sample_rate", 4096.0);
      d.acquisition.recordSeconds = parameterReal(m, "acquisition.record_s", 2.0);
      d.acquisition.preTriggerFraction = parameterReal(m, "acquisition.pre_trigger", 0.1);
      d.acquisition.triggerLevel = parameterReal(m, "acquisition.trigger_level", 10.0);
      d.frfMaxHz = parameterReal(m, "acquisition.frf_max_hz", 0.0);
      auto estimator = core::signal::parseFrfEstimator(parameterText(m, "acquisition.estimator", "H1"));
      if (!estimator)
        return core::makeError(estimator.error().code, estimator.error().message, "acquisition.estimator");
      d.estimator = *estimator;
      d.rules.doubleHit = parameterBool(m, "rules.double_hit", true);
      d.rules.overload = parameterBool(m, "rules.overload", true);
      d.rules.minPeakForceN = parameterReal(m, "rules.min_peak_force", 0.0);
      d.rules.minForceSnrDb = parameterReal(m, "rules.min_force_snr", 30.0);
      d.rules.minCoherence = parameterReal(m, "rules.min_coherence", 0.0);
      break;
    }
    case FormSection::Channel: {
      ChannelAssignment& c = d.channels[index];
      c.name = parameterText(m, "channel.name", c.name);
      c.transducer.model = parameterText(m, "channel.model", c.transducer.model);
      c.transducer.serial = parameterText(m, "channel.serial", c.transducer.serial);
      c.transducer.sensitivityMvPerUnit = parameterReal(m, "channel.sensitivity", c.transducer.sensitivityMvPerUnit);
      c.transducer.iepe = parameterBool(m, "channel.iepe", c.transducer.iepe);
      c.calibrationDate = parameterText(m, "channel.calibration_date", c.calibrationDate);
      const std::string dof = parameterText(m, "channel.dof", "");
      if (!c.roving) {
        auto parsed = core::parseDof(dof);
        if (!parsed) return core::makeError(parsed.error().code, parsed.error().message, "channel.dof");
        c.dof = *parsed;
      }
      break;
    }
  }
  definition = std::move(d);
  return {};
}

}  // namespace mozzi::devices::campaign
