#pragma once
// What an impact campaign is (thesis §1.4, §1.6): the specimen and its
// measurement DOFs, how it is held, how it is excited, which transducer sits
// on which channel and DOF, how each hit is acquired, checked and averaged.
// Stored as JSON with the campaign (campaign.settings_json, docs/formats/
// project.md); the roving schedule (order, skips) is stored beside it.
//
// Excitation (thesis §1.6, eq. 21): a roving hammer over the points with the
// accelerometers fixed measures one row of the FRF matrix; a roving
// accelerometer with the hammer at a fixed point measures one column. A
// channel marked `roving` measures at the current point's DOF (the hammer of a
// roving-hammer campaign, the accelerometer of a roving-accelerometer one);
// every other channel measures at its own fixed DOF.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/result.h"
#include "core/signal/frf_estimator.h"
#include "core/signal/time_record.h"
#include "devices/common/acquisition.h"
#include "devices/common/parameters.h"

namespace mozzi::devices::campaign {

enum class ConstraintKind { FreeFree, Clamped, OnRig };
const char* constraintKindName(ConstraintKind kind);  // "free-free", "clamped", "on-rig"
core::Result<ConstraintKind> parseConstraintKind(const std::string& text);

struct Constraint {
  ConstraintKind kind = ConstraintKind::FreeFree;
  std::vector<int> clampedNodes;  // node labels held fixed (Clamped)
  std::string description;        // "front-constrained: steering head clamped", "Motostiffmeter"
};

enum class ExcitationKind { RovingHammer, RovingAccelerometer };
const char* excitationKindName(ExcitationKind kind);  // "roving-hammer", "roving-accelerometer"
core::Result<ExcitationKind> parseExcitationKind(const std::string& text);

// One acquisition channel: the transducer on it and where it measures.
struct ChannelAssignment {
  int input = 0;     // device input, AI0 = 0
  std::string name;  // "hammer", "acc 1"
  core::signal::Transducer transducer;
  std::string calibrationDate;  // ISO 8601 date of the transducer's last calibration, "" unknown
  std::uint8_t rangeCode = 0;   // DAQ input range (InputRange::code)
  double conditionerGain = 1.0;
  bool roving = false;  // measures at the current point's DOF
  core::Dof dof;        // fixed DOF (ignored when roving)
};

struct AcquisitionSettings {
  double sampleRateHz = 1024.0;
  double recordSeconds = 2.0;       // record length
  double preTriggerFraction = 0.1;  // of the record, before the trigger (common practice 10%)
  double triggerLevel = 10.0;       // force trigger level [N], rising slope on the force channel
};

struct WindowSettings {
  // Force window on the hammer channel (rectangular up to forceWidthS after
  // the trigger, then a half-cosine taper); 0 = rectangular over the record.
  double forceWidthS = 0.0;
  double forceTaperS = 0.0;
  // Exponential window on every channel; 0 = none. Its added damping is
  // removed again by identify (core/signal/window.h).
  double exponentialTauS = 0.0;
};

// Automatic rejection rules (thesis §1.6 practice; core/signal/hit_quality.h).
struct RejectionRules {
  bool doubleHit = true;       // a second impact after the main pulse
  bool overload = true;        // a channel at the converter's full scale
  double minPeakForceN = 0.0;  // force too low: |peak| below this [N] (0 = only the SNR check)
  double minForceSnrDb = 30.0;
  // Poor coherence: mean coherence over [coherenceBandLowHz, coherenceBandHighHz]
  // of the point's running average with the hit added, from the second hit
  // of a point on; 0 = off. Band 0:0 = the stored FRF band.
  double minCoherence = 0.0;
  double coherenceBandLowHz = 0.0;
  double coherenceBandHighHz = 0.0;
};

struct CampaignDefinition {
  // Specimen: the virtual specimen key when simulated ("fork-a-with-wheel"),
  // else empty; the mesh template the DOFs come from, when any.
  std::string specimenKey;
  std::string meshTemplate;
  std::vector<core::Dof> points;  // the measurement DOFs in roving order
  Constraint constraint;
  ExcitationKind excitation = ExcitationKind::RovingHammer;
  std::optional<core::Dof> fixedPoint;  // the fixed hammer (roving accelerometer) or reference accelerometer DOF
  std::vector<ChannelAssignment> channels;
  AcquisitionSettings acquisition;
  int hitsPerPoint = 5;
  WindowSettings windows;
  core::signal::FrfEstimator estimator = core::signal::FrfEstimator::H1;
  double frfMaxHz = 0.0;  // stored FRF lines up to here; 0 = sampleRate / 2.56 (analyser practice)
  RejectionRules rules;
  // Station: driver registry key and serial ("" = the first device found),
  // rig parameters (ParameterSpec keys of the driver), seed of a simulated rig.
  std::string driver;
  std::string deviceSerial;
  ParameterMap deviceParameters;
  std::uint64_t seed = 1;

  // Every field in its domain; the error names the field.
  core::Result<void> validate() const;

  std::int64_t recordScans() const;      // round(recordSeconds * sampleRateHz)
  std::int64_t preTriggerScans() const;  // as SoftwareTrigger cuts it
  double storedBandHz() const;           // frfMaxHz or sampleRate / 2.56
  int forceChannel() const;              // index into channels of the Force transducer (-1 none)
  core::Dof channelDof(std::size_t channel, const core::Dof& point) const;
  std::vector<std::size_t> rovingChannels() const;
  core::signal::FrfOptions frfOptions() const;
};

nlohmann::json definitionToJson(const CampaignDefinition& definition);
// Parses and validates; errors name the JSON field.
core::Result<CampaignDefinition> definitionFromJson(const nlohmann::json& json);
core::Result<CampaignDefinition> parseDefinition(const std::string& text);

// The device configuration of one hit: channels with the DOFs of `point`,
// rate, rig parameters (definition's, then `overrides`).
AcquisitionConfig acquisitionConfigFor(const CampaignDefinition& definition, const core::Dof& point,
                                       const ParameterMap& overrides = {});

// The time record of a hit from its samples (recordScans x channels, EU) at
// `point`, sampled at the device's actual rate; fullScale per channel [EU]
// (empty: unknown).
core::signal::TimeRecord timeRecordFor(const CampaignDefinition& definition, const core::Dof& point,
                                       double sampleRateHz, const std::vector<double>& fullScale, core::Matrix samples);

}  // namespace mozzi::devices::campaign
